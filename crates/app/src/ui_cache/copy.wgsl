// A cached part of the UI copied over the paint callback's viewport: one
// triangle covers the viewport, and each pixel takes its texel (the
// texture is the viewport's size, premultiplied as egui draws).

@group(0) @binding(0) var part: texture_2d<f32>;

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

@fragment
fn fs_copy(in: CopyOut) -> @location(0) vec4<f32> {
    let size = vec2<f32>(textureDimensions(part));
    let texel = vec2<i32>(clamp(in.uv * size, vec2<f32>(0.0), size - 1.0));
    return textureLoad(part, texel, 0);
}
