//! The first visit: a page opened without a link starts on the journal's
//! tetrahedron (Table 2) with its tables, and a dismissible hint of three
//! things to try, each ticked off as the student does it. "What am I
//! looking at?" labels the parts of the screen. Links and embedded views
//! skip all of it: they set up their own view.

use edgewise_core::mesh::Structure;
use edgewise_core::schema::ElementKind;

use super::EdgewiseApp;
use crate::history::History;

/// The sample a first visit opens: the journal's Table 2.
const FIRST_SAMPLE: &str = "tetrahedron";

/// The three things to try.
pub const STEPS: [&str; 3] = [
    "Click an edge, in the 3D view or in the Edges table.",
    "Click a blue id in a table to follow that reference.",
    "Run vertexAdjacentEdge (Algorithm menu) and step through it with →.",
];

/// The hint's progress.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Tour {
    pub done: [bool; 3],
}

/// One labelled part of the screen for "What am I looking at?".
#[derive(Clone, Copy, Debug)]
pub(crate) struct Part {
    pub rect: egui::Rect,
    pub title: &'static str,
    pub text: &'static str,
}

impl EdgewiseApp {
    /// The starting view of a page opened without a link: the journal's
    /// tetrahedron as winged-edge tables (not an undoable step), and the
    /// hint unless it was dismissed before.
    pub fn first_visit(&mut self) {
        if self
            .load_sample(FIRST_SAMPLE, Some(Structure::WingedEdge))
            .is_err()
        {
            return;
        }
        self.finish_pending();
        self.tab_mut().history = History::default();
        if self.settings.welcome {
            self.tour = Some(Tour::default());
        }
    }

    /// The hint's progress, or None when it is not shown.
    pub fn tour(&self) -> Option<&Tour> {
        self.tour.as_ref()
    }

    /// Closes the hint for good (in this browser).
    pub fn dismiss_tour(&mut self) {
        self.tour = None;
        self.explaining = false;
        if self.settings.welcome {
            self.settings.welcome = false;
            crate::stored_settings::store(&self.settings);
        }
    }

    /// Notes what the student did: a reference followed in a table, or
    /// the frame's state.
    pub(super) fn tour_progress(&mut self, followed: bool) {
        let selection = self
            .tab()
            .document
            .as_ref()
            .and_then(edgewise_model::document::Document::selection);
        let ran = self
            .tab()
            .run
            .session()
            .is_some_and(|s| s.trace.algorithm().name == "vertexAdjacentEdge" && s.step() > 0);
        let Some(tour) = &mut self.tour else {
            return;
        };
        if selection.is_some_and(|s| s.kind == ElementKind::Edge) {
            tour.done[0] = true;
        }
        if followed {
            tour.done[1] = true;
        }
        if ran {
            tour.done[2] = true;
        }
    }

    /// The hint, in the top right corner of the 3D view: over the view
    /// alone, so it covers none of the controls its steps ask for.
    pub(super) fn tour_ui(&mut self, ctx: &egui::Context) {
        let Some(tour) = self.tour.clone() else {
            return;
        };
        let Some(view) = self.layout.view else {
            return;
        };
        // The hint stays open over any mesh opened next; only the first
        // names it.
        let on_table_2 = self
            .tab()
            .document
            .as_ref()
            .is_some_and(|document| document.sample.as_deref() == Some(FIRST_SAMPLE));
        let corner = egui::pos2(view.x + view.w - 12.0, view.y + 12.0);
        let mut dismiss = false;
        let window = egui::Id::unique(TOUR_WINDOW);
        let shown = egui::Window::new("Welcome to Edgewise")
            .id(window)
            .pivot(egui::Align2::RIGHT_TOP)
            .fixed_pos(corner)
            .resizable(false)
            .collapsible(true)
            // On a phone it would cover the view: its title bar opens it.
            .default_open(!self.layout.compact)
            .show(ctx, |ui| {
                ui.set_max_width(320.0_f32.min(view.w - 48.0).max(160.0));
                ui.label(if on_table_2 {
                    "This is the tetrahedron of the winged-edge paper's Table 2: the 3D \
                     view above, the records the structure stores below. Try:"
                } else {
                    "The 3D view above, the records the structure stores below. Try:"
                });
                for (step, done) in STEPS.iter().zip(tour.done) {
                    ui.horizontal_wrapped(|ui| {
                        ui.label(if done { "✔" } else { "○" });
                        if done {
                            ui.weak(*step);
                        } else {
                            ui.label(*step);
                        }
                    });
                }
                if tour.done.iter().all(|&d| d) {
                    ui.strong("That is the whole idea. Open any mesh from Samples next.");
                }
                ui.horizontal(|ui| {
                    if ui.button("What am I looking at?").clicked() {
                        self.explaining = true;
                    }
                    if ui.button("Dismiss").clicked() {
                        dismiss = true;
                    }
                });
            });
        if let Some(shown) = shown {
            self.layout.overlays.push(crate::state::NamedRect {
                name: "welcome",
                rect: shown.response.rect.into(),
            });
        }
        if dismiss {
            self.dismiss_tour();
        }
        self.ui_cache
            .whole_layer(TOUR_WINDOW, egui::LayerId::new(egui::Order::Middle, window));
    }

    /// "What am I looking at?": each part of the screen outlined and
    /// labelled (as widgets, so screen readers find them too); a click
    /// anywhere or Esc closes it.
    pub(super) fn explain_ui(&mut self, ctx: &egui::Context) {
        if !self.explaining {
            return;
        }
        let painter = ctx.layer_painter(egui::LayerId::new(
            egui::Order::Middle,
            egui::Id::unique("explain_shade"),
        ));
        let visuals = ctx.global_style().visuals.clone();
        painter.rect_filled(ctx.content_rect(), 0.0, egui::Color32::from_black_alpha(90));
        for (index, part) in self.screen_parts.iter().enumerate() {
            let rect = part.rect.shrink(4.0);
            painter.rect_stroke(
                rect,
                6.0,
                egui::Stroke::new(2.5, visuals.selection.stroke.color),
                egui::StrokeKind::Inside,
            );
            // A bar too thin to hold its label gets it just below.
            let (at, pivot) = if rect.height() < 80.0 {
                (
                    rect.center_bottom() + egui::vec2(0.0, 8.0),
                    egui::Align2::CENTER_TOP,
                )
            } else {
                (rect.center(), egui::Align2::CENTER_CENTER)
            };
            egui::Area::new(egui::Id::unique("explain").with(index))
                .order(egui::Order::Foreground)
                .fixed_pos(at)
                .pivot(pivot)
                .interactable(false)
                .show(ctx, |ui| {
                    egui::Frame::popup(ui.style()).show(ui, |ui| {
                        ui.set_max_width((rect.width() - 32.0).clamp(160.0, 420.0));
                        ui.strong(part.title);
                        ui.label(part.text);
                    });
                });
        }
        let closed = ctx.input(|i| i.pointer.any_pressed() || i.key_pressed(egui::Key::Escape));
        // The click that opened it does not close it.
        if closed && self.explain_shown_once {
            self.explaining = false;
            self.explain_shown_once = false;
        } else {
            self.explain_shown_once = true;
        }
    }

    /// "What am I looking at?" is shown.
    pub fn explaining(&self) -> bool {
        self.explaining
    }
}

/// The welcome card's window id, and its name in the UI cache.
const TOUR_WINDOW: &str = "welcome card";

/// The parts "What am I looking at?" explains, in the order they are laid
/// out.
pub(crate) const TOP_BAR: (&str, &str) = (
    "Menus",
    "Open a mesh or a sample, choose winged-edge or half-edge, run an algorithm, share a link.",
);
pub(crate) const VIEW: (&str, &str) = (
    "The mesh in 3D",
    "Vertices are spheres, edges arrows (a half-edge runs inside its own face), faces \
     see-through. Click to select; drag to turn it; the line below says what is selected.",
);
pub(crate) const TABLES: (&str, &str) = (
    "The records",
    "What the structure really stores: a row per face, edge and vertex. Blue ids are \
     references: click one to follow it. Coloured cells match the labels in 3D.",
);
pub(crate) const ALGORITHM: (&str, &str) = (
    "The algorithm",
    "Its code, its variables and the step controls. Each step is coloured in both views.",
);
