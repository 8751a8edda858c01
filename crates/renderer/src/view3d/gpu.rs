//! GPU plumbing every drawable shares: the depth format, the frame uniform
//! and its bind group, the pipeline factory, template and vertex buffers,
//! and the style vertex. Drawables import from here; this file imports no
//! drawable.
//!
//! Everything works on WebGL2 as well as WebGPU: per-instance data comes in
//! instance vertex buffers (no storage buffers), draws use neither a base
//! vertex nor a first instance, and there is a single uniform buffer.

use bytemuck::{Pod, Zeroable};
use wgpu::util::DeviceExt as _;

/// The depth buffer eframe must be configured with (`depth_buffer: 24` in
/// `NativeOptions` and `WebOptions`); the pipelines use the matching format.
pub const DEPTH_BITS: u8 = 24;

pub fn depth_format() -> wgpu::TextureFormat {
    egui_wgpu::depth_format_from_bits(DEPTH_BITS, 0).unwrap_or(wgpu::TextureFormat::Depth24Plus)
}

/// The per-frame uniform; mirrors `Frame` in shaders/common.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct FrameUniform {
    pub clip_from_world: [[f32; 4]; 4],
    pub eye: [f32; 4],
    pub light: [f32; 4],
    pub sizes: [f32; 4],
    pub params: [f32; 4],
    pub orientation_colour: [f32; 4],
    pub background: [f32; 4],
    pub coarse_line: [f32; 4],
    pub coarse_face: [f32; 4],
    /// How elements without a style of their own fade while others are
    /// highlighted: on (1 or 0), then [`super::style::FADE_LINE`],
    /// [`super::style::FADE_FACE_ALPHA`] and [`super::style::FADE_FACE_MIX`].
    pub fade: [f32; 4],
}

/// The layout of bind group 0, the frame uniform, which every pipeline uses.
pub fn frame_bind_group_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("view3d frame"),
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: wgpu::BufferSize::new(size_of::<FrameUniform>() as u64),
            },
            count: None,
        }],
    })
}

/// One view's frame uniform buffer and the bind group over it (each view has
/// its own camera, so its own uniform).
pub struct FrameBindGroup {
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
}

impl FrameBindGroup {
    pub fn new(device: &wgpu::Device, layout: &wgpu::BindGroupLayout) -> Self {
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("view3d frame"),
            size: size_of::<FrameUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("view3d frame"),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: uniform.as_entire_binding(),
            }],
        });
        Self {
            uniform,
            bind_group,
        }
    }

    pub fn write(&self, queue: &wgpu::Queue, frame: &FrameUniform) {
        queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(frame));
    }

    pub fn bind(&self, pass: &mut wgpu::RenderPass<'static>) {
        pass.set_bind_group(0, &self.bind_group, &[]);
    }
}

/// Per-element look on the GPU: colour (with alpha for faces) and extras
/// (x: emphasis, y: arrow ends kept in place).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub struct StyleVertex {
    pub colour: [u8; 4],
    pub extra: [u8; 4],
}

/// The vertex layout of a style buffer at shader locations `colour` and
/// `colour + 1`.
pub fn style_layout(
    step_mode: wgpu::VertexStepMode,
    attributes: &[wgpu::VertexAttribute; 2],
) -> wgpu::VertexBufferLayout<'_> {
    wgpu::VertexBufferLayout {
        array_stride: size_of::<StyleVertex>() as u64,
        step_mode,
        attributes,
    }
}

/// How a pipeline blends and tests depth.
pub struct PipelineSpec<'a> {
    pub label: &'a str,
    pub shader: &'a wgpu::ShaderModule,
    pub vertex_entry: &'a str,
    pub fragment_entry: &'a str,
    pub buffers: &'a [Option<wgpu::VertexBufferLayout<'a>>],
    /// See-through: blended, depth tested but not written.
    pub transparent: bool,
    /// Pushed slightly back so edges lying on a face stay in front of it.
    pub depth_bias: bool,
    /// A line list (two template points per line) instead of triangles.
    pub lines: bool,
}

/// Creates pipelines (and their template buffers, through `device`) for one
/// target format, all over the frame bind group.
pub struct PipelineFactory<'a> {
    pub device: &'a wgpu::Device,
    layout: wgpu::PipelineLayout,
    target_format: wgpu::TextureFormat,
    constants: TargetConstants,
}

/// The values of common.wgsl's pipeline-overridable constants for a target
/// format, which every pipeline of the view passes to both its stages.
pub struct TargetConstants([(&'static str, f64); 1]);

impl TargetConstants {
    pub fn new(target_format: wgpu::TextureFormat) -> Self {
        Self([(
            "srgb_target",
            if target_format.is_srgb() { 1.0 } else { 0.0 },
        )])
    }

    pub fn options(&self) -> wgpu::PipelineCompilationOptions<'_> {
        wgpu::PipelineCompilationOptions {
            constants: &self.0,
            ..wgpu::PipelineCompilationOptions::default()
        }
    }
}

impl<'a> PipelineFactory<'a> {
    pub fn new(
        device: &'a wgpu::Device,
        frame_layout: &wgpu::BindGroupLayout,
        target_format: wgpu::TextureFormat,
    ) -> Self {
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("view3d"),
            bind_group_layouts: &[Some(frame_layout)],
            immediate_size: 0,
        });
        Self {
            device,
            layout,
            target_format,
            constants: TargetConstants::new(target_format),
        }
    }

    pub fn shader(&self, label: &str, source: &str) -> wgpu::ShaderModule {
        self.device
            .create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(label),
                source: wgpu::ShaderSource::Wgsl(source.into()),
            })
    }

    pub fn create(&self, spec: &PipelineSpec<'_>) -> wgpu::RenderPipeline {
        // Premultiplied alpha, like egui.
        let blend = wgpu::BlendState {
            color: wgpu::BlendComponent {
                src_factor: wgpu::BlendFactor::One,
                dst_factor: wgpu::BlendFactor::OneMinusSrcAlpha,
                operation: wgpu::BlendOperation::Add,
            },
            alpha: wgpu::BlendComponent {
                src_factor: wgpu::BlendFactor::One,
                dst_factor: wgpu::BlendFactor::OneMinusSrcAlpha,
                operation: wgpu::BlendOperation::Add,
            },
        };
        self.device
            .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(spec.label),
                layout: Some(&self.layout),
                vertex: wgpu::VertexState {
                    module: spec.shader,
                    entry_point: Some(spec.vertex_entry),
                    compilation_options: self.constants.options(),
                    buffers: spec.buffers,
                },
                primitive: wgpu::PrimitiveState {
                    topology: if spec.lines {
                        wgpu::PrimitiveTopology::LineList
                    } else {
                        wgpu::PrimitiveTopology::TriangleList
                    },
                    cull_mode: None,
                    ..Default::default()
                },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: depth_format(),
                    depth_write_enabled: Some(!spec.transparent),
                    depth_compare: Some(wgpu::CompareFunction::LessEqual),
                    stencil: wgpu::StencilState::default(),
                    bias: if spec.depth_bias {
                        wgpu::DepthBiasState {
                            constant: 2,
                            slope_scale: 1.5,
                            clamp: 0.0,
                        }
                    } else {
                        wgpu::DepthBiasState::default()
                    },
                }),
                multisample: wgpu::MultisampleState::default(),
                fragment: Some(wgpu::FragmentState {
                    module: spec.shader,
                    entry_point: Some(spec.fragment_entry),
                    compilation_options: self.constants.options(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: self.target_format,
                        blend: Some(blend),
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
    }
}

/// A template mesh instanced once per element: vertices and the triangles
/// over them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Template<V> {
    pub vertices: Vec<V>,
    pub indices: Vec<u16>,
}

impl<V> Template<V> {
    /// A template from a plain triangle list (every vertex used once).
    pub fn from_triangle_list(vertices: Vec<V>) -> Self {
        let indices = (0..vertices.len())
            .filter_map(|i| u16::try_from(i).ok())
            .collect();
        Self { vertices, indices }
    }

    #[cfg(test)]
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }
}

/// A template on the GPU, shared by every view.
pub struct TemplateBuffer {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
}

impl TemplateBuffer {
    pub fn new<V: Pod>(device: &wgpu::Device, label: &str, template: &Template<V>) -> Self {
        // Index buffers are padded to 4 bytes (a WebGPU copy rule).
        let mut indices = template.indices.clone();
        if indices.len() % 2 == 1 {
            indices.push(0);
        }
        Self {
            vertices: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytemuck::cast_slice(&template.vertices),
                usage: wgpu::BufferUsages::VERTEX,
            }),
            indices: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytemuck::cast_slice(&indices),
                usage: wgpu::BufferUsages::INDEX,
            }),
            index_count: u32::try_from(template.indices.len()).unwrap_or(0),
        }
    }
}

/// A vertex buffer holding `count` elements (never empty on the GPU, which
/// rejects zero-sized vertex buffers).
pub struct VertexData {
    pub buffer: wgpu::Buffer,
    pub count: u32,
}

/// The most of `data` that one buffer of at most `max_buffer_size` bytes
/// holds. wgpu panics on a larger buffer, so a mesh grown past it (an
/// editing run that makes a million edges) is drawn in part, never a dead
/// page.
pub fn fitting<'a, T>(label: &str, data: &'a [T], max_buffer_size: u64) -> &'a [T] {
    let most = usize::try_from(max_buffer_size).unwrap_or(usize::MAX) / size_of::<T>().max(1);
    if data.len() > most {
        log::warn!(
            "{label}: {} elements do not fit in one buffer; drawing the first {most}",
            data.len()
        );
        &data[..most]
    } else {
        data
    }
}

impl VertexData {
    pub fn new<T: Pod + Default>(device: &wgpu::Device, label: &str, data: &[T]) -> Self {
        let data = fitting(label, data, device.limits().max_buffer_size);
        let fallback = [T::default()];
        let contents: &[T] = if data.is_empty() { &fallback } else { data };
        Self {
            buffer: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytemuck::cast_slice(contents),
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            }),
            count: u32::try_from(data.len()).unwrap_or(0),
        }
    }

    /// Rewrites in place when the size matches, else reallocates.
    pub fn update<T: Pod + Default>(
        slot: &mut Option<Self>,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        label: &str,
        data: &[T],
    ) {
        match slot {
            Some(existing) if existing.count as usize == data.len() && !data.is_empty() => {
                queue.write_buffer(&existing.buffer, 0, bytemuck::cast_slice(data));
            }
            _ => *slot = Some(Self::new(device, label, data)),
        }
    }
}

/// An index buffer of `count` u32 indices (never empty on the GPU).
pub struct IndexData {
    pub buffer: wgpu::Buffer,
    pub count: u32,
}

impl IndexData {
    pub fn new(device: &wgpu::Device, label: &str, indices: &[u32]) -> Self {
        let fitted = fitting(label, indices, device.limits().max_buffer_size);
        // Cut down to whole lines and triangles.
        let indices = if fitted.len() < indices.len() {
            &fitted[..fitted.len() - fitted.len() % 6]
        } else {
            indices
        };
        let contents: &[u32] = if indices.is_empty() { &[0] } else { indices };
        Self {
            buffer: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytemuck::cast_slice(contents),
                usage: wgpu::BufferUsages::INDEX,
            }),
            count: u32::try_from(indices.len()).unwrap_or(0),
        }
    }
}

/// One view's per-element data for a drawable (sphere or arrow instances,
/// face corners) and each element's style. Both are rewritten in place
/// while the element count stays and reallocated when it changes.
pub struct StyledBuffers<T> {
    /// Buffer labels: elements, styles.
    labels: [&'static str; 2],
    elements: Option<VertexData>,
    styles: Option<VertexData>,
    element: std::marker::PhantomData<T>,
}

impl<T: Pod + Default> StyledBuffers<T> {
    pub fn new(elements_label: &'static str, styles_label: &'static str) -> Self {
        Self {
            labels: [elements_label, styles_label],
            elements: None,
            styles: None,
            element: std::marker::PhantomData,
        }
    }

    /// Replaces the elements (a new mesh, usually of another size).
    pub fn replace_elements(&mut self, device: &wgpu::Device, elements: &[T]) {
        self.elements = Some(VertexData::new(device, self.labels[0], elements));
    }

    /// Replaces the elements and their styles (the few drawn in full over
    /// the coarse level of detail).
    pub fn replace(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        (elements, styles): &(Vec<T>, Vec<StyleVertex>),
    ) {
        self.replace_elements(device, elements);
        self.write_styles(device, queue, styles);
    }

    /// Rewrites the elements, in place while their count stays (the axes,
    /// every frame).
    pub fn write_elements(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, elements: &[T]) {
        VertexData::update(&mut self.elements, device, queue, self.labels[0], elements);
    }

    /// Rewrites the styles, in place while their count stays.
    pub fn write_styles(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        styles: &[StyleVertex],
    ) {
        VertexData::update(&mut self.styles, device, queue, self.labels[1], styles);
    }

    /// Rewrites runs of styles in place, each from its first element; runs
    /// past the buffer's end are cut off there.
    pub fn patch_styles(&self, queue: &wgpu::Queue, runs: &[(u32, Vec<StyleVertex>)]) {
        let Some(styles) = &self.styles else {
            return;
        };
        for (first, run) in runs {
            let room = (styles.count as usize).saturating_sub(*first as usize);
            let run = &run[..run.len().min(room)];
            if !run.is_empty() {
                let offset = u64::from(*first) * size_of::<StyleVertex>() as u64;
                queue.write_buffer(&styles.buffer, offset, bytemuck::cast_slice(run));
            }
        }
    }

    /// The elements and their styles, once both have been uploaded.
    pub fn uploaded(&self) -> Option<(&VertexData, &VertexData)> {
        Some((self.elements.as_ref()?, self.styles.as_ref()?))
    }
}

/// The vertex buffers of an instanced drawable: its template's vertices
/// (`V`), one instance per element (`I`), and each element's style.
pub fn instanced_layouts<'a, V, I>(
    template: &'a [wgpu::VertexAttribute],
    instance: &'a [wgpu::VertexAttribute],
    style: &'a [wgpu::VertexAttribute; 2],
) -> [Option<wgpu::VertexBufferLayout<'a>>; 3] {
    [
        Some(wgpu::VertexBufferLayout {
            array_stride: size_of::<V>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: template,
        }),
        Some(wgpu::VertexBufferLayout {
            array_stride: size_of::<I>() as u64,
            step_mode: wgpu::VertexStepMode::Instance,
            attributes: instance,
        }),
        Some(style_layout(wgpu::VertexStepMode::Instance, style)),
    ]
}

/// Draws `instances` copies of `template`: the template in vertex buffer 0,
/// `instance_buffers` from slot 1 on.
pub fn draw_instanced(
    pass: &mut wgpu::RenderPass<'static>,
    pipeline: &wgpu::RenderPipeline,
    template: &TemplateBuffer,
    instance_buffers: &[&wgpu::Buffer],
    instances: u32,
) {
    if instances == 0 || template.index_count == 0 {
        return;
    }
    pass.set_pipeline(pipeline);
    pass.set_vertex_buffer(0, template.vertices.slice(..));
    for (slot, buffer) in (1_u32..).zip(instance_buffers) {
        pass.set_vertex_buffer(slot, buffer.slice(..));
    }
    pass.set_index_buffer(template.indices.slice(..), wgpu::IndexFormat::Uint16);
    pass.draw_indexed(0..template.index_count, 0, 0..instances);
}

#[cfg(test)]
mod tests {
    use super::fitting;

    #[test]
    fn what_does_not_fit_in_a_buffer_is_cut_not_a_panic() {
        let data = vec![[0.0_f32; 4]; 1000];
        assert_eq!(fitting("test", &data, 256).len(), 16);
        assert_eq!(fitting("test", &data, 16_000).len(), 1000);
        assert_eq!(fitting("test", &data, 15_999).len(), 999);
        assert!(fitting("test", &data, 0).is_empty());
    }
}
