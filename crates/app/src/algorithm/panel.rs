//! The algorithm view (the journal's Figure 7): controls, the step slider,
//! the variables, and the source with the current line and the exact
//! expression being executed highlighted. Clicking a line number toggles a
//! breakpoint.

use edgewise_model::trace_role::TraceRole;
use std::ops::Range;
use std::sync::Arc;

use edgewise_core::{
    lang::{Algorithm, Type, Value},
    mesh::Mesh,
};
use egui::{Align, Color32, RichText, Sense, vec2};

use super::{
    AlgorithmRun, Algorithms, Run, TraceFrame,
    highlight::{CodeStyle, Mark},
    quiz_ui::{self, Shown},
};
use crate::command::Command;
use edgewise_model::theme::Theme;

/// The least height of the source listing, in points: a dozen lines. In a
/// phone's sheet everything above it scrolls away; in a side panel the
/// variables scroll to leave it.
const SOURCE_LEAST_HEIGHT: f32 = 240.0;

/// The height an embed keeps for its question card, in points: the
/// heading, a two-line prompt, the answer buttons and the verdict.
pub(crate) const EMBED_CARD_HEIGHT: f32 = 150.0;

impl Algorithms {
    /// Draws the algorithm view. Returns what the user asked for, for the
    /// app to carry out.
    pub fn panel_ui(
        &mut self,
        run: &mut AlgorithmRun,
        ui: &mut egui::Ui,
        theme: &Theme,
        mesh: Option<&Mesh>,
    ) -> Option<Command> {
        match &run.run {
            Run::Idle => self.library_ui(ui, mesh),
            Run::Picking(_) => picking_ui(run, ui),
            Run::Tracing(_) => self.tracing_ui(run, ui, theme),
        }
    }

    /// With nothing running: the algorithms for the mesh's structure, one
    /// click from running.
    fn library_ui(&self, ui: &mut egui::Ui, mesh: Option<&Mesh>) -> Option<Command> {
        let Some(mesh) = mesh else {
            ui.weak("Open a mesh, then choose an algorithm to run on it.");
            return None;
        };
        let structure = mesh.structure();
        ui.label(format!(
            "Algorithms for the {} structure. Choose one, then pick its inputs.",
            structure.prose()
        ));
        ui.add_space(4.0);
        let mut chosen = None;
        egui::ScrollArea::vertical()
            .auto_shrink([false, true])
            .show(ui, |ui| {
                // Helpers (called by the others) come last, folded away.
                let ours = || {
                    self.library
                        .entries()
                        .iter()
                        .map(|entry| &entry.algorithm)
                        .filter(|algorithm| algorithm.structure == structure)
                };
                let mut button = |ui: &mut egui::Ui, algorithm: &Arc<Algorithm>| {
                    let button = ui
                        .button(RichText::new(&algorithm.name).monospace())
                        .on_hover_text(algorithm_hover(algorithm));
                    if button.clicked() {
                        chosen = Some(algorithm.name.clone());
                    }
                };
                for algorithm in ours().filter(|a| !a.is_helper()) {
                    button(ui, algorithm);
                }
                if ours().any(|a| a.is_helper()) {
                    ui.collapsing("Helpers the others call", |ui| {
                        for algorithm in ours().filter(|a| a.is_helper()) {
                            button(ui, algorithm);
                        }
                    });
                }
            });
        chosen.map(|name| Command::RunAlgorithm {
            name,
            args: Vec::new(),
        })
    }

    fn tracing_ui(
        &mut self,
        run: &mut AlgorithmRun,
        ui: &mut egui::Ui,
        theme: &Theme,
    ) -> Option<Command> {
        let session = run.session()?;
        let algorithm = Arc::clone(session.trace.algorithm());
        let (step, steps, playing) = (session.step(), session.steps(), session.playing);
        if self.in_sheet {
            // A phone's sheet: the step controls stay put at its top and the
            // rest scrolls beneath them, so a step is always one tap away.
            let control = self.controls_ui(run, ui, step, steps, playing);
            let rest = egui::ScrollArea::vertical()
                .id_salt("sheet_trace")
                .auto_shrink(false)
                .show(ui, |ui| {
                    header_ui(ui, &algorithm);
                    self.trace_state_ui(run, ui, &algorithm, theme)
                })
                .inner;
            return control.or(rest);
        }
        header_ui(ui, &algorithm);
        let control = self.controls_ui(run, ui, step, steps, playing);
        control.or(self.trace_state_ui(run, ui, &algorithm, theme))
    }

    /// The question asked at the step, the step's status, the variables, the
    /// source with its current line, and the legend.
    fn trace_state_ui(
        &mut self,
        run: &mut AlgorithmRun,
        ui: &mut egui::Ui,
        algorithm: &Arc<Algorithm>,
        theme: &Theme,
    ) -> Option<Command> {
        let everything = Shown {
            code: true,
            tables: true,
        };
        let answered = question_ui(run, ui, theme, everything);
        let breakpoints = self.breakpoints(run.algorithm());
        let Some(frame) = run.frame(theme).cloned() else {
            return answered;
        };
        // Where the panel has room, the legend goes first, at the bottom, so
        // the source takes the height the rest leaves, however many rows the
        // panel's width wraps the legend into. In a phone's sheet, which
        // scrolls, the source keeps a least height and the legend follows.
        if !self.in_sheet {
            egui::Panel::bottom("algorithm_legend")
                .frame(egui::Frame::NONE.inner_margin(egui::Margin::symmetric(0, 4)))
                .show(ui, |ui| legend_ui(ui, theme));
        }
        status_ui(ui, &frame, theme);
        ui.add_space(4.0);
        if self.in_sheet {
            variables_ui(ui, &frame, theme);
        } else {
            // A flip has ten variables: listed whole, they left the source
            // three lines. They scroll instead, in what the source's least
            // height leaves, and at least a quarter of the room.
            let room = ui.available_height();
            egui::ScrollArea::vertical()
                .id_salt("trace_variables")
                .auto_shrink([false, true])
                .max_height((room - SOURCE_LEAST_HEIGHT).max(room / 4.0))
                .show(ui, |ui| variables_ui(ui, &frame, theme));
        }
        ui.separator();
        let toggled = self.source_ui(run, ui, algorithm, &frame, &breakpoints, theme);
        if self.in_sheet {
            legend_ui(ui, theme);
        }
        answered.or(toggled)
    }

    /// The step buttons, the step slider and the delay, and the question
    /// asked at the step, for embedded views (which show no code, and the
    /// tables only if asked).
    pub fn trace_controls_ui(
        &mut self,
        run: &mut AlgorithmRun,
        ui: &mut egui::Ui,
        theme: &Theme,
        tables: bool,
    ) -> Option<Command> {
        let session = run.session()?;
        let (step, steps, playing) = (session.step(), session.steps(), session.playing);
        let control = self.controls_ui(run, ui, step, steps, playing);
        let shows = Shown {
            code: false,
            tables,
        };
        if run.session().is_none_or(|s| s.quiz.is_none()) {
            return control;
        }
        // The card keeps one height for the whole run, with or without a
        // question at the step, so that the page around an embed does not
        // move as questions come and go (a longer card scrolls).
        let width = ui.available_width();
        let answered = ui
            .allocate_ui(vec2(width, EMBED_CARD_HEIGHT), |ui| {
                ui.set_min_height(EMBED_CARD_HEIGHT);
                egui::ScrollArea::vertical()
                    .id_salt("embed_question")
                    .max_height(EMBED_CARD_HEIGHT)
                    .auto_shrink(false)
                    .show(ui, |ui| question_ui(run, ui, theme, shows))
                    .inner
            })
            .inner;
        control.or(answered)
    }

    fn controls_ui(
        &mut self,
        run: &mut AlgorithmRun,
        ui: &mut egui::Ui,
        step: usize,
        steps: usize,
        playing: bool,
    ) -> Option<Command> {
        let shown = ui.scope(|ui| self.step_buttons_ui(run, ui, step, steps, playing));
        self.step_controls = Some(shown.response.rect);
        shown.inner
    }

    fn step_buttons_ui(
        &mut self,
        run: &mut AlgorithmRun,
        ui: &mut egui::Ui,
        step: usize,
        steps: usize,
        playing: bool,
    ) -> Option<Command> {
        let mut command = None;
        ui.horizontal_wrapped(|ui| {
            if ui
                .add_enabled(step > 0, egui::Button::new("|◀"))
                .on_hover_text("Go to the start (Home)")
                .clicked()
            {
                command = Some(Command::Goto(0));
            }
            if ui
                .add_enabled(step > 0, egui::Button::new("◀ Back"))
                .on_hover_text("Step back (←)")
                .clicked()
            {
                command = Some(Command::Back(1));
            }
            if ui
                .add_enabled(step < steps, egui::Button::new("Step ▶"))
                .on_hover_text("Step forward (Space or →)")
                .clicked()
            {
                command = Some(Command::Step(1));
            }
            // Over and out matter only in an algorithm that calls others.
            let calls = run
                .session()
                .is_some_and(|s| s.trace.algorithm().calls_others());
            if calls {
                if ui
                    .add_enabled(step < steps, egui::Button::new("Step over"))
                    .on_hover_text("Run the call on this step as one step (O)")
                    .clicked()
                {
                    command = Some(Command::StepOver);
                }
                let inside = run.session().is_some_and(|s| s.depth() > 0);
                if ui
                    .add_enabled(inside, egui::Button::new("Step out"))
                    .on_hover_text("Run to the step after this call returns (U)")
                    .clicked()
                {
                    command = Some(Command::StepOut);
                }
            }
            if ui
                .add_enabled(step < steps, egui::Button::new("▶|"))
                .on_hover_text("Go to the end (End)")
                .clicked()
            {
                command = Some(Command::Goto(steps));
            }
            let play_label = if playing { "❚❚ Pause" } else { "▶ Play" };
            if ui
                .button(play_label)
                .on_hover_text("Step automatically; stops at breakpoints (P)")
                .clicked()
            {
                command = Some(Command::SetPlaying(!playing));
            }
            if !self.breakpoints(run.algorithm()).is_empty()
                && ui
                    .add_enabled(step < steps, egui::Button::new("▶▶ Breakpoint"))
                    .on_hover_text("Go to the next step on a breakpoint line")
                    .clicked()
            {
                command = Some(Command::ContinueToBreakpoint);
            }
            if ui
                .button("✖ Abort")
                .on_hover_text("Stop the algorithm")
                .clicked()
            {
                command = Some(Command::Abort);
            }
        });
        ui.horizontal(|ui| {
            let mut k = step;
            let slider = egui::Slider::new(&mut k, 0..=steps)
                .show_value(false)
                .text(format!("step {step} of {steps}"));
            if ui.add(slider).changed() {
                command = Some(Command::Goto(k));
            }
        });
        ui.add(
            egui::Slider::new(&mut self.delay, 0.05..=2.0)
                .logarithmic(true)
                .suffix(" s")
                .text("delay between steps when playing"),
        );
        command
    }

    fn source_ui(
        &mut self,
        run: &mut AlgorithmRun,
        ui: &mut egui::Ui,
        algorithm: &Arc<Algorithm>,
        frame: &TraceFrame,
        breakpoints: &std::collections::BTreeSet<u32>,
        theme: &Theme,
    ) -> Option<Command> {
        let style = CodeStyle::new(self.code_size, theme.dark);
        let source = Arc::clone(&algorithm.source);
        let lines = line_ranges(&source, algorithm.first_line, algorithm.last_line);
        let emphasis_colour = match frame.operation {
            "lookup" => theme.trace_colour(TraceRole::Lookup),
            "compare" => theme.trace_colour(TraceRole::Compared),
            _ => ui.visuals().selection.bg_fill,
        }
        .gamma_multiply(0.55);
        let emphasis: Vec<Mark> = frame
            .span
            .map(|(start, end)| Mark {
                range: start as usize..end as usize,
                background: emphasis_colour,
                text: Some(style.emphasis_text),
                underline: egui::Stroke::NONE,
            })
            .into_iter()
            .collect();
        let line_fill = ui.visuals().selection.bg_fill.gamma_multiply(0.22);
        let row_height = ui.fonts_mut(|f| f.row_height(&style.font)) + 2.0;
        // How far apart the rows are: each is as tall as the style's least
        // interactive height where that is taller (a touch screen's), as the
        // tables' rows are, so the offset below is known before layout.
        let pitch = row_height.max(ui.spacing().interact_size.y);
        let gutter = ui.fonts_mut(|f| f.glyph_width(&style.font, '0')) * 4.0 + 18.0;
        let needs_scroll = run.scrolled_to != Some(frame.line);
        let highlighted = self.highlighted(&source).clone();
        let mut toggled = None;
        let mut scrolled = false;
        let mut area = egui::ScrollArea::both()
            .id_salt("algorithm_source")
            .auto_shrink([false, false])
            .max_height(ui.available_height());
        if self.in_sheet {
            area = area.min_scrolled_height(SOURCE_LEAST_HEIGHT);
        } else if needs_scroll {
            // The offset that centres the line, set before the rows are laid
            // out so that it shows in this frame, as the tables do
            // (`tables::DrawnRows`); scrolling to the row after them showed it
            // a frame later. Step 0's line, the header, is not marked, but
            // going back to it scrolls the code back to its top.
            if let Some(row) = lines.iter().position(|&(number, _)| number == frame.line) {
                let shown = ui.available_height();
                let most = (lines.len() as f32 * pitch - shown).max(0.0);
                let centred = (row as f32 + 0.5) * pitch - shown / 2.0;
                area = area.vertical_scroll_offset(centred.clamp(0.0, most));
                scrolled = true;
            }
        }
        let mut in_sight: Option<[u32; 2]> = None;
        area.show(ui, |ui| {
            ui.spacing_mut().item_spacing.y = 0.0;
            let sight = ui.clip_rect().y_range();
            for (number, range) in lines {
                let current = frame.step > 0 && number == frame.line;
                let background = ui.painter().add(egui::Shape::Noop);
                let row = ui.horizontal(|ui| {
                    let (rect, response) =
                        ui.allocate_exact_size(vec2(gutter, pitch), Sense::click());
                    let has_breakpoint = breakpoints.contains(&number);
                    let painter = ui.painter();
                    if has_breakpoint {
                        painter.circle_filled(
                            rect.left_center() + vec2(8.0, 0.0),
                            row_height * 0.28,
                            Color32::from_rgb(0xd0, 0x30, 0x30),
                        );
                    }
                    painter.text(
                        rect.right_center() - vec2(6.0, 0.0),
                        egui::Align2::RIGHT_CENTER,
                        number.to_string(),
                        style.font.clone(),
                        ui.visuals().weak_text_color(),
                    );
                    let response = response.on_hover_text(if has_breakpoint {
                        "Remove the breakpoint"
                    } else {
                        "Set a breakpoint: Play stops on this line"
                    });
                    response.widget_info(|| {
                        egui::WidgetInfo::labeled(
                            egui::Role::Button,
                            true,
                            format!("breakpoint line {number}"),
                        )
                    });
                    if response.clicked() {
                        toggled = Some(number);
                    }
                    let marks = if current { emphasis.as_slice() } else { &[] };
                    let job = highlighted.layout(&source, range.clone(), marks, &style);
                    ui.add(egui::Label::new(job).extend());
                });
                let rect = row.response.rect;
                if sight.contains(rect.center().y) {
                    in_sight = Some(in_sight.map_or([number; 2], |[first, _]| [first, number]));
                }
                if current {
                    ui.painter().set(
                        background,
                        egui::Shape::rect_filled(
                            egui::Rect::from_min_max(
                                rect.min,
                                egui::pos2(ui.max_rect().right(), rect.max.y),
                            ),
                            2.0,
                            line_fill,
                        ),
                    );
                }
                // In a phone's sheet the sheet scrolls too, to the line.
                if self.in_sheet && needs_scroll && number == frame.line {
                    ui.scroll_to_rect_animation(
                        rect,
                        Some(Align::Center),
                        egui::style::ScrollAnimation::none(),
                    );
                    scrolled = true;
                }
            }
        });
        if scrolled {
            run.scrolled_to = Some(frame.line);
        }
        self.source_lines = in_sight;
        toggled.map(Command::ToggleBreakpoint)
    }
}

/// While inputs are being picked: the prompt, fields for Integer and
/// Boolean parameters, Start and Cancel.
fn picking_ui(run: &mut AlgorithmRun, ui: &mut egui::Ui) -> Option<Command> {
    let Run::Picking(pending) = &mut run.run else {
        return None;
    };
    let algorithm = Arc::clone(&pending.algorithm);
    header_ui(ui, &algorithm);
    ui.add_space(6.0);
    match pending.prompt() {
        Some(prompt) => {
            ui.label(RichText::new(prompt).strong().size(16.0));
            ui.weak("Click it in the 3D view or in its table; only that kind can be picked.");
        }
        None => {
            ui.label("Every input is given.");
        }
    }
    let mut edited = false;
    for param in algorithm.params() {
        let Some(slot) = pending.inputs.iter_mut().find(|(n, _)| *n == param.name) else {
            continue;
        };
        ui.horizontal(|ui| {
            ui.monospace(format!("{} : {}", param.name, param.ty));
            match (param.ty, &mut slot.1) {
                (Type::Integer, Value::Integer(n)) => {
                    edited |= ui.add(egui::DragValue::new(n)).changed();
                }
                (Type::Float, Value::Float(x)) => {
                    edited |= ui.add(egui::DragValue::new(x).speed(0.01)).changed();
                }
                (Type::Boolean, Value::Boolean(b)) => {
                    edited |= ui.checkbox(b, "").changed();
                }
                (_, value) => {
                    ui.label(edgewise_model::algorithm::frame::value_text(*value));
                }
            }
        });
    }
    let ready = pending.missing().is_none();
    let mut start = false;
    let mut cancel = false;
    ui.horizontal(|ui| {
        start = ui
            .add_enabled(ready, egui::Button::new("Start"))
            .on_disabled_hover_text("pick the remaining inputs first")
            .clicked();
        cancel = ui.button("Cancel").clicked();
    });
    if edited {
        run.changed();
    }
    if cancel {
        return Some(Command::Abort);
    }
    start.then_some(Command::Start)
}

/// The algorithm's name, signature and description.
fn header_ui(ui: &mut egui::Ui, algorithm: &Algorithm) {
    ui.label(RichText::new(&algorithm.name).heading().monospace());
    ui.weak(algorithm.signature());
    if let Some(description) = &algorithm.description {
        ui.label(description);
    }
}

fn algorithm_hover(algorithm: &Algorithm) -> String {
    match &algorithm.description {
        Some(description) => format!("{}\n{description}", algorithm.signature()),
        None => algorithm.signature(),
    }
}

/// The card of the question asked at the current step, if any.
fn question_ui(
    run: &mut AlgorithmRun,
    ui: &mut egui::Ui,
    theme: &Theme,
    shows: Shown,
) -> Option<Command> {
    let Run::Tracing(session) = &mut run.run else {
        return None;
    };
    let step = session.step();
    let quiz = session.quiz.as_mut()?;
    quiz_ui::question_ui(quiz, ui, &session.trace, step, theme, shows)
}

/// The message line's sentence, and the output once done, or the error.
fn status_ui(ui: &mut egui::Ui, frame: &TraceFrame, theme: &Theme) {
    let (fill, text_colour) = if frame.error.is_some() {
        (
            ui.visuals().error_fg_color.gamma_multiply(0.12),
            ui.visuals().error_fg_color,
        )
    } else if frame.done {
        (
            theme.trace_colour(TraceRole::Output).gamma_multiply(0.15),
            ui.visuals().strong_text_color(),
        )
    } else {
        (ui.visuals().faint_bg_color, ui.visuals().text_color())
    };
    egui::Frame::new()
        .fill(fill)
        .inner_margin(6.0)
        .corner_radius(4.0)
        .show(ui, |ui| {
            ui.set_width(ui.available_width());
            ui.label(RichText::new(&frame.message).color(text_colour));
            if frame.done || frame.error.is_some() {
                let marked: Vec<String> = frame.marked.iter().map(ToString::to_string).collect();
                if !marked.is_empty() {
                    ui.label(format!("Marked: {}", marked.join(", ")));
                }
            }
            if frame.output_count > frame.output.len() {
                ui.weak(format!(
                    "… {} earlier messages; the latest {} follow",
                    frame.output_count - frame.output.len(),
                    frame.output.len()
                ));
            }
            for line in &frame.output {
                ui.monospace(line);
            }
        });
}

/// The variables and their values; element values carry the purple chip
/// that marks them in the view.
fn variables_ui(ui: &mut egui::Ui, frame: &TraceFrame, theme: &Theme) {
    if frame.calls.len() > 1 {
        ui.horizontal_wrapped(|ui| {
            ui.weak("Call stack:");
            ui.label(RichText::new(frame.calls.join(" → ")).monospace());
        })
        .response
        .on_hover_text("The started algorithm first; the variables below are the innermost call's");
    }
    egui::Grid::new("trace_variables")
        .num_columns(3)
        .spacing(vec2(10.0, 2.0))
        .show(ui, |ui| {
            for variable in &frame.variables {
                ui.label(RichText::new(&variable.name).monospace().strong());
                ui.weak(variable.ty);
                let element = ["Vertex ", "Edge ", "Face "]
                    .iter()
                    .any(|p| variable.value.starts_with(p));
                let mut text = RichText::new(&variable.value).monospace();
                if element && !frame.done {
                    text = text.background_color(
                        theme.trace_colour(TraceRole::Variable).gamma_multiply(0.3),
                    );
                }
                // A long value (an array of vectors) is cut with "…" at the
                // panel's edge, never widening it; hovering shows it whole.
                ui.add(egui::Label::new(text).truncate())
                    .on_hover_text(RichText::new(&variable.value).monospace());
                ui.end_row();
            }
        });
}

/// The journal's colour meanings, as chips, wrapped to the panel's width.
/// Each chip and its words are one item, so a row never ends between them
/// (and, laid out whole, the row does not widen the panel: nested
/// horizontal layouts had made the panel most of the window).
fn legend_ui(ui: &mut egui::Ui, theme: &Theme) {
    ui.horizontal_wrapped(|ui| {
        for role in TraceRole::ALL {
            let words = match role.glyph() {
                Some(glyph) => format!("{glyph} {}", role.meaning()),
                None => format!("name: {}", role.meaning()),
            };
            let galley = ui.painter().layout_no_wrap(
                words,
                egui::TextStyle::Small.resolve(ui.style()),
                ui.visuals().text_color(),
            );
            let chip = vec2(12.0, 12.0);
            let gap = ui.spacing().item_spacing.x;
            let size = vec2(chip.x + gap + galley.size().x, chip.y.max(galley.size().y));
            let (rect, _) = ui.allocate_exact_size(size, Sense::hover());
            let chip_rect = egui::Rect::from_center_size(
                egui::pos2(rect.left() + chip.x / 2.0, rect.center().y),
                chip,
            );
            ui.painter()
                .rect_filled(chip_rect, 2.0, theme.trace_colour(role));
            let text_at = egui::pos2(
                chip_rect.right() + gap,
                rect.center().y - galley.size().y / 2.0,
            );
            ui.painter()
                .galley(text_at, galley, ui.visuals().text_color());
        }
    });
}

/// The byte range of each source line `first..=last` (1-based), without
/// its line break.
fn line_ranges(source: &str, first: u32, last: u32) -> Vec<(u32, Range<usize>)> {
    let mut out = Vec::new();
    let mut start = 0;
    for (number, line) in (1_u32..).zip(source.split_inclusive('\n')) {
        let end = start + line.len();
        if number >= first && number <= last {
            let text_end = start + line.trim_end_matches(['\n', '\r']).len();
            out.push((number, start..text_end));
        }
        start = end;
        if number > last {
            break;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_ranges_cover_the_chosen_lines() {
        let source = "a\nbb\r\nccc\nd";
        assert_eq!(
            line_ranges(source, 2, 4),
            vec![(2, 2..4), (3, 6..9), (4, 10..11)]
        );
    }
}
