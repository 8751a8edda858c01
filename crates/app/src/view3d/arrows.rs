//! Edges drawn as arrows (a shaft and a cone head pointing at the end
//! vertex): one instanced template per edge or half-edge.

use std::f32::consts::TAU;

use bytemuck::{Pod, Zeroable};

use super::gpu::{ArrowInstance, PipelineFactory, PipelineSpec, style_layout};
use super::scene::Scene;

const SHADER: &str = concat!(
    include_str!("shaders/common.wgsl"),
    include_str!("shaders/arrows.wgsl")
);

/// Sides around the shaft and the cone.
const SEGMENTS: usize = 10;

/// A template vertex: see `vs_arrow` in shaders/arrows.wgsl for what the
/// selectors mean.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct ArrowVertex {
    pub shape: [f32; 4],
    pub normal_kind: f32,
}

/// The unit arrow as a triangle list: shaft tube, cone, and the disc closing
/// the cone's base.
pub fn template() -> Vec<ArrowVertex> {
    let ring = |i: usize| {
        let (sin, cos) = (TAU * i as f32 / SEGMENTS as f32).sin_cos();
        (cos, sin)
    };
    let vertex = |(x, y): (f32, f32), along: f32, radius: f32, normal_kind: f32| ArrowVertex {
        shape: [x, y, along, radius],
        normal_kind,
    };
    let mut out = Vec::with_capacity(SEGMENTS * 12);
    for i in 0..SEGMENTS {
        let (a, b) = (ring(i), ring(i + 1));
        // Shaft: from the start to the head's base, shaft radius.
        let (s0, s1) = (vertex(a, 0.0, 0.0, 0.0), vertex(b, 0.0, 0.0, 0.0));
        let (h0, h1) = (vertex(a, 1.0, 0.0, 0.0), vertex(b, 1.0, 0.0, 0.0));
        out.extend([s0, s1, h1, s0, h1, h0]);
        // Cone: from the head's base (head radius) to the tip.
        let mid = ((a.0 + b.0) * 0.5, (a.1 + b.1) * 0.5);
        out.extend([
            vertex(a, 1.0, 1.0, 1.0),
            vertex(b, 1.0, 1.0, 1.0),
            vertex(mid, 2.0, 2.0, 1.0),
        ]);
        // Base disc, facing backwards.
        out.extend([
            vertex(b, 1.0, 1.0, 2.0),
            vertex(a, 1.0, 1.0, 2.0),
            vertex((0.0, 0.0), 1.0, 2.0, 2.0),
        ]);
    }
    out
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

pub fn pipeline(factory: &PipelineFactory<'_>) -> wgpu::RenderPipeline {
    let shader = factory.shader("view3d arrows", SHADER);
    let template = wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32];
    let instance = wgpu::vertex_attr_array![2 => Float32x3, 3 => Float32x3];
    let style = wgpu::vertex_attr_array![4 => Unorm8x4, 5 => Unorm8x4];
    factory.create(&PipelineSpec {
        label: "view3d arrows",
        shader: &shader,
        vertex_entry: "vs_arrow",
        fragment_entry: "fs_lit",
        buffers: &[
            Some(wgpu::VertexBufferLayout {
                array_stride: size_of::<ArrowVertex>() as u64,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &template,
            }),
            Some(wgpu::VertexBufferLayout {
                array_stride: size_of::<ArrowInstance>() as u64,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &instance,
            }),
            Some(style_layout(wgpu::VertexStepMode::Instance, &style)),
        ],
        transparent: false,
        depth_bias: false,
    })
}
