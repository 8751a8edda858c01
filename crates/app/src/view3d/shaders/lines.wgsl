// Edges as one-pixel lines: the coarse level of detail, for edges only a
// few pixels long on screen. Each instance is the edge's arrow, drawn from
// its start to its end, in the arrow's colour.

struct LineOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) colour: vec4<f32>,
};

@vertex
fn vs_line(
    // 0 at the start, 1 at the end.
    @location(0) along: f32,
    @location(1) start: vec3<f32>,
    @location(2) end: vec3<f32>,
    @location(3) colour: vec4<f32>,
    // x: emphasis (highlighted); see vs_arrow.
    @location(4) extra: vec4<f32>,
) -> LineOut {
    var out: LineOut;
    let world = mix(start, end, along);
    out.clip = frame.clip_from_world * vec4<f32>(world, 1.0);
    let pixel = pixel_size(mix(start, end, 0.5));
    let size = length(end - start) / max(pixel, 1e-30);
    out.colour = vec4<f32>(fade_small(colour.rgb, size, 24.0, extra.x + extra.y), colour.a);
    return out;
}

@fragment
fn fs_line(in: LineOut) -> @location(0) vec4<f32> {
    return to_target(in.colour.rgb, 1.0);
}
