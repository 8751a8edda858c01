// The coarse level of detail's base image, copied over the view (after
// common.wgsl and texture_copy.wgsl). The image is drawn unfaded; while
// plain elements fade, the copy fades it as a whole, which fades each line
// and face as drawing them faded would (style.rs's FADE_FACE_ALPHA).

@group(1) @binding(0) var copied_image: texture_2d<f32>;

@fragment
fn fs_base_image(in: CopyOut) -> @location(0) vec4<f32> {
    let image = copied_texel(in.uv);
    let fade = frame.fade.x * frame.fade.y;
    let background = to_target(frame.background.rgb, image.a).rgb;
    return vec4<f32>(mix(image.rgb, background, fade), image.a);
}
