// A texture the size of the viewport copied over it: one triangle covers
// the viewport, and each pixel takes its texel. The shader that uses this
// declares `copied_image: texture_2d<f32>` at its own binding.

struct CopyOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@vertex
fn vs_copy(@builtin(vertex_index) index: u32) -> CopyOut {
    // (0, 0), (2, 0), (0, 2): a triangle whose middle is the viewport.
    let x = f32((index << 1u) & 2u);
    let y = f32(index & 2u);
    var out: CopyOut;
    out.clip = vec4<f32>(x * 2.0 - 1.0, 1.0 - y * 2.0, 0.0, 1.0);
    out.uv = vec2<f32>(x, y);
    return out;
}

fn copied_texel(uv: vec2<f32>) -> vec4<f32> {
    let size = vec2<f32>(textureDimensions(copied_image));
    let texel = vec2<i32>(clamp(uv * size, vec2<f32>(0.0), size - 1.0));
    return textureLoad(copied_image, texel, 0);
}
