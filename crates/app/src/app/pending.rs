//! Opening or converting a large mesh in slices across frames (as many as
//! fit in a frame's time budget), so the page keeps painting: a progress bar shows how far it is and
//! Cancel drops it. The tab keeps showing its old mesh until the new one is
//! ready; small meshes are shown at once.

use std::collections::VecDeque;

use egui::Widget as _;

use super::EdgewiseApp;
use crate::history::Kind;
use edgewise_core::mesh::{Issue, MeshStats};
use edgewise_model::document::Document;
use edgewise_pictures::geometry::MeshGeometry;
use edgewise_renderer::view3d::Preparation;

/// Meshes with more faces than this are prepared in slices across frames; below
/// it, all of the work takes a few frames' time.
pub(crate) const LARGE_FACES: usize = 50_000;

/// A frame makes slices until it has spent this long on them, so a fast
/// machine shows a large mesh in a frame or two and a slow one keeps
/// painting between slices. The last slice a frame starts may run past it
/// (torus-200k's largest takes about 60 ms in Chromium), and a frame under
/// `SwiftShader` costs up to 100 ms more, so this keeps every frame well
/// inside the quarter second a page may freeze.
const SLICE_BUDGET: std::time::Duration = std::time::Duration::from_millis(40);

/// How many finished jobs are remembered for the JavaScript API to collect.
const JOBS_REMEMBERED: usize = 16;

/// What showing the prepared mesh means.
pub(crate) enum Commit {
    /// A load: the new mesh replaces the tab's.
    Open { frame: bool, merge: bool },
    /// A structure switch of the tab's mesh `mesh_id`; dropped if that mesh
    /// changed meanwhile.
    Convert { mesh_id: u64 },
}

/// A mesh being prepared for a tab.
pub(crate) struct PendingMesh {
    pub(crate) id: u64,
    /// "Opening torus-200k", "Converting torus-200k to winged-edge".
    pub(crate) label: String,
    document: Document,
    preparation: Preparation,
    commit: Commit,
    /// Worked out in a frame of its own once the slices are done.
    checked: Option<Checked>,
}

/// What a pending mesh's panels need, worked out before it is shown.
struct Checked {
    /// A load's broken records (a conversion's mesh is checked already).
    broken: Option<Vec<Issue>>,
    stats: MeshStats,
}

impl PendingMesh {
    /// This frame's share of the work, begun at `start`: slices while they
    /// fit in [`SLICE_BUDGET`], then the rule check and statistics in a
    /// frame of their own. True once the mesh can be shown, which is left
    /// to a frame that made nothing else, since that frame also draws the
    /// new mesh whole.
    fn advance(&mut self, start: web_time::Instant) -> bool {
        if !self.preparation.is_done() {
            while !self.preparation.step() && start.elapsed() < SLICE_BUDGET {}
            return false;
        }
        if self.checked.is_none() {
            let mesh = self.document.mesh();
            self.checked = Some(Checked {
                broken: matches!(self.commit, Commit::Open { .. }).then(|| mesh.validate()),
                stats: mesh.live_stats(),
            });
            return false;
        }
        true
    }

    /// From 0 to 1: the slices, then the checks as one step more.
    pub(crate) fn progress(&self) -> f32 {
        let slices = Preparation::SLICES as f32;
        let checked = if self.checked.is_some() { 1.0 } else { 0.0 };
        (self.preparation.progress() * slices + checked) / (slices + 1.0)
    }
}

/// How each finished job ended, newest last: None when shown, else why not.
#[derive(Default)]
pub(crate) struct JobLog {
    next_id: u64,
    finished: VecDeque<(u64, Option<String>)>,
}

impl JobLog {
    fn next_id(&mut self) -> u64 {
        self.next_id += 1;
        self.next_id
    }

    fn finish(&mut self, id: u64, outcome: Option<String>) {
        if self.finished.len() == JOBS_REMEMBERED {
            self.finished.pop_front();
        }
        self.finished.push_back((id, outcome));
    }
}

impl EdgewiseApp {
    /// Shows `document` in the active tab as `commit` says: at once if it is
    /// small, else in slices across the next frames.
    pub(crate) fn show_document(&mut self, document: Document, commit: Commit, label: String) {
        let geometry = MeshGeometry::from_mesh(document.mesh());
        let large = document.mesh().face_count() > LARGE_FACES;
        let id = self.jobs.next_id();
        let tab = self.tab_mut();
        let pending = PendingMesh {
            id,
            label,
            preparation: Preparation::new(geometry, tab.pane.view.has_gpu()),
            document,
            commit,
            checked: None,
        };
        if large {
            if let Some(replaced) = tab.pending.replace(pending) {
                self.jobs.finish(
                    replaced.id,
                    Some(format!("{} was replaced", replaced.label)),
                );
            }
            self.request_repaint();
        } else {
            self.commit_pending(self.active_tab, pending);
        }
    }

    /// The id of the active tab's pending mesh, if one is being prepared.
    pub fn pending_job(&self) -> Option<u64> {
        self.tab().pending.as_ref().map(|pending| pending.id)
    }

    /// How job `id` ended: None while it runs, `Some(Ok)` once its mesh is
    /// shown, `Some(Err(why))` if it was cancelled or replaced.
    pub fn job_outcome(&self, id: u64) -> Option<Result<(), String>> {
        self.jobs
            .finished
            .iter()
            .find(|(finished, _)| *finished == id)
            .map(|(_, outcome)| outcome.clone().map_or(Ok(()), Err))
    }

    /// Makes slices of every tab's pending mesh, at least one and then as
    /// many as fit in [`SLICE_BUDGET`], and shows those that are ready.
    /// Called once per frame.
    pub(crate) fn advance_pending(&mut self, ctx: &egui::Context) {
        let start = web_time::Instant::now();
        for index in 0..self.tabs.len() {
            let Some(pending) = &mut self.tabs[index].pending else {
                continue;
            };
            if pending.advance(start)
                && let Some(pending) = self.tabs[index].pending.take()
            {
                self.commit_pending(index, pending);
            }
            ctx.request_repaint();
        }
    }

    /// Makes the active tab's pending mesh's remaining slices now and shows
    /// it, for a course link's algorithm and step, which need it.
    pub(crate) fn finish_pending(&mut self) {
        if let Some(pending) = self.tab_mut().pending.take() {
            self.commit_pending(self.active_tab, pending);
        }
    }

    /// [`crate::command::Command::Cancel`]: drops the active tab's pending
    /// mesh; the tab keeps what it shows.
    pub(crate) fn cancel_pending(&mut self) -> Result<(), String> {
        let pending = self
            .tab_mut()
            .pending
            .take()
            .ok_or("nothing is being opened or converted")?;
        self.jobs
            .finish(pending.id, Some(format!("{} was cancelled", pending.label)));
        Ok(())
    }

    fn commit_pending(&mut self, index: usize, pending: PendingMesh) {
        let PendingMesh {
            id,
            label,
            document,
            preparation,
            commit,
            checked,
        } = pending;
        let (broken, stats) = checked.map_or((None, None), |c| (c.broken, Some(c.stats)));
        let tab = &mut self.tabs[index];
        let outcome = match commit {
            Commit::Open { frame, merge } => {
                tab.structure = document.structure();
                tab.pane
                    .show_prepared(document.mesh_id(), preparation, frame);
                let entry = format!("open {}", document.name);
                // A traced edit is kept (or undone) before the new mesh
                // replaces it, so undo gives it back.
                tab.end_run();
                let before = tab.document.replace(document);
                tab.history.record(entry, Kind::Load, before, merge);
                // Another mesh ends the exercise on this tab.
                tab.practice = None;
                match broken {
                    Some(broken) => tab.diagnose_with(broken),
                    None => tab.rediagnose(),
                }
                tab.diagnosable = None;
                tab.renumbering = None;
                tab.error = None;
                None
            }
            Commit::Convert { mesh_id } => {
                if tab.document.as_ref().map(Document::mesh_id) == Some(mesh_id) {
                    let structure = document.structure();
                    tab.structure = structure;
                    tab.pane
                        .show_prepared(document.mesh_id(), preparation, false);
                    let before = tab.document.replace(document);
                    let entry = format!("convert to {}", structure.prose());
                    tab.history.record(entry, Kind::Load, before, false);
                    None
                } else {
                    Some(format!("{label} was dropped: the mesh changed meanwhile"))
                }
            }
        };
        if outcome.is_none() {
            if let Some(stats) = stats {
                tab.seed_stats(stats);
            }
            tab.run.mesh_changed();
        }
        self.jobs.finish(id, outcome);
        self.request_repaint();
    }

    /// The active tab's pending mesh: what it is, a progress bar and Cancel.
    pub(crate) fn pending_ui(&mut self, ctx: &egui::Context) {
        let Some(pending) = &self.tab().pending else {
            return;
        };
        let (label, progress) = (pending.label.clone(), pending.progress());
        let mut cancel = false;
        egui::Area::new(egui::Id::unique("pending_mesh"))
            .order(egui::Order::Foreground)
            .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
            .show(ctx, |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| {
                    ui.set_width(320.0);
                    ui.heading(format!("{label}…"));
                    egui::ProgressBar::new(progress).show_percentage().ui(ui);
                    ui.horizontal(|ui| {
                        ui.label("The mesh shown stays until the new one is ready.");
                    });
                    cancel = ui.button("Cancel (Esc)").clicked();
                });
            });
        if cancel || ctx.input(|i| i.key_pressed(egui::Key::Escape)) {
            self.issue(crate::command::Command::Cancel);
        }
    }
}
