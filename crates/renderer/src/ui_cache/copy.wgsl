// A cached part of the UI copied over its paint callback's viewport (after
// texture_copy.wgsl); the texture is premultiplied, as egui draws.

@group(0) @binding(0) var copied_image: texture_2d<f32>;

@fragment
fn fs_part(in: CopyOut) -> @location(0) vec4<f32> {
    return copied_texel(in.uv);
}
