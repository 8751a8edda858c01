//! Vertex removal (dissolve): an interior vertex and its edges removed, the
//! faces around it merged into one.

use super::patch::{Dart, Patch};
use super::refusal::{Action, Refusal};
use super::{Applied, run};
use crate::mesh::edit::{Edit, Editor};
use crate::mesh::ids::VertexId;
use crate::schema::{Column, ElementRef, Records};

/// Removes interior vertex `v` of valence k with its k edges; the k faces
/// around it become one: V − 1, E − k, F − (k − 1).
///
/// The turn around `v` starts at the dart its incident edge names, h0,
/// and goes on clockwise seen from outside (h1 = the twin of the dart after
/// h0, and so on). Face f0 of h0 is kept; in it and in each other face fi,
/// the darts other than hi and the one after it make a path Pi from the
/// next neighbour round to ui, the start of hi. The merged face walks P0,
/// then Pk−1, …, P1.
///
/// Refused for a vertex on the boundary or without edges, when a face
/// around `v` passes it twice, and when the merged face would pass a vertex
/// twice, have fewer than three edges, or be glued along every edge to one
/// other face (every vertex of a tetrahedron).
///
/// Makes nothing. Deletes, in order: the k edges, from h0's on around `v`;
/// the faces but f0, in the same order; `v`. Writes:
///
/// 1. for each i from 0: the last dart of Pi → the first of Pi−1 (P0's last
///    → Pk−1's first);
/// 2. each dart of P1 … Pk−1 joins f0, in turn;
/// 3. incident edges: f0 takes the first dart of P0 if its incident edge
///    was deleted; each neighbour ui takes the last dart of Pi (which ends
///    there) if its was deleted.
pub fn remove_vertex<M: Edit + ?Sized>(
    editor: &mut Editor<'_, M>,
    vertex: VertexId,
) -> Result<Applied, Refusal> {
    run(editor, |patch| plan(patch, vertex))
}

fn plan<M: Records + ?Sized>(patch: &mut Patch<'_, M>, vertex: VertexId) -> Result<(), Refusal> {
    let v = patch.vertex(vertex.raw())?;
    let action = Action::Removing(v);
    let ring = patch.ring(v)?;
    if ring.is_empty() {
        return Err(Refusal::IsolatedVertex { vertex: v });
    }
    let mut faces = Vec::with_capacity(ring.len());
    for &h in &ring {
        let Some(face) = patch.face_of(h)? else {
            return Err(Refusal::BoundaryVertex { vertex: v });
        };
        if faces.contains(&face) {
            return Err(Refusal::PassesTwice { face, vertex: v });
        }
        faces.push(face);
    }
    let mut paths: Vec<Vec<Dart>> = Vec::with_capacity(ring.len());
    for &h in &ring {
        paths.push(patch.cycle(h)?.into_iter().skip(2).collect());
    }
    let merged: Vec<Dart> = paths
        .iter()
        .take(1)
        .chain(paths.iter().skip(1).rev())
        .flatten()
        .copied()
        .collect();
    let kept = faces[0];
    if merged.len() < 3 {
        return Err(Refusal::FaceTooSmall {
            action,
            face: kept,
            edges: merged.len(),
        });
    }
    let mut corners: Vec<VertexId> = Vec::with_capacity(merged.len());
    for &dart in &merged {
        let corner = patch.start(dart)?;
        if corners.contains(&corner) {
            return Err(Refusal::NotSimple {
                action,
                vertex: corner,
            });
        }
        corners.push(corner);
    }
    let beyond: Vec<_> = merged
        .iter()
        .map(|&dart| patch.face_of(patch.twin(dart)?))
        .collect::<Result<_, _>>()?;
    if let Some(&Some(other)) = beyond.first()
        && beyond.iter().all(|&face| face == Some(other))
        && patch.cycle(patch.face_dart(other)?)?.len() == merged.len()
    {
        return Err(Refusal::TooSmall {
            action,
            faces: [kept.min(other), kept.max(other)],
        });
    }

    let mut deleted_rows: Vec<ElementRef> = Vec::with_capacity(ring.len() * 2);
    for &h in &ring {
        deleted_rows.push(patch.row(h));
        deleted_rows.push(patch.row(patch.twin(h)?));
    }
    let kept_edge = patch.row(patch.face_dart(kept)?);
    let neighbour_edges: Vec<_> = ring
        .iter()
        .map(|&h| Ok((patch.start(h)?, patch.vertex_row(patch.start(h)?)?)))
        .collect::<Result<_, Refusal>>()?;
    let ends: Vec<(Dart, Dart)> = paths
        .iter()
        .map(|path| match (path.first(), path.last()) {
            (Some(&first), Some(&last)) => Ok((first, last)),
            _ => Err(Refusal::Broken {
                element: patch.element(v.into()),
                column: Column::IncidentEdge,
            }),
        })
        .collect::<Result<_, _>>()?;

    let k = ring.len();
    for i in 0..k {
        let (_, last) = ends[i];
        let (first, _) = ends[(i + k - 1) % k];
        patch.set_next(last, first);
    }
    for path in paths.iter().skip(1) {
        for &dart in path {
            patch.set_face(dart, Some(kept));
        }
    }
    if deleted_rows.contains(&kept_edge) {
        patch.set_face_dart(kept, ends[0].0);
    }
    for ((u, row), &(_, last)) in neighbour_edges.into_iter().zip(&ends) {
        if row.is_some_and(|row| deleted_rows.contains(&row)) {
            patch.set_vertex_dart(u, last);
        }
    }
    for &h in &ring {
        patch.delete_edge(h)?;
    }
    for &face in faces.iter().skip(1) {
        patch.delete_face(face);
    }
    patch.delete_vertex(v);
    Ok(())
}
