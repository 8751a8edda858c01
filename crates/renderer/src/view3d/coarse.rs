//! The coarse level of detail: edges as one-pixel lines and faces in one
//! flat colour, drawn from the mesh's own vertices with index buffers and
//! no instancing. When a mesh's edges are only a few pixels long on screen,
//! arrows and spheres show no more than a wireframe does; and a software
//! renderer (`SwiftShader`) runs each instance of an instanced draw as a draw
//! of its own, so 600k instanced lines cost it about eight times what one
//! indexed line list of the same lines does.
//!
//! Colours come from the frame uniform (`coarse_line`, `coarse_face`):
//! every element drawn here has the base look, so a selection or a trace
//! step never touches these buffers. Highlighted elements are drawn again
//! in full on top (see `StyleUpload::full_*`).

use std::ops::Range;

use super::gpu::{IndexData, PipelineFactory, PipelineSpec, VertexData};
use edgewise_pictures::scene::Scene;

const SHADER: &str = concat!(
    include_str!("shaders/common.wgsl"),
    include_str!("shaders/faces.wgsl"),
    include_str!("shaders/coarse.wgsl")
);

/// Every index of a buffer.
const ALL: Range<u32> = 0..u32::MAX;

/// The coarse geometry: the mesh's vertices, one line per edge (a half-edge
/// and its pair share one), and the faces' triangles.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CoarseGeometry {
    pub positions: Vec<[f32; 3]>,
    /// Two vertex indices per line.
    pub lines: Vec<u32>,
    /// Three vertex indices per triangle.
    pub triangles: Vec<u32>,
}

/// The coarse geometry of a scene. Edges with an end out of range, or
/// both ends at one vertex, are left out.
pub fn geometry(scene: &Scene) -> CoarseGeometry {
    let geometry = &scene.geometry;
    let vertex_count = geometry.positions.len();
    let in_range = |v: u32| (v as usize) < vertex_count;
    let mut lines = Vec::with_capacity(geometry.edges.len() * 2);
    for (e, edge) in (0_u32..).zip(&geometry.edges) {
        // A half-edge is drawn by the lower-numbered of it and its pair.
        let drawn_by_pair = edge.pair.is_some_and(|p| {
            p < e
                && geometry
                    .edges
                    .get(p as usize)
                    .is_some_and(|q| q.pair == Some(e))
        });
        if drawn_by_pair || !in_range(edge.start) || !in_range(edge.end) || edge.start == edge.end {
            continue;
        }
        lines.extend([edge.start, edge.end]);
    }
    CoarseGeometry {
        positions: geometry
            .positions
            .iter()
            .map(glam::Vec3::to_array)
            .collect(),
        lines,
        triangles: scene.triangles.iter().flatten().copied().collect(),
    }
}

/// The coarse pipelines, shared by every view.
pub struct CoarseRenderer {
    lines: wgpu::RenderPipeline,
    transparent_faces: wgpu::RenderPipeline,
    solid_faces: wgpu::RenderPipeline,
}

impl CoarseRenderer {
    pub fn new(factory: &PipelineFactory<'_>) -> Self {
        let shader = factory.shader("view3d coarse", SHADER);
        let position = wgpu::vertex_attr_array![0 => Float32x3];
        let buffers = [Some(wgpu::VertexBufferLayout {
            array_stride: 12,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &position,
        })];
        let spec =
            |label, vertex_entry, fragment_entry, transparent: bool, lines: bool| PipelineSpec {
                label,
                shader: &shader,
                vertex_entry,
                fragment_entry,
                buffers: &buffers,
                transparent,
                depth_bias: !lines,
                lines,
            };
        Self {
            lines: factory.create(&spec(
                "view3d coarse lines",
                "vs_coarse_line",
                "fs_coarse_line",
                false,
                true,
            )),
            transparent_faces: factory.create(&spec(
                "view3d coarse faces",
                "vs_coarse_face",
                "fs_face_transparent",
                true,
                false,
            )),
            solid_faces: factory.create(&spec(
                "view3d coarse solid faces",
                "vs_coarse_face",
                "fs_face_solid",
                false,
                false,
            )),
        }
    }

    pub fn draw_lines(&self, pass: &mut wgpu::RenderPass<'static>, buffers: &CoarseBuffers) {
        Self::draw(pass, &self.lines, buffers, buffers.lines.as_ref(), ALL);
    }

    pub fn draw_faces(
        &self,
        pass: &mut wgpu::RenderPass<'static>,
        buffers: &CoarseBuffers,
        solid: bool,
    ) {
        let pipeline = if solid {
            &self.solid_faces
        } else {
            &self.transparent_faces
        };
        Self::draw(pass, pipeline, buffers, buffers.triangles.as_ref(), ALL);
    }

    /// Draws `part` of the lines-then-see-through-faces sequence that
    /// [`CoarseBuffers::primitive_count`] counts: drawn part by part in
    /// order, it gives what drawing the lines and then the faces does.
    pub fn draw_part(
        &self,
        pass: &mut wgpu::RenderPass<'static>,
        buffers: &CoarseBuffers,
        part: Range<u32>,
    ) {
        let lines = buffers.line_count();
        let in_lines = part.start.min(lines)..part.end.min(lines);
        let in_faces = part.start.max(lines) - lines..part.end.max(lines) - lines;
        if !in_lines.is_empty() {
            let indices = in_lines.start * 2..in_lines.end * 2;
            Self::draw(pass, &self.lines, buffers, buffers.lines.as_ref(), indices);
        }
        if !in_faces.is_empty() {
            let indices = in_faces.start * 3..in_faces.end * 3;
            let triangles = buffers.triangles.as_ref();
            Self::draw(pass, &self.transparent_faces, buffers, triangles, indices);
        }
    }

    /// Draws the indices in `range` (cut to those there are).
    fn draw(
        pass: &mut wgpu::RenderPass<'static>,
        pipeline: &wgpu::RenderPipeline,
        buffers: &CoarseBuffers,
        indices: Option<&IndexData>,
        range: Range<u32>,
    ) {
        let (Some(positions), Some(indices)) = (&buffers.positions, indices) else {
            return;
        };
        let (start, end) = (range.start, range.end.min(indices.count));
        if positions.count == 0 || start >= end {
            return;
        }
        pass.set_pipeline(pipeline);
        pass.set_vertex_buffer(0, positions.buffer.slice(..));
        pass.set_index_buffer(indices.buffer.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(start..end, 0, 0..1);
    }
}

/// One view's coarse buffers.
#[derive(Default)]
pub struct CoarseBuffers {
    positions: Option<VertexData>,
    lines: Option<IndexData>,
    triangles: Option<IndexData>,
}

impl CoarseBuffers {
    fn line_count(&self) -> u32 {
        self.lines.as_ref().map_or(0, |l| l.count / 2)
    }

    /// How many lines and triangles there are, in the order
    /// [`CoarseRenderer::draw_part`] draws them.
    pub fn primitive_count(&self) -> u32 {
        let triangles = self.triangles.as_ref().map_or(0, |t| t.count / 3);
        self.line_count().saturating_add(triangles)
    }

    /// Replaces the buffers with a new mesh's.
    pub fn replace(&mut self, device: &wgpu::Device, geometry: &CoarseGeometry) {
        self.positions = Some(VertexData::new(
            device,
            "view3d coarse positions",
            &geometry.positions,
        ));
        self.lines = Some(IndexData::new(
            device,
            "view3d coarse lines",
            &geometry.lines,
        ));
        self.triangles = Some(IndexData::new(
            device,
            "view3d coarse triangles",
            &geometry.triangles,
        ));
    }
}

#[cfg(test)]
mod tests {
    use glam::Vec3;

    use super::*;
    use edgewise_pictures::geometry::{EdgeGeometry, MeshGeometry};

    #[test]
    fn a_half_edge_and_its_pair_make_one_line_and_broken_edges_none() {
        let edge = |start, end, pair| EdgeGeometry {
            start,
            end,
            face: None,
            pair,
        };
        let scene = Scene::new(MeshGeometry {
            positions: vec![Vec3::ZERO, Vec3::X, Vec3::Y],
            edges: vec![
                edge(0, 1, Some(1)),
                edge(1, 0, Some(0)),
                edge(1, 2, Some(2)),
                edge(2, 9, None),
                edge(2, 2, None),
            ],
            faces: vec![vec![0, 1, 2]],
            half_edges: true,
        });
        let coarse = geometry(&scene);
        assert_eq!(coarse.lines, vec![0, 1, 1, 2]);
        assert_eq!(coarse.triangles, vec![0, 1, 2]);
        assert_eq!(coarse.positions.len(), 3);
    }
}
