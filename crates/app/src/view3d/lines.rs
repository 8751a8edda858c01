//! Edges drawn as one-pixel lines: the coarse level of detail. When a
//! mesh's edges are only a few pixels long on screen, 36-triangle arrows
//! cost a software renderer far more than they show; a line per edge shows
//! the same wireframe. The lines read the arrows' own instance and style
//! buffers, so switching costs no upload.

use super::arrows::{ArrowBuffers, ArrowInstance};
use super::gpu::{
    PipelineFactory, PipelineSpec, Template, TemplateBuffer, draw_instanced, instanced_layouts,
};

const SHADER: &str = concat!(
    include_str!("shaders/common.wgsl"),
    include_str!("shaders/lines.wgsl")
);

/// The line pipeline and its two-point template, shared by every view.
pub struct LineRenderer {
    pipeline: wgpu::RenderPipeline,
    template: TemplateBuffer,
}

impl LineRenderer {
    pub fn new(factory: &PipelineFactory<'_>) -> Self {
        let template = Template {
            vertices: vec![0.0_f32, 1.0],
            indices: vec![0, 1],
        };
        Self {
            pipeline: pipeline(factory),
            template: TemplateBuffer::new(factory.device, "view3d line", &template),
        }
    }

    /// Draws every arrow of `buffers` as a line.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'static>, buffers: &ArrowBuffers) {
        let Some((instances, styles)) = buffers.uploaded() else {
            return;
        };
        draw_instanced(
            pass,
            &self.pipeline,
            &self.template,
            &[&instances.buffer, &styles.buffer],
            instances.count.min(styles.count),
        );
    }
}

fn pipeline(factory: &PipelineFactory<'_>) -> wgpu::RenderPipeline {
    let shader = factory.shader("view3d lines", SHADER);
    let template = wgpu::vertex_attr_array![0 => Float32];
    let instance = wgpu::vertex_attr_array![1 => Float32x3, 2 => Float32x3];
    let style = wgpu::vertex_attr_array![3 => Unorm8x4, 4 => Unorm8x4];
    factory.create(&PipelineSpec {
        label: "view3d lines",
        shader: &shader,
        vertex_entry: "vs_line",
        fragment_entry: "fs_line",
        buffers: &instanced_layouts::<f32, ArrowInstance>(&template, &instance, &style),
        transparent: false,
        depth_bias: false,
        lines: true,
    })
}
