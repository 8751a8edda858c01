// Faces: triangulated, each triangle corner carrying its face's colour.
// Drawn see-through (after everything opaque, depth test without writes) or
// solid.

struct FaceOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) colour: vec4<f32>,
    // 1 for a highlighted face.
    @location(2) highlighted: f32,
};

@vertex
fn vs_face(
    @location(0) position: vec3<f32>,
    @location(1) colour: vec4<f32>,
    @location(2) extra: vec4<f32>,
) -> FaceOut {
    var out: FaceOut;
    out.clip = frame.clip_from_world * vec4<f32>(position, 1.0);
    out.world = position;
    out.colour = plain_face(colour, extra);
    out.highlighted = extra.x;
    return out;
}

fn face_normal(world: vec3<f32>) -> vec3<f32> {
    return cross(dpdx(world), dpdy(world));
}

@fragment
fn fs_face_transparent(in: FaceOut) -> @location(0) vec4<f32> {
    let rgb = shade(in.colour.rgb, face_normal(in.world), in.world, 0.72);
    return to_target(rgb, in.colour.a);
}

@fragment
fn fs_face_solid(in: FaceOut) -> @location(0) vec4<f32> {
    // Base faces lean towards the background so edges and vertices stand
    // out against them; highlighted faces keep their colour.
    let base = mix(in.colour.rgb, frame.background.rgb, 0.45 * (1.0 - step(0.5, in.highlighted)));
    let rgb = shade(base, face_normal(in.world), in.world, 0.6);
    return to_target(rgb, 1.0);
}
