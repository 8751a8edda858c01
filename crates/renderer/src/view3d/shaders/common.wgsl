// Shared by every 3D view shader: the per-frame uniform, lighting and the
// conversion to the render target.

struct Frame {
    clip_from_world: mat4x4<f32>,
    // World position of the eye (w unused).
    eye: vec4<f32>,
    // Unit direction towards the light, world space (w unused).
    light: vec4<f32>,
    // Vertex radius, arrow shaft radius, arrow head radius, arrow head length.
    sizes: vec4<f32>,
    // x: unused (see `srgb_target`),
    // y: how much of the vertex radius arrow ends are pulled back,
    // z: lift of orientation marks off their face,
    // w: world size of one pixel per unit of clip w (distance in front of the eye).
    params: vec4<f32>,
    orientation_colour: vec4<f32>,
    // The view's background (gamma space), which tiny elements fade into.
    background: vec4<f32>,
    // The coarse level of detail's edge and face colours (gamma space; the
    // face's alpha is its opacity).
    coarse_line: vec4<f32>,
    coarse_face: vec4<f32>,
    // x: 1 while elements without a style of their own fade (others are
    // highlighted); y: how far their lines move to the background; z: what
    // their faces keep of their opacity; w: how far faces move.
    fade: vec4<f32>,
};

@group(0) @binding(0) var<uniform> frame: Frame;

// Whether the render target is sRGB, so colours are converted to linear.
// Fixed per pipeline rather than read from the frame: a software renderer
// (SwiftShader) runs both sides of a branch on a uniform, and the
// conversion's three `pow`s nearly doubled what a lit pixel cost.
override srgb_target: bool;

// Output of the lit (sphere and arrow) vertex shaders.
struct LitOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) colour: vec4<f32>,
};

fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    let low = c / 12.92;
    let high = pow((c + vec3<f32>(0.055)) / 1.055, vec3<f32>(2.4));
    return select(high, low, c <= vec3<f32>(0.04045));
}

// Two-sided Blinn-Phong with a light over the viewer's shoulder; `ambient`
// is how bright the unlit side stays.
fn shade(base: vec3<f32>, normal: vec3<f32>, world: vec3<f32>, ambient: f32) -> vec3<f32> {
    let to_eye = normalize(frame.eye.xyz - world);
    var n = to_eye;
    if dot(normal, normal) > 1e-20 {
        n = normalize(normal);
    }
    if dot(n, to_eye) < 0.0 {
        n = -n;
    }
    let diffuse = max(dot(n, frame.light.xyz), 0.0);
    let half_vector = normalize(frame.light.xyz + to_eye);
    let specular = pow(max(dot(n, half_vector), 0.0), 48.0) * 0.16;
    return base * (ambient + (1.0 - ambient) * diffuse) + vec3<f32>(specular);
}

// Premultiplied colour for the target (egui blends premultiplied).
fn to_target(rgb: vec3<f32>, alpha: f32) -> vec4<f32> {
    var c = clamp(rgb, vec3<f32>(0.0), vec3<f32>(1.0));
    if srgb_target {
        c = srgb_to_linear(c);
    }
    return vec4<f32>(c * alpha, alpha);
}

// World size of one pixel at a world position, so thin things can be kept
// at least a pixel wide instead of breaking up into sparkles.
fn pixel_size(world: vec3<f32>) -> f32 {
    let clip = frame.clip_from_world * vec4<f32>(world, 1.0);
    return max(clip.w, 0.0) * frame.params.w;
}

// Base colours of elements only a few pixels big fade towards the
// background, so a dense mesh seen whole reads as a surface with a light
// wireframe instead of a solid mass; highlighted elements never fade.
// `size` is the element's size in pixels, `full` the size it is fully
// coloured at.
fn fade_small(colour: vec3<f32>, size: f32, full: f32, highlighted: f32) -> vec3<f32> {
    let keep = clamp(size / full, 0.0, 1.0);
    let amount = (1.0 - keep) * 0.8 * (1.0 - step(0.5, highlighted));
    return mix(colour, frame.background.rgb, amount);
}

// An element without a style of its own (`extra.w`) fades while others
// are highlighted, as style.rs fades it: the same styles serve both, so a
// first selection does not rewrite every element's style.
fn plain_line(colour: vec4<f32>, extra: vec4<f32>) -> vec4<f32> {
    let amount = frame.fade.x * frame.fade.y * step(0.5, extra.w);
    return vec4<f32>(mix(colour.rgb, frame.background.rgb, amount), colour.a);
}

fn plain_face(colour: vec4<f32>, extra: vec4<f32>) -> vec4<f32> {
    let on = frame.fade.x * step(0.5, extra.w);
    let rgb = mix(colour.rgb, frame.background.rgb, frame.fade.w * on);
    return vec4<f32>(rgb, colour.a * mix(1.0, frame.fade.z, on));
}

// A position no triangle can be rasterised at (outside the depth range).
fn culled() -> vec4<f32> {
    return vec4<f32>(0.0, 0.0, -2.0, 1.0);
}

@fragment
fn fs_lit(in: LitOut) -> @location(0) vec4<f32> {
    return to_target(shade(in.colour.rgb, in.normal, in.world, 0.42), 1.0);
}
