//! The working copy an operation is planned on. Every read goes through it
//! and every change lands in it; the mesh is not touched until the finished
//! plan is committed through an [`Editor`]. So a refusal found at any point
//! of the planning leaves the mesh exactly as it was, and the committed
//! changes are only the final value of each cell that changed.
//!
//! Operations are written once for both structures in terms of [`Dart`]s:
//! one side of an edge, walked counter-clockwise around the face (or the
//! boundary loop) on that side. A half-edge is a dart; a winged edge is two,
//! its left side running start → end and its right side end → start. The
//! plan keeps the successor (and predecessor) of each changed dart and turns
//! them into the columns each structure stores only when it is finished.

use std::collections::{HashMap, HashSet};

use glam::Vec3;

use super::Applied;
use super::refusal::Refusal;
use crate::mesh::edit::{Change, Edit, Editor};
use crate::mesh::ids::{EdgeId, FaceId, HalfEdgeId, VertexId};
use crate::mesh::validate::Element;
use crate::mesh::winged_edge::Side;
use crate::schema::{Column, ElementKind, ElementRef, LookupError, Records, Structure};

/// One side of an edge, walked counter-clockwise around its face: a
/// half-edge, or a winged edge with the side its face is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Dart {
    Half(HalfEdgeId),
    Wing(EdgeId, Side),
}

/// A cell the plan changed, at the level the operations think in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Key {
    Next(Dart),
    Prev(Dart),
    Face(Dart),
    End(Dart),
    VertexEdge(VertexId),
    FaceEdge(FaceId),
    Position(VertexId),
}

/// The new value of a [`Key`].
#[derive(Clone, Copy, Debug, PartialEq)]
enum Value {
    Dart(Dart),
    Face(Option<FaceId>),
    Vertex(VertexId),
    Incident(Option<Dart>),
    Point(Vec3),
}

/// A mesh as an operation sees it while planning: the mesh as it is, under
/// the changes planned so far.
pub(crate) struct Patch<'m, M: Records + ?Sized> {
    mesh: &'m M,
    structure: Structure,
    /// Rows per table, with the rows the plan made.
    lengths: [u32; 3],
    /// Rows made, in order (a half-edge pair by its first half).
    created: Vec<ElementRef>,
    /// The pairs of the half-edges made.
    twins: HashMap<HalfEdgeId, HalfEdgeId>,
    /// Changes in the order each cell was first changed; a later change of
    /// the same cell replaces the value in place.
    changes: Vec<(Key, Value)>,
    index: HashMap<Key, usize>,
    /// Rows to delete, in order (a half-edge pair by its first half).
    deleted: Vec<ElementRef>,
    /// Every row that will be deleted, both halves of a pair included.
    gone: HashSet<ElementRef>,
}

fn slot(kind: ElementKind) -> usize {
    match kind {
        ElementKind::Vertex => 0,
        ElementKind::Edge => 1,
        ElementKind::Face => 2,
    }
}

impl<'m, M: Records + ?Sized> Patch<'m, M> {
    pub(crate) fn new(mesh: &'m M) -> Self {
        let length = |kind| u32::try_from(mesh.count(kind)).unwrap_or(u32::MAX);
        Self {
            mesh,
            structure: mesh.structure(),
            lengths: ElementKind::ALL.map(length),
            created: Vec::new(),
            twins: HashMap::new(),
            changes: Vec::new(),
            index: HashMap::new(),
            deleted: Vec::new(),
            gone: HashSet::new(),
        }
    }

    // ------------------------------------------------------------ naming

    /// A row as messages name it: edge rows are half-edges in a half-edge
    /// mesh.
    pub(crate) fn element(&self, row: ElementRef) -> Element {
        Element::of(self.structure, row)
    }

    /// The row a dart is stored in: the half-edge, or the winged edge.
    pub(crate) fn row(&self, dart: Dart) -> ElementRef {
        match dart {
            Dart::Half(h) => h.into(),
            Dart::Wing(e, _) => e.into(),
        }
    }

    /// How messages name the edge of a dart.
    pub(crate) fn name(&self, dart: Dart) -> Element {
        self.element(self.row(dart))
    }

    // ------------------------------------------------------------ arguments

    /// Refuses an id that names no live row of `kind`.
    fn exists(&self, row: ElementRef) -> Result<(), Refusal> {
        if self.mesh.contains(row) {
            Ok(())
        } else if (row.id as usize) < self.mesh.count(row.kind) {
            Err(Refusal::Deleted(self.element(row)))
        } else {
            Err(Refusal::NoSuchElement(self.element(row)))
        }
    }

    pub(crate) fn vertex(&self, id: u32) -> Result<VertexId, Refusal> {
        let v = VertexId::new(id);
        self.exists(v.into()).map(|()| v)
    }

    pub(crate) fn face(&self, id: u32) -> Result<FaceId, Refusal> {
        let f = FaceId::new(id);
        self.exists(f.into()).map(|()| f)
    }

    /// The dart an edge id names: the half-edge itself, or a winged edge's
    /// left side (start → end). Either way it runs the way the user named
    /// the edge.
    pub(crate) fn edge(&self, id: u32) -> Result<Dart, Refusal> {
        self.exists(ElementRef::new(ElementKind::Edge, id))?;
        Ok(match self.structure {
            Structure::HalfEdge => Dart::Half(HalfEdgeId::new(id)),
            Structure::WingedEdge => Dart::Wing(EdgeId::new(id), Side::Left),
        })
    }

    // ------------------------------------------------------------ reading

    fn get(&self, key: Key) -> Option<Value> {
        self.index.get(&key).map(|&at| self.changes[at].1)
    }

    fn is_new(&self, row: ElementRef) -> bool {
        row.id as usize >= self.mesh.count(row.kind)
    }

    /// A reference as the mesh holds it. A reference to a row that is not
    /// there is a broken table, reported where it is stored.
    fn stored(&self, row: ElementRef, column: Column) -> Result<Option<ElementRef>, Refusal> {
        let broken = Refusal::Broken {
            element: self.element(row),
            column,
        };
        match self.mesh.reference(row, column) {
            Ok(Some(target)) if !self.mesh.contains(target) => Err(broken),
            Ok(target) => Ok(target),
            Err(
                LookupError::NoSuchElement(_)
                | LookupError::Deleted(_)
                | LookupError::NotApplicable { .. },
            ) => Err(broken),
        }
    }

    fn required(&self, row: ElementRef, column: Column) -> Result<ElementRef, Refusal> {
        self.stored(row, column)?.ok_or(Refusal::Broken {
            element: self.element(row),
            column,
        })
    }

    fn broken(&self, dart: Dart, column: Column) -> Refusal {
        Refusal::Broken {
            element: self.name(dart),
            column,
        }
    }

    fn end_column(dart: Dart) -> Column {
        match dart {
            Dart::Half(_) | Dart::Wing(_, Side::Left) => Column::EndVertex,
            Dart::Wing(_, Side::Right) => Column::StartVertex,
        }
    }

    fn face_column(dart: Dart) -> Column {
        match dart {
            Dart::Half(_) => Column::Face,
            Dart::Wing(_, side) => Column::face_of(side),
        }
    }

    /// The vertex a dart ends at, as the mesh has it.
    fn stored_end(&self, dart: Dart) -> Result<VertexId, Refusal> {
        let row = self.row(dart);
        if self.is_new(row) {
            return Err(self.broken(dart, Self::end_column(dart)));
        }
        Ok(VertexId::new(
            self.required(row, Self::end_column(dart))?.id,
        ))
    }

    /// The face a dart walks, as the mesh has it.
    fn stored_face(&self, dart: Dart) -> Result<Option<FaceId>, Refusal> {
        let row = self.row(dart);
        if self.is_new(row) {
            return Ok(None);
        }
        Ok(self
            .stored(row, Self::face_column(dart))?
            .map(|f| FaceId::new(f.id)))
    }

    /// The other side of a dart's edge.
    pub(crate) fn twin(&self, dart: Dart) -> Result<Dart, Refusal> {
        match dart {
            Dart::Wing(e, side) => Ok(Dart::Wing(e, side.opposite())),
            Dart::Half(h) => match self.twins.get(&h) {
                Some(&pair) => Ok(Dart::Half(pair)),
                None => Ok(Dart::Half(HalfEdgeId::new(
                    self.required(h.into(), Column::PairEdge)?.id,
                ))),
            },
        }
    }

    /// Where a dart ends.
    pub(crate) fn end(&self, dart: Dart) -> Result<VertexId, Refusal> {
        match self.get(Key::End(dart)) {
            Some(Value::Vertex(v)) => Ok(v),
            _ => self.stored_end(dart),
        }
    }

    /// Where a dart starts: where its twin ends.
    pub(crate) fn start(&self, dart: Dart) -> Result<VertexId, Refusal> {
        self.end(self.twin(dart)?)
    }

    /// The face a dart walks (`None` on a boundary loop).
    pub(crate) fn face_of(&self, dart: Dart) -> Result<Option<FaceId>, Refusal> {
        match self.get(Key::Face(dart)) {
            Some(Value::Face(f)) => Ok(f),
            _ => self.stored_face(dart),
        }
    }

    /// The dart after `dart` counter-clockwise around its face.
    pub(crate) fn next(&self, dart: Dart) -> Result<Dart, Refusal> {
        match self.get(Key::Next(dart)) {
            Some(Value::Dart(next)) => Ok(next),
            _ => self.stored_step(dart, true),
        }
    }

    /// The dart before `dart` counter-clockwise around its face.
    pub(crate) fn prev(&self, dart: Dart) -> Result<Dart, Refusal> {
        match self.get(Key::Prev(dart)) {
            Some(Value::Dart(prev)) => Ok(prev),
            _ => self.stored_step(dart, false),
        }
    }

    /// The next (or previous) dart as the mesh has it. A winged edge names
    /// only the edge of its wing; the side is the one walking the same face
    /// and meeting this dart at its end (or start), which also tells the two
    /// sides of an edge with one face on both apart.
    fn stored_step(&self, dart: Dart, forward: bool) -> Result<Dart, Refusal> {
        match dart {
            Dart::Half(h) => {
                let column = if forward {
                    Column::SuccessorEdge
                } else {
                    Column::PredecessorEdge
                };
                if self.is_new(h.into()) {
                    return Err(self.broken(dart, column));
                }
                Ok(Dart::Half(HalfEdgeId::new(
                    self.required(h.into(), column)?.id,
                )))
            }
            Dart::Wing(e, side) => {
                let column = if forward {
                    Column::predecessor_of(side)
                } else {
                    Column::successor_of(side)
                };
                if self.is_new(e.into()) {
                    return Err(self.broken(dart, column));
                }
                let wing = EdgeId::new(self.required(e.into(), column)?.id);
                let face = self.stored_face(dart)?;
                let meet = if forward {
                    self.stored_end(dart)?
                } else {
                    self.stored_end(Dart::Wing(e, side.opposite()))?
                };
                for side in [Side::Left, Side::Right] {
                    let candidate = Dart::Wing(wing, side);
                    let at = if forward {
                        self.stored_end(Dart::Wing(wing, side.opposite()))?
                    } else {
                        self.stored_end(candidate)?
                    };
                    if self.stored_face(candidate)? == face && at == meet {
                        return Ok(candidate);
                    }
                }
                Err(self.broken(dart, column))
            }
        }
    }

    /// The dart of an edge row that ends at `v`, if either does.
    fn dart_ending_at(&self, row: ElementRef, v: VertexId) -> Result<Dart, Refusal> {
        let dart = match self.structure {
            Structure::HalfEdge => Dart::Half(HalfEdgeId::new(row.id)),
            Structure::WingedEdge => Dart::Wing(EdgeId::new(row.id), Side::Left),
        };
        if self.end(dart)? == v {
            return Ok(dart);
        }
        let twin = self.twin(dart)?;
        if self.structure == Structure::WingedEdge && self.end(twin)? == v {
            return Ok(twin);
        }
        Err(Refusal::Broken {
            element: Element::Vertex(v),
            column: Column::IncidentEdge,
        })
    }

    /// The dart ending at `v` that its incident edge names (`None` for an
    /// isolated vertex).
    pub(crate) fn vertex_dart(&self, v: VertexId) -> Result<Option<Dart>, Refusal> {
        if let Some(Value::Incident(dart)) = self.get(Key::VertexEdge(v)) {
            return Ok(dart);
        }
        match self.stored(v.into(), Column::IncidentEdge)? {
            None => Ok(None),
            Some(row) => self.dart_ending_at(row, v).map(Some),
        }
    }

    /// The dart of `f` that its incident edge names (a winged edge with `f`
    /// on both sides gives its left side).
    pub(crate) fn face_dart(&self, f: FaceId) -> Result<Dart, Refusal> {
        if let Some(Value::Incident(Some(dart))) = self.get(Key::FaceEdge(f)) {
            return Ok(dart);
        }
        let row = self.required(f.into(), Column::IncidentEdge)?;
        Ok(match self.structure {
            Structure::HalfEdge => Dart::Half(HalfEdgeId::new(row.id)),
            Structure::WingedEdge => {
                let left = Dart::Wing(EdgeId::new(row.id), Side::Left);
                if self.face_of(left)? == Some(f) {
                    left
                } else {
                    Dart::Wing(EdgeId::new(row.id), Side::Right)
                }
            }
        })
    }

    /// The row a vertex's incident edge names.
    pub(crate) fn vertex_row(&self, v: VertexId) -> Result<Option<ElementRef>, Refusal> {
        Ok(self.vertex_dart(v)?.map(|dart| self.row(dart)))
    }

    pub(crate) fn position(&self, v: VertexId) -> Result<Vec3, Refusal> {
        if let Some(Value::Point(p)) = self.get(Key::Position(v)) {
            return Ok(p);
        }
        self.mesh.position(v).ok_or(Refusal::Broken {
            element: Element::Vertex(v),
            column: Column::Position,
        })
    }

    /// The most darts a walk can meet before it must have come back.
    fn budget(&self) -> usize {
        let rows = self.lengths[slot(ElementKind::Edge)] as usize;
        match self.structure {
            Structure::HalfEdge => rows,
            Structure::WingedEdge => rows * 2,
        }
    }

    /// The darts of the cycle through `start` (a face, or a boundary loop),
    /// from `start` on.
    pub(crate) fn cycle(&self, start: Dart) -> Result<Vec<Dart>, Refusal> {
        let mut darts = vec![start];
        let mut current = self.next(start)?;
        while current != start {
            if darts.len() > self.budget() {
                return Err(self.broken(start, Column::SuccessorEdge));
            }
            darts.push(current);
            current = self.next(current)?;
        }
        Ok(darts)
    }

    /// The darts ending at `v`, turning clockwise seen from outside (the
    /// half-edge paper's loop: next, then twin), from `first`.
    pub(crate) fn ring_from(&self, v: VertexId, first: Dart) -> Result<Vec<Dart>, Refusal> {
        let mut darts = vec![first];
        let mut current = self.twin(self.next(first)?)?;
        while current != first {
            if darts.len() > self.budget() || self.end(current)? != v {
                return Err(Refusal::Broken {
                    element: Element::Vertex(v),
                    column: Column::IncidentEdge,
                });
            }
            darts.push(current);
            current = self.twin(self.next(current)?)?;
        }
        Ok(darts)
    }

    /// The darts ending at `v`, from the one its incident edge names.
    pub(crate) fn ring(&self, v: VertexId) -> Result<Vec<Dart>, Refusal> {
        match self.vertex_dart(v)? {
            None => Ok(Vec::new()),
            Some(first) => self.ring_from(v, first),
        }
    }

    /// Whether `v` lies on a boundary loop.
    pub(crate) fn on_boundary(&self, v: VertexId) -> Result<bool, Refusal> {
        for dart in self.ring(v)? {
            if self.face_of(dart)?.is_none() {
                return Ok(true);
            }
        }
        Ok(false)
    }

    /// The vertices joined to `v` by an edge, in ring order.
    pub(crate) fn neighbours(&self, v: VertexId) -> Result<Vec<VertexId>, Refusal> {
        self.ring(v)?
            .into_iter()
            .map(|dart| self.start(dart))
            .collect()
    }

    /// A dart running from `a` to `b`, if an edge joins them.
    pub(crate) fn dart_between(&self, a: VertexId, b: VertexId) -> Result<Option<Dart>, Refusal> {
        for dart in self.ring(b)? {
            if self.start(dart)? == a {
                return Ok(Some(dart));
            }
        }
        Ok(None)
    }

    // ------------------------------------------------------------ changing

    fn put(&mut self, key: Key, value: Value) {
        match self.index.get(&key) {
            Some(&at) => self.changes[at].1 = value,
            None => {
                self.index.insert(key, self.changes.len());
                self.changes.push((key, value));
            }
        }
    }

    /// Makes `next` follow `dart` around its face.
    pub(crate) fn set_next(&mut self, dart: Dart, next: Dart) {
        self.put(Key::Next(dart), Value::Dart(next));
        self.put(Key::Prev(next), Value::Dart(dart));
    }

    pub(crate) fn set_face(&mut self, dart: Dart, face: Option<FaceId>) {
        self.put(Key::Face(dart), Value::Face(face));
    }

    /// Makes a dart end at `v` (so its twin starts there).
    pub(crate) fn set_end(&mut self, dart: Dart, v: VertexId) {
        self.put(Key::End(dart), Value::Vertex(v));
    }

    /// Makes `dart`'s edge the incident edge of `v`; `dart` ends at `v`.
    pub(crate) fn set_vertex_dart(&mut self, v: VertexId, dart: Dart) {
        self.put(Key::VertexEdge(v), Value::Incident(Some(dart)));
    }

    /// Makes `dart`'s edge the incident edge of `f`; `dart` walks `f`.
    pub(crate) fn set_face_dart(&mut self, f: FaceId, dart: Dart) {
        self.put(Key::FaceEdge(f), Value::Incident(Some(dart)));
    }

    pub(crate) fn set_position(&mut self, v: VertexId, position: Vec3) {
        self.put(Key::Position(v), Value::Point(position));
    }

    fn make(&mut self, kind: ElementKind, rows: u32) -> u32 {
        let id = self.lengths[slot(kind)];
        self.lengths[slot(kind)] = id.saturating_add(rows);
        self.created.push(ElementRef::new(kind, id));
        id
    }

    /// A new vertex at `position`: the next free vertex id.
    pub(crate) fn new_vertex(&mut self, position: Vec3) -> VertexId {
        let v = VertexId::new(self.make(ElementKind::Vertex, 1));
        self.set_position(v, position);
        v
    }

    /// A new edge, as its two darts: the first is the first half-edge (the
    /// next free id, its pair the one after) or the left side of the next
    /// free winged edge, so it runs from the edge's start to its end.
    pub(crate) fn new_edge(&mut self) -> (Dart, Dart) {
        match self.structure {
            Structure::HalfEdge => {
                let first = HalfEdgeId::new(self.make(ElementKind::Edge, 2));
                let second = HalfEdgeId::new(first.raw().saturating_add(1));
                self.twins.insert(first, second);
                self.twins.insert(second, first);
                (Dart::Half(first), Dart::Half(second))
            }
            Structure::WingedEdge => {
                let e = EdgeId::new(self.make(ElementKind::Edge, 1));
                (Dart::Wing(e, Side::Left), Dart::Wing(e, Side::Right))
            }
        }
    }

    /// A new face: the next free face id.
    pub(crate) fn new_face(&mut self) -> FaceId {
        FaceId::new(self.make(ElementKind::Face, 1))
    }

    fn delete(&mut self, row: ElementRef) {
        self.deleted.push(row);
        self.gone.insert(row);
    }

    pub(crate) fn delete_vertex(&mut self, v: VertexId) {
        self.delete(v.into());
    }

    pub(crate) fn delete_face(&mut self, f: FaceId) {
        self.delete(f.into());
    }

    /// Deletes a dart's edge: a winged edge, or both halves of a pair.
    pub(crate) fn delete_edge(&mut self, dart: Dart) -> Result<(), Refusal> {
        if let Dart::Half(_) = dart {
            let twin = self.twin(dart)?;
            let row = self.row(twin);
            self.gone.insert(row);
        }
        self.delete(self.row(dart));
        Ok(())
    }

    // ------------------------------------------------------------ committing

    /// The planned changes, as the columns each structure stores.
    pub(crate) fn finish(self) -> Plan {
        let mut writes = Vec::with_capacity(self.changes.len() * 2);
        let edge_row = |dart: Dart| match dart {
            Dart::Half(h) => ElementRef::from(h),
            Dart::Wing(e, _) => ElementRef::from(e),
        };
        for &(key, value) in &self.changes {
            let reference = |row, column, target| Write::Reference(row, column, target);
            match (key, value) {
                (Key::Next(dart), Value::Dart(next)) => match dart {
                    Dart::Half(h) => writes.push(reference(
                        h.into(),
                        Column::SuccessorEdge,
                        Some(edge_row(next)),
                    )),
                    Dart::Wing(e, side) => writes.push(reference(
                        e.into(),
                        Column::predecessor_of(side),
                        Some(edge_row(next)),
                    )),
                },
                // A winged edge stores its predecessor as the successor
                // wing; a half-edge's is derived, so nothing is written.
                (Key::Prev(Dart::Wing(e, side)), Value::Dart(prev)) => writes.push(reference(
                    e.into(),
                    Column::successor_of(side),
                    Some(edge_row(prev)),
                )),
                (Key::Face(dart), Value::Face(face)) => writes.push(reference(
                    edge_row(dart),
                    Self::face_column(dart),
                    face.map(ElementRef::from),
                )),
                (Key::End(dart), Value::Vertex(v)) => writes.push(reference(
                    edge_row(dart),
                    Self::end_column(dart),
                    Some(v.into()),
                )),
                (Key::VertexEdge(v), Value::Incident(dart)) => writes.push(reference(
                    v.into(),
                    Column::IncidentEdge,
                    dart.map(edge_row),
                )),
                (Key::FaceEdge(f), Value::Incident(dart)) => writes.push(reference(
                    f.into(),
                    Column::IncidentEdge,
                    dart.map(edge_row),
                )),
                (Key::Position(v), Value::Point(p)) => writes.push(Write::Position(v, p)),
                _ => {}
            }
        }
        writes.retain(|write| match write {
            Write::Reference(row, ..) => !self.gone.contains(row),
            Write::Position(v, _) => !self.gone.contains(&ElementRef::from(*v)),
        });
        Plan {
            created: self.created,
            writes,
            deleted: self.deleted,
        }
    }
}

/// One stored cell to write.
#[derive(Clone, Copy, Debug)]
enum Write {
    Reference(ElementRef, Column, Option<ElementRef>),
    Position(VertexId, Vec3),
}

/// A finished plan: the rows to make, the cells to write, the rows to
/// delete, in that order.
#[derive(Debug)]
pub(crate) struct Plan {
    created: Vec<ElementRef>,
    writes: Vec<Write>,
    deleted: Vec<ElementRef>,
}

impl Plan {
    /// Makes the planned changes through `editor`, skipping writes that
    /// would store what a cell already holds. If any change fails, every
    /// change made so far is taken back and the mesh is as it was.
    pub(crate) fn commit<M: Edit + ?Sized>(
        self,
        editor: &mut Editor<'_, M>,
    ) -> Result<Applied, Refusal> {
        let mark = editor.journal().len();
        match self.write(editor) {
            Ok(()) => {
                let journal: Vec<Change> = editor.journal()[mark..].to_vec();
                let rows = |created: bool| {
                    journal
                        .iter()
                        .filter_map(|change| match (change, created) {
                            (Change::Create(row), true) | (Change::Delete(row), false) => {
                                Some(*row)
                            }
                            _ => None,
                        })
                        .collect()
                };
                Ok(Applied {
                    made: rows(true),
                    deleted: rows(false),
                    journal,
                })
            }
            Err(refusal) => {
                while editor.journal().len() > mark {
                    if editor.undo_last().is_err() {
                        break;
                    }
                }
                Err(refusal)
            }
        }
    }

    fn write<M: Edit + ?Sized>(&self, editor: &mut Editor<'_, M>) -> Result<(), Refusal> {
        for &planned in &self.created {
            let made = editor.create(planned.kind).map_err(Refusal::EditFailed)?;
            if made != planned {
                return Err(Refusal::Numbering { planned, made });
            }
        }
        for &write in &self.writes {
            match write {
                Write::Reference(row, column, target) => {
                    if editor.mesh().reference(row, column).ok() != Some(target) {
                        editor
                            .set(row, column, target)
                            .map_err(Refusal::EditFailed)?;
                    }
                }
                Write::Position(v, position) => {
                    if editor.mesh().position(v) != Some(position) {
                        editor
                            .set_position(v, position)
                            .map_err(Refusal::EditFailed)?;
                    }
                }
            }
        }
        for &row in &self.deleted {
            if editor.mesh().contains(row) {
                editor.delete(row).map_err(Refusal::EditFailed)?;
            }
        }
        Ok(())
    }
}
