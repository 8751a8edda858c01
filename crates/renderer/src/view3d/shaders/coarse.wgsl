// The coarse level of detail: the mesh's own vertices, drawn as one line
// per edge and flat faces, in the colours of the frame uniform, faded as
// plain elements are. Used with faces.wgsl, whose fragment shaders draw the
// faces.

// Every element drawn here is plain: it has no style of its own.
const PLAIN: vec4<f32> = vec4<f32>(0.0, 0.0, 0.0, 1.0);

struct LineOut {
    @builtin(position) clip: vec4<f32>,
};

@vertex
fn vs_coarse_line(@location(0) position: vec3<f32>) -> LineOut {
    var out: LineOut;
    out.clip = frame.clip_from_world * vec4<f32>(position, 1.0);
    return out;
}

@fragment
fn fs_coarse_line(in: LineOut) -> @location(0) vec4<f32> {
    return to_target(plain_line(frame.coarse_line, PLAIN).rgb, 1.0);
}

@vertex
fn vs_coarse_face(@location(0) position: vec3<f32>) -> FaceOut {
    var out: FaceOut;
    out.clip = frame.clip_from_world * vec4<f32>(position, 1.0);
    out.world = position;
    out.colour = plain_face(frame.coarse_face, PLAIN);
    out.highlighted = 0.0;
    return out;
}
