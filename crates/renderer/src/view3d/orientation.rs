//! Face orientation marks: a small curved arrow in each face turning the way
//! the structure traverses it: counter-clockwise about the outward normal on
//! a half-edge mesh, clockwise on a winged-edge mesh (the journal's Table 1).

use std::f32::consts::{PI, TAU};

use bytemuck::{Pod, Zeroable};

use super::gpu::{
    PipelineFactory, PipelineSpec, Template, TemplateBuffer, VertexData, draw_instanced,
};
use edgewise_pictures::scene::Scene;

const SHADER: &str = concat!(
    include_str!("shaders/common.wgsl"),
    include_str!("shaders/orientation.wgsl")
);

const ARC_SEGMENTS: usize = 20;
/// The arc runs from this angle for `ARC_SPAN` radians, counter-clockwise.
const ARC_START: f32 = 0.35 * PI;
const ARC_SPAN: f32 = 1.45 * PI;
const WIDTH: f32 = 0.16;
const HEAD_WIDTH: f32 = 0.42;
const HEAD_LENGTH: f32 = 0.5;

/// An orientation mark instance: center and the two scaled in-plane axes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct MarkInstance {
    pub center: [f32; 3],
    pub u: [f32; 3],
    pub v: [f32; 3],
}

/// The unit mark (radius 1) as a triangle list in its own plane.
pub fn template() -> Template<[f32; 2]> {
    let point = |angle: f32, radius: f32| {
        let (sin, cos) = angle.sin_cos();
        [cos * radius, sin * radius]
    };
    let (inner, outer) = (1.0 - WIDTH * 0.5, 1.0 + WIDTH * 0.5);
    let mut out = Vec::with_capacity(ARC_SEGMENTS * 6 + 3);
    for i in 0..ARC_SEGMENTS {
        let a0 = ARC_START + ARC_SPAN * i as f32 / ARC_SEGMENTS as f32;
        let a1 = ARC_START + ARC_SPAN * (i + 1) as f32 / ARC_SEGMENTS as f32;
        let (p0, p1, q0, q1) = (
            point(a0, inner),
            point(a1, inner),
            point(a0, outer),
            point(a1, outer),
        );
        out.extend([p0, q0, q1, p0, q1, p1]);
    }
    // Head at the end of the arc, pointing along the counter-clockwise tangent.
    let end = ARC_START + ARC_SPAN;
    let tip_angle = end + HEAD_LENGTH;
    out.extend([
        point(end, 1.0 - HEAD_WIDTH * 0.5),
        point(end, 1.0 + HEAD_WIDTH * 0.5),
        point(tip_angle.min(end + TAU), 1.0),
    ]);
    Template::from_triangle_list(out)
}

/// One mark per face with room for it, scaled to fit inside the face.
pub fn instances(scene: &Scene) -> Vec<MarkInstance> {
    let mut out = Vec::with_capacity(scene.face_count());
    for (f, face) in scene.geometry.faces.iter().enumerate() {
        let (Some(&radius), Some(&normal), Some(&center)) = (
            scene.orientation_radius.get(f),
            scene.face_normals.get(f),
            scene.face_centroids.get(f),
        ) else {
            continue;
        };
        let Some(&first) = face.first() else {
            continue;
        };
        if radius <= 0.0 {
            continue;
        }
        let toward_first = scene.position(first) - center;
        let u = (toward_first - normal * toward_first.dot(normal)).normalize_or_zero();
        if u == glam::Vec3::ZERO {
            continue;
        }
        // The template's arc turns from u towards v: v = n × u turns it
        // counter-clockwise about n, u × n clockwise.
        let v = if scene.geometry.half_edges {
            normal.cross(u)
        } else {
            u.cross(normal)
        };
        out.push(MarkInstance {
            center: center.to_array(),
            u: (u * radius).to_array(),
            v: (v * radius).to_array(),
        });
    }
    out
}

/// The orientation mark pipeline and template, shared by every view.
pub struct OrientationRenderer {
    pipeline: wgpu::RenderPipeline,
    template: TemplateBuffer,
}

impl OrientationRenderer {
    pub fn new(factory: &PipelineFactory<'_>) -> Self {
        Self {
            pipeline: pipeline(factory),
            template: TemplateBuffer::new(factory.device, "view3d mark", &template()),
        }
    }

    /// Draws one view's marks once they are uploaded (they take their colour
    /// from the frame uniform, so they have no style buffer).
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'static>, buffers: &OrientationBuffers) {
        let Some(marks) = &buffers.marks else {
            return;
        };
        draw_instanced(
            pass,
            &self.pipeline,
            &self.template,
            &[&marks.buffer],
            marks.count,
        );
    }
}

/// One view's mark instances.
#[derive(Default)]
pub struct OrientationBuffers {
    marks: Option<VertexData>,
}

impl OrientationBuffers {
    /// Replaces the marks (a new mesh).
    pub fn replace_marks(&mut self, device: &wgpu::Device, marks: &[MarkInstance]) {
        self.marks = Some(VertexData::new(device, "view3d marks", marks));
    }
}

fn pipeline(factory: &PipelineFactory<'_>) -> wgpu::RenderPipeline {
    let shader = factory.shader("view3d orientation", SHADER);
    let template = wgpu::vertex_attr_array![0 => Float32x2];
    let instance = wgpu::vertex_attr_array![1 => Float32x3, 2 => Float32x3, 3 => Float32x3];
    factory.create(&PipelineSpec {
        label: "view3d orientation",
        shader: &shader,
        vertex_entry: "vs_orientation",
        fragment_entry: "fs_orientation",
        buffers: &[
            Some(wgpu::VertexBufferLayout {
                array_stride: 8,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &template,
            }),
            Some(wgpu::VertexBufferLayout {
                array_stride: size_of::<MarkInstance>() as u64,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &instance,
            }),
        ],
        transparent: false,
        depth_bias: false,
        lines: false,
    })
}

#[cfg(test)]
mod tests {
    use edgewise_core::mesh::{Mesh, Structure, generate};
    use glam::Vec3;

    use super::*;
    use edgewise_pictures::geometry::MeshGeometry;

    /// The sense each mark of the open square (in the plane z = 0, its faces
    /// counter-clockwise seen from +z) turns about +z: 1 counter-clockwise.
    fn turns(structure: Structure) -> Vec<f32> {
        let (mesh, _) = Mesh::build(&generate::open_square(), structure).expect("builds");
        let scene = Scene::new(MeshGeometry::from_mesh(&mesh));
        instances(&scene)
            .iter()
            .map(|mark| {
                Vec3::from(mark.u)
                    .cross(Vec3::from(mark.v))
                    .dot(Vec3::Z)
                    .signum()
            })
            .collect()
    }

    #[test]
    fn marks_turn_the_way_each_structure_traverses_its_faces() {
        assert_eq!(turns(Structure::HalfEdge), [1.0, 1.0], "counter-clockwise");
        assert_eq!(turns(Structure::WingedEdge), [-1.0, -1.0], "clockwise");
    }
}
