//! Several meshes at once, in tabs. The active tab's mesh, view and run
//! live in the app's own fields, so everything else works on "the" mesh; a
//! tab switch parks them and unparks the other tab's.

use edgewise_core::mesh::Structure;

use super::EdgewiseApp;
use crate::{
    algorithm::Run,
    document::Document,
    state::TabState,
    view3d::{SceneStyles, View3d},
};

/// An inactive tab's mesh, view and algorithm run.
pub(super) struct ParkedTab {
    document: Option<Document>,
    view: View3d,
    styles: SceneStyles,
    run: Run,
    structure: Structure,
}

impl EdgewiseApp {
    /// Opens an empty tab and switches to it; returns its index.
    pub fn new_tab(&mut self) -> usize {
        let view = View3d::new(self.render_state.as_ref());
        let parked = ParkedTab {
            document: None,
            view,
            styles: SceneStyles::default(),
            run: Run::Idle,
            structure: self.structure,
        };
        self.tabs.push(Some(parked));
        let index = self.tabs.len() - 1;
        self.switch_tab(index).ok();
        index
    }

    /// Makes tab `index` the active one.
    pub fn switch_tab(&mut self, index: usize) -> Result<(), String> {
        if index == self.active_tab {
            return Ok(());
        }
        let Some(slot) = self.tabs.get_mut(index) else {
            return Err(self.fail(format!(
                "there is no tab {index} (there are {}, numbered from 0)",
                self.tabs.len()
            )));
        };
        let Some(incoming) = slot.take() else {
            return Ok(());
        };
        let outgoing = self.park(incoming);
        if let Some(old) = self.tabs.get_mut(self.active_tab) {
            *old = Some(outgoing);
        }
        self.active_tab = index;
        self.twin = None;
        Ok(())
    }

    /// Closes tab `index`; the last tab cannot be closed.
    pub fn close_tab(&mut self, index: usize) -> Result<(), String> {
        if self.tabs.len() <= 1 {
            return Err(self.fail("the last tab cannot be closed".to_owned()));
        }
        if index >= self.tabs.len() {
            return Err(self.fail(format!("there is no tab {index}")));
        }
        if index == self.active_tab {
            let neighbour = if index + 1 < self.tabs.len() {
                index + 1
            } else {
                index - 1
            };
            self.switch_tab(neighbour)?;
        }
        self.tabs.remove(index);
        if index < self.active_tab {
            self.active_tab -= 1;
        }
        Ok(())
    }

    /// Swaps the active tab's contents for `incoming`'s and returns them.
    fn park(&mut self, incoming: ParkedTab) -> ParkedTab {
        let run = self.algorithms.replace_run(incoming.run);
        let outgoing = ParkedTab {
            document: std::mem::replace(&mut self.document, incoming.document),
            view: std::mem::replace(&mut self.view, incoming.view),
            styles: std::mem::replace(&mut self.styles, incoming.styles),
            run,
            structure: std::mem::replace(&mut self.structure, incoming.structure),
        };
        self.paint_key = None;
        self.hovered = None;
        outgoing
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
        let document = if index == self.active_tab {
            self.document.as_ref()
        } else {
            self.tabs
                .get(index)
                .and_then(Option::as_ref)
                .and_then(|t| t.document.as_ref())
        };
        document.map_or_else(|| "New tab".to_owned(), |d| d.name.clone())
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
            self.new_tab();
            return;
        }
        if let Some(i) = switch {
            self.switch_tab(i).ok();
        }
        if let Some(i) = close {
            self.close_tab(i).ok();
        }
    }
}
