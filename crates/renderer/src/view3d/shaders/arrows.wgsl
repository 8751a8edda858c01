// Edge arrows: one instanced shaft-and-cone per edge or half-edge (and per
// axis). The template is a unit arrow described by selectors, so the head
// keeps its size whatever the edge length.

@vertex
fn vs_arrow(
    // x, y: direction around the axis; z: where along the arrow (0 start,
    // 1 head base, 2 tip); w: which radius (0 shaft, 1 head, 2 none).
    @location(0) shape: vec4<f32>,
    // Normal: 0 around the shaft, 1 on the cone, 2 facing backwards.
    @location(1) normal_kind: f32,
    @location(2) start: vec3<f32>,
    @location(3) end: vec3<f32>,
    @location(4) style_colour: vec4<f32>,
    // x: emphasis (highlighted), y: 1 to keep the ends where they are,
    // z: extra thickness (1 + 40 z; the axes), w: no style of its own.
    @location(5) extra: vec4<f32>,
) -> LitOut {
    let colour = plain_line(style_colour, extra);
    var out: LitOut;
    out.colour = colour;
    out.world = start;
    out.normal = vec3<f32>(0.0, 0.0, 1.0);
    let span = end - start;
    let full = length(span);
    if full < 1e-30 {
        out.clip = culled();
        return out;
    }
    let dir = span / full;
    let emphasis = (1.0 + 0.5 * extra.x) * (1.0 + 40.0 * extra.z);
    let gap = min(frame.sizes.x * frame.params.y * (1.0 - extra.y), 0.3 * full);
    let a = start + dir * gap;
    let len = full - 2.0 * gap;
    let head_length = min(frame.sizes.w * emphasis, 0.5 * len);
    // At least about a pixel wide, so a dense mesh reads as a steady wireframe.
    let pixel = pixel_size(a + dir * (0.5 * len));
    // Highlighted arrows are at least three pixels thick.
    let shaft_radius = max(frame.sizes.y * emphasis, (0.6 + 0.9 * extra.x) * pixel);
    out.colour = vec4<f32>(fade_small(colour.rgb, len / max(pixel, 1e-30), 24.0, extra.x + extra.y), colour.a);
    let head_radius = max(frame.sizes.z * emphasis, shaft_radius * (1.0 + 0.8 * extra.x));

    var helper = vec3<f32>(0.0, 1.0, 0.0);
    if abs(dir.y) > 0.9 {
        helper = vec3<f32>(1.0, 0.0, 0.0);
    }
    let u = normalize(cross(dir, helper));
    let v = cross(dir, u);
    let radial = u * shape.x + v * shape.y;

    var along = len;
    if shape.z < 0.5 {
        along = 0.0;
    } else if shape.z < 1.5 {
        along = len - head_length;
    }
    var radius = 0.0;
    if shape.w < 0.5 {
        radius = shaft_radius;
    } else if shape.w < 1.5 {
        radius = head_radius;
    }
    var normal = radial;
    if normal_kind > 1.5 {
        normal = -dir;
    } else if normal_kind > 0.5 {
        normal = radial * head_length + dir * head_radius;
    }

    let world = a + dir * along + radial * radius;
    out.clip = frame.clip_from_world * vec4<f32>(world, 1.0);
    out.world = world;
    out.normal = normal;
    return out;
}
