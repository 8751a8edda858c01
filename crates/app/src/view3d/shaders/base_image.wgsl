// The coarse level of detail's base image, copied over the view: one
// triangle covers the viewport, and each pixel takes its texel. The image
// is drawn unfaded; while plain elements fade, the copy fades it as a
// whole, which fades each line and face as drawing them faded would
// (style.rs's FADE_FACE_ALPHA). Used after common.wgsl.

@group(1) @binding(0) var base_image: texture_2d<f32>;

struct CopyOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@vertex
fn vs_base_image(@builtin(vertex_index) index: u32) -> CopyOut {
    // (0, 0), (2, 0), (0, 2): a triangle whose middle is the viewport.
    let x = f32((index << 1u) & 2u);
    let y = f32(index & 2u);
    var out: CopyOut;
    out.clip = vec4<f32>(x * 2.0 - 1.0, 1.0 - y * 2.0, 0.0, 1.0);
    out.uv = vec2<f32>(x, y);
    return out;
}

@fragment
fn fs_base_image(in: CopyOut) -> @location(0) vec4<f32> {
    let size = vec2<f32>(textureDimensions(base_image));
    let texel = vec2<i32>(clamp(in.uv * size, vec2<f32>(0.0), size - 1.0));
    let image = textureLoad(base_image, texel, 0);
    let fade = frame.fade.x * frame.fade.y;
    let background = to_target(frame.background.rgb, image.a).rgb;
    return vec4<f32>(mix(image.rgb, background, fade), image.a);
}
