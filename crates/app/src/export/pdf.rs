//! A PDF handout of a run: one landscape A4 page per step, each the view
//! as vector shapes ([`VectorView`]) under the step's sentence and its
//! variables, so a lecturer prints the walk instead of taking a screenshot
//! per step.
//!
//! Written by hand in PDF 1.4: the shapes need only paths, fills, strokes,
//! a transparency state per opacity and the standard Helvetica font, so no
//! font is embedded and a 22-step handout is a few tens of kilobytes.

use std::fmt::Write as _;

use egui::{Color32, Pos2};

use super::n;
use crate::view3d::vector::{Shape, VectorView, label_size, shaft_end};

/// Landscape A4, in PDF points.
pub const PAGE: (f32, f32) = (842.0, 595.0);
/// The most pages a handout holds.
pub const MAX_PAGES: usize = 300;
const MARGIN: f32 = 36.0;
/// Opacities are rounded to twentieths, one graphics state each.
const OPACITY_STEPS: u32 = 20;
/// A circle's control-point distance, as a fraction of its radius.
const KAPPA: f32 = 0.552_284_8;

/// One page: the view and the lines above it.
#[derive(Clone, Debug)]
pub struct Page {
    pub view: VectorView,
    /// The step's sentence first, then the variables.
    pub lines: Vec<String>,
}

/// The handout as PDF bytes.
pub fn handout(title: &str, pages: &[Page]) -> Vec<u8> {
    let mut objects: Vec<String> = Vec::new();
    // 1: catalog, 2: pages, 3: font, 4: graphics states, 5: info; then a
    // page and its contents for each page.
    let page_ids: Vec<usize> = (0..pages.len()).map(|i| 6 + 2 * i).collect();
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
    for (i, page) in pages.iter().enumerate() {
        let contents = page_contents(page, i + 1, pages.len());
        objects.push(format!(
            "<< /Type /Page /Parent 2 0 R /MediaBox [0 0 {} {}] \
             /Resources << /Font << /F1 3 0 R >> /ExtGState 4 0 R >> /Contents {} 0 R >>",
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
    // The view, scaled to fit the rest of the page, y up.
    let top = height - y + 8.0;
    let room = (width - 2.0 * MARGIN, height - top - MARGIN);
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
            // Helvetica's digits and letters average about 0.55 em.
            let text_width = text.chars().count() as f32 * font * 0.55;
            let _ = writeln!(
                out,
                "{} rg {} RG 0.8 w {} {} {} {} re B 0 g {} rg BT /F1 {} Tf {} {} Td ({}) Tj ET",
                rgb(view.palette.label_fill),
                rgb(border.unwrap_or(view.palette.label_stroke)),
                n(x - size.x * 0.5),
                n(y - size.y * 0.5),
                n(size.x),
                n(size.y),
                rgb(view.palette.label_text),
                n(font),
                n(x - text_width * 0.5),
                n(y - font * 0.35),
                pdf_text(text)
            );
        }
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
    fn the_cross_reference_table_points_at_each_object() {
        let view = VectorView {
            size: egui::vec2(200.0, 100.0),
            palette: crate::view3d::Palette::new(false),
            shapes: vec![Shape::Disc {
                centre: Pos2::new(10.0, 10.0),
                radius: 4.0,
                fill: Color32::RED,
            }],
        };
        let page = Page {
            view,
            lines: vec!["Step 1 of 1: done".to_owned()],
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
        assert!(text[xref..].starts_with("xref\n0 10\n"));
        let entries: Vec<usize> = text[xref..]
            .lines()
            .skip(3)
            .take(9)
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
