//! Property tests on random valid meshes (tori and subdivided cubes, randomly
//! triangulated, relabelled, reordered, with faces removed to make
//! boundaries; fans glued at a vertex) and on random garbage: the builder
//! never panics, vertices joining several fans are split, `validate()` finds
//! nothing on what it builds, the conversions round-trip, the Euler
//! characteristic agrees with V − E + F, and every iterator visits exactly
//! what a brute-force search finds.

use std::collections::{BTreeMap, BTreeSet, HashMap};

use edgewise_core::mesh::{
    BuildError, BuildWarning, EdgeId, FaceId, HalfEdgeId, HalfEdgeMesh, Navigation, Polygons,
    VertexId, WingedEdgeMesh, generate,
};
use glam::Vec3;
use proptest::prelude::*;

/// Random decisions drawn from a byte string proptest can shrink.
struct Choices<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Choices<'_> {
    fn next(&mut self) -> u8 {
        let byte = self
            .bytes
            .get(self.at % self.bytes.len().max(1))
            .copied()
            .unwrap_or(0);
        self.at += 1;
        byte.wrapping_add((self.at / self.bytes.len().max(1)) as u8)
    }
    fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (usize::from(self.next()) * 256 + usize::from(self.next())) % n
        }
    }
}

/// A closed surface to start from, faces counter-clockwise seen from outside.
#[derive(Clone, Copy, Debug)]
enum Base {
    /// The benchmark torus of triangles.
    Torus(u32, u32),
    /// A torus of quads, each kept or split along a random diagonal.
    QuadTorus(u32, u32),
    /// A cube with each side divided into n × n quads, each kept or split.
    SubdividedCube(u32),
}

fn split_or_keep(quad: [u32; 4], choices: &mut Choices<'_>, faces: &mut Vec<Vec<u32>>) {
    let [a, b, c, d] = quad;
    match choices.next() % 3 {
        0 => faces.push(vec![a, b, c, d]),
        1 => faces.extend([vec![a, b, c], vec![a, c, d]]),
        _ => faces.extend([vec![a, b, d], vec![b, c, d]]),
    }
}

fn base_mesh(base: Base, choices: &mut Choices<'_>) -> (Vec<Vec3>, Vec<Vec<u32>>) {
    match base {
        Base::Torus(nu, nv) => {
            let torus = generate::torus(nu, nv);
            (
                torus.positions().to_vec(),
                torus.faces().map(<[u32]>::to_vec).collect(),
            )
        }
        Base::QuadTorus(nu, nv) => {
            let positions = generate::torus(nu, nv).positions().to_vec();
            let index = |i: u32, j: u32| (j % nv) * nu + (i % nu);
            let mut faces = Vec::new();
            for j in 0..nv {
                for i in 0..nu {
                    split_or_keep(
                        [
                            index(i, j),
                            index(i + 1, j),
                            index(i + 1, j + 1),
                            index(i, j + 1),
                        ],
                        choices,
                        &mut faces,
                    );
                }
            }
            (positions, faces)
        }
        Base::SubdividedCube(n) => {
            let mut ids: HashMap<[u32; 3], u32> = HashMap::new();
            let mut positions = Vec::new();
            let mut id = |p: [u32; 3], positions: &mut Vec<Vec3>| {
                *ids.entry(p).or_insert_with(|| {
                    positions.push(Vec3::new(p[0] as f32, p[1] as f32, p[2] as f32) / n as f32);
                    positions.len() as u32 - 1
                })
            };
            let mut faces = Vec::new();
            for axis in 0..3 {
                let (b, c) = ((axis + 1) % 3, (axis + 2) % 3);
                for side in [0, n] {
                    for i in 0..n {
                        for j in 0..n {
                            let mut corner = |di: u32, dj: u32| {
                                let mut p = [0; 3];
                                p[axis] = side;
                                p[b] = i + di;
                                p[c] = j + dj;
                                id(p, &mut positions)
                            };
                            let mut quad = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)];
                            if side == 0 {
                                quad.reverse();
                            }
                            split_or_keep(quad, choices, &mut faces);
                        }
                    }
                }
            }
            (positions, faces)
        }
    }
}

/// The base mesh with vertices relabelled, faces shuffled and rotated, some
/// faces removed, and positions perturbed.
fn random_mesh(base: Base, remove_per_256: u8, bytes: &[u8]) -> Polygons {
    let mut choices = Choices { bytes, at: 0 };
    let (positions, mut faces) = base_mesh(base, &mut choices);
    let n = positions.len();
    let mut relabel: Vec<u32> = (0..n as u32).collect();
    for i in (1..n).rev() {
        relabel.swap(i, choices.below(i + 1));
    }
    let mut new_positions = vec![Vec3::ZERO; n];
    for (old, &new) in relabel.iter().enumerate() {
        let jitter = Vec3::new(f32::from(choices.next()), f32::from(choices.next()), 0.0) * 1e-4;
        new_positions[new as usize] = positions[old] + jitter;
    }
    for i in (1..faces.len()).rev() {
        faces.swap(i, choices.below(i + 1));
    }
    faces.retain(|_| choices.next() >= remove_per_256);
    for face in &mut faces {
        let turn = choices.below(face.len());
        face.rotate_left(turn);
        for v in face.iter_mut() {
            *v = relabel[*v as usize];
        }
    }
    Polygons::from_faces(new_positions, faces)
}

/// What the builds must make of `polygons`, found by brute force apart from
/// the builder: each vertex whose corners fall into separate fans (corners
/// whose faces share an edge at the vertex are in one fan) split, the fan
/// with the first corner keeping the vertex, copies numbered after the input's
/// by vertex, then by each fan's first corner. Removing faces from a closed
/// mesh leaves such vertices where two holes touch.
fn split_by_brute_force(polygons: &Polygons) -> (Polygons, Vec<BuildWarning>) {
    // Per vertex, its corners in order: (face, position in face, neighbours).
    let mut corners: Vec<Vec<(usize, usize, [u32; 2])>> = vec![Vec::new(); polygons.vertex_count()];
    for (f, face) in polygons.faces().enumerate() {
        for (k, &v) in face.iter().enumerate() {
            let prev = face[(k + face.len() - 1) % face.len()];
            let next = face[(k + 1) % face.len()];
            corners[v as usize].push((f, k, [prev, next]));
        }
    }
    let mut faces: Vec<Vec<u32>> = polygons.faces().map(<[u32]>::to_vec).collect();
    let mut positions = polygons.positions().to_vec();
    let mut warnings = Vec::new();
    for (v, around) in corners.iter().enumerate() {
        // Fan labels, merged until no shared edge joins two labels.
        let mut label: Vec<usize> = (0..around.len()).collect();
        let mut changed = true;
        while changed {
            changed = false;
            for a in 0..around.len() {
                for b in 0..around.len() {
                    let shared = around[a].2.iter().any(|u| around[b].2.contains(u));
                    if shared && label[b] > label[a] {
                        label[b] = label[a];
                        changed = true;
                    }
                }
            }
        }
        // Each label ends as its fan's first corner, so sorted labels are
        // the fans in order.
        let fans: Vec<usize> = label
            .iter()
            .copied()
            .collect::<BTreeSet<_>>()
            .into_iter()
            .collect();
        if fans.len() < 2 {
            continue;
        }
        let copies: Vec<u32> = (1..fans.len())
            .map(|_| {
                positions.push(positions[v]);
                positions.len() as u32 - 1
            })
            .collect();
        for (&(f, k, _), l) in around.iter().zip(&label) {
            let fan = fans.iter().position(|x| x == l).expect("a fan");
            if fan > 0 {
                faces[f][k] = copies[fan - 1];
            }
        }
        warnings.push(BuildWarning::SplitVertex {
            vertex: VertexId::new(v as u32),
            copies: copies.into_iter().map(VertexId::new).collect(),
        });
    }
    (Polygons::from_faces(positions, faces), warnings)
}

/// Fans of faces glued at shared hub vertices: `hubs[i]` lists hub `i`'s fans
/// as (faces, closed), a closed fan going all the way round its hub. Faces
/// have three to five corners, vertices are relabelled and faces shuffled
/// and rotated. Returns the polygons and each hub's vertex and fan count.
fn glued_fans(hubs: &[Vec<(usize, bool)>], bytes: &[u8]) -> (Polygons, Vec<(u32, usize)>) {
    let mut choices = Choices { bytes, at: 0 };
    let mut count = hubs.len() as u32;
    let mut fresh = || {
        count += 1;
        count - 1
    };
    let mut faces: Vec<Vec<u32>> = Vec::new();
    for (hub, fans) in (0u32..).zip(hubs) {
        for &(size, closed) in fans {
            let closed = closed && size >= 3;
            let rim: Vec<u32> = (0..size + usize::from(!closed)).map(|_| fresh()).collect();
            for i in 0..size {
                let mut face = vec![hub, rim[i]];
                face.extend((0..choices.below(3)).map(|_| fresh()));
                face.push(rim[(i + 1) % rim.len()]);
                faces.push(face);
            }
        }
    }
    let n = count as usize;
    let mut relabel: Vec<u32> = (0..count).collect();
    for i in (1..n).rev() {
        relabel.swap(i, choices.below(i + 1));
    }
    for i in (1..faces.len()).rev() {
        faces.swap(i, choices.below(i + 1));
    }
    for face in &mut faces {
        let turn = choices.below(face.len());
        face.rotate_left(turn);
        for v in face.iter_mut() {
            *v = relabel[*v as usize];
        }
    }
    let positions = (0..n)
        .map(|i| Vec3::new(i as f32, (i * i % 11) as f32, (i % 5) as f32))
        .collect();
    let hubs = (0..hubs.len())
        .map(|hub| (relabel[hub], hubs[hub].len()))
        .collect();
    (Polygons::from_faces(positions, faces), hubs)
}

fn base_strategy() -> impl Strategy<Value = Base> {
    prop_oneof![
        (3u32..9, 3u32..7).prop_map(|(nu, nv)| Base::Torus(nu, nv)),
        (3u32..8, 3u32..6).prop_map(|(nu, nv)| Base::QuadTorus(nu, nv)),
        (1u32..5).prop_map(Base::SubdividedCube),
    ]
}

fn sorted<T: Ord>(items: impl IntoIterator<Item = T>) -> Vec<T> {
    let mut items: Vec<T> = items.into_iter().collect();
    items.sort();
    items
}

fn is_rotation<T: PartialEq + Copy>(a: &[T], b: &[T]) -> bool {
    a.len() == b.len()
        && (a.is_empty()
            || (0..a.len()).any(|k| a.iter().cycle().skip(k).zip(b).all(|(x, y)| x == y)))
}

/// Everything a brute-force pass over the polygon list tells.
struct BruteForce {
    faces_at: Vec<BTreeSet<u32>>,
    neighbours: Vec<BTreeSet<u32>>,
    /// Faces using each undirected edge.
    edge_faces: BTreeMap<(u32, u32), Vec<u32>>,
}

impl BruteForce {
    fn new(polygons: &Polygons) -> Self {
        let n = polygons.vertex_count();
        let mut faces_at = vec![BTreeSet::new(); n];
        let mut neighbours = vec![BTreeSet::new(); n];
        let mut edge_faces: BTreeMap<(u32, u32), Vec<u32>> = BTreeMap::new();
        for (f, face) in polygons.faces().enumerate() {
            for (k, &a) in face.iter().enumerate() {
                let b = face[(k + 1) % face.len()];
                faces_at[a as usize].insert(f as u32);
                neighbours[a as usize].insert(b);
                neighbours[b as usize].insert(a);
                edge_faces
                    .entry((a.min(b), a.max(b)))
                    .or_default()
                    .push(f as u32);
            }
        }
        Self {
            faces_at,
            neighbours,
            edge_faces,
        }
    }

    fn face_neighbours(&self, polygons: &Polygons, f: usize) -> Vec<u32> {
        let face = polygons.face(f).expect("face");
        sorted(face.iter().enumerate().flat_map(|(k, &a)| {
            let b = face[(k + 1) % face.len()];
            self.edge_faces[&(a.min(b), a.max(b))]
                .iter()
                .copied()
                .filter(move |&g| g != f as u32)
        }))
    }

    /// Connected components (vertices joined by edges) and boundary loops
    /// (cycles of edges used once; at a manifold vertex they cannot cross).
    fn components_and_loops(&self, vertex_count: usize) -> (usize, usize) {
        fn root(parent: &mut [usize], mut v: usize) -> usize {
            while parent[v] != v {
                parent[v] = parent[parent[v]];
                v = parent[v];
            }
            v
        }
        let mut parent: Vec<usize> = (0..vertex_count).collect();
        let mut boundary_parent: Vec<usize> = (0..vertex_count).collect();
        let mut on_boundary = vec![false; vertex_count];
        for (&(a, b), faces) in &self.edge_faces {
            let (ra, rb) = (root(&mut parent, a as usize), root(&mut parent, b as usize));
            parent[ra] = rb;
            if faces.len() == 1 {
                on_boundary[a as usize] = true;
                on_boundary[b as usize] = true;
                let (ra, rb) = (
                    root(&mut boundary_parent, a as usize),
                    root(&mut boundary_parent, b as usize),
                );
                boundary_parent[ra] = rb;
            }
        }
        let components = (0..vertex_count)
            .filter(|&v| root(&mut parent, v) == v)
            .count();
        let loops = (0..vertex_count)
            .filter(|&v| on_boundary[v] && root(&mut boundary_parent, v) == v)
            .count();
        (components, loops)
    }
}

/// Builds both structures and checks every property, against the polygons
/// with non-manifold vertices split by brute force.
fn check_all(input: &Polygons) {
    let half = HalfEdgeMesh::build(input);
    let winged = WingedEdgeMesh::build(input);
    let ((he, he_warnings), (we, we_warnings)) = match (half, winged) {
        (Ok(half), Ok(winged)) => (half, winged),
        (a, b) => panic!("unexpected refusal: {a:?} / {b:?}"),
    };
    let (split, splits) = split_by_brute_force(input);
    let polygons = &split;
    let brute = BruteForce::new(polygons);
    let unused: Vec<usize> = (0..polygons.vertex_count())
        .filter(|&v| brute.faces_at[v].is_empty())
        .collect();
    assert_eq!(he_warnings.get(..splits.len()), Some(&splits[..]));
    assert_eq!(he_warnings.len(), splits.len() + unused.len());
    assert_eq!(he_warnings, we_warnings);
    assert_eq!(
        he.vertex_count(),
        input.vertex_count()
            + splits
                .iter()
                .map(|w| match w {
                    BuildWarning::SplitVertex { copies, .. } => copies.len(),
                    BuildWarning::UnusedVertex { .. } => 0,
                })
                .sum::<usize>()
    );

    // validate() finds nothing.
    assert_eq!(he.validate(), vec![]);
    assert_eq!(we.validate(), vec![]);

    // Round trips.
    assert_eq!(&he.to_polygons(), polygons);
    assert_eq!(he.to_winged_edge().expect("he → we"), we);
    let he_from_we = we.to_half_edge().expect("we → he");
    assert_eq!(he_from_we.to_winged_edge().expect("he → we"), we);
    assert_eq!(
        he_from_we
            .to_winged_edge()
            .expect("he → we")
            .to_half_edge()
            .expect("we → he"),
        he_from_we
    );
    assert_eq!(
        HalfEdgeMesh::build(&he_from_we.to_polygons())
            .expect("rebuild")
            .0,
        he_from_we
    );
    let we_polygons = we.to_polygons();
    assert_eq!(WingedEdgeMesh::build(&we_polygons).expect("rebuild").0, we);
    assert_eq!(we_polygons.positions(), polygons.positions());
    for (ours, theirs) in we_polygons.faces().zip(polygons.faces()) {
        assert!(
            is_rotation(ours, theirs),
            "{ours:?} is not {theirs:?} rotated"
        );
    }
    let (_, correspondence) = he.to_winged_edge_with_correspondence().expect("convert");
    for (e, edge) in we.edges().iter().enumerate() {
        let (forward, backward) = correspondence
            .half_edges(EdgeId::new(e as u32))
            .expect("pair");
        assert_eq!(
            he.half_edge(forward).map(|h| h.end_vertex),
            Some(edge.end_vertex)
        );
        assert_eq!(
            he.half_edge(backward).map(|h| h.end_vertex),
            Some(edge.start_vertex)
        );
        assert_eq!(correspondence.edge(backward), Some(EdgeId::new(e as u32)));
    }

    // Statistics against V − E + F and a brute-force count.
    let stats = he.stats();
    assert_eq!(we.stats(), stats);
    let (v, e, f) = (
        polygons.vertex_count(),
        brute.edge_faces.len(),
        polygons.face_count(),
    );
    assert_eq!(
        (stats.vertices, stats.edges, stats.faces, stats.half_edges),
        (v, e, f, 2 * e)
    );
    assert_eq!(stats.euler_characteristic, v as i64 - e as i64 + f as i64);
    assert_eq!(
        stats
            .components
            .iter()
            .map(|c| c.euler_characteristic)
            .sum::<i64>(),
        stats.euler_characteristic
    );
    let (components, loops) = brute.components_and_loops(v);
    assert_eq!(
        (stats.connected_components(), stats.boundary_loops),
        (components, loops)
    );
    for component in &stats.components {
        if component.faces > 0 && component.boundary_loops == 0 {
            assert_eq!(
                component.genus.map(|g| 2 - 2 * g as i64),
                Some(component.euler_characteristic)
            );
        }
    }

    // Iterators against brute force, around every vertex...
    for vertex in 0..v {
        let id = VertexId::new(vertex as u32);
        let ending_here = (0..he.half_edge_count() as u32)
            .map(HalfEdgeId::new)
            .filter(|&h| he.half_edges()[h.index()].end_vertex == id);
        assert_eq!(sorted(he.around_vertex(id)), sorted(ending_here));
        let touching = (0..we.edge_count() as u32)
            .map(EdgeId::new)
            .filter(|&x| we.edges()[x.index()].other_vertex(id).is_some());
        assert_eq!(sorted(we.around_vertex(id)), sorted(touching.clone()));
        // Incident edges are the lowest-numbered candidates.
        assert_eq!(we.vertices()[vertex].incident_edge, touching.min());
        assert_eq!(
            he.vertices()[vertex].incident_edge,
            (0..he.half_edge_count() as u32)
                .map(HalfEdgeId::new)
                .find(|&h| he.half_edges()[h.index()].end_vertex == id)
        );
        let faces: Vec<u32> = brute.faces_at[vertex].iter().copied().collect();
        assert_eq!(sorted(he.vertex_faces(id).map(FaceId::raw)), faces);
        assert_eq!(sorted(we.vertex_faces(id).map(FaceId::raw)), faces);
        let neighbours: Vec<u32> = brute.neighbours[vertex].iter().copied().collect();
        let he_order: Vec<u32> = he.vertex_neighbours(id).map(VertexId::raw).collect();
        let we_order: Vec<u32> = we.vertex_neighbours(id).map(VertexId::raw).collect();
        assert_eq!(sorted(he_order.iter().copied()), neighbours);
        assert!(
            is_rotation(&he_order, &we_order),
            "{he_order:?} / {we_order:?}"
        );
    }
    // ...and around every face.
    for face in 0..f {
        let id = FaceId::new(face as u32);
        let listed: Vec<u32> = polygons.face(face).expect("face").to_vec();
        assert_eq!(
            he.face_vertices(id).map(VertexId::raw).collect::<Vec<_>>(),
            listed
        );
        assert!(is_rotation(
            &we.face_vertices(id).map(VertexId::raw).collect::<Vec<_>>(),
            &listed
        ));
        let in_face = (0..he.half_edge_count() as u32)
            .map(HalfEdgeId::new)
            .filter(|&h| he.half_edges()[h.index()].face == Some(id));
        assert_eq!(sorted(he.around_face(id)), sorted(in_face));
        let bordering = we
            .edges()
            .iter()
            .enumerate()
            .filter(|(_, x)| x.left_face == Some(id) || x.right_face == Some(id));
        assert_eq!(
            sorted(we.around_face(id).map(|(x, _)| x)),
            sorted(bordering.map(|(x, _)| EdgeId::new(x as u32)))
        );
        let across = brute.face_neighbours(polygons, face);
        assert_eq!(sorted(he.face_neighbours(id).map(FaceId::raw)), across);
        assert_eq!(sorted(we.face_neighbours(id).map(FaceId::raw)), across);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 40, ..ProptestConfig::default() })]

    #[test]
    fn closed_meshes_keep_every_property(base in base_strategy(), bytes in prop::collection::vec(any::<u8>(), 1..64)) {
        let polygons = random_mesh(base, 0, &bytes);
        check_all(&polygons);
        let stats = HalfEdgeMesh::build(&polygons).expect("closed").0.stats();
        let expected_genus = match base { Base::SubdividedCube(_) => 0, _ => 1 };
        prop_assert_eq!(stats.components.len(), 1);
        prop_assert_eq!(stats.components[0].genus, Some(expected_genus));
    }

    #[test]
    fn meshes_with_holes_keep_every_property(
        base in base_strategy(),
        remove in 1u8..100,
        bytes in prop::collection::vec(any::<u8>(), 1..64),
    ) {
        // Holes that touch leave vertices joining several fans; check_all
        // expects them split.
        check_all(&random_mesh(base, remove, &bytes));
    }

    /// Several fans glued at a vertex load: one vertex per fan, and V grows
    /// by (fans − 1) for each such vertex.
    #[test]
    fn fans_glued_at_a_vertex_are_split(
        hubs in prop::collection::vec(prop::collection::vec((1usize..6, any::<bool>()), 1..5), 1..4),
        bytes in prop::collection::vec(any::<u8>(), 1..64),
    ) {
        let (polygons, hubs) = glued_fans(&hubs, &bytes);
        check_all(&polygons);
        let (mesh, warnings) = HalfEdgeMesh::build(&polygons).expect("builds");
        let extra: usize = hubs.iter().map(|&(_, fans)| fans - 1).sum();
        prop_assert_eq!(mesh.vertex_count(), polygons.vertex_count() + extra);
        let mut split: Vec<(u32, usize)> = warnings
            .iter()
            .filter_map(|w| match w {
                BuildWarning::SplitVertex { vertex, copies } => Some((vertex.raw(), copies.len() + 1)),
                BuildWarning::UnusedVertex { .. } => None,
            })
            .collect();
        split.sort_unstable();
        let mut expected: Vec<(u32, usize)> = hubs.into_iter().filter(|&(_, fans)| fans > 1).collect();
        expected.sort_unstable();
        prop_assert_eq!(split, expected);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// Random polygon soup over six vertices (mostly faces of distinct
    /// vertices, sometimes anything): never a panic, both builders agree, and
    /// whatever is accepted is sound.
    #[test]
    fn random_polygon_soup_never_panics(
        vertices in prop_oneof![4 => 6usize..8, 1 => 0usize..6],
        faces in prop::collection::vec(
            prop_oneof![
                4 => prop::sample::subsequence(vec![0u32, 1, 2, 3, 4, 5], 3..=4).prop_shuffle(),
                1 => prop::collection::vec(0u32..9, 0..6),
            ],
            0..7,
        ),
    ) {
        let polygons = Polygons::from_faces(vec![Vec3::ONE; vertices], &faces);
        let half = HalfEdgeMesh::build(&polygons);
        let winged = WingedEdgeMesh::build(&polygons);
        match (&half, &winged) {
            (Ok(_), Ok(_)) => {
                check_all(&polygons);
            }
            (Err(a), Err(b)) => {
                prop_assert_eq!(a, b);
                prop_assert!(!a.to_string().is_empty());
                // Vertices joining several fans are split, never refused.
                prop_assert!(!matches!(a, BuildError::NonManifoldVertex { .. }), "{}", a);
            }
            _ => prop_assert!(false, "the builders disagree: {:?} / {:?}", half, winged),
        }
    }

    /// Valid tables with random fields overwritten: validate, stats,
    /// navigation and export never panic or hang, and whatever `validate()`
    /// accepts converts and round-trips.
    #[test]
    fn mutated_tables_never_panic(
        base in 0usize..3,
        mutations in prop::collection::vec((any::<u8>(), 0u8..8, 0u32..14), 0..3),
    ) {
        let positions = (0..8).map(|i| Vec3::new((i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32)).collect();
        let polygons = match base {
            0 => Polygons::from_triangles(positions, &[[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]),
            1 => Polygons::from_triangles(positions, &[[0, 1, 3], [0, 3, 2], [4, 5, 6]]),
            _ => Polygons::from_faces(positions, [&[0u32, 2, 3, 1][..], &[0, 1, 5, 4], &[1, 3, 7, 5]]),
        };
        let (he, _) = HalfEdgeMesh::build(&polygons).expect("valid base");
        let (we, _) = WingedEdgeMesh::build(&polygons).expect("valid base");

        let (mut vertices, mut faces, mut rows) = he.into_raw_parts();
        for &(row, field, value) in &mutations {
            let id = HalfEdgeId::new(value);
            let row = usize::from(row);
            let (v, f, h) = (row % vertices.len(), row % faces.len(), row % rows.len());
            match field {
                0 => vertices[v].incident_edge = (value < 13).then_some(id),
                1 => faces[f].incident_edge = id,
                2 => rows[h].end_vertex = VertexId::new(value),
                3 => rows[h].face = (value < 5).then_some(FaceId::new(value)),
                4 => rows[h].pair_edge = id,
                _ => rows[h].successor_edge = id,
            }
        }
        let count = rows.len();
        let mesh = HalfEdgeMesh::from_raw_parts(vertices, faces, rows);
        let issues = mesh.validate();
        let _ = mesh.stats();
        let _ = mesh.to_polygons();
        for v in 0..9 {
            prop_assert!(mesh.around_vertex(VertexId::new(v)).count() <= count);
            let _ = mesh.vertex_neighbours(VertexId::new(v)).count();
            let _ = mesh.vertex_faces(VertexId::new(v)).count();
        }
        for f in 0..5 {
            prop_assert!(mesh.around_face(FaceId::new(f)).count() <= count);
            let _ = mesh.face_neighbours(FaceId::new(f)).count();
        }
        for h in 0..count as u32 + 2 {
            let _ = (mesh.start_vertex(HalfEdgeId::new(h)), mesh.predecessor_edge(HalfEdgeId::new(h)));
        }
        match mesh.to_winged_edge() {
            Ok(winged) => {
                prop_assert!(issues.is_empty());
                prop_assert_eq!(winged.validate(), vec![]);
                prop_assert_eq!(winged.to_half_edge().expect("valid").to_winged_edge().expect("valid"), winged);
            }
            Err(_) => prop_assert!(!issues.is_empty()),
        }

        let (mut vertices, mut faces, mut edges) = we.into_raw_parts();
        for &(row, field, value) in &mutations {
            let id = EdgeId::new(value);
            let row = usize::from(row);
            let (v, f, e) = (row % vertices.len(), row % faces.len(), row % edges.len());
            match field {
                0 => vertices[v].incident_edge = (value < 13).then_some(id),
                1 => faces[f].incident_edge = id,
                2 => edges[e].start_vertex = VertexId::new(value),
                3 => edges[e].right_face = (value < 5).then_some(FaceId::new(value)),
                4 => edges[e].left_predecessor = id,
                5 => edges[e].right_successor = id,
                6 => edges[e].end_vertex = VertexId::new(value),
                _ => edges[e].left_face = (value < 5).then_some(FaceId::new(value)),
            }
        }
        let count = edges.len();
        let mesh = WingedEdgeMesh::from_raw_parts(vertices, faces, edges);
        let issues = mesh.validate();
        let _ = mesh.stats();
        let _ = mesh.to_polygons();
        for v in 0..9 {
            prop_assert!(mesh.around_vertex(VertexId::new(v)).count() <= 2 * count);
            let _ = mesh.vertex_neighbours(VertexId::new(v)).count();
            let _ = mesh.vertex_faces(VertexId::new(v)).count();
        }
        for f in 0..5 {
            prop_assert!(mesh.around_face(FaceId::new(f)).count() <= 2 * count);
            let _ = mesh.face_vertices(FaceId::new(f)).count();
            let _ = mesh.face_neighbours(FaceId::new(f)).count();
        }
        match mesh.to_half_edge() {
            Ok(half) => {
                prop_assert!(issues.is_empty());
                prop_assert_eq!(half.validate(), vec![]);
                prop_assert_eq!(half.to_winged_edge().expect("valid").validate(), vec![]);
            }
            Err(_) => prop_assert!(!issues.is_empty()),
        }
    }
}
