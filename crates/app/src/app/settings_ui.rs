//! The Settings window (trace colours, code size, theme) and presentation
//! mode (fullscreen, chosen panels, larger type, Escape leaves).

use super::EdgewiseApp;
use crate::platform;
use edgewise_model::{
    settings::{CODE_SIZES, Settings},
    trace_role::TraceRole,
};

/// How much larger everything is drawn when presenting.
const PRESENTATION_ZOOM: f32 = 1.4;

/// Which panels a presentation shows besides the 3D view.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Presentation {
    pub algorithm: bool,
    pub tables: bool,
    pub menu: bool,
}

impl Default for Presentation {
    fn default() -> Self {
        Self {
            algorithm: true,
            tables: true,
            menu: false,
        }
    }
}

impl EdgewiseApp {
    /// Replaces the settings, applies them and saves them in the browser.
    pub fn set_settings(&mut self, settings: Settings) {
        let (settings, message) = settings.sanitized();
        if let Some(message) = message {
            self.report(message);
        }
        self.theme = settings.theme();
        self.algorithms.code_size = settings.code_size;
        crate::stored_settings::store(&settings);
        self.settings = settings;
    }

    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// Flips between the light and the dark theme.
    pub(super) fn toggle_theme(&mut self) {
        let mut settings = self.settings.clone();
        settings.dark = !settings.dark;
        self.set_settings(settings);
    }

    /// The Settings window, when open.
    pub(super) fn settings_window_ui(&mut self, ctx: &egui::Context) {
        if !self.show_settings {
            return;
        }
        let mut open = true;
        let mut settings = self.settings.clone();
        egui::Window::new("Settings")
            .open(&mut open)
            .resizable(false)
            .collapsible(false)
            .show(ctx, |ui| {
                ui.horizontal(|ui| {
                    ui.label("Theme");
                    ui.selectable_value(&mut settings.dark, false, "Light");
                    ui.selectable_value(&mut settings.dark, true, "Dark");
                });
                ui.add(
                    egui::Slider::new(&mut settings.code_size, CODE_SIZES)
                        .step_by(1.0)
                        .suffix(" pt")
                        .text("algorithm view font size"),
                );
                ui.separator();
                ui.strong("Trace colours");
                ui.weak("The meaning of each colour during a trace (the journal's Table 3).");
                let theme = settings.theme();
                egui::Grid::new("trace_colours")
                    .num_columns(2)
                    .show(ui, |ui| {
                        for role in TraceRole::ALL {
                            let mut colour = theme.trace_colour(role);
                            let response = ui.color_edit_button_srgba(&mut colour);
                            response.widget_info(|| {
                                egui::WidgetInfo::labeled(
                                    egui::Role::ColorWell,
                                    true,
                                    format!("colour of {}", role.key()),
                                )
                            });
                            if response.changed() {
                                settings.set_colour(role, colour);
                            }
                            ui.label(role.meaning());
                            ui.end_row();
                        }
                    });
                egui::CollapsingHeader::new("Selection colours")
                    .default_open(false)
                    .show(ui, |ui| {
                        egui::Grid::new("role_colours")
                            .num_columns(2)
                            .show(ui, |ui| {
                                for role in edgewise_model::selection::Role::all() {
                                    let mut colour = theme.role_colour(role);
                                    let response = ui.color_edit_button_srgba(&mut colour);
                                    let name = role.title(edgewise_core::schema::ElementKind::Edge);
                                    response.widget_info(|| {
                                        egui::WidgetInfo::labeled(
                                            egui::Role::ColorWell,
                                            true,
                                            format!("colour of {name}"),
                                        )
                                    });
                                    if response.changed() {
                                        settings.set_role_colour(role, colour);
                                    }
                                    ui.label(name);
                                    ui.end_row();
                                }
                                let mut colour = theme.boundary_override.unwrap_or(
                                    edgewise_pictures::palette::Palette::new(theme.dark).boundary,
                                );
                                let response = ui.color_edit_button_srgba(&mut colour);
                                response.widget_info(|| {
                                    egui::WidgetInfo::labeled(
                                        egui::Role::ColorWell,
                                        true,
                                        "colour of boundary half-edges",
                                    )
                                });
                                if response.changed() {
                                    settings.set_boundary_colour(colour);
                                }
                                ui.label("Boundary half-edges");
                                ui.end_row();
                            });
                    });
                if ui
                    .add_enabled(
                        !settings.colours.is_empty(),
                        egui::Button::new("Reset to the journal's colours"),
                    )
                    .clicked()
                {
                    settings.reset_colours();
                }
                ui.weak("Settings are kept in this browser.");
            });
        if settings != self.settings {
            self.set_settings(settings);
        }
        self.show_settings = open;
    }

    /// Starts presenting: fullscreen, larger type, only the chosen panels.
    pub fn enter_presentation(&mut self, ctx: &egui::Context, presentation: Presentation) {
        if self.presentation.is_none() {
            self.zoom_before_presenting = ctx.zoom_factor();
            ctx.set_zoom_factor(self.zoom_before_presenting * PRESENTATION_ZOOM);
        }
        self.presentation = Some(presentation);
        platform::set_fullscreen(ctx, true);
    }

    /// Leaves presentation mode and fullscreen.
    pub fn leave_presentation(&mut self, ctx: &egui::Context) {
        if self.presentation.take().is_some() {
            ctx.set_zoom_factor(self.zoom_before_presenting);
            platform::set_fullscreen(ctx, false);
        }
    }

    pub fn presentation(&self) -> Option<Presentation> {
        self.presentation
    }

    /// Escape leaves; so does leaving fullscreen by the browser's own means.
    pub(super) fn presentation_keys(&mut self, ctx: &egui::Context) {
        if self.presentation.is_none() {
            return;
        }
        let escape = ctx.input(|i| i.key_pressed(egui::Key::Escape));
        if escape || platform::left_fullscreen() {
            self.leave_presentation(ctx);
        }
    }

    /// The Present menu: choose the panels, then start.
    pub(super) fn present_menu_ui(&mut self, ui: &mut egui::Ui) {
        let mut start = None;
        ui.menu_button("Present…", |ui| {
            let choice = &mut self.presentation_choice;
            ui.label("Show, besides the 3D view:");
            ui.checkbox(&mut choice.algorithm, "Algorithm view");
            ui.checkbox(&mut choice.tables, "Tables");
            ui.checkbox(&mut choice.menu, "Menu bar");
            if ui.button("Start presenting").clicked() {
                start = Some(*choice);
                ui.close();
            }
            ui.weak("Fullscreen with larger type; Escape leaves.");
        });
        if let Some(presentation) = start {
            self.enter_presentation(ui.ctx(), presentation);
        }
    }

    /// A quiet reminder of how to leave, when the menu bar is hidden: in
    /// the view's top right corner, clear of the panels' controls.
    pub(super) fn presentation_hint_ui(&mut self, ctx: &egui::Context) {
        let Some(view) = self.layout.view else {
            return;
        };
        if self.presentation.is_some_and(|p| !p.menu) {
            let shown = egui::Area::new(egui::Id::unique("presentation_hint"))
                .pivot(egui::Align2::RIGHT_TOP)
                .fixed_pos(egui::pos2(view.x + view.w - 8.0, view.y + 8.0))
                .interactable(false)
                .show(ctx, |ui| {
                    ui.weak("Esc leaves the presentation");
                });
            self.layout.overlays.push(crate::state::NamedRect {
                name: "presentationHint",
                rect: shown.response.rect.into(),
            });
        }
    }
}
