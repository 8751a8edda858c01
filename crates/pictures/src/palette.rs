//! The view's colours: the base palette for light and dark themes (the
//! journal's scheme: gray base, highlights in the app's colours), and the
//! colour each element is drawn in, faded or not. The GPU view and the
//! vector pictures both draw in these.

use ecolor::Color32;

use crate::options::ViewOptions;
use crate::styles::ElementStyle;

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
    /// Base colour of a boundary half-edge (one without a face), as the
    /// half-edge explainer sets them apart.
    pub boundary: Color32,
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
                boundary: Color32::from_rgb(222, 150, 92),
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
                boundary: Color32::from_rgb(172, 92, 30),
            }
        }
    }

    /// The palette `options` ask for: their theme, and their boundary
    /// colour if one is set.
    pub fn of(options: &ViewOptions) -> Self {
        let mut palette = Self::new(options.dark);
        if let Some(boundary) = options.boundary {
            palette.boundary = boundary;
        }
        palette
    }

    /// A colour washed towards the background, for faded elements.
    pub fn faded(&self, colour: Color32) -> Color32 {
        mix(colour, self.background, FADE_LINE)
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

pub fn rgb(colour: Color32) -> [u8; 3] {
    let [r, g, b, _] = colour.to_srgba_unmultiplied();
    [r, g, b]
}

/// How far a faded vertex or edge moves towards the background.
pub const FADE_LINE: f32 = 0.72;
/// How far a faded face moves towards the background.
pub const FADE_FACE_MIX: f32 = 0.4;
/// What a faded face keeps of its opacity: as much of its colour shows as
/// of a faded line's, so fading a picture of plain lines and faces as a
/// whole (the coarse view's base image) fades each as drawing it faded does.
pub const FADE_FACE_ALPHA: f32 = (1.0 - FADE_LINE) / (1.0 - FADE_FACE_MIX);

/// The colour a vertex or edge is drawn in, `base` being its colour
/// without a style of its own.
pub fn line_colour(style: &ElementStyle, palette: &Palette, base: Color32) -> Color32 {
    let colour = style.colour.unwrap_or(base);
    if style.faded {
        palette.faded(colour)
    } else {
        colour
    }
}

/// The colour a see-through face is drawn in, and its opacity.
pub fn face_colour(style: &ElementStyle, palette: &Palette) -> (Color32, f32) {
    let (colour, mut alpha) = match style.colour {
        Some(colour) => (colour, palette.face_highlight_alpha),
        None => (palette.face, palette.face_alpha),
    };
    if style.faded {
        alpha *= FADE_FACE_ALPHA;
    }
    let colour = if style.faded {
        mix(colour, palette.background, FADE_FACE_MIX)
    } else {
        colour
    };
    (colour, alpha)
}

/// `colour` faded towards the background as an element `size` pixels big
/// is, like `fade_small` in shaders/common.wgsl: a dense mesh seen whole
/// reads as a surface with a light wireframe.
pub fn fade_small(colour: Color32, size: f32, full: f32, palette: &Palette) -> Color32 {
    let keep = (size / full).clamp(0.0, 1.0);
    mix(colour, palette.background, (1.0 - keep) * 0.8)
}

/// `#rrggbb`.
pub fn to_hex(colour: Color32) -> String {
    let [r, g, b, _] = colour.to_srgba_unmultiplied();
    format!("#{r:02x}{g:02x}{b:02x}")
}
