//! Faces: filled, mostly transparent so the whole structure shows (or solid
//! as an option). Triangles are drawn non-indexed, three corners each.

use super::gpu::{PipelineFactory, PipelineSpec, StyleVertex, StyledBuffers, style_layout};
use edgewise_pictures::scene::Scene;

const SHADER: &str = concat!(
    include_str!("shaders/common.wgsl"),
    include_str!("shaders/faces.wgsl")
);

/// The corners of every triangle, in triangle order.
pub fn corners(scene: &Scene) -> Vec<[f32; 3]> {
    scene
        .triangles
        .iter()
        .flat_map(|t| t.map(|v| scene.position(v).to_array()))
        .collect()
}

/// Per-corner styles from per-face styles.
pub fn corner_styles(scene: &Scene, face_style: impl Fn(usize) -> StyleVertex) -> Vec<StyleVertex> {
    let mut out = Vec::with_capacity(scene.triangles.len() * 3);
    for (f, range) in scene.face_triangle_start.windows(2).enumerate() {
        let style = face_style(f);
        let corners = range[1].saturating_sub(range[0]) as usize * 3;
        out.extend(std::iter::repeat_n(style, corners));
    }
    out
}

/// The see-through and solid face pipelines, shared by every view.
pub struct FaceRenderer {
    transparent: wgpu::RenderPipeline,
    solid: wgpu::RenderPipeline,
}

impl FaceRenderer {
    pub fn new(factory: &PipelineFactory<'_>) -> Self {
        let (transparent, solid) = pipelines(factory);
        Self { transparent, solid }
    }

    /// Draws one view's faces once both corners and styles are uploaded.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'static>, buffers: &FaceBuffers, solid: bool) {
        let Some((corners, styles)) = buffers.uploaded() else {
            return;
        };
        let count = corners.count.min(styles.count);
        if count == 0 {
            return;
        }
        pass.set_pipeline(if solid {
            &self.solid
        } else {
            &self.transparent
        });
        pass.set_vertex_buffer(0, corners.buffer.slice(..));
        pass.set_vertex_buffer(1, styles.buffer.slice(..));
        pass.draw(0..count, 0..1);
    }
}

/// One view's triangle corners and their styles.
pub type FaceBuffers = StyledBuffers<[f32; 3]>;

fn pipelines(factory: &PipelineFactory<'_>) -> (wgpu::RenderPipeline, wgpu::RenderPipeline) {
    let shader = factory.shader("view3d faces", SHADER);
    let position = wgpu::vertex_attr_array![0 => Float32x3];
    let style = wgpu::vertex_attr_array![1 => Unorm8x4, 2 => Unorm8x4];
    let buffers = [
        Some(wgpu::VertexBufferLayout {
            array_stride: 12,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &position,
        }),
        Some(style_layout(wgpu::VertexStepMode::Vertex, &style)),
    ];
    let transparent = factory.create(&PipelineSpec {
        label: "view3d faces",
        shader: &shader,
        vertex_entry: "vs_face",
        fragment_entry: "fs_face_transparent",
        buffers: &buffers,
        transparent: true,
        depth_bias: true,
        lines: false,
    });
    let solid = factory.create(&PipelineSpec {
        label: "view3d solid faces",
        shader: &shader,
        vertex_entry: "vs_face",
        fragment_entry: "fs_face_solid",
        buffers: &buffers,
        transparent: false,
        depth_bias: true,
        lines: false,
    });
    (transparent, solid)
}
