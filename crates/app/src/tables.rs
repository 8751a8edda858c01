//! The face, edge and vertex tables, as the structure really holds them.
//!
//! Rows are virtualised (only visible rows are laid out), so the 200k-face
//! sample scrolls as smoothly as a tetrahedron. A cell holding a reference is
//! a link: clicking it selects that element, so a student can walk the
//! structure from the tables alone.

use edgewise_core::mesh::{Mesh, Structure, VertexId};
use edgewise_core::schema::{Column, ElementKind, ElementRef, Records, Storage};
use egui::{RichText, emath::GuiRounding as _};
use egui_extras::TableBuilder;

use edgewise_model::{paint::Paint, selection::Role};

const ROW_HEIGHT: f32 = 20.0;
/// The least width of a column after the id column, in points.
/// On a touch screen, at least a touch target ([`least_width`]).
const COLUMN_LEAST_WIDTH: f32 = 32.0;
/// The space between a table's cells, in points: less than egui's usual 8, so
/// that beside a run at 1280x800 the three tables show every reference.
const CELL_SPACING: f32 = 6.0;

/// The least width of a column after the id column: a touch target where
/// widgets are (on a touch screen).
fn least_width(ui: &egui::Ui) -> f32 {
    COLUMN_LEAST_WIDTH.max(ui.spacing().interact_size.y)
}

/// A table's column headers: the id, the columns, the labels.
struct Headers {
    full: Vec<&'static str>,
    /// As the journal's Table 1 shortens them, for narrow tables.
    short: Vec<&'static str>,
    /// Whether each column is derived, shown dimmed.
    derived: Vec<bool>,
}

impl Headers {
    fn of(structure: Structure, kind: ElementKind) -> Self {
        let mut headers = Self {
            full: vec!["id"],
            short: vec!["id"],
            derived: vec![false],
        };
        for entry in Column::table(structure, kind) {
            let (full, short): (&[&str], &[&str]) = match entry.column {
                Column::Position => (&Column::COORDINATES, &Column::COORDINATES),
                _ => (
                    std::slice::from_ref(&entry.header),
                    std::slice::from_ref(&entry.short),
                ),
            };
            headers.full.extend(full);
            headers.short.extend(short);
            headers
                .derived
                .extend(full.iter().map(|_| entry.storage == Storage::Derived));
        }
        headers.full.push("labels");
        headers.short.push("labels");
        headers.derived.push(false);
        headers
    }
}

/// The width a table of `kind` needs for its references to show, with short
/// headers and without its labels (the last column, which may scroll away).
/// Side by side, the tables share the width in these proportions.
pub fn references_width(ui: &egui::Ui, mesh: &Mesh, kind: ElementKind) -> f32 {
    let headers = Headers::of(mesh.structure(), kind);
    let references = &headers.short[..headers.short.len() - 1];
    columns_width(ui, references, &widest_cells(mesh, &headers))
}

/// The widest text each column of `headers` holds in `mesh`: an id of as
/// many digits as the largest table has rows, or a coordinate.
fn widest_cells(mesh: &Mesh, headers: &Headers) -> Vec<String> {
    let rows = [ElementKind::Face, ElementKind::Edge, ElementKind::Vertex]
        .map(|kind| mesh.count(kind))
        .into_iter()
        .max()
        .unwrap_or_default();
    let id = "0".repeat(rows.max(1).ilog10() as usize + 1);
    headers
        .full
        .iter()
        .map(|header| {
            if Column::COORDINATES.contains(header) {
                "-0.000".to_owned()
            } else {
                id.clone()
            }
        })
        .collect()
}

/// How wide a table is whose columns have the headers `titles` and cells
/// as wide as `cells` (monospace), as `egui_extras` sizes it: each column
/// as wide as its widest text (the id's button padded), at least
/// [`least_width`], and the cell spacing after it.
fn columns_width(ui: &egui::Ui, titles: &[&str], cells: &[String]) -> f32 {
    let body = egui::TextStyle::Body.resolve(ui.style());
    let mono = egui::TextStyle::Monospace.resolve(ui.style());
    let spacing = ui.spacing();
    let width = |text: &str, font: &egui::FontId| {
        ui.fonts_mut(|f| {
            f.layout_no_wrap(text.to_owned(), font.clone(), egui::Color32::WHITE)
                .size()
                .x
        })
    };
    titles
        .iter()
        .zip(cells)
        .enumerate()
        .map(|(i, (title, cell))| {
            let padding = if i == 0 {
                2.0 * spacing.button_padding.x
            } else {
                0.0
            };
            let content = width(title, &body).max(width(cell, &mono) + padding);
            content.max(least_width(ui)) + CELL_SPACING
        })
        .sum()
}

/// Shown for a missing (boundary) face.
const NONE: &str = "∅";

/// What the user did in a table this frame.
#[derive(Default)]
pub struct TablesResponse {
    /// A row or a reference cell was clicked.
    pub clicked: Option<ElementRef>,
    /// The click was on a reference cell: a reference followed.
    pub followed: bool,
    /// The row id or reference under the pointer: the 3D view previews it.
    pub hovered: Option<ElementRef>,
    /// A row's id was right-clicked, where the pointer was: the edit menu.
    pub context: Option<(ElementRef, egui::Pos2)>,
    /// A stored reference cell was edited by hand (double-click, type an id
    /// or `-`, Enter): the row, the column and the id, or why the text is
    /// not one.
    pub set_cell: Option<(ElementRef, Column, Result<Option<u32>, String>)>,
}

/// The reference cell being typed into, kept in egui's memory between
/// frames.
#[derive(Clone, Debug, Default)]
struct CellEdit {
    cell: Option<(ElementRef, Column)>,
    text: String,
}

fn cell_edit_id() -> egui::Id {
    egui::Id::unique("edgewise_cell_edit")
}

/// What a typed cell means: an id, or none (`-`, `null` or nothing).
fn parse_cell(text: &str) -> Result<Option<u32>, String> {
    let text = text.trim();
    if text.is_empty() || text == NONE || text.eq_ignore_ascii_case("null") || text == "-" {
        return Ok(None);
    }
    text.parse::<u32>().map(Some).map_err(|_| {
        let shown: String = text.chars().take(20).collect();
        format!("`{shown}` is not an id: type a row number, or - for none")
    })
}

/// One cell of a row.
enum Cell {
    /// The row's own id: clicking it selects the row.
    Id(ElementRef),
    Text(String),
    /// A reference to another element, and the column that holds it.
    Link(Option<ElementRef>, Column),
}

/// Draws one table of `kind` filling `ui`, coloured by `paint`, scrolling
/// just enough to show row `scroll_to` if given, with the row of
/// `previewed` (the element under the pointer in the 3D view) outlined.
pub fn table_ui(
    ui: &mut egui::Ui,
    mesh: &Mesh,
    kind: ElementKind,
    paint: &Paint,
    scroll_to: Option<u32>,
    previewed: Option<ElementRef>,
    response: &mut TablesResponse,
) -> IdColumn {
    let preview_stroke = egui::Stroke::new(
        1.5,
        edgewise_pictures::palette::Palette::new(ui.visuals().dark_mode).hover,
    );
    ui.spacing_mut().item_spacing.x = CELL_SPACING;
    let least = least_width(ui);
    let table_headers = Headers::of(mesh.structure(), kind);
    let widest = widest_cells(mesh, &table_headers);
    let Headers {
        full: headers,
        short: shorts,
        derived,
    } = table_headers;
    // The journal's short headers where the full ones would not fit, so
    // that every column shows without scrolling sideways.
    let short = columns_width(ui, &headers, &widest) > ui.available_width();
    let shown = if short { &shorts } else { &headers };
    let rows = mesh.count(kind);
    let drawn_id = ui.make_persistent_id(("edgewise drawn rows", kind));
    let drawn = ui.data(|d| d.get_temp::<DrawnRows>(drawn_id));
    // On a touch screen a row is as tall as a touch target, so that its id
    // (a button) lies inside its own row.
    let row_height = ROW_HEIGHT.max(ui.spacing().interact_size.y);
    let pitch = row_height + ui.spacing().item_spacing.y;

    let mut table = TableBuilder::new(ui)
        // Resizable columns keep their widths: sized for the full headers
        // (the table across the window), they would push the last references
        // off a narrow table, so each set of headers keeps its own.
        .id_salt((kind, short))
        // Rows are told apart by `RowBand`'s hairlines: stripes cost pixels.
        .striped(false)
        .resizable(true)
        // Fill the panel: a table that shrank to its rows would shrink the panel too.
        .auto_shrink(false)
        // Jump to the row a step or selection names: each frame of a smooth
        // scroll costs a whole repaint, several times a step's own.
        .animate_scrolling(false)
        .cell_layout(egui::Layout::left_to_right(egui::Align::Center));
    if let Some(row) = scroll_to {
        table = match drawn.map(|d| d.jump_to(row as usize, rows, pitch)) {
            Some(Jump::Stay) => table,
            Some(Jump::Offset(offset)) => table.vertical_scroll_offset(offset),
            Some(Jump::AfterLayout) | None => table.scroll_to_row(row as usize, None),
        };
    }
    let mut id_cells = Vec::new();
    let mut id_header = None;
    let mut next_left = None;
    let mut drawn_now = DrawnRows {
        first: usize::MAX,
        last: 0,
        height: 0.0,
        rows,
    };
    for (i, _) in headers.iter().enumerate() {
        table = table.column(if i + 1 == headers.len() {
            egui_extras::Column::remainder().at_least(60.0)
        } else {
            egui_extras::Column::auto().at_least(if i == 0 { 36.0 } else { least })
        });
    }
    table
        .header(ROW_HEIGHT, |mut header| {
            for (i, (title, full)) in shown.iter().zip(&headers).enumerate() {
                header.col(|ui| {
                    match i {
                        0 => id_header = Some((ui.max_rect(), ui.clip_rect())),
                        // The id column reaches the next one's left edge.
                        1 => next_left = Some(ui.max_rect().left()),
                        _ => {}
                    }
                    let text = RichText::new(*title).strong();
                    let label = ui.label(if derived[i] { text.weak() } else { text });
                    if title != full {
                        label.on_hover_text(*full);
                    }
                });
            }
        })
        .body(|mut body| {
            drawn_now.height = body.ui_mut().clip_rect().height();
            let editing = body
                .ui_mut()
                .data(|d| d.get_temp::<CellEdit>(cell_edit_id()))
                .and_then(|edit| edit.cell);
            body.rows(row_height, rows, |mut row| {
                drawn_now.first = drawn_now.first.min(row.index());
                drawn_now.last = drawn_now.last.max(row.index());
                let id = row.index() as u32;
                let element = ElementRef { kind, id };
                let row_colour = paint.colour_of(element);
                let mut cells = row_cells(mesh, element);
                if let (Some(last), Some(labels)) = (cells.last_mut(), paint.labels.get(&element)) {
                    *last = Cell::Text(labels.clone());
                }
                let mut clicked_link = None;
                for (i, cell) in cells.into_iter().enumerate() {
                    row.col(|ui| {
                        if i == 0 {
                            let band = RowBand {
                                colour: row_colour,
                                outline: (previewed == Some(element)).then_some(preview_stroke),
                            };
                            band.paint(ui);
                        }
                        if let Cell::Id(element) = cell {
                            id_cells.push((element, ui.max_rect(), ui.clip_rect()));
                        }
                        let column = RowColumn {
                            element,
                            header: headers.get(i).copied().unwrap_or_default(),
                            dim: derived.get(i).copied().unwrap_or_default(),
                            editing,
                        };
                        if let Some(target) = column.cell_ui(ui, cell, paint, response) {
                            clicked_link = Some(target);
                        }
                    });
                }
                if let Some(target) = clicked_link {
                    response.clicked = Some(target);
                }
            });
        });
    if drawn_now.first <= drawn_now.last {
        ui.data_mut(|d| d.insert_temp(drawn_id, drawn_now));
    }
    IdColumn {
        header: id_header,
        width: next_left
            .zip(id_header)
            .map(|(next, (id, _))| next - id.left()),
        cells: id_cells,
    }
}

/// One cell of a table's row, for [`RowColumn::cell_ui`].
struct RowColumn {
    /// The row.
    element: ElementRef,
    /// The column's full header.
    header: &'static str,
    /// The column is derived, shown dimmed.
    dim: bool,
    /// The cell being edited, if any.
    editing: Option<(ElementRef, Column)>,
}

impl RowColumn {
    /// Draws `cell`: an id, text, a reference being edited, a reference an
    /// edit wrote (the old value struck through), or a reference to follow.
    /// Returns the element a click on the id or the reference names.
    fn cell_ui(
        &self,
        ui: &mut egui::Ui,
        cell: Cell,
        paint: &Paint,
        response: &mut TablesResponse,
    ) -> Option<ElementRef> {
        let element = self.element;
        match cell {
            Cell::Id(element) => id_cell_ui(ui, element, paint, response).then_some(element),
            Cell::Text(text) => {
                let mut text = RichText::new(text).monospace();
                if self.dim {
                    text = text.weak();
                }
                ui.label(text);
                None
            }
            Cell::Link(_, column) if self.editing == Some((element, column)) => {
                if let Some(result) = cell_edit_ui(ui) {
                    response.set_cell = Some((element, column, result));
                }
                None
            }
            Cell::Link(target, column)
                if paint.struck.contains_key(&(element, Role::Column(column))) =>
            {
                let cell = (element, Role::Column(column));
                let old = paint.struck.get(&cell).cloned().unwrap_or_default();
                let tint = paint.cells.get(&cell).copied();
                written_cell_ui(ui, &old, target, tint);
                None
            }
            Cell::Link(target, column) => {
                let reference = Reference {
                    element,
                    column,
                    target,
                    header: self.header,
                    dim: self.dim,
                };
                reference.ui(ui, paint, response)
            }
        }
    }
}

/// A reference cell of a table's row: a link that selects its target (or
/// "none"), which a double click or Enter edits unless the column is
/// derived.
struct Reference<'a> {
    /// The row.
    element: ElementRef,
    column: Column,
    target: Option<ElementRef>,
    /// The column's full header, for screen readers.
    header: &'a str,
    /// A derived column: dimmed, and not editable.
    dim: bool,
}

impl Reference<'_> {
    /// Draws the cell; gives the target when its link was clicked.
    fn ui(
        self,
        ui: &mut egui::Ui,
        paint: &Paint,
        response: &mut TablesResponse,
    ) -> Option<ElementRef> {
        let Self {
            element,
            column,
            target,
            header,
            dim,
        } = self;
        let words = target.map_or_else(|| NONE.to_owned(), |target| target.id.to_string());
        let mut text = RichText::new(&words).monospace();
        // A tinted cell is one the trace reads or writes; an empty one is
        // weak even where it can be edited.
        if let Some(tint) = paint.cells.get(&(element, Role::Column(column))) {
            text = text.background_color(tint.gamma_multiply(0.55)).strong();
        } else if dim || target.is_none() {
            text = text.weak();
        }
        let Some(target) = target else {
            let label = ui.label(text);
            if !dim {
                start_cell_edit(ui, label, element, column, &words);
            }
            return None;
        };
        let target_name = target.to_string();
        let link = ui.link(text).on_hover_text(format!("select {target_name}"));
        // Screen readers (and UI tests) hear which reference this is.
        let row_name = element.to_string();
        link.widget_info(|| {
            egui::WidgetInfo::labeled(
                egui::Role::Link,
                true,
                format!("{header} of {row_name}: {target_name}"),
            )
        });
        let clicked = link.clicked();
        if clicked {
            response.followed = true;
        }
        if link.hovered() {
            response.hovered = Some(target);
        }
        if !dim {
            start_cell_edit(ui, link, element, column, &words);
        }
        clicked.then_some(target)
    }
}

/// A row's id: selects the row on a click, opens the edit menu on a right
/// click, and names the rules a broken record breaks. Whether it was
/// clicked.
fn id_cell_ui(
    ui: &mut egui::Ui,
    element: ElementRef,
    paint: &Paint,
    response: &mut TablesResponse,
) -> bool {
    let rules = paint.broken.get(&element);
    let mut id = RichText::new(element.id.to_string()).monospace();
    if rules.is_some() {
        id = id.color(ui.visuals().error_fg_color).strong();
    }
    let hover = match rules {
        Some(rules) => format!("{element} breaks a rule:\n{}", rules.join("\n")),
        None => format!("select {element}"),
    };
    let label = ui
        .selectable_label(paint.focus == Some(element), id)
        .on_hover_text(hover);
    if label.hovered() {
        response.hovered = Some(element);
    }
    if label.secondary_clicked() {
        let at = label
            .interact_pointer_pos()
            .unwrap_or(label.rect.left_bottom());
        response.context = Some((element, at));
    }
    label.clicked()
}

/// The id cells a table drew, where, and within what clip: a table
/// scrolled sideways draws them again at its left edge.
pub struct IdColumn {
    /// The header's cell and clip.
    header: Option<(egui::Rect, egui::Rect)>,
    /// From the id column's left edge to the next column's.
    width: Option<f32>,
    /// Each row's id cell and clip.
    cells: Vec<(ElementRef, egui::Rect, egui::Rect)>,
}

impl IdColumn {
    /// Draws the ids over the left edge of `viewport` (the sideways scroll
    /// area's visible part), so that a row keeps its name however far the
    /// references scroll.
    pub fn sticky_ui(
        &self,
        ui: &mut egui::Ui,
        viewport: egui::Rect,
        paint: &Paint,
        response: &mut TablesResponse,
    ) {
        let (Some((header, header_clip)), Some(width)) = (self.header, self.width) else {
            return;
        };
        let shift = egui::vec2(viewport.left() - header.left(), 0.0);
        // The cleared frame's colour: panels are transparent over it.
        let fill = edgewise_pictures::palette::Palette::new(ui.visuals().dark_mode).background;
        let gap = ui.spacing().item_spacing.y * 0.5;
        let band = |cell: egui::Rect| {
            egui::Rect::from_x_y_ranges(
                cell.left()..=cell.left() + width,
                (cell.top() - gap)..=(cell.bottom() + gap),
            )
        };
        // A cell's clip is its own column's, scrolled away with it: keep
        // only its rows (the body's, below the header).
        let clip =
            |clip: egui::Rect| egui::Rect::from_x_y_ranges(viewport.x_range(), clip.y_range());
        let header = header.translate(shift);
        let painter = ui.painter_at(clip(header_clip));
        painter.rect_filled(band(header), 0.0, fill);
        painter.text(
            header.left_center(),
            egui::Align2::LEFT_CENTER,
            "id",
            egui::TextStyle::Body.resolve(ui.style()),
            ui.visuals().strong_text_color(),
        );
        for &(element, cell, cell_clip) in &self.cells {
            let cell = cell.translate(shift);
            let clip = clip(cell_clip);
            let band = band(cell);
            let painter = ui.painter_at(clip);
            painter.rect_filled(band, 0.0, fill);
            if let Some(colour) = paint.colour_of(element) {
                painter.rect_filled(band, 0.0, colour.gamma_multiply(0.28));
            }
            painter.vline(
                band.right(),
                band.y_range(),
                ui.visuals().widgets.noninteractive.bg_stroke,
            );
            let builder = egui::UiBuilder::new()
                .id_salt(("sticky id", element))
                .max_rect(cell)
                .layout(egui::Layout::left_to_right(egui::Align::Center));
            ui.scope_builder(builder, |ui| {
                ui.set_clip_rect(clip);
                if id_cell_ui(ui, element, paint, response) {
                    response.clicked = Some(element);
                }
            });
        }
    }
}

/// The rows a table drew last frame, and the height it showed them in. A
/// row to show is scrolled to with an offset set before the rows are laid
/// out, so it shows in the same frame: `egui_extras`'s `scroll_to_row`
/// scrolls after them, and the row appears a frame (a whole repaint) later.
#[derive(Clone, Copy, Debug, PartialEq)]
struct DrawnRows {
    first: usize,
    last: usize,
    height: f32,
    /// The table's rows then.
    rows: usize,
}

/// How a table brings a row into view.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Jump {
    /// It was drawn whole last frame.
    Stay,
    /// To this scroll offset, which centres it.
    Offset(f32),
    /// `egui_extras`'s way: near the end, and in a table whose rows just
    /// changed, where an offset past what egui last measured would make it
    /// spring back over many frames.
    AfterLayout,
}

impl DrawnRows {
    /// How to show `row` of `rows`, `pitch` apart. `egui_extras` draws from
    /// the row cut off at the top to one past the row cut off at the
    /// bottom.
    fn jump_to(self, row: usize, rows: usize, pitch: f32) -> Jump {
        let whole = self.first + 1..=self.last.saturating_sub(2);
        if whole.contains(&row) || (self.first == 0 && row == 0) {
            return Jump::Stay;
        }
        let centred = (row as f32 + 0.5) * pitch - self.height / 2.0;
        if rows != self.rows || (row as f32 + 1.0) * pitch + self.height > rows as f32 * pitch {
            Jump::AfterLayout
        } else {
            Jump::Offset(centred.max(0.0))
        }
    }
}

/// A row's background across the table's whole width: a hairline under
/// it, its colour in the selection or the trace, and the outline of the
/// element the 3D view previews.
///
/// Painted once per row as plain quads, without anti-aliased edges (rows
/// lie on whole pixels), rather than as `egui_extras` stripes, a feathered
/// rectangle per cell: under a software renderer every shape costs, and a
/// selection on torus-200k, which repaints the tables, got about 30 ms
/// faster. Rows are told apart by hairlines rather than by a stripe behind
/// every other one: each pixel an egui shape covers costs a software
/// renderer about 45 ns, and the stripes' third of the tables cost every
/// frame about 11 ms.
struct RowBand {
    colour: Option<egui::Color32>,
    outline: Option<egui::Stroke>,
}

impl RowBand {
    /// Paints the band behind the row whose first cell is `ui`.
    fn paint(&self, ui: &egui::Ui) {
        let cell = ui.max_rect();
        let gap = ui.spacing().item_spacing.y * 0.5;
        let rect = egui::Rect::from_x_y_ranges(
            ui.clip_rect().x_range(),
            (cell.top() - gap)..=(cell.bottom() + gap),
        )
        .round_to_pixels(ui.pixels_per_point());
        let mut quads = egui::Mesh::default();
        if let Some(colour) = self.colour {
            quads.add_colored_rect(rect, colour.gamma_multiply(0.28));
        }
        let hairline = egui::Rect::from_x_y_ranges(
            rect.x_range(),
            (rect.bottom() - 1.0 / ui.pixels_per_point())..=rect.bottom(),
        );
        quads.add_colored_rect(
            hairline,
            ui.visuals().widgets.noninteractive.bg_stroke.color,
        );
        let painter = ui.painter();
        painter.add(egui::Shape::mesh(quads));
        if let Some(stroke) = self.outline {
            painter.hline(rect.x_range(), rect.top(), stroke);
            painter.hline(rect.x_range(), rect.bottom(), stroke);
        }
    }
}

/// Starts typing into a stored reference cell on a double-click.
fn start_cell_edit(
    ui: &egui::Ui,
    cell: egui::Response,
    element: ElementRef,
    column: Column,
    text: &str,
) {
    let cell = cell.on_hover_text("double-click to change this reference");
    if cell.double_clicked() {
        ui.data_mut(|d| {
            d.insert_temp(
                cell_edit_id(),
                CellEdit {
                    cell: Some((element, column)),
                    text: text.to_owned(),
                },
            );
        });
    }
}

/// The cell being typed into: Enter gives what was typed, Escape or a
/// click elsewhere gives up.
fn cell_edit_ui(ui: &mut egui::Ui) -> Option<Result<Option<u32>, String>> {
    let mut edit = ui
        .data(|d| d.get_temp::<CellEdit>(cell_edit_id()))
        .unwrap_or_default();
    let field = ui.add(
        egui::TextEdit::singleline(&mut edit.text)
            .desired_width(48.0)
            .font(egui::TextStyle::Monospace),
    );
    if !field.has_focus() && !field.lost_focus() {
        field.request_focus();
    }
    let (enter, escape) = ui.input(|i| {
        (
            i.key_pressed(egui::Key::Enter),
            i.key_pressed(egui::Key::Escape),
        )
    });
    let result = if field.lost_focus() && enter {
        Some(parse_cell(&edit.text))
    } else {
        None
    };
    if result.is_some() || escape || (field.lost_focus() && !enter) {
        ui.data_mut(|d| d.remove::<CellEdit>(cell_edit_id()));
    } else {
        ui.data_mut(|d| d.insert_temp(cell_edit_id(), edit));
    }
    result
}

/// The cells of one row, in the order of [`Column::table`]: the id, the
/// coordinates of a vertex, each reference with the column it is in, and the
/// labels.
fn row_cells(mesh: &Mesh, element: ElementRef) -> Vec<Cell> {
    if !mesh.contains(element) {
        if (element.id as usize) < mesh.count(element.kind) {
            // A deleted row keeps its number until the ids are compacted.
            return vec![Cell::Id(element), Cell::Text("deleted".to_owned())];
        }
        return Vec::new();
    }
    let mut cells = vec![Cell::Id(element)];
    for entry in Column::table(mesh.structure(), element.kind) {
        if entry.column == Column::Position {
            let p = mesh.position(VertexId::new(element.id)).unwrap_or_default();
            cells.extend([p.x, p.y, p.z].map(coordinate));
        } else {
            let target = mesh.reference(element, entry.column).ok().flatten();
            cells.push(Cell::Link(target, entry.column));
        }
    }
    cells.push(Cell::Text(String::new()));
    cells
}

/// A cell the current step wrote: the old value struck through, then the
/// new one, on the write colour.
fn written_cell_ui(
    ui: &mut egui::Ui,
    old: &str,
    new: Option<ElementRef>,
    tint: Option<egui::Color32>,
) {
    let new = new.map_or_else(|| NONE.to_owned(), |target| target.id.to_string());
    ui.spacing_mut().item_spacing.x = 3.0;
    ui.label(RichText::new(old).monospace().strikethrough().weak());
    let mut text = RichText::new(new.clone()).monospace().strong();
    if let Some(tint) = tint {
        text = text.background_color(tint.gamma_multiply(0.55));
    }
    ui.label(text)
        .on_hover_text(format!("was {old}, now {new}"));
}

fn coordinate(value: f32) -> Cell {
    Cell::Text(format!("{value:.3}"))
}

#[cfg(test)]
mod tests {
    use super::{DrawnRows, Jump};

    #[test]
    fn a_row_drawn_whole_stays_and_another_is_centred_before_the_end() {
        // Rows 10 to 31 drawn: 10 cut off at the top, 30 at the bottom, 31
        // past the end; 440 points, 20 rows of 22, fill the table.
        let drawn = DrawnRows {
            first: 10,
            last: 31,
            height: 440.0,
            rows: 1000,
        };
        let pitch = 22.0;
        assert_eq!(drawn.jump_to(11, 1000, pitch), Jump::Stay);
        assert_eq!(drawn.jump_to(29, 1000, pitch), Jump::Stay);
        for row in [10, 30, 500, 978] {
            let Jump::Offset(offset) = drawn.jump_to(row, 1000, pitch) else {
                panic!("row {row} is jumped to");
            };
            let middle = offset + 220.0;
            assert!(
                (middle - (row as f32 + 0.5) * pitch).abs() < 0.01,
                "row {row} centred: offset {offset}"
            );
        }
        assert_eq!(
            drawn.jump_to(2, 1000, pitch),
            Jump::Offset(0.0),
            "not above the top"
        );
        assert_eq!(
            drawn.jump_to(990, 1000, pitch),
            Jump::AfterLayout,
            "nor past the end"
        );
        let top = DrawnRows {
            first: 0,
            last: 21,
            height: 440.0,
            rows: 1000,
        };
        assert_eq!(
            top.jump_to(0, 1000, pitch),
            Jump::Stay,
            "the first row at the top"
        );
    }
}
