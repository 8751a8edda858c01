// Vertex spheres: one instanced icosphere per vertex.

@vertex
fn vs_sphere(
    @location(0) unit: vec3<f32>,
    @location(1) center: vec3<f32>,
    @location(2) colour: vec4<f32>,
    // x: emphasis (highlighted), others unused.
    @location(3) extra: vec4<f32>,
) -> LitOut {
    let radius = frame.sizes.x * (1.0 + 0.45 * extra.x);
    let world = center + unit * radius;
    var out: LitOut;
    out.clip = frame.clip_from_world * vec4<f32>(world, 1.0);
    out.world = world;
    out.normal = unit;
    out.colour = colour;
    return out;
}
