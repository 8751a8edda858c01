//! Edge collapse: an edge shrunk to a point, with the link-condition check
//! that keeps the mesh a manifold.

use super::patch::{Dart, Patch};
use super::refusal::{Action, EdgeName, Refusal};
use super::{Applied, EdgeRow, Operation, run};
use crate::mesh::edit::{Edit, Editor};
use crate::mesh::ids::{FaceId, VertexId};
use crate::schema::Records;

/// A triangle beside the collapsed edge, which the collapse removes.
struct Triangle {
    face: FaceId,
    /// Its third corner.
    corner: VertexId,
    /// Its edge touching b (deleted), and the dart of its other edge (kept),
    /// which takes the place of `deleted`'s twin.
    deleted: Dart,
    kept: Dart,
    /// The twin of `deleted`, whose place `kept` takes.
    replaced: Dart,
}

/// Collapses the named edge a → b: b merges into a, which moves to
/// (a + b) / 2; V − 1, E − 1 − k, F − k, where k is the number of triangles
/// beside the edge. Each triangle (a, b, c) beside it is removed, and its
/// edges b–c and c–a become one edge, c–a; a face of four or more edges
/// beside it loses the edge.
///
/// Refused when the edge has one face on both sides, and when the result
/// would not be a manifold mesh: when a and b share a neighbour other than
/// the third corners of the triangles beside the edge (the link condition),
/// when both are on the boundary but the edge is not, when a merged edge
/// would have the same face, or no face, on both sides, and when only two
/// faces glued along every edge would be left (every edge of a
/// tetrahedron), and when a face that passes both ends would pass a twice.
///
/// Makes nothing. Deletes, in order: the edge; for each triangle (the
/// first half's side first) its other edge at b, then the face; then b.
/// Writes, with d and t the first and second half of the edge:
///
/// 1. for each side (d's first), if it is a triangle: its dart c → a (on
///    t's side a → x) takes the place of the twin of its edge at b: that
///    twin's face, and (the dart before it) → it → (the dart after it);
///    if it is not a triangle (or the boundary): (the dart before) → (the
///    dart after), skipping the edge;
/// 2. every other dart that ended at b ends at a, in turn around b from d;
/// 3. a's position;
/// 4. incident edges: a's becomes the edge before d on its side if it was
///    the collapsed edge; a triangle's third corner takes the kept edge if
///    its incident edge was deleted, and so does the face whose dart the
///    kept edge replaced; a face of four or more edges takes the edge after
///    the collapsed one if its incident edge was the collapsed edge.
pub fn collapse_edge<M: Edit + ?Sized>(
    editor: &mut Editor<'_, M>,
    edge: EdgeRow,
) -> Result<Applied, Refusal> {
    run(editor, |patch| plan(patch, edge))
}

fn plan<M: Records + ?Sized>(patch: &mut Patch<'_, M>, edge: EdgeRow) -> Result<(), Refusal> {
    let collapse = Collapse::read(patch, edge)?;
    collapse.check_link_condition(patch)?;
    collapse.check_boundary(patch)?;
    collapse.check_edges_beyond(patch)?;
    let around_b = patch.ring_from(collapse.b, collapse.d)?;
    collapse.check_faces_stay_simple(patch, &around_b)?;
    collapse.write(patch, &around_b)
}

/// What a collapse of d (a → b) reads before it changes anything.
struct Collapse {
    /// The two halves of the edge: d runs a → b, t is its twin.
    d: Dart,
    t: Dart,
    a: VertexId,
    b: VertexId,
    /// The faces on d's and t's sides (`None` for the boundary).
    faces: [Option<FaceId>; 2],
    /// The triangle on each side, if that side is one.
    triangles: [Option<Triangle>; 2],
    name: EdgeName,
    action: Action,
}

impl Collapse {
    /// Reads the edge and the triangles beside it; refuses an edge with
    /// one face on both sides.
    fn read<M: Records + ?Sized>(patch: &Patch<'_, M>, edge: EdgeRow) -> Result<Self, Refusal> {
        let d = patch.edge(edge.0)?;
        let name = EdgeName(patch.name(d));
        let t = patch.twin(d)?;
        let (a, b) = (patch.start(d)?, patch.end(d)?);
        let faces = [patch.face_of(d)?, patch.face_of(t)?];
        if let [Some(face), Some(other)] = faces
            && face == other
        {
            return Err(Refusal::SameFaceOnBothSides {
                operation: Operation::CollapseEdge,
                edge: name,
                face,
            });
        }
        let mut triangles: [Option<Triangle>; 2] = [None, None];
        for (slot, side) in triangles.iter_mut().zip([d, t]) {
            let Some(face) = patch.face_of(side)? else {
                continue;
            };
            if patch.cycle(side)?.len() != 3 {
                continue;
            }
            let s1 = patch.next(side)?;
            let s2 = patch.next(s1)?;
            // On d's side s1 runs b → c; on t's side s2 runs x → b.
            let (deleted, kept) = if side == d { (s1, s2) } else { (s2, s1) };
            *slot = Some(Triangle {
                face,
                corner: patch.end(s1)?,
                deleted,
                kept,
                replaced: patch.twin(deleted)?,
            });
        }
        Ok(Self {
            d,
            t,
            a,
            b,
            faces,
            triangles,
            name,
            action: Action::Collapsing(name),
        })
    }

    /// The link condition: the ends share no neighbour but the triangles'
    /// third corners.
    fn check_link_condition<M: Records + ?Sized>(
        &self,
        patch: &Patch<'_, M>,
    ) -> Result<(), Refusal> {
        let corners: Vec<VertexId> = self.triangles.iter().flatten().map(|t| t.corner).collect();
        let of_b = patch.neighbours(self.b)?;
        for shared in patch.neighbours(self.a)? {
            if shared != self.b && of_b.contains(&shared) && !corners.contains(&shared) {
                return Err(Refusal::LinkCondition {
                    action: self.action,
                    edge: self.name,
                    a: self.a,
                    b: self.b,
                    shared,
                });
            }
        }
        Ok(())
    }

    /// Two boundary vertices joined by an inner edge would pinch the
    /// boundary into one vertex.
    fn check_boundary<M: Records + ?Sized>(&self, patch: &Patch<'_, M>) -> Result<(), Refusal> {
        if self.faces.iter().all(Option::is_some)
            && patch.on_boundary(self.a)?
            && patch.on_boundary(self.b)?
        {
            return Err(Refusal::BoundaryPinch {
                action: self.action,
                edge: self.name,
                a: self.a,
                b: self.b,
            });
        }
        Ok(())
    }

    /// Each triangle's two remaining edges become one: refused when that
    /// edge would have one face (or none) on both sides, or when what is
    /// left beyond it is the rest of a tetrahedron.
    fn check_edges_beyond<M: Records + ?Sized>(&self, patch: &Patch<'_, M>) -> Result<(), Refusal> {
        for triangle in self.triangles.iter().flatten() {
            let beyond_deleted = patch.face_of(triangle.replaced)?;
            let beyond_kept = patch.face_of(patch.twin(triangle.kept)?)?;
            if beyond_deleted == beyond_kept {
                return Err(Refusal::MergedEdge {
                    action: self.action,
                    a: self.a,
                    b: triangle.corner,
                    face: beyond_deleted,
                });
            }
            // Two triangles beyond, on the same three vertices once b is a:
            // the rest of a tetrahedron.
            let corners = (
                third_corner(patch, triangle.replaced)?,
                third_corner(patch, patch.twin(triangle.kept)?)?,
            );
            if let (Some(one), Some(other)) = (beyond_deleted, beyond_kept)
                && let (Some(p), Some(q)) = corners
                && p == q
            {
                return Err(Refusal::TooSmall {
                    action: self.action,
                    faces: [one.min(other), one.max(other)],
                });
            }
        }
        Ok(())
    }

    /// A face that passes both a and b (not along the edge) would pass a
    /// twice, as KEF and remove-vertex refuse. `around_b`: every dart that
    /// ends at b, in turn from d.
    fn check_faces_stay_simple<M: Records + ?Sized>(
        &self,
        patch: &Patch<'_, M>,
        around_b: &[Dart],
    ) -> Result<(), Refusal> {
        let removed: Vec<FaceId> = self.triangles.iter().flatten().map(|t| t.face).collect();
        let mut checked: Vec<FaceId> = Vec::new();
        for &dart in around_b {
            let Some(face) = patch.face_of(dart)? else {
                continue;
            };
            if removed.contains(&face) || checked.contains(&face) {
                continue;
            }
            checked.push(face);
            let mut corners = Vec::new();
            for side in patch.cycle(dart)? {
                if side == self.d || side == self.t {
                    continue;
                }
                let start = patch.start(side)?;
                let corner = if start == self.b { self.a } else { start };
                if corners.contains(&corner) {
                    return Err(Refusal::NotSimple {
                        action: self.action,
                        vertex: corner,
                    });
                }
                corners.push(corner);
            }
        }
        Ok(())
    }

    /// The writes and deletions, in the order [`collapse_edge`] lists them.
    fn write<M: Records + ?Sized>(
        self,
        patch: &mut Patch<'_, M>,
        around_b: &[Dart],
    ) -> Result<(), Refusal> {
        let Self {
            d,
            t,
            a,
            b,
            faces,
            triangles,
            ..
        } = self;
        // The incident edges as they were, to decide which must move.
        let a_edge = patch.vertex_row(a)?;
        let before_d = patch.prev(d)?;
        let corner_edges: Vec<_> = triangles
            .iter()
            .flatten()
            .map(|tri| patch.vertex_row(tri.corner))
            .collect::<Result<_, _>>()?;
        let face_edges: Vec<_> = triangles
            .iter()
            .flatten()
            .map(|tri| {
                patch
                    .face_of(tri.replaced)?
                    .map(|f| patch.face_dart(f).map(|dart| (f, patch.row(dart))))
                    .transpose()
            })
            .collect::<Result<_, _>>()?;
        let mut side_faces = Vec::new();
        for (side, face) in [d, t].into_iter().zip(faces) {
            if let Some(face) = face
                && patch.cycle(side)?.len() > 3
            {
                side_faces.push((face, patch.row(patch.face_dart(face)?), patch.next(side)?));
            }
        }
        let gone: Vec<Dart> = triangles
            .iter()
            .flatten()
            .flat_map(|tri| [tri.deleted, tri.replaced])
            .chain([d, t])
            .collect();

        // 1. Each side: the triangle's kept dart replaces the twin of its
        // deleted one, or the cycle skips the edge.
        for (side, triangle) in [d, t].into_iter().zip(&triangles) {
            match triangle {
                Some(tri) => {
                    let (before, after) = (patch.prev(tri.replaced)?, patch.next(tri.replaced)?);
                    patch.set_face(tri.kept, patch.face_of(tri.replaced)?);
                    patch.set_next(before, tri.kept);
                    patch.set_next(tri.kept, after);
                }
                None => {
                    let (before, after) = (patch.prev(side)?, patch.next(side)?);
                    patch.set_next(before, after);
                }
            }
        }
        // 2. and 3. What ended at b ends at a, which moves to the middle.
        for &dart in around_b {
            if !gone.contains(&dart) {
                patch.set_end(dart, a);
            }
        }
        let middle = (patch.position(a)? + patch.position(b)?) / 2.0;
        patch.set_position(a, middle);
        // 4. The incident edges that named a deleted edge.
        if a_edge == Some(patch.row(t)) {
            patch.set_vertex_dart(a, before_d);
        }
        let replacement = |dart: Dart| {
            triangles
                .iter()
                .flatten()
                .find(|tri| tri.replaced == dart)
                .map_or(dart, |tri| tri.kept)
        };
        for ((tri, corner_edge), face_edge) in
            triangles.iter().flatten().zip(corner_edges).zip(face_edges)
        {
            if corner_edge
                .is_some_and(|row| row == patch.row(tri.deleted) || row == patch.row(tri.replaced))
            {
                // The kept edge's dart that ends at the corner.
                let twin = patch.twin(tri.kept)?;
                let at_corner = if patch.end(tri.kept)? == tri.corner {
                    tri.kept
                } else {
                    twin
                };
                patch.set_vertex_dart(tri.corner, at_corner);
            }
            if let Some((face, row)) = face_edge
                && (row == patch.row(tri.deleted) || row == patch.row(tri.replaced))
            {
                patch.set_face_dart(face, tri.kept);
            }
        }
        for (face, row, after) in side_faces {
            if row == patch.row(d) || row == patch.row(t) {
                patch.set_face_dart(face, replacement(after));
            }
        }

        patch.delete_edge(d)?;
        for tri in triangles.iter().flatten() {
            patch.delete_edge(tri.deleted)?;
            patch.delete_face(tri.face);
        }
        patch.delete_vertex(b);
        Ok(())
    }
}

/// The corner of a triangle that `dart` does not touch, or `None` when
/// its face is not a triangle (or is the boundary).
fn third_corner<M: Records + ?Sized>(
    patch: &Patch<'_, M>,
    dart: Dart,
) -> Result<Option<VertexId>, Refusal> {
    if patch.face_of(dart)?.is_none() || patch.cycle(dart)?.len() != 3 {
        return Ok(None);
    }
    Ok(Some(patch.end(patch.next(dart)?)?))
}
