//! Vertices drawn as small spheres: one instanced icosphere per vertex.

use std::collections::HashMap;

use bytemuck::{Pod, Zeroable};
use glam::Vec3;

use super::gpu::{
    PipelineFactory, PipelineSpec, StyledBuffers, Template, TemplateBuffer, draw_instanced,
    instanced_layouts,
};
use edgewise_pictures::scene::Scene;

const SHADER: &str = concat!(
    include_str!("shaders/common.wgsl"),
    include_str!("shaders/spheres.wgsl")
);

/// Instance counts above which spheres use their second and third level of
/// detail (320, 80, 20 triangles): many vertices are small on screen.
const SPHERE_DETAIL_LIMITS: [u32; 2] = [5_000, 50_000];

/// A sphere instance: the vertex's position.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct SphereInstance {
    pub center: [f32; 3],
}

/// A unit icosphere, each triangle split in four `subdivisions` times
/// (0: 20 triangles on 12 vertices, 1: 80 on 42, 2: 320 on 162). The vertex
/// is also its normal.
pub fn icosphere(subdivisions: u32) -> Template<[f32; 3]> {
    let t = (1.0 + 5.0_f32.sqrt()) / 2.0;
    let mut vertices: Vec<Vec3> = [
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
    .map(Vec3::normalize)
    .to_vec();
    let mut triangles: Vec<[u16; 3]> = vec![
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
    for _ in 0..subdivisions.min(4) {
        let mut midpoints: HashMap<(u16, u16), u16> = HashMap::new();
        let mut midpoint = |a: u16, b: u16, vertices: &mut Vec<Vec3>| {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                let p = (vertices[usize::from(a)] + vertices[usize::from(b)]).normalize();
                vertices.push(p);
                u16::try_from(vertices.len() - 1).unwrap_or(0)
            })
        };
        triangles = triangles
            .iter()
            .flat_map(|&[a, b, c]| {
                let ab = midpoint(a, b, &mut vertices);
                let bc = midpoint(b, c, &mut vertices);
                let ca = midpoint(c, a, &mut vertices);
                [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
            })
            .collect();
    }
    Template {
        vertices: vertices.iter().map(Vec3::to_array).collect(),
        indices: triangles.into_iter().flatten().collect(),
    }
}

/// One instance per vertex.
pub fn instances(scene: &Scene) -> Vec<SphereInstance> {
    (0..scene.vertex_count())
        .map(|v| SphereInstance {
            center: scene
                .position(u32::try_from(v).unwrap_or(u32::MAX))
                .to_array(),
        })
        .collect()
}

/// The sphere pipeline and icosphere templates, shared by every view.
pub struct SphereRenderer {
    pipeline: wgpu::RenderPipeline,
    /// Finest first; see [`SPHERE_DETAIL_LIMITS`].
    templates_by_detail: [TemplateBuffer; 3],
}

impl SphereRenderer {
    pub fn new(factory: &PipelineFactory<'_>) -> Self {
        Self {
            pipeline: pipeline(factory),
            templates_by_detail: [2, 1, 0].map(|subdivisions| {
                TemplateBuffer::new(factory.device, "view3d sphere", &icosphere(subdivisions))
            }),
        }
    }

    /// Draws one view's spheres once both instances and styles are uploaded.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'static>, buffers: &SphereBuffers) {
        let Some((instances, styles)) = buffers.uploaded() else {
            return;
        };
        let count = instances.count.min(styles.count);
        let detail = SPHERE_DETAIL_LIMITS
            .iter()
            .filter(|&&limit| count > limit)
            .count();
        draw_instanced(
            pass,
            &self.pipeline,
            &self.templates_by_detail[detail.min(2)],
            &[&instances.buffer, &styles.buffer],
            count,
        );
    }
}

/// One view's sphere instances and their styles.
pub type SphereBuffers = StyledBuffers<SphereInstance>;

fn pipeline(factory: &PipelineFactory<'_>) -> wgpu::RenderPipeline {
    let shader = factory.shader("view3d spheres", SHADER);
    let template = wgpu::vertex_attr_array![0 => Float32x3];
    let instance = wgpu::vertex_attr_array![1 => Float32x3];
    let style = wgpu::vertex_attr_array![2 => Unorm8x4, 3 => Unorm8x4];
    factory.create(&PipelineSpec {
        label: "view3d spheres",
        shader: &shader,
        vertex_entry: "vs_sphere",
        fragment_entry: "fs_lit",
        buffers: &instanced_layouts::<[f32; 3], SphereInstance>(&template, &instance, &style),
        transparent: false,
        depth_bias: false,
        lines: false,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn icosphere_is_a_closed_unit_sphere() {
        for (subdivisions, vertices, triangles) in [(0, 12, 20), (1, 42, 80), (2, 162, 320)] {
            let sphere = icosphere(subdivisions);
            assert_eq!(sphere.vertices.len(), vertices);
            assert_eq!(sphere.triangle_count(), triangles);
            for v in &sphere.vertices {
                assert!((Vec3::from(*v).length() - 1.0).abs() < 1e-5);
            }
            // Outward winding: each triangle's normal points away from the center.
            for t in sphere.indices.chunks(3) {
                let [a, b, c] =
                    [t[0], t[1], t[2]].map(|i| Vec3::from(sphere.vertices[usize::from(i)]));
                assert!((b - a).cross(c - a).dot(a + b + c) > 0.0);
            }
        }
    }
}
