//! Face split (MEF, make edge and face): two corners of a face joined by a
//! new edge, which cuts the face in two.

use super::patch::{Dart, Patch};
use super::refusal::{Action, EdgeName, Refusal};
use super::{Applied, run};
use crate::mesh::edit::{Edit, Editor};
use crate::mesh::ids::{FaceId, VertexId};
use crate::schema::Records;

/// Joins vertices `u` and `w` of face `f` by a new edge, cutting `f` in two;
/// E + 1, F + 1. This is also the Euler operator MEF ([`super::mef`]).
///
/// With du and dw the darts of `f` ending at u and at w, the darts from u
/// round to w (after du, up to dw) make one part and those from w round to
/// u the other. `f` keeps the part its incident edge is on, so its incident
/// edge stays; the new face takes the other part. That keeps MEF followed by
/// KEF ([`super::kef`], which keeps the lower-numbered face) an exact undo.
///
/// Refused when u = w, when either vertex is not on `f` or `f` passes it
/// twice, when u and w follow each other around `f` (a two-edge face would
/// result; so a triangle cannot be split), and when an edge already joins
/// them.
///
/// Makes, in order: the edge (starting at u, ending at w; its first half
/// runs u → w), then the face. Deletes nothing. Writes, with k1 and k2 the
/// new edge's first and second half:
///
/// 1. the ends: k1 ends at w, k2 at u;
/// 2. du → k1 → the dart after dw, then dw → k2 → the dart after du;
/// 3. the faces: of the half of the new edge closing `f`'s part (k1 when
///    `f` keeps the part from w round to u, else k2), `f`; of the other
///    half, the new face; then of each dart of the part that moves, the new
///    face, in walking order;
/// 4. the new face's incident edge: the new edge.
pub fn split_face<M: Edit + ?Sized>(
    editor: &mut Editor<'_, M>,
    face: FaceId,
    u: VertexId,
    w: VertexId,
) -> Result<Applied, Refusal> {
    run(editor, |patch| {
        let f = patch.face(face.raw())?;
        let (u, w) = (patch.vertex(u.raw())?, patch.vertex(w.raw())?);
        cut(patch, f, u, w, Action::SplittingFace(f))
    })
}

/// The dart of `face`'s cycle `darts` that ends at `v`, refused if there
/// is none or more than one.
pub(super) fn corner<M: Records + ?Sized>(
    patch: &Patch<'_, M>,
    darts: &[Dart],
    face: FaceId,
    v: VertexId,
) -> Result<Dart, Refusal> {
    let mut found = None;
    for &dart in darts {
        if patch.end(dart)? == v {
            if found.is_some() {
                return Err(Refusal::PassesTwice { face, vertex: v });
            }
            found = Some(dart);
        }
    }
    found.ok_or(Refusal::NotOnFace { face, vertex: v })
}

/// Plans the cut of `f` between `u` and `w` described at [`split_face`];
/// `action` names what the refusals are about.
pub(super) fn cut<M: Records + ?Sized>(
    patch: &mut Patch<'_, M>,
    f: FaceId,
    u: VertexId,
    w: VertexId,
    action: Action,
) -> Result<(), Refusal> {
    if u == w {
        return Err(Refusal::SameVertex { vertex: u });
    }
    let incident = patch.face_dart(f)?;
    let darts = patch.cycle(incident)?;
    let du = corner(patch, &darts, f, u)?;
    let dw = corner(patch, &darts, f, w)?;
    let (after_u, after_w) = (patch.next(du)?, patch.next(dw)?);
    if patch.end(after_u)? == w || patch.end(after_w)? == u {
        return Err(Refusal::AdjacentOnFace {
            face: f,
            a: u,
            b: w,
        });
    }
    if let Some(existing) = patch.dart_between(u, w)? {
        return Err(Refusal::EdgeExists {
            action,
            a: u,
            b: w,
            existing: EdgeName(patch.name(existing)),
        });
    }
    // The part from u round to w, and the part from w round to u.
    let start = darts.iter().position(|&dart| dart == after_u).unwrap_or(0);
    let mut u_to_w = Vec::new();
    let mut w_to_u = Vec::new();
    let mut into_first = true;
    for i in 0..darts.len() {
        let dart = darts[(start + i) % darts.len()];
        if into_first {
            u_to_w.push(dart);
        } else {
            w_to_u.push(dart);
        }
        if dart == dw {
            into_first = false;
        }
    }
    let keeps_u_to_w = u_to_w.contains(&incident);

    let (k1, k2) = patch.new_edge();
    let g = patch.new_face();
    patch.set_end(k1, w);
    patch.set_end(k2, u);
    patch.set_next(du, k1);
    patch.set_next(k1, after_w);
    patch.set_next(dw, k2);
    patch.set_next(k2, after_u);
    let (kept, moved, moving) = if keeps_u_to_w {
        (k2, k1, w_to_u)
    } else {
        (k1, k2, u_to_w)
    };
    patch.set_face(kept, Some(f));
    patch.set_face(moved, Some(g));
    for dart in moving {
        patch.set_face(dart, Some(g));
    }
    patch.set_face_dart(g, moved);
    Ok(())
}
