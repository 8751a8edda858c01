//! A code editor widget: multiline text with a line-number gutter, an
//! optional highlighter, and diagnostics drawn where they apply.
//!
//! A diagnostic tints its line with the theme's error colour, marks the line
//! number in the gutter (hover for the message), underlines the field at its
//! column with a wavy line, and prints its message in room made under the
//! line, so a student sees what is wrong and where without hovering. The OBJ
//! editor uses it with one diagnostic; the algorithm editor can pass several
//! and its own highlighter.

use std::{collections::BTreeMap, ops::Range, sync::Arc};

use egui::{
    Align, Color32, FontId, Pos2, Rect, Sense, Shape, Stroke,
    text::{ByteIndex, CCursor, LayoutJob, TextFormat},
};
use serde::Serialize;

/// One problem at a place in the text.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Diagnostic {
    /// 1-based line.
    pub line: usize,
    /// 1-based column in characters, when one field is at fault.
    pub column: Option<usize>,
    pub message: String,
}

/// Lays out `text` with colours: must return a job over exactly `text`. The
/// editor sets the wrap width and makes room for diagnostics itself.
pub type Highlighter = dyn Fn(&egui::Style, &str) -> LayoutJob;

/// A code editor over a `String`; see the module docs.
pub struct CodeEditor<'a> {
    id_salt: &'a str,
    text: &'a mut String,
    diagnostics: &'a [Diagnostic],
    highlighter: Option<&'a Highlighter>,
    hint: &'a str,
    rows: usize,
    max_bytes: usize,
}

/// What [`CodeEditor::show`] gives back.
pub struct EditorOutput {
    /// The text field's response: `changed()` after an edit.
    pub response: egui::Response,
    /// Why typed or pasted text was refused this frame, if it was.
    pub refused: Option<String>,
}

/// The gutter's padding either side of the numbers.
const GUTTER_PAD: f32 = 6.0;

impl<'a> CodeEditor<'a> {
    pub fn new(id_salt: &'a str, text: &'a mut String) -> Self {
        Self {
            id_salt,
            text,
            diagnostics: &[],
            highlighter: None,
            hint: "",
            rows: 20,
            max_bytes: usize::MAX,
        }
    }

    /// Refuses typed or pasted text that would make the text longer than
    /// `max_bytes`, before the text field sees it: a huge paste would
    /// otherwise be laid out, and rebuilt, in full.
    pub fn max_bytes(mut self, max_bytes: usize) -> Self {
        self.max_bytes = max_bytes;
        self
    }

    pub fn diagnostics(mut self, diagnostics: &'a [Diagnostic]) -> Self {
        self.diagnostics = diagnostics;
        self
    }

    pub fn highlighter(mut self, highlighter: &'a Highlighter) -> Self {
        self.highlighter = Some(highlighter);
        self
    }

    pub fn hint_text(mut self, hint: &'a str) -> Self {
        self.hint = hint;
        self
    }

    pub fn desired_rows(mut self, rows: usize) -> Self {
        self.rows = rows;
        self
    }

    /// Draws the editor (scrolling inside the space it is given).
    pub fn show(self, ui: &mut egui::Ui) -> EditorOutput {
        let field = ui.scope_id().with(("code_editor_field", self.id_salt));
        let refused = refuse_oversized_input(ui, field, self.text.len(), self.max_bytes);
        let response = egui::ScrollArea::vertical()
            .id_salt(self.id_salt)
            .show(ui, |ui| self.contents_ui(ui))
            .inner;
        // The field's id is only known once it is drawn: kept for next frame.
        ui.data_mut(|d| d.insert_temp(field, response.id));
        EditorOutput { response, refused }
    }

    fn contents_ui(mut self, ui: &mut egui::Ui) -> egui::Response {
        let look = Look::of(ui, self.text);
        let by_line = messages_by_line(self.diagnostics);
        // The frame, gutter and tints go behind the text: reserve their slot now.
        let background = ui.painter().add(Shape::Noop);
        let field = self.field_ui(ui, &look, &by_line);
        paint_background(ui, background, &field, &look, &by_line, self.id_salt);
        // Line numbers, underlines and messages over the text.
        paint_line_numbers(ui, &field, &look, &by_line);
        paint_underlines(ui.painter(), &field, &look, self.text, self.diagnostics);
        messages_ui(ui, &field, &look, self.text, &by_line);
        field.response
    }

    /// The gutter's room and the text field, laid out with room made under
    /// each line that has a message.
    fn field_ui(
        &mut self,
        ui: &mut egui::Ui,
        look: &Look,
        by_line: &BTreeMap<usize, String>,
    ) -> Field {
        let highlighter = self.highlighter;
        ui.horizontal_top(|ui| {
            ui.spacing_mut().item_spacing.x = 0.0;
            let (gutter, _) =
                ui.allocate_exact_size(egui::vec2(look.gutter_width, 0.0), Sense::hover());
            let mut layouter = |ui: &egui::Ui, buffer: &dyn egui::TextBuffer, wrap: f32| {
                let text = buffer.as_str();
                let mut job = match highlighter {
                    Some(highlight) => highlight(ui.style(), text),
                    None => LayoutJob::single_section(
                        text.to_owned(),
                        TextFormat::simple(look.code_font.clone(), ui.visuals().text_color()),
                    ),
                };
                job.wrap.max_width = wrap;
                for (line, message) in by_line {
                    let height = ui.fonts_mut(|f| {
                        f.layout(
                            message.clone(),
                            look.message_font.clone(),
                            look.error,
                            (wrap - look.message_indent).max(40.0),
                        )
                        .size()
                        .y
                    });
                    make_room_under(&mut job, text, *line, height + 4.0);
                }
                ui.fonts_mut(|f| f.layout_job(job))
            };
            let output = egui::TextEdit::multiline(&mut *self.text)
                .id_salt(self.id_salt)
                .font(look.code_font.clone())
                .code_editor()
                .frame(egui::Frame::NONE)
                .margin(egui::Margin::symmetric(4, 2))
                .desired_width(f32::INFINITY)
                .desired_rows(self.rows)
                .hint_text(self.hint)
                .layouter(&mut layouter)
                .show(ui);
            Field {
                lines: place_lines(&output.galley, output.galley_pos, look.row_height),
                gutter: Rect::from_x_y_ranges(gutter.x_range(), output.response.rect.y_range()),
                text_rect: output.response.rect,
                response: output.response.response,
            }
        })
        .inner
    }
}

/// The fonts, colours and sizes the editor draws with.
struct Look {
    code_font: FontId,
    message_font: FontId,
    row_height: f32,
    error: Color32,
    /// A message's text on its tinted band.
    message_colour: Color32,
    gutter_width: f32,
    /// How far a message sits right of the text's left edge.
    message_indent: f32,
}

impl Look {
    fn of(ui: &egui::Ui, text: &str) -> Self {
        let code_font = egui::TextStyle::Monospace.resolve(ui.style());
        let message_font = FontId::proportional(code_font.size);
        let (row_height, digit_width) =
            ui.fonts_mut(|f| (f.row_height(&code_font), f.glyph_width(&code_font, '0')));
        let error = ui.visuals().error_fg_color;
        // Messages are text on the tinted band: lighter on dark backgrounds
        // so they stay readable when projected.
        let message_colour = if ui.visuals().dark_mode {
            error.lerp_to_gamma(Color32::WHITE, 0.45)
        } else {
            error.lerp_to_gamma(Color32::BLACK, 0.2)
        };
        let line_count = text.split('\n').count();
        let digits = line_count.max(10).ilog10() as f32 + 1.0;
        Self {
            code_font,
            message_font,
            row_height,
            error,
            message_colour,
            gutter_width: digits * digit_width + 2.0 * GUTTER_PAD,
            message_indent: 2.0 * digit_width,
        }
    }
}

/// What the text field drew, for the layers behind and over it.
struct Field {
    response: egui::Response,
    lines: Vec<PlacedLine>,
    gutter: Rect,
    text_rect: Rect,
}

impl Field {
    /// The gutter and the text together.
    fn whole(&self) -> Rect {
        self.gutter.union(self.text_rect)
    }
}

/// Behind the text: the frame, the gutter, each message's tinted band and
/// its gutter marker (hover for the message).
fn paint_background(
    ui: &egui::Ui,
    slot: egui::layers::ShapeIdx,
    field: &Field,
    look: &Look,
    by_line: &BTreeMap<usize, String>,
    id_salt: &str,
) {
    let visuals = ui.visuals();
    let whole = field.whole();
    let mut shapes = vec![
        Shape::rect_filled(
            whole,
            visuals.widgets.inactive.corner_radius,
            visuals.extreme_bg_color,
        ),
        Shape::rect_filled(field.gutter, 0.0, visuals.faint_bg_color),
    ];
    for (&line, message) in by_line {
        let Some(placed) = field.lines.get(line - 1) else {
            continue;
        };
        let band = Rect::from_x_y_ranges(whole.x_range(), placed.rows.clone());
        shapes.push(Shape::rect_filled(
            band,
            0.0,
            look.error.gamma_multiply(0.14),
        ));
        let marker = Rect::from_x_y_ranges(
            field.gutter.left() + 2.0..=field.gutter.right() - 2.0,
            placed.top..=placed.top + look.row_height,
        );
        shapes.push(Shape::rect_filled(marker, 3.0, look.error));
        ui.interact(
            marker,
            ui.scope_id().with((id_salt, "marker", line)),
            Sense::hover(),
        )
        .on_hover_text(message.as_str());
    }
    let stroke = if field.response.has_focus() {
        visuals.selection.stroke
    } else {
        visuals.widgets.inactive.bg_stroke
    };
    shapes.push(Shape::rect_stroke(
        whole,
        visuals.widgets.inactive.corner_radius,
        stroke,
        egui::StrokeKind::Inside,
    ));
    ui.painter().set(slot, Shape::Vec(shapes));
}

/// The line numbers, in white on the lines with a message.
fn paint_line_numbers(
    ui: &egui::Ui,
    field: &Field,
    look: &Look,
    by_line: &BTreeMap<usize, String>,
) {
    let painter = ui.painter();
    let weak = ui.visuals().weak_text_color();
    for (i, placed) in field.lines.iter().enumerate() {
        let line = i + 1;
        let colour = if by_line.contains_key(&line) {
            Color32::WHITE
        } else {
            weak
        };
        painter.text(
            Pos2::new(field.gutter.right() - GUTTER_PAD, placed.top),
            egui::Align2::RIGHT_TOP,
            line.to_string(),
            look.code_font.clone(),
            colour,
        );
    }
}

/// A wavy line under the field each diagnostic with a column names.
fn paint_underlines(
    painter: &egui::Painter,
    field: &Field,
    look: &Look,
    text: &str,
    diagnostics: &[Diagnostic],
) {
    for diagnostic in diagnostics {
        let Some(placed) = field.lines.get(diagnostic.line.wrapping_sub(1)) else {
            continue;
        };
        let Some(span) = diagnostic.column.and_then(|column| {
            line_range(text, diagnostic.line).and_then(|range| field_at(&text[range], column))
        }) else {
            continue;
        };
        let at = |chars: usize| {
            placed
                .galley
                .pos_from_cursor(CCursor::new(placed.first_char + chars))
                .translate(placed.galley_pos.to_vec2())
        };
        let (start, end) = (at(span.start), at(span.end));
        // Under the field's first row; at least a few pixels wide for an
        // empty field.
        let right = if end.top() == start.top() {
            end.left()
        } else {
            field.text_rect.right()
        };
        let (left, right) = (start.left(), right.max(start.left() + 6.0));
        let y = start.top() + look.row_height + 0.5;
        painter.add(wavy_line(left, right, y, Stroke::new(1.5, look.error)));
    }
}

/// Each line's messages, in the room made under it, or after its one word.
fn messages_ui(
    ui: &mut egui::Ui,
    field: &Field,
    look: &Look,
    text: &str,
    by_line: &BTreeMap<usize, String>,
) {
    for (&line, message) in by_line {
        let Some(placed) = field.lines.get(line - 1) else {
            continue;
        };
        let label = egui::Label::new(
            egui::RichText::new(message.as_str())
                .font(look.message_font.clone())
                .color(look.message_colour),
        )
        .selectable(false);
        let text_rect = field.text_rect;
        if has_blank(text, line) {
            // In the room made under the line.
            let rect = Rect::from_min_max(
                Pos2::new(
                    text_rect.left() + look.message_indent,
                    placed.top + look.row_height + 1.0,
                ),
                Pos2::new(text_rect.right() - 4.0, placed.message_bottom),
            );
            put_left(ui, rect, label.wrap());
        } else {
            // A line of one word has no room under it: the message follows
            // the word, shortened if need be (hover shows it all).
            let rect = Rect::from_min_max(
                Pos2::new(placed.right + look.message_indent, placed.top),
                Pos2::new(text_rect.right() - 4.0, placed.top + look.row_height),
            );
            put_left(ui, rect, label.truncate());
        }
    }
}

/// Adds `label` in `rect`, left-aligned (`Ui::put` would centre and justify it).
fn put_left(ui: &mut egui::Ui, rect: Rect, label: egui::Label) {
    ui.scope_builder(
        egui::UiBuilder::new()
            .max_rect(rect)
            .layout(egui::Layout::top_down(Align::LEFT)),
        |ui| ui.add(label),
    );
}

/// Where a source line ended up on screen.
struct PlacedLine {
    /// The top of its first row.
    top: f32,
    /// The vertical extent of all its rows.
    rows: std::ops::RangeInclusive<f32>,
    /// The bottom of the room made for a message (the bottom of its tallest row).
    message_bottom: f32,
    /// The right end of its first row's text.
    right: f32,
    /// The line's first character, for column positions.
    first_char: usize,
    galley: Arc<egui::Galley>,
    galley_pos: Pos2,
}

/// Each source line's rows, from the galley (rows that end in a newline end a line).
fn place_lines(galley: &Arc<egui::Galley>, galley_pos: Pos2, row_height: f32) -> Vec<PlacedLine> {
    let mut lines: Vec<PlacedLine> = Vec::new();
    let mut new_line = true;
    let mut chars = 0;
    for row in &galley.rows {
        let rect = row.rect().translate(galley_pos.to_vec2());
        if new_line {
            lines.push(PlacedLine {
                top: rect.top(),
                rows: rect.top()..=rect.bottom(),
                message_bottom: rect.bottom(),
                right: rect.right(),
                first_char: chars,
                galley: Arc::clone(galley),
                galley_pos,
            });
        } else if let Some(last) = lines.last_mut() {
            last.rows = *last.rows.start()..=rect.bottom();
            if rect.height() > row_height + 1.0 {
                last.message_bottom = rect.bottom();
            }
        }
        chars += row.char_count_including_newline().0;
        new_line = row.ends_with_newline;
    }
    lines
}

/// The character range of the field (run of non-blanks) starting at
/// 1-based `column` of `line`.
fn field_at(line: &str, column: usize) -> Option<Range<usize>> {
    let start = column.checked_sub(1)?;
    let chars: Vec<char> = line.chars().collect();
    if start > chars.len() {
        return None;
    }
    let len = chars[start..]
        .iter()
        .take_while(|c| !c.is_whitespace())
        .count();
    Some(start..start + len)
}

/// Drops this frame's typed and pasted text when the field whose id was kept
/// under `field` has the focus and the text would grow past `max_bytes`.
fn refuse_oversized_input(
    ui: &egui::Ui,
    field: egui::Id,
    len: usize,
    max_bytes: usize,
) -> Option<String> {
    let id = ui.data(|d| d.get_temp::<egui::Id>(field))?;
    if !ui.memory(|m| m.has_focus(id)) {
        return None;
    }
    ui.input_mut(|input| {
        let mut refused = None;
        input.events.retain(|event| match event {
            egui::Event::Paste(added) | egui::Event::Text(added)
                if len + added.len() > max_bytes =>
            {
                refused = Some(format!(
                    "{} bytes were not added: this editor holds at most {max_bytes} bytes",
                    added.len()
                ));
                false
            }
            _ => true,
        });
        refused
    })
}

/// Messages joined per line, in line order.
fn messages_by_line(diagnostics: &[Diagnostic]) -> BTreeMap<usize, String> {
    let mut by_line: BTreeMap<usize, String> = BTreeMap::new();
    for d in diagnostics.iter().filter(|d| d.line > 0) {
        let entry = by_line.entry(d.line).or_default();
        if !entry.is_empty() {
            entry.push('\n');
        }
        entry.push_str(&d.message);
    }
    by_line
}

/// Makes a row `extra` taller under 1-based `line`, keeping its text at the
/// top: the line's glyphs align to the top of their row, and its last blank
/// (invisible wherever it sits) gets the tall line height. A line without
/// blanks is left as it is (its message goes beside it).
fn make_room_under(job: &mut LayoutJob, text: &str, line: usize, extra: f32) {
    let Some(range) = line_range(text, line) else {
        return;
    };
    let row = job
        .sections
        .first()
        .map_or(14.0, |s| s.format.font_id.size * 1.3);
    let Some(blank) = text[range.clone()]
        .char_indices()
        .rev()
        .find(|(_, c)| c.is_whitespace())
        .map(|(i, c)| range.start + i..range.start + i + c.len_utf8())
    else {
        return;
    };
    format_range(job, range, |format| format.valign = Align::TOP);
    format_range(job, blank, |format| format.line_height = Some(row + extra));
}

/// Whether 1-based `line` has a blank, so [`make_room_under`] can make room.
fn has_blank(text: &str, line: usize) -> bool {
    line_range(text, line).is_some_and(|range| text[range].contains(char::is_whitespace))
}

/// The byte range of 1-based `line` in `text`, without its newline.
fn line_range(text: &str, line: usize) -> Option<Range<usize>> {
    let mut start = 0;
    for (i, content) in text.split('\n').enumerate() {
        if i + 1 == line {
            return Some(start..start + content.len());
        }
        start += content.len() + 1;
    }
    None
}

/// Applies `f` to the format of the bytes in `range`, splitting sections at
/// its ends.
fn format_range(job: &mut LayoutJob, range: Range<usize>, f: impl Fn(&mut TextFormat)) {
    let mut sections = Vec::with_capacity(job.sections.len() + 2);
    for section in job.sections.drain(..) {
        let (start, end) = (section.byte_range.start.0, section.byte_range.end.0);
        let cuts = [
            start,
            range.start.clamp(start, end),
            range.end.clamp(start, end),
            end,
        ];
        for (i, piece) in cuts.windows(2).enumerate() {
            if piece[0] < piece[1] {
                let mut part = section.clone();
                part.byte_range = ByteIndex(piece[0])..ByteIndex(piece[1]);
                if piece[0] != start {
                    part.leading_space = 0.0;
                }
                if i == 1 {
                    f(&mut part.format);
                }
                sections.push(part);
            }
        }
    }
    job.sections = sections;
}

/// A wavy underline from `left` to `right` at `y`, like a spelling checker's.
fn wavy_line(left: f32, right: f32, y: f32, stroke: Stroke) -> Shape {
    const STEP: f32 = 2.5;
    const AMPLITUDE: f32 = 1.5;
    let steps = ((right - left) / STEP).ceil().max(1.0) as usize;
    let points = (0..=steps)
        .map(|i| {
            let x = (left + i as f32 * STEP).min(right);
            let up = if i % 2 == 0 { -AMPLITUDE } else { AMPLITUDE };
            Pos2::new(x, y + up)
        })
        .collect();
    Shape::line(points, stroke)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_are_found_by_number() {
        let text = "v 0 0 0\nf 1 2 3\n";
        assert_eq!(line_range(text, 1), Some(0..7));
        assert_eq!(line_range(text, 2), Some(8..15));
        assert_eq!(line_range(text, 3), Some(16..16));
        assert_eq!(line_range(text, 4), None);
    }

    #[test]
    fn a_field_runs_to_the_next_blank() {
        assert_eq!(field_at("f 1 2 17", 7), Some(6..8));
        assert_eq!(field_at("f 1 2 17", 2), Some(1..1));
        assert_eq!(field_at("f", 9), None);
        assert_eq!(field_at("f", 0), None);
    }

    #[test]
    fn formatting_a_range_splits_sections_and_keeps_the_text() {
        let mut job = LayoutJob::single_section("abc def".to_owned(), TextFormat::default());
        format_range(&mut job, 2..5, |f| f.italics = true);
        let pieces: Vec<(usize, usize, bool)> = job
            .sections
            .iter()
            .map(|s| (s.byte_range.start.0, s.byte_range.end.0, s.format.italics))
            .collect();
        assert_eq!(pieces, [(0, 2, false), (2, 5, true), (5, 7, false)]);
    }
}
