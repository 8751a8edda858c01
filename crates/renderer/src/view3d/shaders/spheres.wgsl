// Vertex spheres: one instanced icosphere per vertex.

@vertex
fn vs_sphere(
    @location(0) unit: vec3<f32>,
    @location(1) center: vec3<f32>,
    @location(2) style_colour: vec4<f32>,
    // x: emphasis (highlighted), w: no style of its own; others unused.
    @location(3) extra: vec4<f32>,
) -> LitOut {
    let colour = plain_line(style_colour, extra);
    let pixel = pixel_size(center);
    // At least about a pixel, and a highlighted sphere at least four, so it
    // stays visible on a dense mesh.
    let radius = max(frame.sizes.x * (1.0 + 0.35 * extra.x), (0.9 + 3.1 * extra.x) * pixel);
    let world = center + unit * radius;
    var out: LitOut;
    out.clip = frame.clip_from_world * vec4<f32>(world, 1.0);
    out.world = world;
    out.normal = unit;
    out.colour = vec4<f32>(fade_small(colour.rgb, radius / max(pixel, 1e-30), 4.0, extra.x), colour.a);
    return out;
}
