//! Edge split: a new vertex at the middle of an edge, joined to the third
//! corner of each triangle beside it so that triangles stay triangles.

use super::patch::Patch;
use super::refusal::{Action, EdgeName, Refusal};
use super::split_face::cut;
use super::{Applied, EdgeRow, run};
use crate::mesh::edit::{Edit, Editor};
use crate::schema::Records;

/// Splits the named edge a → b at m = (a + b) / 2; V + 1, E + 1 + k, F + k,
/// where k is the number of triangles beside the edge (0, 1 or 2). A face
/// of four or more edges just gains the new vertex.
///
/// Refused only when both sides are triangles with the same third corner
/// (they would share all three vertices, and m would be joined to that
/// corner twice).
///
/// Makes, in order: the vertex m; the edge from m to b; then for each side
/// that was a triangle (the first half's side first) the edge and face of
/// a face split. Deletes nothing. Writes, with d and t the named edge's
/// first and second half and g, gt the new edge's:
///
/// 1. m's position;
/// 2. the ends: d ends at m (so t starts there; a winged edge now ends at
///    m), g ends at b, gt at m;
/// 3. d → g → the dart that followed d, then the dart that preceded t →
///    gt → t;
/// 4. g joins d's face, gt joins t's;
/// 5. incident edges: m's is the named edge; b's becomes the new edge if it
///    was the named one;
/// 6. for each side that was a triangle (a, b, c): the face split of that
///    face between m and c, as [`super::split_face`] writes it.
pub fn split_edge<M: Edit + ?Sized>(
    editor: &mut Editor<'_, M>,
    edge: EdgeRow,
) -> Result<Applied, Refusal> {
    run(editor, |patch| plan(patch, edge))
}

fn plan<M: Records + ?Sized>(patch: &mut Patch<'_, M>, edge: EdgeRow) -> Result<(), Refusal> {
    let d = patch.edge(edge.0)?;
    let action = Action::Splitting(EdgeName(patch.name(d)));
    let t = patch.twin(d)?;
    let (a, b) = (patch.start(d)?, patch.end(d)?);
    // The third corner of each triangle beside the edge, with its face.
    let mut triangles = Vec::new();
    for side in [d, t] {
        if let Some(face) = patch.face_of(side)?
            && patch.cycle(side)?.len() == 3
        {
            triangles.push((face, patch.end(patch.next(side)?)?));
        }
    }
    if let [(_, c), (_, x)] = triangles[..]
        && c == x
    {
        return Err(Refusal::SharedCorner { action, vertex: c });
    }
    let b_edge = patch.vertex_row(b)?;
    let middle = (patch.position(a)? + patch.position(b)?) / 2.0;

    let m = patch.new_vertex(middle);
    let (g, gt) = patch.new_edge();
    patch.set_end(d, m);
    patch.set_end(g, b);
    patch.set_end(gt, m);
    let after = patch.next(d)?;
    patch.set_next(d, g);
    patch.set_next(g, after);
    // Read only now: on a dangling edge the dart before t is g.
    let before = patch.prev(t)?;
    patch.set_next(before, gt);
    patch.set_next(gt, t);
    patch.set_face(g, patch.face_of(d)?);
    patch.set_face(gt, patch.face_of(t)?);
    patch.set_vertex_dart(m, d);
    if b_edge == Some(patch.row(d)) {
        patch.set_vertex_dart(b, g);
    }
    for (face, corner) in triangles {
        cut(patch, face, m, corner, action)?;
    }
    Ok(())
}
