//! A 3D view with the geometry and colours it draws: what a tab and its
//! side-by-side twin share. Both follow their document by keys: the
//! geometry is made again exactly when the mesh id differs from the one it
//! was made from, and the styles when the [`PaintKey`] does, so no change
//! of mesh, selection, step or theme needs a hand-written reset.

use edgewise_core::mesh::Mesh;
use edgewise_pictures::geometry::MeshGeometry;
use edgewise_pictures::options::ViewOptions;
use edgewise_pictures::styles::SceneStyles;
use edgewise_renderer::view3d::{Preparation, View3d, ViewResponse};

use edgewise_model::{document::Document, paint::Paint};

/// Everything a view's colours and labels are derived from, each by a
/// number that changes with it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct PaintKey {
    /// The document's generation: its mesh and selection.
    pub(crate) document: u64,
    /// The run's generation: its algorithm and step (0 for a view with
    /// no run).
    pub(crate) run: u64,
    /// The broken records and last changes marked.
    pub(crate) marks: u64,
    pub(crate) theme: u64,
}

pub(crate) struct Pane {
    pub(crate) view: View3d,
    styles: SceneStyles,
    /// The mesh id of the document whose geometry the view holds.
    geometry_of: Option<u64>,
    /// What `styles` were derived from.
    styled: Option<PaintKey>,
}

impl Pane {
    /// An empty pane drawing with `render_state` (none in headless tests).
    pub(crate) fn new(render_state: Option<&eframe::egui_wgpu::RenderState>) -> Self {
        Self {
            view: View3d::new(render_state),
            styles: SceneStyles::default(),
            geometry_of: None,
            styled: None,
        }
    }

    /// Makes the view's geometry from `document`'s mesh unless it was made
    /// from that very mesh.
    pub(crate) fn follow_mesh(&mut self, document: &Document) {
        if self.geometry_of != Some(document.mesh_id()) {
            self.view
                .set_geometry(MeshGeometry::from_mesh(document.mesh()), false);
            self.geometry_of = Some(document.mesh_id());
        }
    }

    /// Shows geometry prepared (in slices, for a large mesh) from the mesh
    /// with `mesh_id`, framing it if `frame` is true.
    pub(crate) fn show_prepared(&mut self, mesh_id: u64, preparation: Preparation, frame: bool) {
        self.view.show_prepared(preparation, frame);
        self.geometry_of = Some(mesh_id);
    }

    /// Whether the styles were derived for `key`.
    pub(crate) fn styled_for(&self, key: PaintKey) -> bool {
        self.styled == Some(key)
    }

    /// Derives the styles of `mesh`'s elements from `paint`, for `key`.
    pub(crate) fn restyle(&mut self, key: PaintKey, mesh: &Mesh, paint: &Paint) {
        self.styles = edgewise_model::paint::scene_styles(mesh, paint, self.styles.generation + 1);
        self.styled = Some(key);
    }

    /// Lays the view out as its first frame at `size` would, with no
    /// window (`edgewise render`).
    pub(crate) fn lay_out_offscreen(&mut self, size: egui::Vec2, options: &ViewOptions) {
        self.view.lay_out_offscreen(size, &self.styles, options);
    }

    /// Draws the view; what was hovered or clicked.
    pub(crate) fn ui(&mut self, ui: &mut egui::Ui, options: &ViewOptions) -> ViewResponse {
        self.view.ui(ui, &self.styles, options)
    }
}
