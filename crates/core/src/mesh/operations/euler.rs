//! The Euler operators and their inverses: MEV and KEV, MEF and KEF, KEMR
//! and MEKR. Each changes V, E, F and the number of boundary loops b so
//! that V − E + F = 2 − 2g − b still holds for every component, and each
//! undoes its partner exactly: the operator followed by its inverse on the
//! edge it made leaves tables that compact to the ones it started from.

use glam::Vec3;

use super::patch::{Dart, Patch};
use super::refusal::{Action, EdgeName, Refusal};
use super::split_face::corner;
use super::{Applied, EdgeRow, Operation, run};
use crate::mesh::edit::{Edit, Editor};
use crate::mesh::ids::{FaceId, VertexId};
use crate::schema::{Column, ElementRef, Records};

/// MEV, make edge and vertex: splits vertex `v`, adding a vertex w and the
/// edge v–w; V + 1, E + 1.
///
/// An edge at `v` names a corner there: the corner after its dart ending
/// at `v`, in the face that dart walks. With two edges, whose darts are ha
/// and hb, the darts ending at `v` after ha up to hb, turning clockwise
/// seen from outside (from h to the twin of the dart after h), move to w;
/// the new edge goes into the corners of ha and hb, and each of their faces
/// gains an edge. With one edge (or the same twice) nothing moves: the new
/// edge dangles from `v` into the face of ha's corner, which walks it out
/// and back, so it has that face on both sides.
///
/// w is placed halfway between `v` and the mean of the vertices whose edges
/// move to it (for a dangling edge, of the corners of its face).
///
/// Refused when an edge does not start or end at `v`, when a dangling
/// edge's corner is a boundary gap, and when both corners are.
///
/// Makes, in order: w; the edge (starting at `v`, ending at w: its first
/// half k1 runs v → w, its second k2 w → v). Deletes nothing. Writes:
///
/// 1. w's position;
/// 2. the ends: k1 ends at w, k2 at `v`;
/// 3. ha → k1 → the dart that followed ha, then hb → k2 → the dart that
///    followed hb (for a dangling edge: ha → k1 → k2 → the dart that
///    followed ha);
/// 4. the faces: k1 takes ha's, k2 hb's;
/// 5. each moved dart ends at w, in turn;
/// 6. incident edges: if `v`'s incident edge moved, w takes it and `v`
///    takes the new edge; otherwise w takes the new edge.
pub fn mev<M: Edit + ?Sized>(
    editor: &mut Editor<'_, M>,
    v: VertexId,
    first: EdgeRow,
    second: Option<EdgeRow>,
) -> Result<Applied, Refusal> {
    run(editor, |patch| {
        let v = patch.vertex(v.raw())?;
        let ha = ending_at(patch, first, v)?;
        let hb = match second {
            Some(edge) => ending_at(patch, edge, v)?,
            None => ha,
        };
        let named = EdgeName(patch.name(patch.edge(first.0)?));
        plan_mev(patch, v, (ha, named), hb)
    })
}

/// The dart of an edge that ends at `v`.
fn ending_at<M: Records + ?Sized>(
    patch: &Patch<'_, M>,
    edge: EdgeRow,
    v: VertexId,
) -> Result<Dart, Refusal> {
    let dart = patch.edge(edge.0)?;
    if patch.end(dart)? == v {
        return Ok(dart);
    }
    let twin = patch.twin(dart)?;
    if patch.end(twin)? == v {
        return Ok(twin);
    }
    Err(Refusal::NotAtVertex {
        edge: EdgeName(patch.name(dart)),
        vertex: v,
    })
}

fn mean(points: &[Vec3]) -> Vec3 {
    points.iter().copied().sum::<Vec3>() / points.len().max(1) as f32
}

/// Plans MEV at `v` between the corners after `ha` (named as the user named
/// its edge) and `hb`.
fn plan_mev<M: Records + ?Sized>(
    patch: &mut Patch<'_, M>,
    v: VertexId,
    (ha, named): (Dart, EdgeName),
    hb: Dart,
) -> Result<(), Refusal> {
    let (face_a, face_b) = (patch.face_of(ha)?, patch.face_of(hb)?);
    let dangling = ha == hb;
    if dangling && face_a.is_none() {
        return Err(Refusal::CornerOnBoundary {
            vertex: v,
            edge: named,
        });
    }
    if face_a.is_none() && face_b.is_none() {
        return Err(Refusal::BothCornersOnBoundary { vertex: v });
    }
    let ring = patch.ring_from(v, ha)?;
    let moved: Vec<Dart> = if dangling {
        Vec::new()
    } else {
        let last = ring
            .iter()
            .position(|&dart| dart == hb)
            .ok_or(Refusal::Broken {
                element: patch.element(v.into()),
                column: Column::IncidentEdge,
            })?;
        ring[1..=last].to_vec()
    };
    let around = if dangling {
        patch
            .cycle(ha)?
            .into_iter()
            .map(|dart| patch.end(dart))
            .collect::<Result<Vec<_>, _>>()?
    } else {
        moved
            .iter()
            .map(|&dart| patch.start(dart))
            .collect::<Result<Vec<_>, _>>()?
    };
    let points = around
        .into_iter()
        .map(|u| patch.position(u))
        .collect::<Result<Vec<_>, _>>()?;
    let position = (patch.position(v)? + mean(&points)) / 2.0;
    let v_edge = patch.vertex_dart(v)?;
    let (after_a, after_b) = (patch.next(ha)?, patch.next(hb)?);

    let w = patch.new_vertex(position);
    let (k1, k2) = patch.new_edge();
    patch.set_end(k1, w);
    patch.set_end(k2, v);
    patch.set_next(ha, k1);
    if dangling {
        patch.set_next(k1, k2);
    } else {
        patch.set_next(k1, after_a);
        patch.set_next(hb, k2);
    }
    patch.set_next(k2, after_b);
    patch.set_face(k1, face_a);
    patch.set_face(k2, face_b);
    for &dart in &moved {
        patch.set_end(dart, w);
    }
    match v_edge {
        Some(incident) if moved.contains(&incident) => {
            patch.set_vertex_dart(w, incident);
            patch.set_vertex_dart(v, k2);
        }
        _ => patch.set_vertex_dart(w, k1),
    }
    Ok(())
}

/// KEV, kill edge and vertex: the inverse of [`mev`]. Contracts the named
/// edge a → b, merging b into a, which stays where it is; V − 1, E − 1.
///
/// Refused when a face beside the edge would be left with fewer than three
/// edges, when the edge has one face on both sides but neither end dangles
/// (it is a bridge: see [`kemr`]), when a and b share a neighbour (it would
/// be joined to a twice: the link condition), and when a and b are on the
/// boundary but the edge is not.
///
/// Makes nothing. Deletes the edge, then b. Writes, with d and t the
/// edge's first and second half:
///
/// 1. every other dart ending at b ends at a, in turn around b from d;
/// 2. (the dart before d) → (the dart after d), then (the dart now before
///    t) → (the dart after t), so a dangling edge is skipped whole;
/// 3. incident edges: a face whose incident edge was the killed one takes
///    the dart now following the one before the killed edge on its side;
///    a, if its incident edge was the killed one, takes b's, or if that
///    was the killed one too, the edge before d (before t when a dangles).
pub fn kev<M: Edit + ?Sized>(
    editor: &mut Editor<'_, M>,
    edge: EdgeRow,
) -> Result<Applied, Refusal> {
    run(editor, |patch| plan_kev(patch, edge))
}

fn plan_kev<M: Records + ?Sized>(patch: &mut Patch<'_, M>, edge: EdgeRow) -> Result<(), Refusal> {
    let d = patch.edge(edge.0)?;
    let name = EdgeName(patch.name(d));
    let action = Action::Contracting(name);
    let t = patch.twin(d)?;
    let (a, b) = (patch.start(d)?, patch.end(d)?);
    let (face_d, face_t) = (patch.face_of(d)?, patch.face_of(t)?);
    let dangles = patch.next(d)? == t || patch.next(t)? == d;
    if face_d == face_t {
        match face_d {
            Some(face) if !dangles => {
                return Err(Refusal::SameFaceOnBothSides {
                    operation: Operation::Kev,
                    edge: name,
                    face,
                });
            }
            Some(face) => {
                let edges = patch.cycle(d)?.len().saturating_sub(2);
                if edges < 3 {
                    return Err(Refusal::FaceTooSmall {
                        action,
                        face,
                        edges,
                    });
                }
            }
            None => {
                return Err(Refusal::Broken {
                    element: name.0,
                    column: Column::Face,
                });
            }
        }
    } else {
        for (face, side) in [(face_d, d), (face_t, t)] {
            if let Some(face) = face {
                let edges = patch.cycle(side)?.len() - 1;
                if edges < 3 {
                    return Err(Refusal::FaceTooSmall {
                        action,
                        face,
                        edges,
                    });
                }
            }
        }
    }
    let of_b = patch.neighbours(b)?;
    for shared in patch.neighbours(a)? {
        if shared != b && of_b.contains(&shared) {
            return Err(Refusal::LinkCondition {
                action,
                edge: name,
                a,
                b,
                shared,
            });
        }
    }
    if face_d.is_some() && face_t.is_some() && patch.on_boundary(a)? && patch.on_boundary(b)? {
        return Err(Refusal::BoundaryPinch {
            action,
            edge: name,
            a,
            b,
        });
    }
    let killed_rows = [patch.row(d), patch.row(t)];
    let killed = |row: ElementRef| killed_rows.contains(&row);
    let a_edge = patch.vertex_row(a)?;
    let b_dart = patch.vertex_dart(b)?;
    let faces = [face_d, face_t]
        .into_iter()
        .flatten()
        .map(|face| Ok((face, patch.row(patch.face_dart(face)?))))
        .collect::<Result<Vec<_>, Refusal>>()?;
    let around_b = patch.ring_from(b, d)?;

    for &dart in around_b.iter().skip(1) {
        patch.set_end(dart, a);
    }
    let mut before_d = patch.prev(d)?;
    let after_d = patch.next(d)?;
    patch.set_next(before_d, after_d);
    let before_t = patch.prev(t)?;
    let after_t = patch.next(t)?;
    patch.set_next(before_t, after_t);
    if before_d == t {
        before_d = before_t;
    }
    for (face, row) in faces {
        if killed(row) {
            let before = if Some(face) == face_d {
                before_d
            } else {
                before_t
            };
            patch.set_face_dart(face, patch.next(before)?);
        }
    }
    if a_edge.is_some_and(killed) {
        match b_dart {
            Some(incident) if !killed(patch.row(incident)) => {
                patch.set_vertex_dart(a, incident);
            }
            _ => patch.set_vertex_dart(a, before_d),
        }
    }
    patch.delete_edge(d)?;
    patch.delete_vertex(b);
    Ok(())
}

/// MEF, make edge and face: joins vertices `u` and `w` of `face` by a new
/// edge, cutting it in two; E + 1, F + 1. The same operation as
/// [`super::split_face`], which documents it.
pub fn mef<M: Edit + ?Sized>(
    editor: &mut Editor<'_, M>,
    face: FaceId,
    u: VertexId,
    w: VertexId,
) -> Result<Applied, Refusal> {
    super::split_face::split_face(editor, face, u, w)
}

/// KEF, kill edge and face: the inverse of [`mef`]. Removes the named edge
/// a → b between two different faces, merging them; E − 1, F − 1. The
/// lower-numbered face is kept, so MEF followed by KEF on its edge keeps
/// the face MEF cut.
///
/// Refused when a side is the boundary, when the edge has one face on both
/// sides (see [`kemr`]), and when the merged face would pass a vertex twice
/// (the two faces meet somewhere else too).
///
/// Makes nothing. Deletes the edge, then the other face. Writes, with d and
/// t the edge's first and second half:
///
/// 1. each dart of the other face but the edge's joins the kept face, from
///    the one after the edge on;
/// 2. (the dart before d) → (the dart after t), then (the dart before t) →
///    (the dart after d);
/// 3. incident edges: the kept face, if its incident edge was the killed
///    one, takes the dart after the killed edge on its side; a, if its
///    incident edge was the killed one, takes the edge before d, and b the
///    edge before t.
pub fn kef<M: Edit + ?Sized>(
    editor: &mut Editor<'_, M>,
    edge: EdgeRow,
) -> Result<Applied, Refusal> {
    run(editor, |patch| plan_kef(patch, edge))
}

fn plan_kef<M: Records + ?Sized>(patch: &mut Patch<'_, M>, edge: EdgeRow) -> Result<(), Refusal> {
    let d = patch.edge(edge.0)?;
    let name = EdgeName(patch.name(d));
    let operation = Operation::Kef;
    let t = patch.twin(d)?;
    let (Some(face_d), Some(face_t)) = (patch.face_of(d)?, patch.face_of(t)?) else {
        return Err(Refusal::OnBoundary {
            operation,
            edge: name,
        });
    };
    if face_d == face_t {
        return Err(Refusal::SameFaceOnBothSides {
            operation,
            edge: name,
            face: face_d,
        });
    }
    let (kept, kept_side, gone, gone_side) = if face_d < face_t {
        (face_d, d, face_t, t)
    } else {
        (face_t, t, face_d, d)
    };
    let kept_darts = patch.cycle(kept_side)?;
    let gone_darts = patch.cycle(gone_side)?;
    let mut corners = Vec::new();
    for &dart in kept_darts.iter().skip(1).chain(gone_darts.iter().skip(1)) {
        let corner = patch.start(dart)?;
        if corners.contains(&corner) {
            return Err(Refusal::NotSimple {
                action: Action::RemovingEdge(name),
                vertex: corner,
            });
        }
        corners.push(corner);
    }
    let (a, b) = (patch.start(d)?, patch.end(d)?);
    let (before_d, after_d) = (patch.prev(d)?, patch.next(d)?);
    let (before_t, after_t) = (patch.prev(t)?, patch.next(t)?);
    let kept_edge = patch.row(patch.face_dart(kept)?);
    let a_edge = patch.vertex_row(a)?;
    let b_edge = patch.vertex_row(b)?;
    let killed_rows = [patch.row(d), patch.row(t)];
    let killed = |row: ElementRef| killed_rows.contains(&row);

    for &dart in gone_darts.iter().skip(1) {
        patch.set_face(dart, Some(kept));
    }
    patch.set_next(before_d, after_t);
    patch.set_next(before_t, after_d);
    if killed(kept_edge) {
        let after = if kept_side == d { after_d } else { after_t };
        patch.set_face_dart(kept, after);
    }
    if a_edge.is_some_and(killed) {
        patch.set_vertex_dart(a, before_d);
    }
    if b_edge.is_some_and(killed) {
        patch.set_vertex_dart(b, before_t);
    }
    patch.delete_edge(d)?;
    patch.delete_face(gone);
    Ok(())
}

/// KEMR, kill edge, make ring: removes the named edge a → b, a bridge that
/// has the same face on both sides, between the face's cycle through a and
/// an inner cycle through b; E − 1, and the inner cycle (the darts after
/// the named one, from b round to b) becomes a boundary loop. The inverse
/// of [`mekr`].
///
/// Refused when the sides have different faces (see [`kef`]) or are the
/// boundary, when an end dangles (see [`kev`]), when the face would be left
/// with fewer than three edges or with only dangling edges (both sides of
/// each), when an edge would be left with no face on either side (the
/// inner cycle walks both sides of an edge, or one whose other side is the
/// boundary), and when a vertex of the inner cycle is on the boundary
/// already (the boundary would pass it twice).
///
/// Makes nothing. Deletes the edge. Writes, with d and t the edge's first
/// and second half:
///
/// 1. each dart of the inner cycle leaves the face, from the one after d;
/// 2. (the dart before d) → (the dart after t), then (the dart before t) →
///    (the dart after d);
/// 3. incident edges: the face, if its incident edge is no longer on it,
///    takes the dart after t; a, if its incident edge was the killed one,
///    takes the edge before d, and b the edge before t.
pub fn kemr<M: Edit + ?Sized>(
    editor: &mut Editor<'_, M>,
    edge: EdgeRow,
) -> Result<Applied, Refusal> {
    run(editor, |patch| plan_kemr(patch, edge))
}

fn plan_kemr<M: Records + ?Sized>(patch: &mut Patch<'_, M>, edge: EdgeRow) -> Result<(), Refusal> {
    let d = patch.edge(edge.0)?;
    let name = EdgeName(patch.name(d));
    let action = Action::RemovingEdge(name);
    let t = patch.twin(d)?;
    let faces = [patch.face_of(d)?, patch.face_of(t)?];
    let face = match faces {
        [Some(face), Some(other)] if face == other => face,
        [None, None] => {
            return Err(Refusal::OnBoundary {
                operation: Operation::Kemr,
                edge: name,
            });
        }
        _ => return Err(Refusal::NotBridge { edge: name, faces }),
    };
    let (a, b) = (patch.start(d)?, patch.end(d)?);
    for (side, vertex) in [(d, b), (t, a)] {
        if patch.next(side)? == patch.twin(side)? {
            return Err(Refusal::Dangling { edge: name, vertex });
        }
    }
    // The darts after d up to t (the inner cycle) and after t up to d.
    let darts = patch.cycle(d)?;
    let at_t = darts
        .iter()
        .position(|&dart| dart == t)
        .unwrap_or(darts.len());
    let inner: Vec<Dart> = darts[1..at_t].to_vec();
    let outer: Vec<Dart> = darts[(at_t + 1).min(darts.len())..].to_vec();
    if outer.len() < 3 {
        return Err(Refusal::FaceTooSmall {
            action,
            face,
            edges: outer.len(),
        });
    }
    // The inner cycle's darts lose the face, so what is across each must
    // have one; the outer cycle keeps it, and must border something.
    for &dart in &inner {
        let twin = patch.twin(dart)?;
        if inner.contains(&twin) || patch.face_of(twin)?.is_none() {
            return Err(Refusal::NoFaceEither {
                action,
                edge: EdgeName(patch.name(dart)),
            });
        }
    }
    // A vertex of the inner cycle already on the boundary would be passed
    // by the boundary twice.
    for &dart in &inner {
        let vertex = patch.end(dart)?;
        if patch.on_boundary(vertex)? {
            return Err(Refusal::PinchesVertex { action, vertex });
        }
    }
    let mut closed = true;
    for &dart in &outer {
        closed &= outer.contains(&patch.twin(dart)?);
    }
    if closed {
        return Err(Refusal::OnlyDangling { action, face });
    }
    let (before_d, after_d) = (patch.prev(d)?, patch.next(d)?);
    let (before_t, after_t) = (patch.prev(t)?, patch.next(t)?);
    let face_edge = patch.row(patch.face_dart(face)?);
    let on_outer = outer.iter().any(|&dart| patch.row(dart) == face_edge);
    let a_edge = patch.vertex_row(a)?;
    let b_edge = patch.vertex_row(b)?;
    let killed_rows = [patch.row(d), patch.row(t)];
    let killed = |row: ElementRef| killed_rows.contains(&row);

    for &dart in &inner {
        patch.set_face(dart, None);
    }
    patch.set_next(before_d, after_t);
    patch.set_next(before_t, after_d);
    if !on_outer {
        patch.set_face_dart(face, after_t);
    }
    if a_edge.is_some_and(killed) {
        patch.set_vertex_dart(a, before_d);
    }
    if b_edge.is_some_and(killed) {
        patch.set_vertex_dart(b, before_t);
    }
    patch.delete_edge(d)?;
    Ok(())
}

/// MEKR, make edge, kill ring: joins vertex `a` of `face` to vertex `b` on
/// a boundary loop by a new edge, a bridge; the loop's darts join the face,
/// which now walks out along the bridge, round the loop and back. E + 1,
/// and one boundary loop fewer: the face becomes an annulus glued into the
/// loop (if the loop was in another component, the two join; if in the
/// same one, a handle appears). The inverse of [`kemr`].
///
/// Refused when `a` and `b` are the same vertex or already joined by an
/// edge, when `a` is not on `face` or `face` passes it twice, when `b` is
/// on no boundary loop or the boundary passes it more than once, and when
/// the face and the loop share a vertex (the face would pass it twice).
///
/// Makes the edge (starting at `a`, ending at `b`: its first half k1 runs
/// a → b, its second k2 b → a). Deletes nothing. Writes, with da the dart
/// of `face` ending at `a` and lb the loop's dart ending at `b`:
///
/// 1. the ends: k1 ends at `b`, k2 at `a`;
/// 2. the faces: k1 and k2 take `face`, then each dart of the loop, from
///    the one after lb round to lb;
/// 3. da → k1 → the dart after lb, then lb → k2 → the dart after da.
///
/// No incident edge changes.
pub fn mekr<M: Edit + ?Sized>(
    editor: &mut Editor<'_, M>,
    face: FaceId,
    a: VertexId,
    b: VertexId,
) -> Result<Applied, Refusal> {
    run(editor, |patch| {
        let f = patch.face(face.raw())?;
        let (a, b) = (patch.vertex(a.raw())?, patch.vertex(b.raw())?);
        plan_mekr(patch, f, a, b)
    })
}

fn plan_mekr<M: Records + ?Sized>(
    patch: &mut Patch<'_, M>,
    f: FaceId,
    a: VertexId,
    b: VertexId,
) -> Result<(), Refusal> {
    let action = Action::Joining {
        face: f,
        boundary: b,
    };
    if a == b {
        return Err(Refusal::SameVertex { vertex: a });
    }
    let darts = patch.cycle(patch.face_dart(f)?)?;
    let da = corner(patch, &darts, f, a)?;
    let mut gaps = Vec::new();
    for dart in patch.ring(b)? {
        if patch.face_of(dart)?.is_none() {
            gaps.push(dart);
        }
    }
    let lb = match gaps[..] {
        [] => return Err(Refusal::NotOnBoundary { vertex: b }),
        [only] => only,
        _ => {
            return Err(Refusal::SeveralBoundaries {
                vertex: b,
                count: gaps.len(),
            });
        }
    };
    if let Some(existing) = patch.dart_between(a, b)? {
        return Err(Refusal::EdgeExists {
            action,
            a,
            b,
            existing: EdgeName(patch.name(existing)),
        });
    }
    let ring = patch.cycle(lb)?;
    let on_loop = ring
        .iter()
        .map(|&dart| patch.end(dart))
        .collect::<Result<Vec<_>, _>>()?;
    for &dart in &darts {
        let corner = patch.end(dart)?;
        if on_loop.contains(&corner) {
            return Err(Refusal::NotSimple {
                action,
                vertex: corner,
            });
        }
    }
    let (after_a, after_b) = (patch.next(da)?, patch.next(lb)?);

    let (k1, k2) = patch.new_edge();
    patch.set_end(k1, b);
    patch.set_end(k2, a);
    patch.set_face(k1, Some(f));
    patch.set_face(k2, Some(f));
    for &dart in ring.iter().skip(1).chain(ring.first()) {
        patch.set_face(dart, Some(f));
    }
    patch.set_next(da, k1);
    patch.set_next(k1, after_b);
    patch.set_next(lb, k2);
    patch.set_next(k2, after_a);
    Ok(())
}
