//! The world axes: three arrows from the origin (x red, y green, z blue),
//! drawn with the arrow pipeline, and their letters.

use glam::Vec3;

use super::arrows::ArrowInstance;
use super::gpu::StyleVertex;
use edgewise_pictures::palette::Palette;
use edgewise_pictures::scene::{Scene, Sizes};

/// Arrow scale multiplier range the shader decodes from `extra.z`
/// (`1 + 40 z`).
const SCALE_RANGE: f32 = 40.0;

/// Length of each axis in world units.
pub fn length(scene: &Scene) -> f32 {
    scene.radius * 0.7
}

/// The three axis arrows and their styles. Their thickness follows the axis
/// length, not the mesh's edges.
pub fn instances(
    scene: &Scene,
    sizes: &Sizes,
    palette: &Palette,
) -> ([ArrowInstance; 3], [StyleVertex; 3]) {
    let length = length(scene);
    let arrows = [Vec3::X, Vec3::Y, Vec3::Z].map(|axis| ArrowInstance {
        start: [0.0; 3],
        end: (axis * length).to_array(),
    });
    let wanted = length * 0.012;
    let scale = if sizes.shaft_radius > 0.0 {
        ((wanted / sizes.shaft_radius - 1.0) / SCALE_RANGE).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let styles = palette.axes.map(|colour| {
        let [r, g, b, _] = colour.to_srgba_unmultiplied();
        StyleVertex {
            colour: [r, g, b, 255],
            extra: [0, 255, (scale * 255.0).round() as u8, 0],
        }
    });
    (arrows, styles)
}

/// Where the axis letters go, with their colours.
pub fn letters(scene: &Scene, palette: &Palette) -> [(Vec3, &'static str, egui::Color32); 3] {
    let length = length(scene) * 1.08;
    [
        (Vec3::X * length, "x", palette.axes[0]),
        (Vec3::Y * length, "y", palette.axes[1]),
        (Vec3::Z * length, "z", palette.axes[2]),
    ]
}
