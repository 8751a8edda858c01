//! Pictures of the active tab for slides and handouts: the SVG of the view
//! and its tables ([`crate::export`]), a PDF handout of a run with a page
//! per step, and screenshots of the whole window, which the browser encodes
//! as PNG.

use std::collections::BTreeMap;
use std::sync::{Arc, Mutex};

use super::{EdgewiseApp, scene_styles};
use crate::{algorithm::frame::frame_at, command::CommandError, paint::Paint};
use edgewise_core::schema::ElementRef;
use edgewise_pictures::geometry::MeshGeometry;
use edgewise_pictures::pdf;
use edgewise_pictures::svg::{self, Picture, RowLook};
use edgewise_pictures::text_table;

/// The most faces a vector picture draws: beyond, the file would be too
/// large to open comfortably, and a PNG serves better.
pub const MAX_PICTURE_FACES: usize = 50_000;
/// The most faces a handout draws over all its pages.
pub const MAX_HANDOUT_FACES: usize = 200_000;

/// Characters of variables on one line of a handout's page.
const VARIABLES_PER_LINE: usize = 120;

/// Where a requested screenshot arrives from the renderer.
pub(super) type ScreenshotSlot = Arc<Mutex<Option<Arc<egui::ColorImage>>>>;

impl EdgewiseApp {
    /// Lays the active tab out as its first frame in a window `width` by
    /// `height` points would, with no window: a mesh being opened is made now,
    /// the camera frames it, and the colours are the current moment's.
    /// [`Self::export_svg`] and [`Self::export_handout`] then work from
    /// the command line (`edgewise render`).
    pub fn lay_out_offscreen(&mut self, width: f32, height: f32) {
        self.finish_pending();
        self.refresh_styles();
        self.sync_view_options();
        let tab = &mut self.tabs[self.active_tab];
        tab.pane
            .lay_out_offscreen(egui::vec2(width, height), &self.view_options);
    }

    /// The view as vector shapes with the tables beside it, highlighted
    /// rows in their colours and roles in words, and the message line as
    /// the caption.
    pub fn export_svg(&self) -> Result<String, CommandError> {
        let tab = self.tab();
        let document = tab
            .document
            .as_ref()
            .ok_or("open a mesh before exporting a picture of it")?;
        let faces = document.mesh().face_count();
        if faces > MAX_PICTURE_FACES {
            return Err(format!(
                "{} has {faces} faces; a vector picture holds at most {MAX_PICTURE_FACES}: \
                 save a PNG of it instead",
                document.name
            )
            .into());
        }
        let view = tab
            .pane
            .view
            .vector_view(&self.view_options)
            .ok_or("the view has not been drawn yet; export it after the next frame")?;
        let tables = text_table::text_tables(document.mesh(), svg::TABLE_ROWS);
        let rows = row_looks(&self.current_paint());
        let title = match tab.run.algorithm() {
            Some(algorithm) => format!("Edgewise: {} on {}", algorithm.name, document.name),
            None => format!("Edgewise: {}", document.name),
        };
        Ok(svg::svg(&Picture {
            title,
            caption: self.message_text(None),
            view: &view,
            tables: &tables,
            rows: &rows,
        }))
    }

    /// A PDF handout of the run: one page per step, from the start to the
    /// end, each the view at that step (the mesh as it then was, for an
    /// algorithm that changes it) under the step's sentence and the
    /// variables. Returns the file's name and bytes.
    pub fn export_handout(&self) -> Result<(String, Vec<u8>), CommandError> {
        let tab = self.tab();
        let (Some(document), Some(session)) = (tab.document.as_ref(), tab.run.session()) else {
            return Err("run an algorithm first: a handout has a page per step of its run".into());
        };
        let trace = &session.trace;
        let steps = trace.len();
        if steps + 1 > pdf::MAX_PAGES {
            return Err(format!(
                "{} has {steps} steps; a handout holds at most {} pages (a step each, with the start)",
                trace.algorithm().name,
                pdf::MAX_PAGES
            )
            .into());
        }
        let faces = document.mesh().face_count();
        if faces * (steps + 1) > MAX_HANDOUT_FACES {
            return Err(format!(
                "a handout of {} steps on {faces} faces would draw more than {MAX_HANDOUT_FACES} \
                 faces in all; run it on a smaller mesh",
                steps + 1
            )
            .into());
        }
        let edits = session.edits();
        let mut mesh = document.mesh().clone();
        let mut applied = tab.edit_applied;
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
            let frame = frame_at(trace, step, &self.theme);
            let styles = scene_styles(&mesh, &frame.paint, 0);
            let view = tab
                .pane
                .view
                .vector_view_of(geometry, &styles, &self.view_options)
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
        let stem = crate::files::mesh_stem(&document.name);
        Ok((
            format!("{stem}-{}.pdf", trace.algorithm().name),
            pdf::handout(&title, &pages),
        ))
    }

    /// Asks for a screenshot of the next frame; [`Self::take_screenshot`]
    /// gives it once drawn.
    pub fn request_screenshot(&mut self) {
        let slot = Arc::new(Mutex::new(None));
        self.screenshot = Some(Arc::clone(&slot));
        if let Some(ctx) = &self.ctx {
            ctx.request_screenshot(move |image| {
                if let Ok(mut slot) = slot.lock() {
                    *slot = Some(image);
                }
            });
            ctx.request_repaint();
        }
    }

    /// The screenshot asked for, once the frame is drawn.
    pub fn take_screenshot(&mut self) -> Option<Arc<egui::ColorImage>> {
        let image = self.screenshot.as_ref()?.lock().ok()?.take()?;
        self.screenshot = None;
        Some(image)
    }
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
