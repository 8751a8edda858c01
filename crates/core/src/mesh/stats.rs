//! Counts and topological invariants: V, E, F, half-edges, boundary loops,
//! connected components, Euler characteristic and genus.

use super::half_edge::HalfEdgeMesh;
use super::ids::{EdgeId, HalfEdgeId, VertexId};
use super::winged_edge::{Side, WingedEdgeMesh};

/// One connected component (an isolated vertex is a component of its own).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ComponentStats {
    /// Its lowest-numbered vertex, to point at it.
    pub first_vertex: VertexId,
    /// Vertices.
    pub vertices: usize,
    /// Edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Boundary loops.
    pub boundary_loops: usize,
    /// V − E + F of the component.
    pub euler_characteristic: i64,
    /// The genus (number of handles) when the component is a closed surface:
    /// (2 − χ) / 2. `None` for components with a boundary or without faces.
    pub genus: Option<u64>,
}

/// Whole-mesh statistics.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MeshStats {
    /// V.
    pub vertices: usize,
    /// E.
    pub edges: usize,
    /// F.
    pub faces: usize,
    /// Half-edges (2E; for a winged-edge mesh, the half-edges it would have).
    pub half_edges: usize,
    /// Boundary loops over the whole mesh.
    pub boundary_loops: usize,
    /// V − E + F.
    pub euler_characteristic: i64,
    /// Connected components in order of their lowest vertex.
    pub components: Vec<ComponentStats>,
}

impl MeshStats {
    /// How many connected components there are.
    pub fn connected_components(&self) -> usize {
        self.components.len()
    }
}

/// Union-find over vertex numbers, with path halving.
struct Components {
    parent: Vec<u32>,
}

impl Components {
    fn new(count: usize) -> Self {
        Self {
            parent: (0..count as u32).collect(),
        }
    }

    fn root(&mut self, mut v: u32) -> u32 {
        loop {
            let Some(&parent) = self.parent.get(v as usize) else {
                return v;
            };
            if parent == v {
                return v;
            }
            let grandparent = self.parent.get(parent as usize).copied().unwrap_or(parent);
            if let Some(slot) = self.parent.get_mut(v as usize) {
                *slot = grandparent;
            }
            v = grandparent;
        }
    }

    fn join(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.root(a), self.root(b));
        if ra != rb {
            let (low, high) = (ra.min(rb), ra.max(rb));
            if let Some(slot) = self.parent.get_mut(high as usize) {
                *slot = low;
            }
        }
    }
}

/// What [`summarize`] needs from either structure.
struct Census {
    vertex_count: usize,
    half_edges: usize,
    /// The two ends of every edge.
    edges: Vec<(VertexId, VertexId)>,
    /// A vertex of every face (if its incident edge leads to one).
    faces: Vec<Option<VertexId>>,
    /// A vertex of every boundary loop.
    boundary_loops: Vec<VertexId>,
}

fn summarize(census: &Census) -> MeshStats {
    let vertex_count = census.vertex_count;
    let mut components = Components::new(vertex_count);
    let in_range = |v: VertexId| v.index() < vertex_count;
    for &(a, b) in &census.edges {
        if in_range(a) && in_range(b) {
            components.join(a.raw(), b.raw());
        }
    }
    let mut index_of_root = vec![u32::MAX; vertex_count];
    let mut list: Vec<ComponentStats> = Vec::new();
    let mut component_of = Vec::with_capacity(vertex_count);
    for v in 0..vertex_count as u32 {
        let root = components.root(v) as usize;
        let slot = &mut index_of_root[root];
        if *slot == u32::MAX {
            *slot = list.len() as u32;
            list.push(ComponentStats {
                first_vertex: VertexId::new(v),
                vertices: 0,
                edges: 0,
                faces: 0,
                boundary_loops: 0,
                euler_characteristic: 0,
                genus: None,
            });
        }
        component_of.push(*slot);
        if let Some(component) = list.get_mut(*slot as usize) {
            component.vertices += 1;
        }
    }
    let component_index = |v: VertexId| component_of.get(v.index()).map(|&c| c as usize);
    let anchors = census
        .edges
        .iter()
        .map(|&(a, _)| (a, 0))
        .chain(census.faces.iter().flatten().map(|&v| (v, 1)));
    for (v, kind) in anchors.chain(census.boundary_loops.iter().map(|&v| (v, 2))) {
        if let Some(c) = component_index(v).and_then(|c| list.get_mut(c)) {
            match kind {
                0 => c.edges += 1,
                1 => c.faces += 1,
                _ => c.boundary_loops += 1,
            }
        }
    }
    for c in &mut list {
        c.euler_characteristic = c.vertices as i64 - c.edges as i64 + c.faces as i64;
        let doubled = 2 - c.euler_characteristic;
        if c.faces > 0 && c.boundary_loops == 0 && doubled >= 0 && doubled % 2 == 0 {
            c.genus = Some((doubled / 2) as u64);
        }
    }
    let (edges, faces) = (census.edges.len(), census.faces.len());
    MeshStats {
        vertices: vertex_count,
        edges,
        faces,
        half_edges: census.half_edges,
        boundary_loops: census.boundary_loops.len(),
        euler_characteristic: vertex_count as i64 - edges as i64 + faces as i64,
        components: list,
    }
}

impl HalfEdgeMesh {
    /// Counts, boundary loops, components, Euler characteristic and genus.
    pub fn stats(&self) -> MeshStats {
        let mut edges = Vec::with_capacity(self.edge_count());
        for (h, half_edge) in (0u32..).map(HalfEdgeId::new).zip(&self.half_edges) {
            // Each pair once: from its lower-numbered half (or alone if broken).
            let pair = half_edge.pair_edge;
            if (h < pair || self.half_edge(pair).is_none())
                && let Some(start) = self.start_vertex(h).or(Some(half_edge.end_vertex))
            {
                edges.push((start, half_edge.end_vertex));
            }
        }
        let faces = self
            .faces
            .iter()
            .map(|face| self.half_edge(face.incident_edge).map(|h| h.end_vertex))
            .collect();
        let mut visited = vec![false; self.half_edges.len()];
        let mut boundary_loops = Vec::new();
        for (h, half_edge) in self.half_edges.iter().enumerate() {
            if half_edge.face.is_some() || visited[h] {
                continue;
            }
            boundary_loops.push(half_edge.end_vertex);
            let mut current = h;
            while let Some(seen) = visited.get_mut(current)
                && !*seen
            {
                *seen = true;
                match self.half_edges.get(current) {
                    Some(next) if next.face.is_none() => current = next.successor_edge.index(),
                    _ => break,
                }
            }
        }
        summarize(&Census {
            vertex_count: self.vertices.len(),
            half_edges: self.half_edges.len(),
            edges,
            faces,
            boundary_loops,
        })
    }
}

impl WingedEdgeMesh {
    /// Counts, boundary loops, components, Euler characteristic and genus.
    pub fn stats(&self) -> MeshStats {
        let edges = self
            .edges
            .iter()
            .map(|edge| (edge.start_vertex, edge.end_vertex))
            .collect();
        let faces = self
            .faces
            .iter()
            .map(|face| self.edge(face.incident_edge).map(|e| e.start_vertex))
            .collect();
        // Boundary sides, two per edge, walked counter-clockwise.
        let side_index = |e: EdgeId, side: Side| e.index() * 2 + usize::from(side == Side::Right);
        let mut visited = vec![false; self.edges.len() * 2];
        let mut boundary_loops = Vec::new();
        for (e, edge) in (0u32..).map(EdgeId::new).zip(&self.edges) {
            for side in [Side::Left, Side::Right] {
                if edge.face(side).is_some() || visited[side_index(e, side)] {
                    continue;
                }
                boundary_loops.push(edge.ccw_start(side));
                let (mut current, mut current_side) = (e, side);
                while let Some(seen) = visited.get_mut(side_index(current, current_side))
                    && !*seen
                {
                    *seen = true;
                    let Some(next) = self
                        .edge(current)
                        .map(|edge| edge.predecessor(current_side))
                    else {
                        break;
                    };
                    let Some(next_side) = self.edge(next).and_then(|edge| edge.side_of(None))
                    else {
                        break;
                    };
                    (current, current_side) = (next, next_side);
                }
            }
        }
        summarize(&Census {
            vertex_count: self.vertices.len(),
            half_edges: self.edges.len() * 2,
            edges,
            faces,
            boundary_loops,
        })
    }
}
