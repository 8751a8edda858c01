//! Splitting vertices where separate fans of faces meet, as CGAL's
//! `duplicate_non_manifold_vertices` does, so scanned and hole-punched meshes
//! (two holes touching at a corner, two cones sharing a tip) still load.
//!
//! Each such vertex becomes one vertex per fan at the same position, which
//! makes the surface manifold without changing a face or an edge. Edges with
//! three or more faces and inconsistent orientation are not repaired: they
//! are caught before fans are looked at, and still refused.

use super::{General, Layout, NONE};
use crate::mesh::error::{BuildError, BuildWarning};
use crate::mesh::ids::VertexId;
use crate::mesh::polygons::Polygons;

/// Runs `build`, and only if it found a vertex joining separate fans, runs it
/// again on [`split_non_manifold_vertices`]'s polygons, with a warning per
/// split vertex first (the app shows the first warning). A mesh without such
/// a vertex pays nothing but this match.
pub(crate) fn build_splitting_fans<M>(
    polygons: &Polygons,
    build: impl Fn(&Polygons) -> Result<(M, Vec<BuildWarning>), BuildError>,
) -> Result<(M, Vec<BuildWarning>), BuildError> {
    match build(polygons) {
        Err(error @ BuildError::NonManifoldVertex { .. }) => {
            let Some((split, mut warnings)) = split_non_manifold_vertices(polygons) else {
                return Err(error);
            };
            // The split keeps every face and edge, so only the larger vertex
            // count can make the second build fail; any other refusal would
            // name copies the file does not have, so the original one stands.
            let (mesh, kept) = build(&split).map_err(|again| match again {
                BuildError::TooLarge { .. } => again,
                _ => error,
            })?;
            warnings.extend(kept);
            Ok((mesh, warnings))
        }
        built => built,
    }
}

/// The polygons with every vertex that joins several fans of faces split into
/// one vertex per fan, and a [`BuildWarning::SplitVertex`] per split vertex;
/// `None` when no vertex needs it (or the input has indices out of range,
/// which the build refuses anyway).
///
/// Corners at a vertex `v` are in one fan when an edge at `v` joins their
/// faces: the corner of face `u→v→b` and the corner where another face leaves
/// `v` towards `u` share the edge `u–v`. The fan holding `v`'s lowest corner
/// keeps `v`; the others get new ids after the existing vertices, in order of
/// the original vertex, then of each fan's lowest corner. Faces keep their
/// numbers, sizes and source lines.
pub(crate) fn split_non_manifold_vertices(
    polygons: &Polygons,
) -> Option<(Polygons, Vec<BuildWarning>)> {
    let indices = polygons.indices();
    let vertex_count = polygons.vertex_count();
    if indices.iter().any(|&v| v as usize >= vertex_count) {
        return None;
    }
    let layout = General::new(polygons);
    let corners = u32::try_from(indices.len()).ok()?;

    // The corners at each vertex, sorted by where their half-edge ends, so the
    // corner leaving v towards u is a binary search away.
    let mut start = vec![0usize; vertex_count + 1];
    for &v in indices {
        start[v as usize + 1] += 1;
    }
    for v in 1..=vertex_count {
        start[v] += start[v - 1];
    }
    let mut cursor = start.clone();
    let mut around = vec![(0u32, 0u32); indices.len()];
    for (c, &v) in (0..corners).zip(indices) {
        around[cursor[v as usize]] = (indices[layout.next(c) as usize], c);
        cursor[v as usize] += 1;
    }
    drop(cursor);
    for window in start.windows(2) {
        if let &[from, to] = window {
            around[from..to].sort_unstable();
        }
    }

    // Union the corners of each fan; the root of a set is its lowest corner.
    let mut parent: Vec<u32> = (0..corners).collect();
    for (c, &v) in (0..corners).zip(indices) {
        let u = indices[layout.prev(c) as usize];
        let leaving = &around[start[v as usize]..start[v as usize + 1]];
        if let Ok(i) = leaving.binary_search_by_key(&u, |&(end, _)| end) {
            let (a, b) = (root(&mut parent, c), root(&mut parent, leaving[i].1));
            parent[a.max(b) as usize] = a.min(b);
        }
    }
    drop(around);
    drop(start);

    // Number the fans at each vertex in order of their lowest corner: roots
    // come before the rest of their set, so one pass in corner order does it.
    let mut fans = vec![0u32; vertex_count];
    let mut fan_of_root = vec![NONE; indices.len()];
    for (c, &v) in (0..corners).zip(indices) {
        if root(&mut parent, c) == c {
            fan_of_root[c as usize] = fans[v as usize];
            fans[v as usize] += 1;
        }
    }

    // Give the extra fans their ids, vertex by vertex.
    let mut first_copy = vec![NONE; vertex_count];
    let mut next_id = u32::try_from(vertex_count).ok()?;
    let mut warnings = Vec::new();
    for (v, &count) in (0u32..).zip(&fans) {
        if count > 1 {
            let end = next_id.checked_add(count - 1)?;
            first_copy[v as usize] = next_id;
            warnings.push(BuildWarning::SplitVertex {
                vertex: VertexId::new(v),
                copies: (next_id..end).map(VertexId::new).collect(),
            });
            next_id = end;
        }
    }
    if warnings.is_empty() {
        return None;
    }

    let mut split = polygons.clone();
    for warning in &warnings {
        if let BuildWarning::SplitVertex { vertex, copies } = warning {
            let position = polygons.positions()[vertex.index()];
            for _ in copies {
                split.push_vertex(position);
            }
        }
    }
    for (c, slot) in (0..corners).zip(split.indices_mut()) {
        let fan = fan_of_root[root(&mut parent, c) as usize];
        if fan > 0 {
            *slot = first_copy[*slot as usize] + fan - 1;
        }
    }
    Some((split, warnings))
}

/// The root of corner `c`'s set, halving the path on the way.
fn root(parent: &mut [u32], mut c: u32) -> u32 {
    while parent[c as usize] != c {
        let grandparent = parent[parent[c as usize] as usize];
        parent[c as usize] = grandparent;
        c = grandparent;
    }
    c
}

#[cfg(test)]
mod tests {
    use glam::Vec3;

    use super::*;

    fn split(vertices: usize, faces: &[&[u32]]) -> Option<(Vec<Vec<u32>>, usize, Vec<String>)> {
        let polygons = Polygons::from_faces(vec![Vec3::ONE; vertices], faces);
        let (split, warnings) = split_non_manifold_vertices(&polygons)?;
        Some((
            split.faces().map(<[u32]>::to_vec).collect(),
            split.vertex_count(),
            warnings.iter().map(ToString::to_string).collect(),
        ))
    }

    #[test]
    fn a_single_fan_is_left_alone() {
        // A closed fan of four triangles around vertex 0, and an open one.
        assert_eq!(
            split(5, &[&[0, 1, 2], &[0, 2, 3], &[0, 3, 4], &[0, 4, 1]]),
            None
        );
        assert_eq!(split(4, &[&[0, 1, 2], &[0, 2, 3]]), None);
    }

    #[test]
    fn each_extra_fan_gets_the_next_id() {
        // Vertex 0 in three open fans; the first and last faces share the
        // edge 0–2, so they are one fan and keep vertex 0.
        let (faces, vertices, warnings) =
            split(8, &[&[1, 0, 2], &[0, 3, 4], &[5, 6, 0], &[2, 0, 7]]).expect("split");
        assert_eq!(
            faces,
            [vec![1, 0, 2], vec![8, 3, 4], vec![5, 6, 9], vec![2, 0, 7]]
        );
        assert_eq!(vertices, 10);
        assert_eq!(
            warnings,
            ["vertex 0 joined 3 fans of faces; split into 0, 8 and 9"]
        );
    }

    #[test]
    fn out_of_range_indices_are_left_to_the_build() {
        assert_eq!(split(3, &[&[0, 1, 2], &[0, 3, 4]]), None);
    }
}
