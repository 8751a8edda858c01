//! Side by side: the open mesh as winged-edge and as half-edge at once, in
//! two 3D views with one linked selection. The twin is the same mesh
//! converted to the other structure; selecting in either view selects the
//! corresponding element in both (a winged edge and its first half-edge).

use edgewise_core::mesh::EdgeCorrespondence;
use edgewise_core::schema::ElementRef;

use super::EdgewiseApp;
use super::pane::{PaintKey, Pane};
use crate::command::CommandError;
use edgewise_model::{
    document::{Document, map_element},
    paint::Paint,
};

/// The other structure's copy of the open mesh and its view.
pub(crate) struct Twin {
    document: Document,
    correspondence: EdgeCorrespondence,
    pane: Pane,
    /// The main document's mesh id the twin was made from.
    source_mesh: u64,
    /// The main document generation whose selection the twin shows.
    synced: u64,
}

impl EdgewiseApp {
    /// [`Command::SetSideBySide`].
    pub(crate) fn show_twin(&mut self, on: bool) -> Result<(), CommandError> {
        self.side_by_side = on;
        if !on {
            self.tab_mut().twin = None;
            return Ok(());
        }
        self.sync_twin()
    }

    pub fn side_by_side(&self) -> bool {
        self.side_by_side
    }

    /// The twin's selection, for `state().twin`.
    pub(super) fn twin_selection(&self) -> Option<ElementRef> {
        self.tab()
            .twin
            .as_ref()
            .and_then(|t| t.document.selection())
    }

    /// Rebuilds the twin when the mesh changed and copies the selection over.
    fn sync_twin(&mut self) -> Result<(), CommandError> {
        let tab = &mut self.tabs[self.active_tab];
        let Some(document) = &tab.document else {
            tab.twin = None;
            return Ok(());
        };
        let stale = tab
            .twin
            .as_ref()
            .is_none_or(|t| t.source_mesh != document.mesh_id());
        if stale {
            let (twin_document, correspondence) = match document.twin() {
                Ok(made) => made,
                Err(message) => {
                    tab.twin = None;
                    self.side_by_side = false;
                    return Err(format!("side by side: {message}").into());
                }
            };
            let mut pane = Pane::new(self.render_state.as_ref());
            pane.follow_mesh(&twin_document);
            pane.view.set_camera(tab.pane.view.camera());
            tab.twin = Some(Twin {
                document: twin_document,
                correspondence,
                pane,
                source_mesh: document.mesh_id(),
                synced: document.generation(),
            });
            return Ok(());
        }
        if let Some(twin) = &mut tab.twin
            && twin.synced != document.generation()
        {
            let mapped = document
                .selection()
                .and_then(|s| map_element(s, document.structure(), &twin.correspondence));
            twin.document.select(mapped).ok();
            twin.synced = document.generation();
        }
        Ok(())
    }

    /// The twin's view, beside the main one; a click there selects in both.
    pub(super) fn twin_view_ui(&mut self, ui: &mut egui::Ui) {
        if let Err(error) = self.sync_twin() {
            self.report(error.to_string());
            return;
        }
        let theme_key = self.theme.key();
        let Some(twin) = &mut self.tabs[self.active_tab].twin else {
            return;
        };
        // The twin shows the selection only: no run, no marks.
        let key = PaintKey {
            document: twin.document.generation(),
            run: 0,
            marks: 0,
            theme: theme_key,
        };
        if !twin.pane.styled_for(key) {
            let paint = Paint::from_selection(twin.document.highlights(), &self.theme);
            twin.pane.restyle(key, twin.document.mesh(), &paint);
        }
        ui.weak(match twin.document.structure() {
            edgewise_core::mesh::Structure::WingedEdge => "The same mesh as winged-edge",
            edgewise_core::mesh::Structure::HalfEdge => "The same mesh as half-edge",
        });
        let response = twin.pane.ui(ui, &self.view_options);
        let clicked = response.clicked.and_then(|element| {
            map_element(element, twin.document.structure(), &twin.correspondence)
        });
        if let Some(element) = clicked {
            self.element_clicked(Some(element));
        } else if response.background_clicked {
            self.element_clicked(None);
        }
    }
}
