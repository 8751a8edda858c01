//! A PDF handout of a run: one landscape A4 page per step, each the view
//! as vector shapes ([`VectorView`]) under the step's sentence and its
//! variables, beside the code with the current line and the tables' rows
//! the step paints, so a lecturer prints the walk instead of taking a
//! screenshot per step.
//!
//! Written by hand in PDF 1.4: the shapes need only paths, fills, strokes,
//! a transparency state per opacity and the standard Helvetica and Courier
//! fonts, so no font is embedded and a 22-step handout is a few tens of
//! kilobytes. The standard fonts lack the trace's glyphs (→ ✓ ★ ✎ ∅), so
//! those are drawn as paths, in Courier's fixed-width cells.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use ecolor::Color32;
use emath::Pos2;

use crate::svg::{RowLook, cell_text, n};
use crate::text_table::TextTable;
use crate::vector::{Shape, VectorView, label_size, shaft_end};
use edgewise_core::schema::ElementRef;

/// Landscape A4, in PDF points.
pub const PAGE: (f32, f32) = (842.0, 595.0);
/// The most pages a handout holds.
pub const MAX_PAGES: usize = 300;
const MARGIN: f32 = 36.0;
/// Opacities are rounded to twentieths, one graphics state each.
const OPACITY_STEPS: u32 = 20;
/// A circle's control-point distance, as a fraction of its radius.
const KAPPA: f32 = 0.552_284_8;

/// Courier's advance, in ems: every character, so glyphs drawn in its
/// place line up with the text around them.
const COURIER_EM: f32 = 0.6;
/// The code's and the tables' type size, in points.
const SMALL: f32 = 7.5;
const SMALL_LEADING: f32 = 9.5;
/// The right column (code and tables), in points.
const SIDE_WIDTH: f32 = 300.0;

/// One page: the view and the lines above it, and beside it the code and
/// the painted rows.
#[derive(Clone, Debug)]
pub struct Page {
    pub view: VectorView,
    /// The step's sentence first, then the variables.
    pub lines: Vec<String>,
    /// The algorithm's source lines, numbered.
    pub code: Vec<(u32, String)>,
    /// The line the step runs, highlighted.
    pub current_line: Option<u32>,
    /// The tables' rows the step paints, and how each is painted.
    pub tables: Vec<TextTable>,
    pub rows: BTreeMap<ElementRef, RowLook>,
}

/// The handout as PDF bytes.
pub fn handout(title: &str, pages: &[Page]) -> Vec<u8> {
    let mut objects: Vec<String> = Vec::new();
    // 1: catalog, 2: pages, 3: Helvetica, 4: graphics states, 5: info,
    // 6: Courier; then a page and its contents for each page.
    let page_ids: Vec<usize> = (0..pages.len()).map(|i| 7 + 2 * i).collect();
    objects.push("<< /Type /Catalog /Pages 2 0 R >>".to_owned());
    objects.push(format!(
        "<< /Type /Pages /Kids [{}] /Count {} >>",
        page_ids
            .iter()
            .map(|id| format!("{id} 0 R"))
            .collect::<Vec<_>>()
            .join(" "),
        pages.len()
    ));
    objects.push(
        "<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica /Encoding /WinAnsiEncoding >>"
            .to_owned(),
    );
    let states: String = (0..=OPACITY_STEPS)
        .map(|i| {
            let alpha = i as f32 / OPACITY_STEPS as f32;
            format!("/A{i} << /Type /ExtGState /ca {alpha:.2} /CA {alpha:.2} >> ")
        })
        .collect();
    objects.push(format!("<< {states}>>"));
    objects.push(format!(
        "<< /Title ({}) /Producer (Edgewise) >>",
        pdf_text(title)
    ));
    objects.push(
        "<< /Type /Font /Subtype /Type1 /BaseFont /Courier /Encoding /WinAnsiEncoding >>"
            .to_owned(),
    );
    for (i, page) in pages.iter().enumerate() {
        let contents = page_contents(page, i + 1, pages.len());
        objects.push(format!(
            "<< /Type /Page /Parent 2 0 R /MediaBox [0 0 {} {}] \
             /Resources << /Font << /F1 3 0 R /F2 6 0 R >> /ExtGState 4 0 R >> /Contents {} 0 R >>",
            PAGE.0,
            PAGE.1,
            page_ids[i] + 1
        ));
        objects.push(format!(
            "<< /Length {} >>\nstream\n{contents}\nendstream",
            contents.len() + 1
        ));
    }

    let mut out = String::from("%PDF-1.4\n");
    let mut offsets = Vec::with_capacity(objects.len());
    for (i, object) in objects.iter().enumerate() {
        offsets.push(out.len());
        let _ = write!(out, "{} 0 obj\n{object}\nendobj\n", i + 1);
    }
    let xref = out.len();
    let _ = write!(out, "xref\n0 {}\n0000000000 65535 f \n", objects.len() + 1);
    for offset in offsets {
        let _ = writeln!(out, "{offset:010} 00000 n ");
    }
    let _ = write!(
        out,
        "trailer\n<< /Size {} /Root 1 0 R /Info 5 0 R >>\nstartxref\n{xref}\n%%EOF\n",
        objects.len() + 1
    );
    out.into_bytes()
}

fn rgb(colour: Color32) -> String {
    let [r, g, b, _] = colour.to_srgba_unmultiplied();
    let c = |v: u8| format!("{:.3}", f32::from(v) / 255.0);
    format!("{} {} {}", c(r), c(g), c(b))
}

/// Text for a PDF string in `WinAnsiEncoding`: Latin-1 kept (as octal escapes
/// beyond ASCII), a few common symbols and the trace roles' glyphs spelled
/// out, anything else `?`.
pub fn pdf_text(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '(' | ')' | '\\' => {
                out.push('\\');
                out.push(c);
            }
            '∅' => out.push_str("none"),
            '→' => out.push_str("->"),
            // The trace roles' glyphs (`TraceRole::glyph`).
            '★' => out.push('*'),
            '✓' => out.push_str("ok"),
            '✎' => out.push('w'),
            '…' => out.push_str("..."),
            '–' | '—' | '−' => out.push('-'),
            ' '..='~' => out.push(c),
            c if (c as u32) >= 0xA0 && (c as u32) <= 0xFF => {
                let _ = write!(out, "\\{:03o}", c as u32);
            }
            c if c.is_whitespace() => out.push(' '),
            _ => out.push('?'),
        }
    }
    out
}

/// The content stream of one page.
fn page_contents(page: &Page, number: usize, count: usize) -> String {
    let (width, height) = PAGE;
    let mut out = String::new();
    let line_height = 15.0;
    let mut y = height - MARGIN;
    for (i, line) in page.lines.iter().enumerate() {
        let size = if i == 0 { 13.0 } else { 10.0 };
        let shown: String = line.chars().take(150).collect();
        let _ = writeln!(
            out,
            "0 g BT /F1 {size} Tf {} {} Td ({}) Tj ET",
            n(MARGIN),
            n(y - size),
            pdf_text(&shown)
        );
        y -= line_height;
    }
    let _ = writeln!(
        out,
        "0.4 g BT /F1 9 Tf {} {} Td (Page {number} of {count}) Tj ET",
        n(width - MARGIN - 70.0),
        n(MARGIN * 0.5)
    );
    // The view, scaled to fit the rest of the page, y up; the code and the
    // rows on the right.
    let top = height - y + 8.0;
    let side = !page.code.is_empty() || !page.tables.is_empty();
    let side_width = if side { SIDE_WIDTH + MARGIN * 0.5 } else { 0.0 };
    if side {
        side_contents(&mut out, page, width - MARGIN - SIDE_WIDTH, height - top);
    }
    let room = (width - 2.0 * MARGIN - side_width, height - top - MARGIN);
    let size = page.view.size;
    let scale = (room.0 / size.x.max(1.0))
        .min(room.1 / size.y.max(1.0))
        .min(2.0);
    let left = MARGIN + (room.0 - size.x * scale) * 0.5;
    let place = |p: Pos2| (left + p.x * scale, height - top - p.y * scale);
    // Clipped to the view's rectangle.
    let (x0, y0) = place(Pos2::new(0.0, size.y));
    let _ = writeln!(
        out,
        "q {} {} {} {} re W n",
        n(x0),
        n(y0),
        n(size.x * scale),
        n(size.y * scale)
    );
    for shape in &page.view.shapes {
        shape_contents(&mut out, shape, &place, scale, &page.view);
    }
    out.push('Q');
    out
}

fn path(points: &[Pos2], place: &dyn Fn(Pos2) -> (f32, f32)) -> String {
    let mut out = String::new();
    for (i, p) in points.iter().enumerate() {
        let (x, y) = place(*p);
        let _ = write!(out, "{} {} {} ", n(x), n(y), if i == 0 { "m" } else { "l" });
    }
    out.push('h');
    out
}

fn opacity_state(opacity: f32) -> u32 {
    (opacity.clamp(0.0, 1.0) * OPACITY_STEPS as f32).round() as u32
}

fn shape_contents(
    out: &mut String,
    shape: &Shape,
    place: &dyn Fn(Pos2) -> (f32, f32),
    scale: f32,
    view: &VectorView,
) {
    match shape {
        Shape::Polygon {
            points,
            fill,
            opacity,
        } => {
            let _ = writeln!(
                out,
                "/A{} gs {} rg {} f /A{OPACITY_STEPS} gs",
                opacity_state(*opacity),
                rgb(*fill),
                path(points, place)
            );
        }
        Shape::Arrow {
            from,
            to,
            head,
            colour,
            width,
        } => {
            let (a, b) = (place(*from), place(shaft_end(*from, *to, head)));
            let _ = writeln!(
                out,
                "{c} RG {c} rg {} w 1 J {} {} m {} {} l S {} f",
                n(width * scale),
                n(a.0),
                n(a.1),
                n(b.0),
                n(b.1),
                path(head, place),
                c = rgb(*colour),
            );
        }
        Shape::Disc {
            centre,
            radius,
            fill,
        } => {
            let (x, y) = place(*centre);
            let r = radius * scale;
            let k = r * KAPPA;
            let _ = writeln!(
                out,
                "{} rg {} {} m {} {} {} {} {} {} c {} {} {} {} {} {} c {} {} {} {} {} {} c {} {} {} {} {} {} c f",
                rgb(*fill),
                n(x + r),
                n(y),
                n(x + r),
                n(y + k),
                n(x + k),
                n(y + r),
                n(x),
                n(y + r),
                n(x - k),
                n(y + r),
                n(x - r),
                n(y + k),
                n(x - r),
                n(y),
                n(x - r),
                n(y - k),
                n(x - k),
                n(y - r),
                n(x),
                n(y - r),
                n(x + k),
                n(y - r),
                n(x + r),
                n(y - k),
                n(x + r),
                n(y),
            );
        }
        Shape::Label {
            centre,
            text,
            border,
        } => {
            let size = label_size(text) * scale;
            let (x, y) = place(*centre);
            let font = 12.0 * scale;
            let text_width = text.chars().count() as f32 * font * COURIER_EM;
            let _ = writeln!(
                out,
                "{} rg {} RG 0.8 w {} {} {} {} re B",
                rgb(view.palette.label_fill),
                rgb(border.unwrap_or(view.palette.label_stroke)),
                n(x - size.x * 0.5),
                n(y - size.y * 0.5),
                n(size.x),
                n(size.y),
            );
            mono_text(
                out,
                text,
                (x - text_width * 0.5, y - font * 0.3),
                font,
                view.palette.label_text,
            );
        }
    }
}

/// The right column: the code with the current line on a band, then the
/// painted rows of each table on their colours, in Courier.
fn side_contents(out: &mut String, page: &Page, left: f32, top: f32) {
    let black = Color32::BLACK;
    let columns = (SIDE_WIDTH / (SMALL * COURIER_EM)) as usize;
    let rows_height: f32 = page
        .tables
        .iter()
        .map(|t| (t.rows.len() as f32 + 2.5) * SMALL_LEADING)
        .sum();
    // The code gets what the rows leave, at least a dozen lines.
    // (and a line's gap between them).
    let room = (top - MARGIN - rows_height - SMALL_LEADING).max(12.0 * SMALL_LEADING);
    let fits = ((room / SMALL_LEADING) as usize).max(1);
    // A long algorithm shows the lines around the current one.
    let at = page
        .current_line
        .and_then(|line| page.code.iter().position(|(n, _)| *n == line))
        .unwrap_or(0);
    let first = at
        .saturating_sub(fits / 3)
        .min(page.code.len().saturating_sub(fits));
    let mut y = top;
    for (number, text) in page.code.iter().skip(first).take(fits) {
        y -= SMALL_LEADING;
        if Some(*number) == page.current_line {
            let _ = writeln!(
                out,
                "0.85 0.92 1 rg {} {} {} {} re f",
                n(left - 2.0),
                n(y - SMALL_LEADING * 0.3),
                n(SIDE_WIDTH + 4.0),
                n(SMALL_LEADING),
            );
        }
        let line = clipped(&format!("{number:>3}  {}", text.trim_end()), columns);
        mono_text(out, &line, (left, y), SMALL, black);
    }
    y -= SMALL_LEADING;
    for table in &page.tables {
        y -= SMALL_LEADING * 1.5;
        let title = format!("{} (the rows painted at this step)", table.title);
        mono_text(out, &clipped(&title, columns), (left, y), SMALL, black);
        // Each column as wide as its header or its widest cell.
        let mut texts: Vec<Vec<String>> = vec![
            std::iter::once("id")
                .chain(table.short.iter().copied())
                .map(str::to_owned)
                .collect(),
        ];
        for (element, cells) in &table.rows {
            let mut row = vec![element.id.to_string()];
            match cells {
                Some(cells) => row.extend(cells.iter().map(cell_text)),
                None => row.push("deleted".to_owned()),
            }
            texts.push(row);
        }
        let mut widths = vec![0; texts[0].len()];
        for row in &texts {
            for (i, cell) in row.iter().enumerate().take(widths.len()) {
                widths[i] = widths[i].max(cell.chars().count());
            }
        }
        for (r, row) in texts.iter().enumerate() {
            y -= SMALL_LEADING;
            let colour = r
                .checked_sub(1)
                .and_then(|i| table.rows.get(i))
                .and_then(|(element, _)| page.rows.get(element))
                .map(|look| look.colour);
            if let Some(colour) = colour {
                let _ = writeln!(
                    out,
                    "/A{} gs {} rg {} {} {} {} re f /A{OPACITY_STEPS} gs",
                    opacity_state(0.3),
                    rgb(colour),
                    n(left - 2.0),
                    n(y - SMALL_LEADING * 0.3),
                    n(SIDE_WIDTH + 4.0),
                    n(SMALL_LEADING),
                );
            }
            let line: String = row
                .iter()
                .zip(&widths)
                .map(|(cell, width)| format!("{cell:<width$} "))
                .collect();
            mono_text(out, &clipped(&line, columns), (left, y), SMALL, black);
        }
    }
}

/// `text` cut to `columns` characters, with `…` where it was cut.
fn clipped(text: &str, columns: usize) -> String {
    if text.chars().count() <= columns {
        return text.to_owned();
    }
    let mut cut: String = text.chars().take(columns.saturating_sub(1)).collect();
    cut.push('…');
    cut
}

/// `text` in Courier from `at` (its baseline's left end), each of the
/// trace's glyphs drawn as a path in its character's cell.
fn mono_text(out: &mut String, text: &str, at: (f32, f32), size: f32, colour: Color32) {
    let cell = size * COURIER_EM;
    let (mut x, y) = at;
    let mut run = String::new();
    let mut run_start = x;
    let flush = |out: &mut String, run: &mut String, start: f32| {
        if !run.is_empty() {
            let _ = writeln!(
                out,
                "{} rg BT /F2 {} Tf {} {} Td ({}) Tj ET",
                rgb(colour),
                n(size),
                n(start),
                n(y),
                pdf_text(run)
            );
            run.clear();
        }
    };
    for c in text.chars() {
        if let Some(glyph) = Glyph::of(c) {
            flush(out, &mut run, run_start);
            glyph.draw(out, (x, y), size, colour);
            run_start = x + cell;
        } else {
            if run.is_empty() {
                run_start = x;
            }
            run.push(c);
        }
        x += cell;
    }
    flush(out, &mut run, run_start);
}

/// The characters the standard fonts lack that the app's labels and
/// tables use.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Glyph {
    Arrow,
    Check,
    Star,
    Pencil,
    Empty,
    Ellipsis,
}

impl Glyph {
    fn of(c: char) -> Option<Self> {
        Some(match c {
            '→' => Self::Arrow,
            '✓' => Self::Check,
            '★' => Self::Star,
            '✎' => Self::Pencil,
            '∅' => Self::Empty,
            '…' => Self::Ellipsis,
            _ => return None,
        })
    }

    /// Draws the glyph in the cell whose baseline starts at `at`.
    fn draw(self, out: &mut String, at: (f32, f32), size: f32, colour: Color32) {
        let (x, y) = at;
        let p = |dx: f32, dy: f32| format!("{} {}", n(x + dx * size), n(y + dy * size));
        let c = rgb(colour);
        let line = n(size * 0.07);
        let _ = match self {
            Self::Arrow => writeln!(
                out,
                "{c} RG {c} rg {line} w {} m {} l S {} m {} l {} l f",
                p(0.04, 0.3),
                p(0.4, 0.3),
                p(0.58, 0.3),
                p(0.36, 0.42),
                p(0.36, 0.18),
            ),
            Self::Check => writeln!(
                out,
                "{c} RG {} w 1 J 1 j {} m {} l {} l S",
                n(size * 0.09),
                p(0.06, 0.33),
                p(0.24, 0.1),
                p(0.56, 0.62),
            ),
            Self::Star => {
                let points: Vec<String> = (0..10)
                    .map(|i| {
                        let angle =
                            std::f32::consts::FRAC_PI_2 + i as f32 * std::f32::consts::PI / 5.0;
                        let r = if i % 2 == 0 { 0.32 } else { 0.13 };
                        p(0.3 + r * angle.cos(), 0.3 + r * angle.sin())
                    })
                    .collect();
                writeln!(
                    out,
                    "{c} rg {} m {} l h f",
                    points[0],
                    points[1..].join(" l ")
                )
            }
            Self::Pencil => writeln!(
                out,
                "{c} RG {c} rg {} w 0 J {} m {} l S {} m {} l {} l f",
                n(size * 0.13),
                p(0.2, 0.16),
                p(0.52, 0.62),
                p(0.06, -0.02),
                p(0.22, 0.08),
                p(0.12, 0.16),
            ),
            Self::Empty => writeln!(
                out,
                "{c} RG {line} w {} m {} {} {} {} {} {} c {} {} {} {} {} {} c S {} m {} l S",
                p(0.52, 0.3),
                p(0.52, 0.42),
                p(0.42, 0.52),
                p(0.3, 0.52),
                p(0.18, 0.52),
                p(0.08, 0.42),
                p(0.08, 0.3),
                p(0.08, 0.18),
                p(0.18, 0.08),
                p(0.3, 0.08),
                p(0.42, 0.08),
                p(0.52, 0.18),
                p(0.52, 0.3),
                p(0.08, 0.02),
                p(0.52, 0.58),
            ),
            Self::Ellipsis => writeln!(
                out,
                "{c} rg {} {} {} {} re {} {} {} {} re {} {} {} {} re f",
                n(x + size * 0.06),
                n(y),
                n(size * 0.08),
                n(size * 0.08),
                n(x + size * 0.26),
                n(y),
                n(size * 0.08),
                n(size * 0.08),
                n(x + size * 0.46),
                n(y),
                n(size * 0.08),
                n(size * 0.08),
            ),
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_escaped_for_win_ansi() {
        assert_eq!(pdf_text("a (b) \\ c"), "a \\(b\\) \\\\ c");
        assert_eq!(pdf_text("∅ → é ✓ ☃"), "none -> \\351 ok ?");
    }

    #[test]
    fn glyphs_are_drawn_in_their_cells_between_courier_runs() {
        let mut out = String::new();
        mono_text(&mut out, "3: ✓ se", (10.0, 20.0), 10.0, Color32::BLACK);
        let lines: Vec<&str> = out.lines().collect();
        assert_eq!(lines.len(), 3, "{out}");
        assert!(lines[0].ends_with("10 20 Td (3: ) Tj ET"), "{out}");
        // The check mark fills the fourth cell, 6 pt wide: x from 28.
        assert!(lines[1].contains(" 1 J 1 j 28.6 23.3 m"), "{out}");
        assert!(lines[2].ends_with("34 20 Td ( se) Tj ET"), "{out}");
    }

    #[test]
    fn the_cross_reference_table_points_at_each_object() {
        let view = VectorView {
            size: emath::vec2(200.0, 100.0),
            palette: crate::palette::Palette::new(false),
            shapes: vec![Shape::Disc {
                centre: Pos2::new(10.0, 10.0),
                radius: 4.0,
                fill: Color32::RED,
            }],
        };
        let page = Page {
            view,
            lines: vec!["Step 1 of 1: done".to_owned()],
            code: vec![(1, "mark e;".to_owned())],
            current_line: Some(1),
            tables: Vec::new(),
            rows: BTreeMap::new(),
        };
        let bytes = handout("test", &[page.clone(), page]);
        let text = String::from_utf8(bytes).expect("ASCII");
        assert!(text.starts_with("%PDF-1.4\n") && text.ends_with("%%EOF\n"));
        assert!(text.contains("/Count 2"));
        let xref: usize = text
            .rsplit("startxref\n")
            .next()
            .and_then(|rest| rest.lines().next())
            .and_then(|offset| offset.parse().ok())
            .expect("startxref");
        assert!(text[xref..].starts_with("xref\n0 11\n"));
        let entries: Vec<usize> = text[xref..]
            .lines()
            .skip(3)
            .take(10)
            .map(|line| line[..10].parse().expect("an offset"))
            .collect();
        for (i, offset) in entries.iter().enumerate() {
            assert!(
                text[*offset..].starts_with(&format!("{} 0 obj\n", i + 1)),
                "object {}",
                i + 1
            );
        }
    }
}
