//! What one moment of a tab shows, as the view, the tables and the pictures
//! all take it: its paint (the step's colours, or the selection's, with the
//! marks), and the SVG and PDF made of it. The app and `edgewise render`
//! both make their pictures here, so a handout from a script is the file the
//! Save menu makes.

use std::collections::BTreeMap;

use edgewise_core::mesh::{Change, Edit, Issue};
use edgewise_core::schema::ElementRef;
use edgewise_pictures::geometry::MeshGeometry;
use edgewise_pictures::pdf;
use edgewise_pictures::styles::SceneStyles;
use edgewise_pictures::svg::{self, Picture, RowLook};
use edgewise_pictures::text_table;
use edgewise_pictures::vector::VectorView;

use crate::algorithm::frame::{TraceFrame, frame_at};
use crate::algorithm::session::TraceSession;
use crate::document::{Document, mesh_stem};
use crate::paint::{Paint, scene_styles};
use crate::theme::Theme;

/// The most faces a vector picture draws: beyond, the file would be too
/// large to open comfortably, and a PNG serves better.
pub const MAX_PICTURE_FACES: usize = 50_000;
/// The most faces a handout draws over all its pages.
pub const MAX_HANDOUT_FACES: usize = 200_000;

/// Characters of variables on one line of a handout's page.
const VARIABLES_PER_LINE: usize = 120;

/// The marks a tab keeps beside its document.
#[derive(Clone, Copy, Debug, Default)]
pub struct Marks<'a> {
    /// What the last edit by hand changed, shown while nothing else is.
    pub last_changes: &'a [Change],
    /// Records that break a rule.
    pub broken: &'a [Issue],
}

/// The paint of a moment: the step's `frame` (or, with none, the
/// selection's), the last changes while neither a selection nor a run is
/// shown, then the broken records and the deleted rows.
pub fn moment_paint(
    document: &Document,
    frame: Option<&TraceFrame>,
    running: bool,
    marks: Marks<'_>,
    theme: &Theme,
) -> Paint {
    let mut paint = match frame {
        Some(frame) => frame.paint.clone(),
        None => Paint::from_selection(document.highlights(), theme),
    };
    if document.selection().is_none() && !running {
        paint.add_changes(marks.last_changes, theme);
    }
    if !marks.broken.is_empty() {
        paint.add_broken(marks.broken, theme);
    }
    paint.add_deleted(Edit::deleted_rows(document.mesh()).iter(), theme);
    paint
}

/// Each painted element's row look: its first colour and every role.
pub fn row_looks(paint: &Paint) -> BTreeMap<ElementRef, RowLook> {
    let mut rows: BTreeMap<_, RowLook> = BTreeMap::new();
    for painted in &paint.painted {
        let look = rows.entry(painted.element).or_insert_with(|| RowLook {
            colour: painted.colour,
            roles: Vec::new(),
        });
        if !look.roles.contains(&painted.role) {
            look.roles.push(painted.role.clone());
        }
    }
    rows
}

/// Refuses a vector picture of a mesh too large for one.
pub fn check_picture_size(document: &Document) -> Result<(), String> {
    let faces = document.mesh().face_count();
    if faces > MAX_PICTURE_FACES {
        return Err(format!(
            "{} has {faces} faces; a vector picture holds at most {MAX_PICTURE_FACES}: \
             save a PNG of it instead",
            document.name
        ));
    }
    Ok(())
}

/// The SVG of a moment: `view` with the tables beside it, the rows `paint`
/// colours highlighted with their roles in words, and `caption` (the
/// message line) above. `algorithm` names the run, if any.
pub fn svg_picture(
    document: &Document,
    algorithm: Option<&str>,
    caption: Option<String>,
    paint: &Paint,
    view: &VectorView,
) -> String {
    let tables = text_table::text_tables(document.mesh(), svg::TABLE_ROWS);
    let rows = row_looks(paint);
    let title = match algorithm {
        Some(algorithm) => format!("Edgewise: {algorithm} on {}", document.name),
        None => format!("Edgewise: {}", document.name),
    };
    svg::svg(&Picture {
        title,
        caption,
        view,
        tables: &tables,
        rows: &rows,
    })
}

/// A PDF handout of a run: one page per step, from the start to the end,
/// each the view at that step (the mesh as it then was, for an algorithm
/// that changes it) under the step's sentence and the variables. The
/// document's mesh has the run's first `applied` changes made; `view_of`
/// draws the view from the same camera, of another mesh (the view's own
/// when `None`) in other styles. Returns the file's name and bytes.
pub fn handout(
    document: &Document,
    session: &TraceSession,
    applied: usize,
    theme: &Theme,
    view_of: impl Fn(Option<MeshGeometry>, &SceneStyles) -> Option<VectorView>,
) -> Result<(String, Vec<u8>), String> {
    let trace = &session.trace;
    let steps = trace.len();
    if steps + 1 > pdf::MAX_PAGES {
        return Err(format!(
            "{} has {steps} steps; a handout holds at most {} pages (a step each, with the start)",
            trace.algorithm().name,
            pdf::MAX_PAGES
        ));
    }
    let faces = document.mesh().face_count();
    if faces * (steps + 1) > MAX_HANDOUT_FACES {
        return Err(format!(
            "a handout of {} steps on {faces} faces would draw more than {MAX_HANDOUT_FACES} \
             faces in all; run it on a smaller mesh",
            steps + 1
        ));
    }
    let edits = session.edits();
    let mut mesh = document.mesh().clone();
    let mut applied = applied;
    let mut pages = Vec::with_capacity(steps + 1);
    let algorithm = trace.algorithm();
    // The lines of the algorithm a step runs in: a call's are its own.
    let code_of = |line: u32| -> Vec<(u32, String)> {
        let routine = algorithm
            .routines()
            .iter()
            .find(|r| (r.first_line..=r.last_line).contains(&line))
            .unwrap_or(algorithm);
        (1_u32..)
            .zip(routine.source.lines())
            .filter(|(number, _)| (routine.first_line..=routine.last_line).contains(number))
            .map(|(number, text)| (number, text.to_owned()))
            .collect()
    };
    for step in 0..=steps {
        let geometry = if edits {
            let wanted = trace.changes_through(step.checked_sub(1));
            trace
                .seek(&mut mesh, applied, wanted)
                .map_err(|error| format!("step {step}: {error}"))?;
            applied = wanted;
            Some(MeshGeometry::from_mesh(&mesh))
        } else {
            None
        };
        let frame = frame_at(trace, step, theme);
        let styles = scene_styles(&mesh, &frame.paint, 0);
        let view = view_of(geometry, &styles)
            .ok_or("the view has not been drawn yet; export it after the next frame")?;
        let mut lines = vec![format!(
            "Step {} of {}: {}",
            frame.step, frame.steps, frame.message
        )];
        let variables: Vec<String> = frame
            .variables
            .iter()
            .map(|v| format!("{} = {}", v.name, v.value))
            .collect();
        // The variables, as many to a line as fit the page.
        let mut line = String::new();
        for variable in variables {
            if !line.is_empty() && line.len() + variable.len() > VARIABLES_PER_LINE {
                lines.push(std::mem::take(&mut line));
            }
            if !line.is_empty() {
                line.push_str("    ");
            }
            line.push_str(&variable);
        }
        if !line.is_empty() {
            lines.push(line);
        }
        let painted: Vec<_> = frame.paint.painted.iter().map(|p| p.element).collect();
        pages.push(pdf::Page {
            view,
            lines,
            code: code_of(frame.line),
            current_line: (step > 0).then_some(frame.line),
            tables: text_table::text_rows(&mesh, &painted),
            rows: row_looks(&frame.paint),
        });
    }
    let title = format!("{} on {}", trace.algorithm().name, document.name);
    let stem = mesh_stem(&document.name);
    Ok((
        format!("{stem}-{}.pdf", trace.algorithm().name),
        pdf::handout(&title, &pages),
    ))
}
