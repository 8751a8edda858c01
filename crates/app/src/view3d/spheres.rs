//! Vertices drawn as small spheres: one instanced icosphere per vertex.

use glam::Vec3;

use super::gpu::{PipelineFactory, PipelineSpec, style_layout};
use super::scene::Scene;

const SHADER: &str = concat!(
    include_str!("shaders/common.wgsl"),
    include_str!("shaders/spheres.wgsl")
);

/// A unit icosphere as a triangle list, each triangle split in four
/// `subdivisions` times (0: 20 triangles, 1: 80, 2: 320).
pub fn icosphere(subdivisions: u32) -> Vec<[f32; 3]> {
    let t = (1.0 + 5.0_f32.sqrt()) / 2.0;
    let corners = [
        Vec3::new(-1.0, t, 0.0),
        Vec3::new(1.0, t, 0.0),
        Vec3::new(-1.0, -t, 0.0),
        Vec3::new(1.0, -t, 0.0),
        Vec3::new(0.0, -1.0, t),
        Vec3::new(0.0, 1.0, t),
        Vec3::new(0.0, -1.0, -t),
        Vec3::new(0.0, 1.0, -t),
        Vec3::new(t, 0.0, -1.0),
        Vec3::new(t, 0.0, 1.0),
        Vec3::new(-t, 0.0, -1.0),
        Vec3::new(-t, 0.0, 1.0),
    ]
    .map(Vec3::normalize);
    const FACES: [[usize; 3]; 20] = [
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    let mut triangles: Vec<[Vec3; 3]> = FACES
        .iter()
        .map(|f| [corners[f[0]], corners[f[1]], corners[f[2]]])
        .collect();
    for _ in 0..subdivisions {
        triangles = triangles
            .iter()
            .flat_map(|&[a, b, c]| {
                let ab = (a + b).normalize();
                let bc = (b + c).normalize();
                let ca = (c + a).normalize();
                [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
            })
            .collect();
    }
    triangles
        .iter()
        .flat_map(|t| t.map(|p| p.to_array()))
        .collect()
}

/// One instance per vertex: its position.
pub fn instances(scene: &Scene) -> Vec<[f32; 3]> {
    (0..scene.vertex_count())
        .map(|v| {
            scene
                .position(u32::try_from(v).unwrap_or(u32::MAX))
                .to_array()
        })
        .collect()
}

pub fn pipeline(factory: &PipelineFactory<'_>) -> wgpu::RenderPipeline {
    let shader = factory.shader("view3d spheres", SHADER);
    let template = wgpu::vertex_attr_array![0 => Float32x3];
    let instance = wgpu::vertex_attr_array![1 => Float32x3];
    let style = wgpu::vertex_attr_array![2 => Unorm8x4, 3 => Unorm8x4];
    factory.create(&PipelineSpec {
        label: "view3d spheres",
        shader: &shader,
        vertex_entry: "vs_sphere",
        fragment_entry: "fs_lit",
        buffers: &[
            Some(wgpu::VertexBufferLayout {
                array_stride: 12,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &template,
            }),
            Some(wgpu::VertexBufferLayout {
                array_stride: 12,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &instance,
            }),
            Some(style_layout(wgpu::VertexStepMode::Instance, &style)),
        ],
        transparent: false,
        depth_bias: false,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn icosphere_is_a_closed_unit_sphere() {
        for (subdivisions, triangles) in [(0, 20), (1, 80), (2, 320)] {
            let vertices = icosphere(subdivisions);
            assert_eq!(vertices.len(), triangles * 3);
            for v in &vertices {
                assert!((Vec3::from(*v).length() - 1.0).abs() < 1e-5);
            }
            // Outward winding: each triangle's normal points away from the center.
            for t in vertices.chunks(3) {
                let [a, b, c] = [t[0], t[1], t[2]].map(Vec3::from);
                assert!((b - a).cross(c - a).dot(a + b + c) > 0.0);
            }
        }
    }
}
