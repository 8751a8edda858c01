//! Embed mode (`?embed=1`), for iframes in lecture notes: only the 3D view,
//! optionally the tables, and the step controls (or an exercise's card and
//! tables), sized to the frame, with no menu bar.

use super::{EdgewiseApp, side_panel_range};

/// About how tall an embed's step controls are, in points: the algorithm's
/// name, the step buttons, the step slider and the delay.
pub(crate) const CONTROLS_HEIGHT: f32 = 100.0;

/// The starting height of an embed's tables, in points.
pub(crate) const TABLES_HEIGHT: f32 = 200.0;

/// What an embedded view shows besides the 3D view.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Embed {
    pub tables: bool,
}

impl EdgewiseApp {
    /// Turns embed mode on (with its options) or off.
    pub fn set_embed(&mut self, embed: Option<Embed>) {
        self.embed = embed;
    }

    pub fn embed(&self) -> Option<Embed> {
        self.embed
    }

    /// The embedded layout: step controls under the view when a trace runs,
    /// the tables if asked for, and the view filling the rest.
    pub(super) fn embed_ui(&mut self, ui: &mut egui::Ui, embed: Embed) {
        self.layout = crate::state::LayoutState {
            window: ui.max_rect().into(),
            ..Default::default()
        };
        let mut chrome = 0.0;
        if self.tab().run.session().is_some() {
            chrome += egui::Panel::bottom("embed_controls")
                .show(ui, |ui| {
                    ui.horizontal(|ui| {
                        if let Some(algorithm) = self.tab().run.algorithm() {
                            ui.strong(egui::RichText::new(&algorithm.name).monospace());
                        }
                    });
                    let asked = self.algorithms.trace_controls_ui(
                        &mut self.tabs[self.active_tab].run,
                        ui,
                        &self.theme,
                        embed.tables,
                    );
                    if let Some(command) = asked {
                        self.issue(command);
                    }
                })
                .response
                .rect
                .height();
        }
        // An exercise is done in the tables, from its card: both show
        // whatever the link asked for.
        let practising = self.tab().practice.is_some();
        if practising {
            egui::Panel::right("embed_practice")
                .resizable(true)
                .default_size(300.0)
                .size_range(side_panel_range(ui.max_rect().width(), 220.0))
                .show(ui, |ui| {
                    egui::ScrollArea::vertical().show(ui, |ui| self.practice_ui(ui));
                });
        }
        if embed.tables || practising {
            chrome += egui::Panel::bottom("tables")
                .resizable(true)
                .default_size(TABLES_HEIGHT)
                .min_size(100.0)
                .show(ui, |ui| self.cached_part_ui(ui, "tables", Self::tables_ui))
                .response
                .rect
                .height();
        }
        self.chrome_height = chrome;
        let view = egui::CentralPanel::default().show(ui, |ui| {
            self.error_ui(ui);
            self.view_ui(ui);
        });
        self.layout.view = Some(view.response.rect.into());
        self.layout.step_controls = self.algorithms.step_controls.take().map(Into::into);
    }
}
