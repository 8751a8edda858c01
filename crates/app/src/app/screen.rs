//! Layouts for the screen at hand. Below [`COMPACT_WIDTH`] CSS pixels (a
//! phone, a narrow window) the top bar folds into one menu and the panels
//! become the tabs of a sheet under the 3D view, so that a course link shows
//! the mesh and its step. On a touch screen every control is at least
//! [`TOUCH_TARGET`] tall (WCAG 2.5.5).

use super::{EdgewiseApp, first_visit};
use crate::state::{MenuLayout, NamedRect};

/// The narrowest window, in CSS pixels, that keeps the side panels.
pub const COMPACT_WIDTH: f32 = 700.0;

/// The least height of a control on a touch screen, in CSS pixels.
pub const TOUCH_TARGET: f32 = 44.0;

/// The most of the window's height the sheet may take: the view keeps a
/// third of it under the top bar.
const SHEET_MOST: f32 = 0.55;

/// A tab of the small-screen sheet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum SheetTab {
    Tables,
    Algorithm,
    ObjEditor,
}

impl SheetTab {
    fn label(self) -> &'static str {
        match self {
            Self::Tables => "Tables",
            Self::Algorithm => "Algorithm",
            Self::ObjEditor => "OBJ editor",
        }
    }

    fn part(self) -> (&'static str, &'static str) {
        match self {
            Self::Tables | Self::ObjEditor => first_visit::TABLES,
            Self::Algorithm => first_visit::ALGORITHM,
        }
    }

    fn panel(self) -> &'static str {
        match self {
            Self::Tables => "tables",
            Self::Algorithm => "algorithm",
            Self::ObjEditor => "objEditor",
        }
    }
}

/// The sheet's tab as the student chose it; a run that starts or ends
/// brings the algorithm (or the tables) back to the front.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Sheet {
    chosen: Option<(SheetTab, bool)>,
}

/// How controls are sized (for a pointer, or for a finger) and how wide
/// the top bar is.
#[derive(Clone, Copy, Debug)]
pub(super) struct Sizing {
    /// A touch has been seen, or the browser says its pointer is coarse.
    touch: bool,
    applied: Option<bool>,
    /// The width, in points, the top bar needs to show every command, as
    /// last measured unfolded.
    bar_width: f32,
}

impl Default for Sizing {
    fn default() -> Self {
        Self {
            touch: false,
            applied: None,
            // As measured in the app's fonts, so that the first frames do
            // not fold and unfold the bar (and the embedding page's frame).
            bar_width: 912.0,
        }
    }
}

/// How the window is laid out at a width of `width` points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Fit {
    /// The top bar's commands are folded into one menu: they do not fit.
    pub folded_bar: bool,
    /// The panels are the tabs of a sheet under the view.
    pub sheet: bool,
}

impl EdgewiseApp {
    /// Sizes the controls for touch once a touch is seen, when the browser
    /// reports a coarse pointer (asked once, at the first frame), or on a
    /// small screen.
    pub(super) fn size_controls(&mut self, ctx: &egui::Context) {
        let touched = ctx.input(|i| {
            i.any_touches()
                || i.events
                    .iter()
                    .any(|event| matches!(event, egui::Event::Touch { .. }))
        });
        let first_frame = self.sizing.applied.is_none();
        self.sizing.touch |= touched || (first_frame && crate::platform::coarse_pointer());
        let narrow = ctx.content_rect().width() < COMPACT_WIDTH;
        let touch = self.sizing.touch || narrow;
        if self.sizing.applied == Some(touch) {
            return;
        }
        // Not in the middle of a press: the first tap, which tells a touch
        // screen, must still land on the control it was aimed at.
        let pressing = ctx
            .input(|i| i.pointer.any_down() || i.pointer.any_pressed() || i.pointer.any_released());
        if pressing {
            ctx.request_repaint();
            return;
        }
        // egui's own height, for a mouse.
        let height = if touch {
            TOUCH_TARGET
        } else {
            egui::style::Spacing::default().interact_size.y
        };
        ctx.global_style_mut(|style| style.spacing.interact_size.y = height);
        self.sizing.applied = Some(touch);
    }

    /// How a window `width` points wide is laid out.
    pub(super) fn fit(&self, width: f32) -> Fit {
        let sheet = width < COMPACT_WIDTH;
        Fit {
            folded_bar: sheet || width < self.sizing.bar_width,
            sheet,
        }
    }

    /// Notes where the unfolded top bar's last command ends.
    pub(super) fn measure_bar(&mut self, right: f32) {
        self.sizing.bar_width = right + 8.0;
    }

    /// The top bar's menu of everything on a small screen.
    pub(super) fn compact_menu_ui(&mut self, ui: &mut egui::Ui) {
        self.menu_ui(ui, "Menu", Self::commands_ui);
    }

    /// A menu button of the top bar: the button is listed in
    /// `state().layout.topBar` (unless it is itself inside a menu) and the
    /// open menu in `menus`.
    pub(super) fn menu_ui(
        &mut self,
        ui: &mut egui::Ui,
        name: &'static str,
        contents: impl FnOnce(&mut Self, &mut egui::Ui),
    ) -> egui::Response {
        let nested = egui::containers::menu::is_in_menu(ui);
        let outer = std::mem::take(&mut self.layout.menu_commands);
        let mut open = None;
        let button = ui
            .menu_button(name, |ui| {
                // A menu longer than the window scrolls (by wheel, drag or
                // Tab, which scrolls the focused entry into view).
                let room = ui.ctx().content_rect().bottom() - ui.cursor().top() - 16.0;
                egui::ScrollArea::vertical()
                    .max_height(room.max(120.0))
                    .show(ui, |ui| contents(self, ui));
                open = Some(MenuLayout::of(ui, name));
            })
            .response;
        let commands = std::mem::replace(&mut self.layout.menu_commands, outer);
        self.layout
            .menus
            .extend(open.map(|menu| MenuLayout { commands, ..menu }));
        self.record_command(name, &button, nested);
        button
    }

    /// Lists a top-bar command in `state().layout.topBar`, or under the
    /// menu that holds it.
    pub(super) fn record_command(
        &mut self,
        name: &'static str,
        button: &egui::Response,
        nested: bool,
    ) {
        let command = NamedRect {
            name,
            rect: button.rect.into(),
        };
        if nested {
            self.layout.menu_commands.push(command);
        } else {
            self.layout.top_bar.push(command);
        }
    }

    /// The tab of the sheet in front: the student's choice while the run
    /// has not started or ended since, else the algorithm during a run.
    fn sheet_tab(&self, offered: &[SheetTab]) -> Option<SheetTab> {
        let running = self.tab().run.is_active();
        let chosen = self
            .sheet
            .chosen
            .filter(|&(tab, with_run)| with_run == running && offered.contains(&tab))
            .map(|(tab, _)| tab);
        let preferred = if running {
            SheetTab::Algorithm
        } else {
            SheetTab::Tables
        };
        chosen
            .or(offered.contains(&preferred).then_some(preferred))
            .or(offered.first().copied())
    }

    /// The small-screen sheet under the view: the tables, the algorithm
    /// panel and the OBJ editor as tabs. Returns its rectangle and the part
    /// of the screen it shows, or None when there is nothing to show.
    pub(super) fn sheet_ui(
        &mut self,
        ui: &mut egui::Ui,
        offered: &[SheetTab],
    ) -> Option<(egui::Rect, (&'static str, &'static str))> {
        let front = self.sheet_tab(offered)?;
        let height = ui.max_rect().height();
        let rect = egui::Panel::bottom("sheet")
            .resizable(true)
            .default_size(height * 0.5)
            .size_range((height * 0.2).min(160.0)..=height * SHEET_MOST)
            .show(ui, |ui| {
                ui.horizontal(|ui| {
                    for &tab in offered {
                        if ui.selectable_label(tab == front, tab.label()).clicked() {
                            self.sheet.chosen = Some((tab, self.tab().run.is_active()));
                        }
                    }
                });
                ui.separator();
                match front {
                    SheetTab::Tables => self.cached_part_ui(ui, "tables", Self::tables_ui),
                    SheetTab::Algorithm => {
                        self.cached_part_ui(ui, "algorithm panel", Self::algorithm_panel_ui);
                    }
                    SheetTab::ObjEditor => {
                        self.cached_part_ui(ui, "OBJ editor", Self::obj_editor_ui);
                    }
                }
            })
            .response
            .rect;
        self.layout.panels.insert(front.panel(), rect.into());
        Some((rect, front.part()))
    }

    /// The sheet's tabs on offer: what the wide layout would show as panels.
    pub(super) fn sheet_tabs(&self, tables: bool, algorithm: bool) -> Vec<SheetTab> {
        let mut offered = Vec::new();
        if tables {
            offered.push(SheetTab::Tables);
        }
        if algorithm {
            offered.push(SheetTab::Algorithm);
        }
        if self.show_obj_editor {
            offered.push(SheetTab::ObjEditor);
        }
        offered
    }
}
