// Face orientation marks: a curved arrow in each face's plane turning from
// `u` towards `v`, the way the structure traverses the face.

struct MarkOut {
    @builtin(position) clip: vec4<f32>,
};

@vertex
fn vs_orientation(
    // Position in the mark's own plane: x along `u`, y along `v`.
    @location(0) local: vec2<f32>,
    @location(1) center: vec3<f32>,
    @location(2) u: vec3<f32>,
    @location(3) v: vec3<f32>,
) -> MarkOut {
    var out: MarkOut;
    let n = cross(u, v);
    var lift = vec3<f32>(0.0);
    if dot(n, n) > 1e-30 {
        lift = normalize(n) * frame.params.z;
    }
    let world = center + u * local.x + v * local.y + lift;
    out.clip = frame.clip_from_world * vec4<f32>(world, 1.0);
    return out;
}

@fragment
fn fs_orientation(in: MarkOut) -> @location(0) vec4<f32> {
    return to_target(frame.orientation_colour.rgb, 1.0);
}
