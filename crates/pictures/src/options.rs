//! The view options the user controls, which a course link carries and the
//! pictures follow.

use ecolor::Color32;
use edgewise_core::schema::ElementKind;
use serde::{Deserialize, Serialize};

/// Which elements clicks can pick (an algorithm asking for a face makes only
/// faces pickable).
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default, Serialize, Deserialize)]
pub enum PickFilter {
    #[default]
    All,
    Only(ElementKind),
}

/// When element ids are drawn.
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default, Serialize, Deserialize)]
pub enum DrawIds {
    /// Only for elements with a highlight or a label.
    #[default]
    Highlighted,
    Always,
    Never,
}

/// The view options the user controls.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ViewOptions {
    pub draw_ids: DrawIds,
    /// Thickness of vertices and edges (1 = default).
    pub mesh_scale: f32,
    /// Size of labels (1 = default).
    pub label_scale: f32,
    pub show_axes: bool,
    pub show_orientation: bool,
    pub solid_faces: bool,
    pub pickable: PickFilter,
    pub dark: bool,
    /// The user's colour for boundary half-edges, in place of the
    /// palette's (from the theme, so not saved with the view).
    #[serde(skip)]
    pub boundary: Option<Color32>,
    /// The frame was cleared to the background colour
    /// ([`Palette::background`]), so the view does not fill it again: each
    /// full-view fill costs a software renderer tens of milliseconds.
    pub backdrop_cleared: bool,
    /// Draw the coarse level of detail from an image kept while the camera,
    /// the mesh and the colours stay (`base_image.rs`); off redraws it every
    /// frame, to compare the two.
    #[serde(skip, default = "on")]
    pub base_image: bool,
    /// How many lines and triangles a frame draws of a new mesh's base
    /// image (see `base_image.rs`).
    #[serde(skip, default = "base_image_part")]
    pub base_image_part: u32,
    /// Draw a large mesh's motion proxy while the camera moves
    /// (`motion_proxy.rs`); off draws the mesh itself, to compare the two.
    #[serde(skip, default = "on")]
    pub motion_proxy: bool,
}

fn on() -> bool {
    true
}

/// Under `SwiftShader` a frame drawing a part of 125k took 150 to 200 ms in
/// all; 100k keeps such frames well under a quarter second, and
/// torus-200k's 300k lines and 200k triangles take five.
const BASE_IMAGE_PART: u32 = 100_000;

fn base_image_part() -> u32 {
    BASE_IMAGE_PART
}

impl Default for ViewOptions {
    fn default() -> Self {
        Self {
            draw_ids: DrawIds::Highlighted,
            mesh_scale: 1.0,
            label_scale: 1.0,
            show_axes: false,
            show_orientation: false,
            solid_faces: false,
            pickable: PickFilter::All,
            dark: false,
            boundary: None,
            backdrop_cleared: false,
            base_image: true,
            base_image_part: BASE_IMAGE_PART,
            motion_proxy: true,
        }
    }
}
