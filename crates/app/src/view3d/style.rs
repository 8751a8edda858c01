//! Colours: the base palette for light and dark themes (the journal's
//! scheme: gray base, highlights in the app's colours) and the per-element
//! GPU styles built from [`SceneStyles`].

use egui::Color32;

use super::arrows::ArrowInstance;
use super::gpu::StyleVertex;
use super::renderer::StyleUpload;
use super::scene::Scene;
use super::spheres::SphereInstance;
use super::{ElementStyle, SceneStyles, faces};

/// The view's own colours for one theme.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Palette {
    pub background: Color32,
    /// Base colour of vertices and edges.
    pub line: Color32,
    /// Base colour of faces and their opacity when see-through.
    pub face: Color32,
    pub face_alpha: f32,
    /// Opacity of a highlighted see-through face.
    pub face_highlight_alpha: f32,
    pub orientation: Color32,
    pub label_fill: Color32,
    pub label_text: Color32,
    pub label_stroke: Color32,
    pub hover: Color32,
    pub axes: [Color32; 3],
}

impl Palette {
    pub fn new(dark: bool) -> Self {
        if dark {
            Self {
                background: Color32::from_rgb(30, 31, 34),
                line: Color32::from_rgb(168, 170, 176),
                face: Color32::from_rgb(128, 132, 142),
                face_alpha: 0.16,
                face_highlight_alpha: 0.5,
                orientation: Color32::from_rgb(104, 176, 186),
                label_fill: Color32::from_rgba_unmultiplied(44, 46, 51, 235),
                label_text: Color32::from_rgb(226, 226, 230),
                label_stroke: Color32::from_rgb(88, 90, 98),
                hover: Color32::from_rgb(96, 172, 255),
                axes: [
                    Color32::from_rgb(226, 104, 94),
                    Color32::from_rgb(112, 196, 120),
                    Color32::from_rgb(112, 150, 236),
                ],
            }
        } else {
            Self {
                background: Color32::from_rgb(247, 247, 245),
                line: Color32::from_rgb(108, 110, 116),
                face: Color32::from_rgb(150, 153, 162),
                face_alpha: 0.2,
                face_highlight_alpha: 0.5,
                orientation: Color32::from_rgb(52, 122, 134),
                label_fill: Color32::from_rgba_unmultiplied(255, 255, 255, 235),
                label_text: Color32::from_rgb(38, 38, 44),
                label_stroke: Color32::from_rgb(186, 188, 194),
                hover: Color32::from_rgb(0, 108, 204),
                axes: [
                    Color32::from_rgb(196, 64, 54),
                    Color32::from_rgb(52, 146, 64),
                    Color32::from_rgb(52, 94, 196),
                ],
            }
        }
    }

    /// A colour washed towards the background, for faded elements.
    pub fn faded(&self, colour: Color32) -> Color32 {
        mix(colour, self.background, 0.72)
    }
}

/// `a` moved towards `b` by `t` (in sRGB space, which is how they look).
pub fn mix(a: Color32, b: Color32, t: f32) -> Color32 {
    let [ar, ag, ab, _] = a.to_srgba_unmultiplied();
    let [br, bg, bb, _] = b.to_srgba_unmultiplied();
    let lerp = |x: u8, y: u8| {
        (f32::from(x) + (f32::from(y) - f32::from(x)) * t)
            .round()
            .clamp(0.0, 255.0) as u8
    };
    Color32::from_rgb(lerp(ar, br), lerp(ag, bg), lerp(ab, bb))
}

fn rgb(colour: Color32) -> [u8; 3] {
    let [r, g, b, _] = colour.to_srgba_unmultiplied();
    [r, g, b]
}

/// The GPU style of a vertex or edge.
pub fn line_style(style: Option<&ElementStyle>, palette: &Palette) -> StyleVertex {
    let highlighted = style.and_then(|s| s.colour);
    let mut colour = highlighted.unwrap_or(palette.line);
    if style.is_some_and(|s| s.faded) {
        colour = palette.faded(colour);
    }
    let [r, g, b] = rgb(colour);
    StyleVertex {
        colour: [r, g, b, 255],
        extra: [if highlighted.is_some() { 255 } else { 0 }, 0, 0, 0],
    }
}

/// The GPU style of a face (alpha for see-through drawing).
pub fn face_style(style: Option<&ElementStyle>, palette: &Palette) -> StyleVertex {
    let highlighted = style.and_then(|s| s.colour);
    let (colour, mut alpha) = match highlighted {
        Some(colour) => (colour, palette.face_highlight_alpha),
        None => (palette.face, palette.face_alpha),
    };
    let faded = style.is_some_and(|s| s.faded);
    if faded {
        alpha *= 0.45;
    }
    let [r, g, b] = rgb(if faded {
        mix(colour, palette.background, 0.4)
    } else {
        colour
    });
    StyleVertex {
        colour: [r, g, b, (alpha * 255.0).round() as u8],
        extra: [if highlighted.is_some() { 255 } else { 0 }, 0, 0, 0],
    }
}

/// Every element's GPU style.
pub fn build(scene: &Scene, styles: &SceneStyles, palette: &Palette, id: u64) -> StyleUpload {
    let vertices: Vec<StyleVertex> = (0..scene.vertex_count())
        .map(|v| line_style(styles.vertices.get(v), palette))
        .collect();
    let edges: Vec<StyleVertex> = (0..scene.edge_count())
        .map(|e| line_style(styles.edges.get(e), palette))
        .collect();
    let highlighted = |list: &[ElementStyle], count: usize| -> Vec<usize> {
        list.iter()
            .take(count)
            .enumerate()
            .filter(|(_, s)| is_highlighted(s))
            .map(|(i, _)| i)
            .collect()
    };
    let full_spheres = highlighted(&styles.vertices, scene.vertex_count())
        .into_iter()
        .map(|v| {
            let center = scene.position(u32::try_from(v).unwrap_or(u32::MAX));
            (
                SphereInstance {
                    center: center.to_array(),
                },
                vertices[v],
            )
        })
        .unzip();
    let full_arrows = highlighted(&styles.edges, scene.edge_count())
        .into_iter()
        .map(|e| {
            let instance = ArrowInstance {
                start: scene.arrow_starts[e].to_array(),
                end: scene.arrow_ends[e].to_array(),
            };
            (instance, edges[e])
        })
        .unzip();
    StyleUpload {
        id,
        vertices,
        edges,
        faces: faces::corner_styles(scene, |f| face_style(styles.faces.get(f), palette)),
        full_spheres,
        full_arrows,
    }
}

/// Whether an element gets a label in the Highlighted mode: it is coloured
/// or carries a label.
pub fn is_highlighted(style: &ElementStyle) -> bool {
    style.colour.is_some() || style.label.is_some()
}
