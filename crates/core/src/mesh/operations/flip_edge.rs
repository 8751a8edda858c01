//! Edge flip: the edge between two triangles turns to join their other two
//! corners.

use super::patch::Patch;
use super::refusal::{Action, EdgeName, Refusal};
use super::{Applied, EdgeRow, Operation, run};
use crate::mesh::edit::{Edit, Editor};
use crate::schema::Records;

/// Flips the edge between two triangles.
///
/// The named edge runs a → b with triangle F = (a, b, c) on its first half
/// and G = (b, a, x) on its second. Afterwards it joins x and c, and the
/// triangles are F = (x, c, a) and G = (c, x, b): each keeps the half of the
/// flipped edge it had and one of its other edges, and takes one edge from
/// the other triangle. The quad a, x, b, c around them is unchanged.
///
/// Refused when either side is the boundary, when the sides are one face or
/// not both triangles, when c = x, and when an edge already joins x and c.
/// So on a tetrahedron every flip is refused.
///
/// Makes and deletes nothing. Writes, with d, d1, d2 the halves of F from
/// the edge on, and t, t1, t2 those of G:
///
/// 1. the ends: d ends at c, t ends at x (a winged edge now starts at x
///    and ends at c);
/// 2. F's cycle d → d2 → t1 → d, then G's cycle t → t2 → d1 → t;
/// 3. t1 moves to F, d1 to G;
/// 4. incident edges: a takes d2's edge and b takes t2's if theirs was the
///    flipped edge; F takes the flipped edge if its incident edge was d1's,
///    G if its was t1's.
pub fn flip_edge<M: Edit + ?Sized>(
    editor: &mut Editor<'_, M>,
    edge: EdgeRow,
) -> Result<Applied, Refusal> {
    run(editor, |patch| plan(patch, edge))
}

fn plan<M: Records + ?Sized>(patch: &mut Patch<'_, M>, edge: EdgeRow) -> Result<(), Refusal> {
    let d = patch.edge(edge.0)?;
    let name = EdgeName(patch.name(d));
    let operation = Operation::FlipEdge;
    let t = patch.twin(d)?;
    let (Some(f), Some(g)) = (patch.face_of(d)?, patch.face_of(t)?) else {
        return Err(Refusal::OnBoundary {
            operation,
            edge: name,
        });
    };
    if f == g {
        return Err(Refusal::SameFaceOnBothSides {
            operation,
            edge: name,
            face: f,
        });
    }
    for (face, dart) in [(f, d), (g, t)] {
        let edges = patch.cycle(dart)?.len();
        if edges != 3 {
            return Err(Refusal::NotTriangle {
                operation,
                face,
                edges,
            });
        }
    }
    let (d1, t1) = (patch.next(d)?, patch.next(t)?);
    let (d2, t2) = (patch.next(d1)?, patch.next(t1)?);
    let (a, b) = (patch.start(d)?, patch.end(d)?);
    let (c, x) = (patch.end(d1)?, patch.end(t1)?);
    let action = Action::Flipping(name);
    if c == x {
        return Err(Refusal::SharedCorner { action, vertex: c });
    }
    if let Some(existing) = patch.dart_between(x, c)? {
        return Err(Refusal::EdgeExists {
            action,
            a: x,
            b: c,
            existing: EdgeName(patch.name(existing)),
        });
    }
    let a_edge = patch.vertex_row(a)?;
    let b_edge = patch.vertex_row(b)?;
    let f_edge = patch.row(patch.face_dart(f)?);
    let g_edge = patch.row(patch.face_dart(g)?);

    patch.set_end(d, c);
    patch.set_end(t, x);
    patch.set_next(d, d2);
    patch.set_next(d2, t1);
    patch.set_next(t1, d);
    patch.set_next(t, t2);
    patch.set_next(t2, d1);
    patch.set_next(d1, t);
    patch.set_face(t1, Some(f));
    patch.set_face(d1, Some(g));
    if a_edge == Some(patch.row(t)) {
        patch.set_vertex_dart(a, d2);
    }
    if b_edge == Some(patch.row(d)) {
        patch.set_vertex_dart(b, t2);
    }
    if f_edge == patch.row(d1) {
        patch.set_face_dart(f, d);
    }
    if g_edge == patch.row(t1) {
        patch.set_face_dart(g, t);
    }
    Ok(())
}
