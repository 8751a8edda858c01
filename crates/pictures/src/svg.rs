//! A picture of the view for slides. An SVG holds the 3D view as vector
//! shapes ([`crate::vector`]) with the three tables beside it, highlighted
//! rows in their colours and roles in words, and a caption (the trace
//! step's sentence, or the selection's), so it prints crisply at any size
//! and its text can be searched and copied. [`crate::pdf`] writes a whole
//! run as a handout.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use ecolor::Color32;
use emath::Pos2;

use edgewise_core::schema::ElementRef;

use crate::palette::{Palette, to_hex as hex};
use crate::text_table::{Cell, TextTable};
use crate::vector::{Shape, VectorView, label_size, shaft_end};

/// Rows each table shows; the rest are counted in a last line.
pub const TABLE_ROWS: usize = 48;
const FONT: &str = "'DejaVu Sans', 'Helvetica Neue', Helvetica, Arial, sans-serif";
const FONT_SIZE: f32 = 12.0;
const ROW: f32 = 18.0;
const MARGIN: f32 = 16.0;
const CAPTION_HEIGHT: f32 = 30.0;
const ID_COLUMN: f32 = 44.0;
const CELL_COLUMN: f32 = 58.0;
const ROLE_COLUMN: f32 = 170.0;

/// A highlighted row: its colour and its roles in words.
#[derive(Clone, Debug, PartialEq)]
pub struct RowLook {
    pub colour: Color32,
    pub roles: Vec<String>,
}

/// Everything an exported picture shows.
#[derive(Clone, Debug)]
pub struct Picture<'a> {
    /// Names the mesh (and the algorithm), for the title and the file.
    pub title: String,
    /// The message line: the step's sentence or the selection's.
    pub caption: Option<String>,
    pub view: &'a VectorView,
    pub tables: &'a [TextTable],
    pub rows: &'a BTreeMap<ElementRef, RowLook>,
}

/// Text made safe inside XML elements and attributes.
pub fn xml_escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if c.is_control() && c != '\n' && c != '\t' => {}
            c => out.push(c),
        }
    }
    out
}

/// A number as SVG and PDF write it: at most two decimals, no `-0`.
pub(crate) fn n(x: f32) -> String {
    if !x.is_finite() {
        return "0".to_owned();
    }
    let rounded = (x * 100.0).round() / 100.0;
    if rounded == 0.0 {
        "0".to_owned()
    } else {
        format!("{rounded}")
    }
}

fn points(points: &[Pos2], dy: f32) -> String {
    points
        .iter()
        .map(|p| format!("{},{}", n(p.x), n(p.y + dy)))
        .collect::<Vec<_>>()
        .join(" ")
}

/// Where each cell column starts, from the table's left, and where the
/// role column starts: wide enough for its header.
fn column_lefts(table: &TextTable) -> (Vec<f32>, f32) {
    let mut x = ID_COLUMN;
    let lefts = table
        .headers
        .iter()
        .map(|header| {
            let left = x;
            x += CELL_COLUMN.max(header.chars().count() as f32 * FONT_SIZE * 0.62 + 12.0);
            left
        })
        .collect();
    (lefts, x)
}

/// The width of one table.
fn table_width(table: &TextTable) -> f32 {
    column_lefts(table).1 + ROLE_COLUMN
}

/// The height of one table with its title and its "more rows" line.
fn table_height(table: &TextTable) -> f32 {
    let more = if table.rows.len() < table.count {
        1.0
    } else {
        0.0
    };
    ROW * (2.0 + table.rows.len() as f32 + more) + MARGIN
}

/// The picture as an SVG document.
pub fn svg(picture: &Picture<'_>) -> String {
    let view = picture.view;
    let palette = &view.palette;
    let top = if picture.caption.is_some() {
        CAPTION_HEIGHT
    } else {
        0.0
    };
    let tables_left = view.size.x + MARGIN;
    let tables_width = picture
        .tables
        .iter()
        .map(table_width)
        .fold(0.0_f32, f32::max);
    let tables_height: f32 = picture.tables.iter().map(table_height).sum();
    let width = (tables_left + tables_width + MARGIN).ceil();
    let height = (top + view.size.y).max(tables_height + MARGIN).ceil();
    let text_colour = hex(palette.label_text);

    let mut out = String::new();
    let _ = write!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" \
         font-family=\"{FONT}\" font-size=\"{FONT_SIZE}\">\n<title>{title}</title>\n\
         <rect width=\"{w}\" height=\"{h}\" fill=\"{bg}\"/>\n",
        w = n(width),
        h = n(height),
        title = xml_escape(&picture.title),
        bg = hex(palette.background),
    );
    if let Some(caption) = &picture.caption {
        let _ = writeln!(
            out,
            "<text x=\"{}\" y=\"20\" font-size=\"14\" fill=\"{text_colour}\">{}</text>",
            n(MARGIN * 0.5),
            xml_escape(caption)
        );
    }
    // Whatever the camera puts outside the view stays outside the picture.
    let _ = writeln!(
        out,
        "<clipPath id=\"view-area\"><rect y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>",
        n(top),
        n(view.size.x),
        n(view.size.y)
    );
    out.push_str("<g id=\"view\" clip-path=\"url(#view-area)\">\n");
    for shape in &view.shapes {
        shape_svg(&mut out, shape, top, palette);
    }
    out.push_str("</g>\n<g id=\"tables\">\n");
    let mut y = MARGIN;
    for table in picture.tables {
        table_svg(&mut out, table, picture.rows, tables_left, y, &text_colour);
        y += table_height(table);
    }
    out.push_str("</g>\n</svg>\n");
    out
}

fn shape_svg(out: &mut String, shape: &Shape, dy: f32, palette: &Palette) {
    match shape {
        Shape::Polygon {
            points: corners,
            fill,
            opacity,
        } => {
            let _ = writeln!(
                out,
                "<polygon points=\"{}\" fill=\"{}\" fill-opacity=\"{}\"/>",
                points(corners, dy),
                hex(*fill),
                n(*opacity)
            );
        }
        Shape::Arrow {
            from,
            to,
            head,
            colour,
            width,
        } => {
            let end = shaft_end(*from, *to, head);
            let colour = hex(*colour);
            let _ = writeln!(
                out,
                "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{colour}\" stroke-width=\"{}\" stroke-linecap=\"round\"/>\
                 <polygon points=\"{}\" fill=\"{colour}\"/>",
                n(from.x),
                n(from.y + dy),
                n(end.x),
                n(end.y + dy),
                n(*width),
                points(head, dy),
            );
        }
        Shape::Disc {
            centre,
            radius,
            fill,
        } => {
            let _ = writeln!(
                out,
                "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\"/>",
                n(centre.x),
                n(centre.y + dy),
                n(*radius),
                hex(*fill)
            );
        }
        Shape::Label {
            centre,
            text,
            border,
        } => {
            let emath::Vec2 {
                x: width,
                y: height,
            } = label_size(text);
            let stroke = hex(border.unwrap_or(palette.label_stroke));
            let _ = writeln!(
                out,
                "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" rx=\"3\" fill=\"{}\" stroke=\"{stroke}\"/>\
                 <text x=\"{}\" y=\"{}\" text-anchor=\"middle\" fill=\"{}\">{}</text>",
                n(centre.x - width * 0.5),
                n(centre.y + dy - height * 0.5),
                n(width),
                n(height),
                hex(palette.label_fill),
                n(centre.x),
                n(centre.y + dy + FONT_SIZE * 0.35),
                hex(palette.label_text),
                xml_escape(text)
            );
        }
    }
}

/// A cell's text as the app's tables show it: an id, `∅`, or a coordinate.
pub fn cell_text(cell: &Cell) -> String {
    match cell {
        Cell::Reference(Some(target)) => target.id.to_string(),
        Cell::Reference(None) => "∅".to_owned(),
        Cell::Coordinate(x) => format!("{x:.3}"),
    }
}

fn table_svg(
    out: &mut String,
    table: &TextTable,
    rows: &BTreeMap<ElementRef, RowLook>,
    left: f32,
    top: f32,
    text_colour: &str,
) {
    let baseline = |row: f32| top + ROW * row + ROW * 0.7;
    let (lefts, role_left) = column_lefts(table);
    let _ = writeln!(
        out,
        "<text x=\"{}\" y=\"{}\" font-weight=\"bold\" fill=\"{text_colour}\">{}: {} rows</text>",
        n(left),
        n(baseline(0.0)),
        table.title,
        table.count
    );
    let mut header = format!(
        "<text x=\"{}\" y=\"{}\" fill=\"{text_colour}\" font-weight=\"bold\">id</text>",
        n(left),
        n(baseline(1.0))
    );
    for (title, column) in table.headers.iter().zip(&lefts) {
        let _ = write!(
            header,
            "<text x=\"{}\" y=\"{}\" fill=\"{text_colour}\" font-weight=\"bold\">{}</text>",
            n(left + column),
            n(baseline(1.0)),
            xml_escape(title)
        );
    }
    out.push_str(&header);
    out.push('\n');
    for (r, (element, cells)) in table.rows.iter().enumerate() {
        let line = 2.0 + r as f32;
        if let Some(look) = rows.get(element) {
            let _ = write!(
                out,
                "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\" fill-opacity=\"0.28\"/>\
                 <text x=\"{}\" y=\"{}\" fill=\"{text_colour}\">{}</text>",
                n(left - 4.0),
                n(top + ROW * line),
                n(table_width(table)),
                n(ROW),
                hex(look.colour),
                n(left + role_left),
                n(baseline(line)),
                xml_escape(&look.roles.join(", "))
            );
        }
        let _ = write!(
            out,
            "<text x=\"{}\" y=\"{}\" fill=\"{text_colour}\">{}</text>",
            n(left),
            n(baseline(line)),
            element.id
        );
        match cells {
            None => {
                let _ = write!(
                    out,
                    "<text x=\"{}\" y=\"{}\" fill=\"{text_colour}\" font-style=\"italic\">deleted</text>",
                    n(left + ID_COLUMN),
                    n(baseline(line))
                );
            }
            Some(cells) => {
                for (cell, column) in cells.iter().zip(&lefts) {
                    let _ = write!(
                        out,
                        "<text x=\"{}\" y=\"{}\" fill=\"{text_colour}\">{}</text>",
                        n(left + column),
                        n(baseline(line)),
                        cell_text(cell)
                    );
                }
            }
        }
        out.push('\n');
    }
    if table.rows.len() < table.count {
        let _ = writeln!(
            out,
            "<text x=\"{}\" y=\"{}\" fill=\"{text_colour}\" font-style=\"italic\">… {} more rows</text>",
            n(left),
            n(baseline(2.0 + table.rows.len() as f32)),
            table.count - table.rows.len()
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_escaped_and_numbers_are_short() {
        assert_eq!(
            xml_escape("a<b & \"c\" 'd'>\u{7}"),
            "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;"
        );
        assert_eq!(n(1.23456), "1.23");
        assert_eq!(n(-0.001), "0");
        assert_eq!(n(f32::NAN), "0");
        assert_eq!(n(12.0), "12");
    }
}
