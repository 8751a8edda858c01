//! Several meshes at once, in tabs. Each [`Tab`] owns everything that
//! belongs to one mesh; the app draws and commands the active one, so a tab
//! switch only changes which one that is.

use edgewise_model::algorithm::run::AlgorithmRun;
use std::borrow::Cow;
use std::cell::RefCell;

use edgewise_core::mesh::{
    Change, Edit as _, Issue, Mesh, MeshStats, Polygons, Renumbering, Structure, VertexId,
    operations::{self, Operation},
};
use edgewise_core::schema::{Column, ElementKind, ElementRef, NameError};

use super::{
    EdgewiseApp,
    edit_menu::EditMenu,
    pane::{PaintKey, Pane},
    twin::Twin,
};
use crate::command::{Command, CommandError};
use crate::{
    history::{History, Kind},
    obj_editor::ObjEditor,
    state::TabState,
};
use edgewise_model::{
    document::Document,
    paint::{MOST_MARKED, Paint},
    practice::Session,
};

/// One open mesh and everything shown for it: its document, 3D view and
/// camera, colours, algorithm run, OBJ editor text, table scroll, error
/// and side-by-side twin.
pub(crate) struct Tab {
    pub(crate) document: Option<Document>,
    /// The 3D view, following the document.
    pub(crate) pane: Pane,
    /// What the views colour: the selection, or the trace's current step
    /// (derived with the pane's styles).
    pub(crate) paint: Paint,
    /// Table rows to bring into view once: where the selection or the
    /// trace's current operation moved to.
    pub(crate) table_scroll: Vec<(ElementKind, u32)>,
    pub(crate) run: AlgorithmRun,
    /// The structure new PLY and OBJ loads are built into.
    pub(crate) structure: Structure,
    pub(crate) obj_editor: ObjEditor,
    /// The last failed load or command, shown until dismissed.
    pub(crate) error: Option<String>,
    pub(crate) twin: Option<Twin>,
    /// The element under the pointer in the 3D view, for the message line.
    pub(crate) hovered: Option<ElementRef>,
    /// The row or reference under the pointer in the tables: the 3D view
    /// previews it.
    pub(crate) table_hovered: Option<ElementRef>,
    /// How many of an editing trace's changes the document's mesh shows.
    pub(crate) edit_applied: usize,
    /// Every load and edit of this tab, to undo and redo.
    pub(crate) history: History,
    /// Every rule the mesh breaks at the editing trace's current step, or
    /// in diagnosis mode.
    /// At most [`MOST_MARKED`] of them.
    broken: Vec<Issue>,
    /// How many records break a rule, all told.
    pub(crate) broken_total: usize,
    /// The mesh is a broken table opened to be fixed: its broken records
    /// are listed until it validates, which ends diagnosis.
    pub(crate) diagnosis: bool,
    /// The old-to-new ids of the last compacting, shown until dismissed.
    pub(crate) renumbering: Option<Renumbering>,
    /// The last refused load, when it is a table file that diagnosis can
    /// open: its name and bytes.
    pub(crate) diagnosable: Option<(String, Vec<u8>)>,
    /// The edit menu, while it is open.
    pub(crate) edit_menu: Option<EditMenu>,
    /// What the last operation applied by hand changed, shown until the
    /// next selection or change.
    last_changes: Vec<Change>,
    /// Counts the changes of `broken` and `last_changes`, which the views
    /// also colour.
    marks: u64,
    /// The statistics of the mesh with this mesh id.
    /// Kept in a cell so that `state()`, which only reads, shares it.
    stats: RefCell<Option<(u64, MeshStats)>>,
    /// [`Self::exact_polygons`] for the mesh it was worked out for.
    exact_polygons: RefCell<Option<(ExactKey, Option<Polygons>)>>,
    /// A large mesh being opened or converted, a slice per frame; the tab
    /// shows its old mesh meanwhile.
    pub(crate) pending: Option<super::pending::PendingMesh>,
    /// The exercise being done on this tab's tables (practice).
    pub(crate) practice: Option<Session>,
}

impl Tab {
    /// An empty tab drawing with `render_state` (none in headless tests).
    pub(crate) fn new(
        render_state: Option<&eframe::egui_wgpu::RenderState>,
        structure: Structure,
    ) -> Self {
        Self {
            document: None,
            pane: Pane::new(render_state),
            paint: Paint::default(),
            table_scroll: Vec::new(),
            run: AlgorithmRun::default(),
            structure,
            obj_editor: ObjEditor::default(),
            error: None,
            twin: None,
            hovered: None,
            table_hovered: None,
            edit_applied: 0,
            history: History::default(),
            broken: Vec::new(),
            broken_total: 0,
            diagnosis: false,
            renumbering: None,
            diagnosable: None,
            edit_menu: None,
            last_changes: Vec::new(),
            marks: 0,
            stats: RefCell::new(None),
            exact_polygons: RefCell::new(None),
            pending: None,
            practice: None,
        }
    }

    /// V, E, F, genus, boundary loops and components of the shown mesh,
    /// worked out once per mesh (an edit's every step is a new mesh id).
    /// Deleted rows do not count.
    pub(crate) fn stats(&self) -> Option<MeshStats> {
        let document = self.document.as_ref()?;
        let id = document.mesh_id();
        let mut cache = self.stats.borrow_mut();
        if cache.as_ref().is_none_or(|(cached, _)| *cached != id) {
            *cache = Some((id, document.mesh().live_stats()));
        }
        cache.as_ref().map(|(_, stats)| stats.clone())
    }

    /// Fills [`Self::stats`]'s cache for the shown mesh with statistics
    /// worked out beforehand (a large mesh's, in a frame before it shows).
    pub(crate) fn seed_stats(&mut self, stats: MeshStats) {
        if let Some(document) = &self.document {
            *self.stats.borrow_mut() = Some((document.mesh_id(), stats));
        }
    }

    /// `mesh` (the document's, or the one before a trace) as polygons, when
    /// building from them gives back exactly its tables, so a link can
    /// carry them instead of the tables; worked out once per mesh.
    pub(crate) fn exact_polygons(&self, mesh: &Mesh) -> Option<Polygons> {
        let document = self.document.as_ref()?;
        let key = ExactKey {
            mesh_id: document.mesh_id(),
            own: std::ptr::eq(mesh, document.mesh()),
        };
        let mut cache = self.exact_polygons.borrow_mut();
        if cache.as_ref().is_none_or(|(cached, _)| *cached != key) {
            let polygons = mesh.to_polygons();
            let exact =
                Mesh::build(&polygons, mesh.structure()).is_ok_and(|(rebuilt, _)| rebuilt == *mesh);
            *cache = Some((key, exact.then_some(polygons)));
        }
        cache.as_ref().and_then(|(_, polygons)| polygons.clone())
    }

    /// Keeps the document's mesh at the editing trace's current step: the
    /// changes up to it applied, the later ones not.
    pub(crate) fn sync_edit(&mut self) {
        let (Some(document), Some(session)) = (&mut self.document, self.run.session()) else {
            self.edit_applied = 0;
            self.diagnose();
            return;
        };
        if !session.edits() {
            self.edit_applied = 0;
            self.diagnose();
            return;
        }
        let wanted = session.changes_wanted();
        if wanted == self.edit_applied {
            return;
        }
        if let Err(error) = document.seek(&session.trace, self.edit_applied, wanted) {
            self.error = Some(error);
        }
        self.edit_applied = wanted;
        let broken = document.mesh().validate();
        self.set_broken(broken);
    }

    /// Keeps the first [`MOST_MARKED`] broken records and counts them all:
    /// a runaway edit can break millions, and each kept one is painted.
    fn set_broken(&mut self, mut issues: Vec<Issue>) {
        self.broken_total = issues.len();
        issues.truncate(MOST_MARKED);
        self.broken = issues;
        self.marks += 1;
    }

    /// The broken records the views mark (at most [`MOST_MARKED`]).
    pub(crate) fn broken(&self) -> &[Issue] {
        &self.broken
    }

    /// What the last operation applied by hand changed.
    pub(crate) fn last_changes(&self) -> &[Change] {
        &self.last_changes
    }

    /// Shows `changes` as what the last operation changed (none: clears
    /// them).
    pub(crate) fn set_last_changes(&mut self, changes: Vec<Change>) {
        self.last_changes = changes;
        self.marks += 1;
    }

    /// The key of what the views colour now: the document's state, the
    /// run's step, the marks and the theme.
    pub(crate) fn paint_key(&self, theme_key: u64) -> Option<PaintKey> {
        let document = self.document.as_ref()?;
        Some(PaintKey {
            document: document.generation(),
            run: self.run.generation(),
            marks: self.marks,
            theme: theme_key,
        })
    }

    /// Outside an editing trace, lists the broken records in diagnosis
    /// mode (none otherwise), and ends diagnosis once there are none.
    fn diagnose(&mut self) {
        if self.diagnosis {
            self.rediagnose();
        } else {
            self.set_broken(Vec::new());
        }
    }

    /// Checks every rule of the mesh after it changed by hand: diagnosis
    /// lasts while any record breaks one.
    pub(crate) fn rediagnose(&mut self) {
        let broken = self
            .document
            .as_ref()
            .map(|d| d.mesh().validate())
            .unwrap_or_default();
        self.diagnose_with(broken);
    }

    /// [`Self::rediagnose`] with the rules already checked: `broken` are
    /// the current mesh's broken records.
    pub(crate) fn diagnose_with(&mut self, broken: Vec<Issue>) {
        // An exercise judges nothing before Check, unless it asks for live
        // feedback: its broken records are the student's to find.
        let broken = if self.practice.as_ref().is_some_and(|p| !p.grades_live()) {
            Vec::new()
        } else {
            broken
        };
        self.set_broken(broken);
        let was = std::mem::replace(&mut self.diagnosis, !self.broken.is_empty());
        if was && !self.diagnosis {
            log::info!("the tables validate: diagnosis is over");
        }
    }

    /// Ends the tab's run, whichever way it ends (Abort, ✖, a new load, a
    /// conversion): its edit is kept undoably or undone, as
    /// [`Self::finish_edit`] decides, and then the run stops.
    pub(crate) fn end_run(&mut self) {
        self.finish_edit();
        self.run.mesh_changed();
    }

    /// Ends an editing run: a run that finished and left a sound mesh keeps
    /// its result, undoable; any other goes back to the mesh it started
    /// from.
    pub(crate) fn finish_edit(&mut self) {
        self.sync_edit();
        let Some(session) = self.run.session().filter(|s| s.edits()) else {
            self.edit_applied = 0;
            return;
        };
        if self.edit_applied == 0 {
            return;
        }
        let finished = session.at_end() && session.trace.outcome().error().is_none();
        let name = format!("{} (traced)", session.trace.algorithm().name);
        let before = self.mesh_before_trace().map(Cow::into_owned);
        let sound = finished
            && self
                .document
                .as_ref()
                .is_some_and(|d| d.mesh().validate().is_empty());
        if sound {
            if let (Some(before), Some(document)) = (before, &mut self.document) {
                let previous = document.with_mesh(before);
                document.sample = None;
                self.history.record(name, Kind::Edit, Some(previous), false);
            }
        } else if let Some(before) = before {
            self.replace_mesh(before);
        }
        self.edit_applied = 0;
        self.set_broken(Vec::new());
    }

    /// Shows `mesh` in place of the document's, keeping its name; gives
    /// back the document as it was.
    fn replace_mesh(&mut self, mesh: Mesh) -> Option<Document> {
        let document = self.document.as_mut()?;
        let before = document.replace_mesh(mesh);
        self.mesh_shown();
        Some(before)
    }

    /// After the document's mesh changed: the last changes are cleared and
    /// the structure follows it (the view follows by itself, `Pane`).
    fn mesh_shown(&mut self) {
        self.set_last_changes(Vec::new());
        if let Some(document) = &self.document {
            self.structure = document.structure();
        }
        self.error = None;
    }

    /// A change by hand: as [`Self::mesh_shown`], and a running algorithm,
    /// whose trace no longer describes the mesh, stops.
    fn mesh_changed_by_hand(&mut self) {
        self.run.mesh_changed();
        self.mesh_shown();
    }

    /// Refuses edits of a mesh whose tables are broken.
    fn sound(&self) -> Result<&Document, CommandError> {
        let document = self.document.as_ref().ok_or("no mesh is open")?;
        if self.diagnosis {
            return Err(format!(
                "{} has broken records; fix them in the tables first (diagnosis)",
                document.name
            )
            .into());
        }
        Ok(document)
    }

    /// Applies a native operation to the open mesh, undoably. A refusal
    /// leaves everything as it was.
    pub(crate) fn apply_operation(
        &mut self,
        operation: Operation,
        ids: &[u32],
    ) -> Result<(), CommandError> {
        let mut mesh = self.sound()?.mesh().clone();
        let shown: Vec<String> = ids.iter().map(ToString::to_string).collect();
        let call = format!("{} {}", operation.name(), shown.join(" "));
        let applied = operations::apply(&mut mesh, operation, ids)
            .map_err(|refusal| format!("{call}: {refusal}"))?;
        self.run.mesh_changed();
        if let Some(before) = self.replace_mesh(mesh) {
            // The view shows what the operation changed, nothing selected.
            let _cleared = self.document.as_mut().map(|d| d.select(None));
            self.set_last_changes(applied.journal);
            self.history.record(call, Kind::Edit, Some(before), false);
        }
        Ok(())
    }

    /// Sets one reference by hand, undoably: how a student fixes a broken
    /// table in diagnosis mode, or breaks a sound one to see what happens.
    pub(crate) fn set_cell(
        &mut self,
        element: ElementRef,
        column: &str,
        target: Option<u32>,
    ) -> Result<(), CommandError> {
        let document = self.document.as_ref().ok_or("no mesh is open")?;
        let structure = document.structure();
        let shown = target.map_or_else(|| "null".to_owned(), |id| id.to_string());
        let call = format!("setCell({element}, {column}, {shown})");
        let resolved = Column::resolve(structure, element.kind, column).map_err(|error| {
            let what = match error {
                NameError::Unknown => format!("there is no column `{column}`"),
                NameError::OtherStructure(other) => {
                    format!("`{column}` is a column of a {} mesh", other.prose())
                }
                NameError::WrongElement(owner) => {
                    format!("`{column}` is a column of {}", with_article(owner))
                }
            };
            format!(
                "{call}: {what}; {} of a {} mesh has {}",
                with_article(element.kind),
                structure.prose(),
                Column::canonical_names_for(structure, element.kind).join(", ")
            )
        })?;
        let Some(target_kind) = resolved.target() else {
            return Err(format!("{call}: `{column}` is not a reference to an element").into());
        };
        let target = target.map(|id| ElementRef::new(target_kind, id));
        let label = format!(
            "{element} {} := {}",
            resolved.language_name().unwrap_or(column),
            target.map_or_else(|| "null".to_owned(), |t| t.to_string())
        );
        self.by_hand(&call, label, |document| {
            document.set_reference(element, resolved, target)
        })
    }

    /// Appends an empty row by hand, undoably.
    pub(crate) fn add_row(&mut self, kind: ElementKind) -> Result<(), CommandError> {
        let call = format!("addRow({})", kind.prose());
        let label = format!("new {} row", kind.prose());
        self.by_hand(&call, label, |document| document.add_row(kind).map(drop))
    }

    /// Marks a row deleted by hand, undoably.
    pub(crate) fn delete_row(&mut self, element: ElementRef) -> Result<(), CommandError> {
        let call = format!("deleteRow({element})");
        self.by_hand(&call, format!("delete {element}"), |document| {
            document.delete_row(element)
        })
    }

    /// Moves a vertex by hand, undoably.
    pub(crate) fn set_position(
        &mut self,
        vertex: u32,
        [x, y, z]: [f32; 3],
    ) -> Result<(), CommandError> {
        let call = format!("setPosition({vertex}, [{x}, {y}, {z}])");
        let label = format!("vertex {vertex} position := ({x}, {y}, {z})");
        self.by_hand(&call, label, |document| {
            document.set_position(VertexId::new(vertex), glam::Vec3::new(x, y, z))
        })
    }

    /// One change of the tables by hand on a copy of the document, kept
    /// undoably as `label` if it succeeds; `call` names it in a refusal.
    fn by_hand(
        &mut self,
        call: &str,
        label: String,
        change: impl FnOnce(&mut Document) -> Result<(), String>,
    ) -> Result<(), CommandError> {
        let mut edited = self.document.as_ref().ok_or("no mesh is open")?.clone();
        change(&mut edited).map_err(|error| format!("{call}: {error}"))?;
        let before = self.document.replace(edited);
        self.history.record(label, Kind::Edit, before, false);
        self.mesh_changed_by_hand();
        self.rediagnose();
        if let Some(practice) = &mut self.practice {
            practice.wrote();
        }
        Ok(())
    }

    /// Drops the deleted rows and renumbers the rest, undoably; the mapping
    /// stays shown until dismissed.
    pub(crate) fn compact_ids(&mut self) -> Result<(), CommandError> {
        let document = self.sound()?;
        if document.mesh().deleted_rows().is_empty() {
            return Err(format!("{} has no deleted rows to compact", document.name).into());
        }
        let mut compacted = document.clone();
        let renumbering = compacted.compact();
        let before = self.document.replace(compacted);
        self.history
            .record("compact ids".to_owned(), Kind::Edit, before, false);
        self.renumbering = Some(renumbering);
        self.mesh_changed_by_hand();
        Ok(())
    }

    /// Takes back the last load or edit.
    pub(crate) fn undo(&mut self) -> Result<(), CommandError> {
        let label = self.history.undo(&mut self.document);
        self.restored("undid", &label.ok_or("nothing to undo")?);
        Ok(())
    }

    /// Makes the last undone change again.
    pub(crate) fn redo(&mut self) -> Result<(), CommandError> {
        let label = self.history.redo(&mut self.document);
        self.restored("redid", &label.ok_or("nothing to redo")?);
        Ok(())
    }

    /// After an undo or redo put a document from the history in place.
    fn restored(&mut self, what: &str, label: &str) {
        log::info!("{what} {label}");
        self.renumbering = None;
        self.mesh_changed_by_hand();
        self.rediagnose();
    }

    /// The mesh an editing trace started from (the shown mesh otherwise):
    /// what a link must carry so that replaying the run reproduces the view.
    pub(crate) fn mesh_before_trace(&self) -> Option<Cow<'_, Mesh>> {
        let document = self.document.as_ref()?;
        let session = self.run.session().filter(|_| self.edit_applied > 0);
        let Some(session) = session else {
            return Some(Cow::Borrowed(document.mesh()));
        };
        let mut before = document.mesh().clone();
        session.trace.seek(&mut before, self.edit_applied, 0).ok()?;
        Some(Cow::Owned(before))
    }

    /// Puts back the mesh from before the last edit, if the last change
    /// was an edit.
    pub(crate) fn restore_before_edit(&mut self) -> Result<(), CommandError> {
        match self.history.last() {
            Some((_, Kind::Edit)) => self.undo(),
            _ => {
                Err("no edit to take back: the mesh has not been edited since it was opened".into())
            }
        }
    }
}

impl Tab {
    /// Runs `f` on this tab's algorithm run and its mesh, refusing when no
    /// mesh is open.
    pub(crate) fn with_mesh(
        &mut self,
        f: impl FnOnce(&mut AlgorithmRun, &Mesh) -> Result<(), String>,
    ) -> Result<(), CommandError> {
        let mesh = self.document.as_ref().map(Document::mesh);
        let mesh = mesh.ok_or("no mesh is open")?;
        Ok(f(&mut self.run, mesh)?)
    }
}

impl EdgewiseApp {
    /// The tab the app shows and commands act on.
    pub(crate) fn tab(&self) -> &Tab {
        // `tabs` is never empty and `active_tab` is kept in range.
        &self.tabs[self.active_tab]
    }

    pub(crate) fn tab_mut(&mut self) -> &mut Tab {
        &mut self.tabs[self.active_tab]
    }

    /// [`Command::NewTab`]: opens an empty tab and switches to it; returns
    /// its index.
    pub(crate) fn open_tab(&mut self) -> usize {
        let structure = self.tab().structure;
        self.tabs
            .push(Tab::new(self.render_state.as_ref(), structure));
        self.active_tab = self.tabs.len() - 1;
        self.active_tab
    }

    /// [`Command::SwitchTab`].
    pub(crate) fn activate_tab(&mut self, index: usize) -> Result<(), CommandError> {
        if index >= self.tabs.len() {
            return Err(format!(
                "there is no tab {index} (there are {}, numbered from 0)",
                self.tabs.len()
            )
            .into());
        }
        self.active_tab = index;
        Ok(())
    }

    /// [`Command::CloseTab`]: the last tab cannot be closed.
    pub(crate) fn remove_tab(&mut self, index: usize) -> Result<(), CommandError> {
        if self.tabs.len() <= 1 {
            return Err("the last tab cannot be closed".into());
        }
        if index >= self.tabs.len() {
            return Err(format!("there is no tab {index}").into());
        }
        if index == self.active_tab {
            let neighbour = if index + 1 < self.tabs.len() {
                index + 1
            } else {
                index - 1
            };
            self.activate_tab(neighbour)?;
        }
        self.tabs.remove(index);
        if index < self.active_tab {
            self.active_tab -= 1;
        }
        Ok(())
    }

    /// The tabs for `state().tabs`.
    pub(super) fn tab_states(&self) -> Vec<TabState> {
        (0..self.tabs.len())
            .map(|i| TabState {
                title: self.tab_title(i),
                active: i == self.active_tab,
            })
            .collect()
    }

    fn tab_title(&self, index: usize) -> String {
        self.tabs
            .get(index)
            .and_then(|tab| tab.document.as_ref())
            .map_or_else(|| "New tab".to_owned(), |d| d.name.clone())
    }

    /// The tab strip; shown when there is more than one tab.
    pub(super) fn tab_bar_ui(&mut self, ui: &mut egui::Ui) {
        let mut switch = None;
        let mut close = None;
        let mut new = false;
        ui.horizontal(|ui| {
            for i in 0..self.tabs.len() {
                let title = self.tab_title(i);
                let response = ui.selectable_label(i == self.active_tab, &title);
                if response.clicked() {
                    switch = Some(i);
                }
                if ui
                    .small_button("✖")
                    .on_hover_text(format!("Close {title}"))
                    .clicked()
                {
                    close = Some(i);
                }
                ui.separator();
            }
            new = ui.button("+").on_hover_text("A new tab").clicked();
        });
        if new {
            self.issue(Command::NewTab);
            return;
        }
        if let Some(i) = switch {
            self.issue(Command::SwitchTab(i));
        }
        if let Some(i) = close {
            self.issue(Command::CloseTab(i));
        }
    }
}

/// "a vertex", "an edge", "a face".
fn with_article(kind: ElementKind) -> &'static str {
    match kind {
        ElementKind::Vertex => "a vertex",
        ElementKind::Edge => "an edge",
        ElementKind::Face => "a face",
    }
}

/// Which mesh [`Tab::exact_polygons`] was worked out for: the document's
/// mesh id, and whether it was that mesh or the one before a trace.
#[derive(Clone, Copy, PartialEq, Eq)]
struct ExactKey {
    mesh_id: u64,
    own: bool,
}
