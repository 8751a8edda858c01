//! Edges drawn as arrows (a shaft and a cone head pointing at the end
//! vertex): one instanced template per edge or half-edge. The world axes are
//! drawn with the same renderer.

use std::f32::consts::TAU;

use bytemuck::{Pod, Zeroable};

use super::gpu::{
    PipelineFactory, PipelineSpec, StyledBuffers, Template, TemplateBuffer, draw_instanced,
    instanced_layouts,
};
use edgewise_pictures::scene::Scene;

const SHADER: &str = concat!(
    include_str!("shaders/common.wgsl"),
    include_str!("shaders/arrows.wgsl")
);

/// Instance count above which arrows use their coarse template (36 triangles
/// instead of 120): many edges are thin on screen.
const ARROW_DETAIL_LIMIT: u32 = 30_000;

/// An arrow instance: start and end in world space.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct ArrowInstance {
    pub start: [f32; 3],
    pub end: [f32; 3],
}

/// A template vertex: see `vs_arrow` in shaders/arrows.wgsl for what the
/// selectors mean.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct ArrowVertex {
    pub shape: [f32; 4],
    pub normal_kind: f32,
}

/// The unit arrow with `segments` sides: shaft tube, cone, and (if `base`)
/// the disc closing the cone, which only shows on arrows seen from behind
/// their head.
pub fn template(segments: u16, base: bool) -> Template<ArrowVertex> {
    let n = segments.max(3);
    let around = |i: f32| {
        let (sin, cos) = (TAU * i / f32::from(n)).sin_cos();
        (cos, sin)
    };
    let vertex = |(x, y): (f32, f32), along: f32, radius: f32, normal_kind: f32| ArrowVertex {
        shape: [x, y, along, radius],
        normal_kind,
    };
    let mut vertices = Vec::new();
    let mut indices: Vec<u16> = Vec::new();
    // Rings: shaft start, shaft end, cone base; then one tip per side (each
    // with its own normal).
    for (along, radius, normal_kind) in [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 1.0)] {
        for i in 0..n {
            vertices.push(vertex(around(f32::from(i)), along, radius, normal_kind));
        }
    }
    for i in 0..n {
        vertices.push(vertex(around(f32::from(i) + 0.5), 2.0, 2.0, 1.0));
    }
    let (shaft_start, shaft_end, cone, tips) = (0, n, 2 * n, 3 * n);
    for i in 0..n {
        let j = (i + 1) % n;
        indices.extend([shaft_start + i, shaft_start + j, shaft_end + j]);
        indices.extend([shaft_start + i, shaft_end + j, shaft_end + i]);
        indices.extend([cone + i, cone + j, tips + i]);
    }
    if base {
        let disc = 4 * n;
        for i in 0..n {
            vertices.push(vertex(around(f32::from(i)), 1.0, 1.0, 2.0));
        }
        vertices.push(vertex((0.0, 0.0), 1.0, 2.0, 2.0));
        let center = 5 * n;
        for i in 0..n {
            indices.extend([disc + (i + 1) % n, disc + i, center]);
        }
    }
    Template { vertices, indices }
}

/// One instance per edge arrow, where [`Scene`] placed it.
pub fn instances(scene: &Scene) -> Vec<ArrowInstance> {
    scene
        .arrow_starts
        .iter()
        .zip(&scene.arrow_ends)
        .map(|(a, b)| ArrowInstance {
            start: a.to_array(),
            end: b.to_array(),
        })
        .collect()
}

/// The arrow pipeline and templates, shared by every view.
pub struct ArrowRenderer {
    pipeline: wgpu::RenderPipeline,
    /// Fine (with the base disc) and coarse; see [`ARROW_DETAIL_LIMIT`].
    templates_by_detail: [TemplateBuffer; 2],
}

impl ArrowRenderer {
    pub fn new(factory: &PipelineFactory<'_>) -> Self {
        Self {
            pipeline: pipeline(factory),
            templates_by_detail: [
                TemplateBuffer::new(factory.device, "view3d arrow", &template(10, true)),
                TemplateBuffer::new(factory.device, "view3d arrow coarse", &template(6, false)),
            ],
        }
    }

    /// Draws one set of arrows once both instances and styles are uploaded.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'static>, buffers: &ArrowBuffers) {
        let Some((instances, styles)) = buffers.uploaded() else {
            return;
        };
        let count = instances.count.min(styles.count);
        let detail = usize::from(count > ARROW_DETAIL_LIMIT);
        draw_instanced(
            pass,
            &self.pipeline,
            &self.templates_by_detail[detail],
            &[&instances.buffer, &styles.buffer],
            count,
        );
    }
}

/// One view's arrow instances and their styles: the mesh's edges, or the
/// axes.
pub type ArrowBuffers = StyledBuffers<ArrowInstance>;

fn pipeline(factory: &PipelineFactory<'_>) -> wgpu::RenderPipeline {
    let shader = factory.shader("view3d arrows", SHADER);
    let template = wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32];
    let instance = wgpu::vertex_attr_array![2 => Float32x3, 3 => Float32x3];
    let style = wgpu::vertex_attr_array![4 => Unorm8x4, 5 => Unorm8x4];
    factory.create(&PipelineSpec {
        label: "view3d arrows",
        shader: &shader,
        vertex_entry: "vs_arrow",
        fragment_entry: "fs_lit",
        buffers: &instanced_layouts::<ArrowVertex, ArrowInstance>(&template, &instance, &style),
        transparent: false,
        depth_bias: false,
        lines: false,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn templates_index_their_own_vertices() {
        for (segments, base, triangles) in [(10, true, 40), (6, false, 18)] {
            let arrow = template(segments, base);
            assert_eq!(arrow.triangle_count(), triangles);
            assert!(
                arrow
                    .indices
                    .iter()
                    .all(|&i| usize::from(i) < arrow.vertices.len())
            );
        }
    }
}
