//! Several meshes at once, in tabs. Each [`Tab`] owns everything that
//! belongs to one mesh; the app draws and commands the active one, so a tab
//! switch only changes which one that is.

use edgewise_core::mesh::Structure;
use edgewise_core::schema::{ElementKind, ElementRef};

use super::{EdgewiseApp, twin::Twin};
use crate::command::{Command, CommandError};
use crate::{
    algorithm::AlgorithmRun,
    document::Document,
    obj_editor::ObjEditor,
    paint::Paint,
    state::TabState,
    view3d::{SceneStyles, View3d},
};

/// One open mesh and everything shown for it: its document, 3D view and
/// camera, colours, algorithm run, OBJ editor text, table scroll, error
/// and side-by-side twin.
pub(crate) struct Tab {
    pub(crate) document: Option<Document>,
    pub(crate) view: View3d,
    pub(crate) styles: SceneStyles,
    /// What the views colour: the selection, or the trace's current step.
    pub(crate) paint: Paint,
    /// (document generation, run generation, theme key) `paint` and
    /// `styles` were derived from.
    pub(crate) paint_key: Option<(u64, u64, u64)>,
    /// Table rows to bring into view once: where the selection or the
    /// trace's current operation moved to.
    pub(crate) table_scroll: Vec<(ElementKind, u32)>,
    pub(crate) run: AlgorithmRun,
    /// The structure new PLY and OBJ loads are built into.
    pub(crate) structure: Structure,
    pub(crate) obj_editor: ObjEditor,
    /// The last failed load or command, shown until dismissed.
    pub(crate) error: Option<String>,
    pub(crate) twin: Option<Twin>,
    /// The element under the pointer in the 3D view, for the message line.
    pub(crate) hovered: Option<ElementRef>,
}

impl Tab {
    /// An empty tab drawing with `render_state` (none in headless tests).
    pub(crate) fn new(
        render_state: Option<&eframe::egui_wgpu::RenderState>,
        structure: Structure,
    ) -> Self {
        Self {
            document: None,
            view: View3d::new(render_state),
            styles: SceneStyles::default(),
            paint: Paint::default(),
            paint_key: None,
            table_scroll: Vec::new(),
            run: AlgorithmRun::default(),
            structure,
            obj_editor: ObjEditor::default(),
            error: None,
            twin: None,
            hovered: None,
        }
    }
}

impl Tab {
    /// Runs `f` on this tab's algorithm run and its mesh, refusing when no
    /// mesh is open.
    pub(crate) fn with_mesh(
        &mut self,
        f: impl FnOnce(&mut AlgorithmRun, &edgewise_core::mesh::Mesh) -> Result<(), String>,
    ) -> Result<(), CommandError> {
        let mesh = self.document.as_ref().map(Document::mesh);
        let mesh = mesh.ok_or("no mesh is open")?;
        Ok(f(&mut self.run, mesh)?)
    }
}

impl EdgewiseApp {
    /// The tab the app shows and commands act on.
    pub(crate) fn tab(&self) -> &Tab {
        // `tabs` is never empty and `active_tab` is kept in range.
        &self.tabs[self.active_tab]
    }

    pub(crate) fn tab_mut(&mut self) -> &mut Tab {
        &mut self.tabs[self.active_tab]
    }

    /// [`Command::NewTab`]: opens an empty tab and switches to it; returns
    /// its index.
    pub(crate) fn open_tab(&mut self) -> usize {
        let structure = self.tab().structure;
        self.tabs
            .push(Tab::new(self.render_state.as_ref(), structure));
        self.active_tab = self.tabs.len() - 1;
        self.active_tab
    }

    /// [`Command::SwitchTab`].
    pub(crate) fn activate_tab(&mut self, index: usize) -> Result<(), CommandError> {
        if index >= self.tabs.len() {
            return Err(format!(
                "there is no tab {index} (there are {}, numbered from 0)",
                self.tabs.len()
            )
            .into());
        }
        self.active_tab = index;
        Ok(())
    }

    /// [`Command::CloseTab`]: the last tab cannot be closed.
    pub(crate) fn remove_tab(&mut self, index: usize) -> Result<(), CommandError> {
        if self.tabs.len() <= 1 {
            return Err("the last tab cannot be closed".into());
        }
        if index >= self.tabs.len() {
            return Err(format!("there is no tab {index}").into());
        }
        if index == self.active_tab {
            let neighbour = if index + 1 < self.tabs.len() {
                index + 1
            } else {
                index - 1
            };
            self.activate_tab(neighbour)?;
        }
        self.tabs.remove(index);
        if index < self.active_tab {
            self.active_tab -= 1;
        }
        Ok(())
    }

    /// The tabs for `state().tabs`.
    pub(super) fn tab_states(&self) -> Vec<TabState> {
        (0..self.tabs.len())
            .map(|i| TabState {
                title: self.tab_title(i),
                active: i == self.active_tab,
            })
            .collect()
    }

    fn tab_title(&self, index: usize) -> String {
        self.tabs
            .get(index)
            .and_then(|tab| tab.document.as_ref())
            .map_or_else(|| "New tab".to_owned(), |d| d.name.clone())
    }

    /// The tab strip; shown when there is more than one tab.
    pub(super) fn tab_bar_ui(&mut self, ui: &mut egui::Ui) {
        let mut switch = None;
        let mut close = None;
        let mut new = false;
        ui.horizontal(|ui| {
            for i in 0..self.tabs.len() {
                let title = self.tab_title(i);
                let response = ui.selectable_label(i == self.active_tab, &title);
                if response.clicked() {
                    switch = Some(i);
                }
                if ui
                    .small_button("✖")
                    .on_hover_text(format!("Close {title}"))
                    .clicked()
                {
                    close = Some(i);
                }
                ui.separator();
            }
            new = ui.button("+").on_hover_text("A new tab").clicked();
        });
        if new {
            self.issue(Command::NewTab);
            return;
        }
        if let Some(i) = switch {
            self.issue(Command::SwitchTab(i));
        }
        if let Some(i) = close {
            self.issue(Command::CloseTab(i));
        }
    }
}
