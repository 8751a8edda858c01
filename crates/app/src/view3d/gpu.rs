//! Shared GPU setup: pipelines (kept in `egui_wgpu`'s callback resources),
//! per-view buffers, and the paint callback that uploads and draws.
//!
//! Everything works on WebGL2 as well as WebGPU: per-instance data comes in
//! instance vertex buffers (no storage buffers), draws use neither a base
//! vertex nor a first instance, and there is a single uniform buffer.

use std::collections::HashMap;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use bytemuck::{Pod, Zeroable};
use eframe::egui_wgpu::{self, CallbackResources, CallbackTrait, RenderState, ScreenDescriptor};
use wgpu::util::DeviceExt as _;

use super::{arrows, faces, orientation, spheres};

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
}

/// Per-element look on the GPU: colour (with alpha for faces) and extras
/// (x: emphasis, y: arrow ends kept in place).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Pod, Zeroable)]
pub struct StyleVertex {
    pub colour: [u8; 4],
    pub extra: [u8; 4],
}

/// An arrow instance: start and end in world space.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct ArrowInstance {
    pub start: [f32; 3],
    pub end: [f32; 3],
}

/// An orientation mark instance: center and the two scaled in-plane axes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct MarkInstance {
    pub center: [f32; 3],
    pub u: [f32; 3],
    pub v: [f32; 3],
}

/// Geometry buffers' contents, built on the CPU when the mesh changes and
/// uploaded once.
#[derive(Default)]
pub struct GeometryUpload {
    pub id: u64,
    pub spheres: Vec<[f32; 3]>,
    pub arrows: Vec<ArrowInstance>,
    /// Three corners per triangle.
    pub faces: Vec<[f32; 3]>,
    pub marks: Vec<MarkInstance>,
}

/// Style buffers' contents, rebuilt when the styles' generation changes.
#[derive(Default)]
pub struct StyleUpload {
    pub id: u64,
    pub vertices: Vec<StyleVertex>,
    pub edges: Vec<StyleVertex>,
    /// Three per triangle, like [`GeometryUpload::faces`].
    pub faces: Vec<StyleVertex>,
}

/// Tells the view which uploads the GPU side has taken, so it can drop its
/// CPU copies.
#[derive(Default)]
pub struct UploadState {
    pub geometry: AtomicU64,
    pub styles: AtomicU64,
}

/// What to draw this frame besides the mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DrawFlags {
    pub axes: bool,
    pub orientation: bool,
    pub solid_faces: bool,
}

/// Pipelines and template meshes shared by every view, stored in
/// `callback_resources`.
pub struct Pipelines {
    bind_group_layout: wgpu::BindGroupLayout,
    sphere: wgpu::RenderPipeline,
    arrow: wgpu::RenderPipeline,
    face_transparent: wgpu::RenderPipeline,
    face_solid: wgpu::RenderPipeline,
    orientation: wgpu::RenderPipeline,
    /// Spheres and arrows at three and two levels of detail: the more
    /// instances, the fewer triangles each.
    spheres_by_detail: [TemplateBuffer; 3],
    arrows_by_detail: [TemplateBuffer; 2],
    mark_template: TemplateBuffer,
    srgb_target: bool,
    views: HashMap<u64, ViewBuffers>,
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

/// A template on the GPU.
struct TemplateBuffer {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
}

impl TemplateBuffer {
    fn new<V: Pod>(device: &wgpu::Device, label: &str, template: &Template<V>) -> Self {
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

/// A vertex buffer holding `count` elements (never empty on the GPU).
struct VertexData {
    buffer: wgpu::Buffer,
    count: u32,
}

impl VertexData {
    fn new<T: Pod + Default>(device: &wgpu::Device, label: &str, data: &[T]) -> Self {
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
    fn update<T: Pod + Default>(
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

/// One view's buffers.
struct ViewBuffers {
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    geometry_id: u64,
    styles_id: u64,
    spheres: Option<VertexData>,
    arrows: Option<VertexData>,
    faces: Option<VertexData>,
    marks: Option<VertexData>,
    vertex_styles: Option<VertexData>,
    edge_styles: Option<VertexData>,
    face_styles: Option<VertexData>,
    axes: Option<VertexData>,
    axes_styles: Option<VertexData>,
}

impl ViewBuffers {
    fn new(device: &wgpu::Device, layout: &wgpu::BindGroupLayout) -> Self {
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
            geometry_id: 0,
            styles_id: 0,
            spheres: None,
            arrows: None,
            faces: None,
            marks: None,
            vertex_styles: None,
            edge_styles: None,
            face_styles: None,
            axes: None,
            axes_styles: None,
        }
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
}

/// Creates pipelines for one target format.
pub struct PipelineFactory<'a> {
    pub device: &'a wgpu::Device,
    pub layout: &'a wgpu::PipelineLayout,
    pub target_format: wgpu::TextureFormat,
}

impl PipelineFactory<'_> {
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
                layout: Some(self.layout),
                vertex: wgpu::VertexState {
                    module: spec.shader,
                    entry_point: Some(spec.vertex_entry),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    buffers: spec.buffers,
                },
                primitive: wgpu::PrimitiveState {
                    topology: wgpu::PrimitiveTopology::TriangleList,
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
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
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

/// The style vertex layout at `first_location` (colour, extra).
pub const STYLE_ATTRIBUTES_SIZE: u64 = size_of::<StyleVertex>() as u64;

impl Pipelines {
    /// Creates the pipelines for a render target format.
    pub fn new(device: &wgpu::Device, target_format: wgpu::TextureFormat) -> Self {
        let bind_group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
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
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("view3d"),
            bind_group_layouts: &[Some(&bind_group_layout)],
            immediate_size: 0,
        });
        let factory = PipelineFactory {
            device,
            layout: &layout,
            target_format,
        };
        let (face_transparent, face_solid) = faces::pipelines(&factory);
        Self {
            sphere: spheres::pipeline(&factory),
            arrow: arrows::pipeline(&factory),
            face_transparent,
            face_solid,
            orientation: orientation::pipeline(&factory),
            spheres_by_detail: [2, 1, 0].map(|subdivisions| {
                TemplateBuffer::new(device, "view3d sphere", &spheres::icosphere(subdivisions))
            }),
            arrows_by_detail: [
                TemplateBuffer::new(device, "view3d arrow", &arrows::template(10, true)),
                TemplateBuffer::new(device, "view3d arrow coarse", &arrows::template(6, false)),
            ],
            mark_template: TemplateBuffer::new(device, "view3d mark", &orientation::template()),
            bind_group_layout,
            srgb_target: target_format.is_srgb(),
            views: HashMap::new(),
        }
    }

    /// Registers the pipelines with an eframe render state (once).
    pub fn install(render_state: &RenderState) {
        let mut renderer = render_state.renderer.write();
        if renderer.callback_resources.get::<Self>().is_none() {
            let pipelines = Self::new(&render_state.device, render_state.target_format);
            renderer.callback_resources.insert(pipelines);
        }
    }

    /// Forgets a view's buffers.
    pub fn remove_view(resources: &mut CallbackResources, view_id: u64) {
        if let Some(pipelines) = resources.get_mut::<Self>() {
            pipelines.views.remove(&view_id);
        }
    }
}

/// Instance counts above which spheres use their second and third level of
/// detail (320, 80, 20 triangles), and arrows their second (120, 36).
const SPHERE_DETAIL_LIMITS: [u32; 2] = [5_000, 50_000];
const ARROW_DETAIL_LIMIT: u32 = 30_000;

/// The paint callback of one view for one frame.
pub struct ViewCallback {
    pub view_id: u64,
    pub frame: FrameUniform,
    pub geometry_id: u64,
    pub styles_id: u64,
    /// Present until the GPU side has taken it.
    pub geometry: Option<Arc<GeometryUpload>>,
    pub styles: Option<Arc<StyleUpload>>,
    pub axes: [ArrowInstance; 3],
    pub axes_styles: [StyleVertex; 3],
    pub flags: DrawFlags,
    pub uploaded: Arc<UploadState>,
}

impl CallbackTrait for ViewCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen_descriptor: &ScreenDescriptor,
        _egui_encoder: &mut wgpu::CommandEncoder,
        resources: &mut CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(pipelines) = resources.get_mut::<Pipelines>() else {
            return Vec::new();
        };
        let srgb = pipelines.srgb_target;
        let layout = &pipelines.bind_group_layout;
        let view = pipelines
            .views
            .entry(self.view_id)
            .or_insert_with(|| ViewBuffers::new(device, layout));

        if let Some(geometry) = &self.geometry
            && geometry.id != view.geometry_id
        {
            view.spheres = Some(VertexData::new(device, "view3d spheres", &geometry.spheres));
            view.arrows = Some(VertexData::new(device, "view3d arrows", &geometry.arrows));
            view.faces = Some(VertexData::new(device, "view3d faces", &geometry.faces));
            view.marks = Some(VertexData::new(device, "view3d marks", &geometry.marks));
            view.geometry_id = geometry.id;
            self.uploaded.geometry.store(geometry.id, Ordering::Release);
        }
        if let Some(styles) = &self.styles
            && styles.id != view.styles_id
        {
            VertexData::update(
                &mut view.vertex_styles,
                device,
                queue,
                "view3d vertex styles",
                &styles.vertices,
            );
            VertexData::update(
                &mut view.edge_styles,
                device,
                queue,
                "view3d edge styles",
                &styles.edges,
            );
            VertexData::update(
                &mut view.face_styles,
                device,
                queue,
                "view3d face styles",
                &styles.faces,
            );
            view.styles_id = styles.id;
            self.uploaded.styles.store(styles.id, Ordering::Release);
        }
        if self.flags.axes {
            VertexData::update(&mut view.axes, device, queue, "view3d axes", &self.axes);
            VertexData::update(
                &mut view.axes_styles,
                device,
                queue,
                "view3d axes styles",
                &self.axes_styles,
            );
        }

        let mut frame = self.frame;
        frame.params[0] = if srgb { 1.0 } else { 0.0 };
        queue.write_buffer(&view.uniform, 0, bytemuck::bytes_of(&frame));
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &CallbackResources,
    ) {
        let Some(pipelines) = resources.get::<Pipelines>() else {
            return;
        };
        let Some(view) = pipelines.views.get(&self.view_id) else {
            return;
        };
        if view.geometry_id != self.geometry_id || view.styles_id != self.styles_id {
            return;
        }
        pass.set_bind_group(0, &view.bind_group, &[]);

        // Opaque first: spheres, arrows, axes, orientation marks.
        if let (Some(spheres), Some(styles)) = (&view.spheres, &view.vertex_styles) {
            let count = spheres.count.min(styles.count);
            let detail = SPHERE_DETAIL_LIMITS
                .iter()
                .filter(|&&limit| count > limit)
                .count();
            let template = &pipelines.spheres_by_detail[detail.min(2)];
            draw_instanced(
                pass,
                &pipelines.sphere,
                template,
                &[&spheres.buffer, &styles.buffer],
                count,
            );
        }
        if let (Some(arrows), Some(styles)) = (&view.arrows, &view.edge_styles) {
            let count = arrows.count.min(styles.count);
            let detail = usize::from(count > ARROW_DETAIL_LIMIT);
            draw_instanced(
                pass,
                &pipelines.arrow,
                &pipelines.arrows_by_detail[detail],
                &[&arrows.buffer, &styles.buffer],
                count,
            );
        }
        if self.flags.axes
            && let (Some(axes), Some(styles)) = (&view.axes, &view.axes_styles)
        {
            draw_instanced(
                pass,
                &pipelines.arrow,
                &pipelines.arrows_by_detail[0],
                &[&axes.buffer, &styles.buffer],
                axes.count.min(styles.count),
            );
        }
        if self.flags.orientation
            && let Some(marks) = &view.marks
        {
            draw_instanced(
                pass,
                &pipelines.orientation,
                &pipelines.mark_template,
                &[&marks.buffer],
                marks.count,
            );
        }
        // Faces last: see-through ones test depth against everything opaque
        // without hiding what is behind them.
        if let (Some(faces), Some(styles)) = (&view.faces, &view.face_styles) {
            let count = faces.count.min(styles.count);
            if count > 0 {
                let pipeline = if self.flags.solid_faces {
                    &pipelines.face_solid
                } else {
                    &pipelines.face_transparent
                };
                pass.set_pipeline(pipeline);
                pass.set_vertex_buffer(0, faces.buffer.slice(..));
                pass.set_vertex_buffer(1, styles.buffer.slice(..));
                pass.draw(0..count, 0..1);
            }
        }
    }
}

fn draw_instanced(
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

/// The vertex layout of a style buffer at shader locations `colour` and
/// `colour + 1`.
pub fn style_layout(
    step_mode: wgpu::VertexStepMode,
    attributes: &[wgpu::VertexAttribute; 2],
) -> wgpu::VertexBufferLayout<'_> {
    wgpu::VertexBufferLayout {
        array_stride: STYLE_ATTRIBUTES_SIZE,
        step_mode,
        attributes,
    }
}
