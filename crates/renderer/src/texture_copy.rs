//! Copying a texture the size of a paint callback's viewport over it, as
//! the 3D view's base image and the UI cache do: one triangle, each pixel
//! its texel (`textureLoad`, since a software renderer pays more for a
//! filtered sample), blended premultiplied as egui draws.

/// The vertex stage (`vs_copy`) and `copied_texel(uv)`; the shader that
/// uses them declares `copied_image` and its fragment stage.
pub const SHADER: &str = include_str!("texture_copy.wgsl");

/// The bind group layout of the copied texture: one texture read with
/// `textureLoad` in the fragment stage.
pub fn image_layout(device: &wgpu::Device, label: &str) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(label),
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: false },
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
            count: None,
        }],
    })
}

/// A texture drawn into and then copied: the view to draw into and the
/// bind group (of [`image_layout`]) that copies it.
pub struct CopySource {
    pub size: [u32; 2],
    pub view: wgpu::TextureView,
    pub bind_group: wgpu::BindGroup,
}

impl CopySource {
    pub fn new(
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        label: &str,
        format: wgpu::TextureFormat,
        size: [u32; 2],
    ) -> Self {
        let view = render_target(
            device,
            label,
            format,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
            size,
        );
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(label),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::TextureView(&view),
            }],
        });
        Self {
            size,
            view,
            bind_group,
        }
    }
}

/// A new `size`-pixel texture's view, to draw into.
pub fn render_target(
    device: &wgpu::Device,
    label: &str,
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
    size: [u32; 2],
) -> wgpu::TextureView {
    device
        .create_texture(&wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d {
                width: size[0],
                height: size[1],
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage,
            view_formats: &[],
        })
        .create_view(&wgpu::TextureViewDescriptor::default())
}

/// A copy pipeline's shader, fragment stage and bind groups.
pub struct CopySpec<'a> {
    pub label: &'a str,
    /// WGSL that includes [`SHADER`].
    pub source: &'a str,
    pub fragment_entry: &'a str,
    pub bind_group_layouts: &'a [Option<&'a wgpu::BindGroupLayout>],
    pub options: wgpu::PipelineCompilationOptions<'a>,
}

/// A pipeline that copies into egui's pass, whose depth attachment it
/// neither tests nor writes.
pub fn pipeline(
    device: &wgpu::Device,
    target_format: wgpu::TextureFormat,
    depth_format: wgpu::TextureFormat,
    spec: &CopySpec<'_>,
) -> wgpu::RenderPipeline {
    let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some(spec.label),
        bind_group_layouts: spec.bind_group_layouts,
        immediate_size: 0,
    });
    let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(spec.label),
        source: wgpu::ShaderSource::Wgsl(spec.source.into()),
    });
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(spec.label),
        layout: Some(&layout),
        vertex: wgpu::VertexState {
            module: &shader,
            entry_point: Some("vs_copy"),
            compilation_options: spec.options.clone(),
            buffers: &[],
        },
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: Some(wgpu::DepthStencilState {
            format: depth_format,
            depth_write_enabled: Some(false),
            depth_compare: Some(wgpu::CompareFunction::Always),
            stencil: wgpu::StencilState::default(),
            bias: wgpu::DepthBiasState::default(),
        }),
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module: &shader,
            entry_point: Some(spec.fragment_entry),
            compilation_options: spec.options.clone(),
            targets: &[Some(wgpu::ColorTargetState {
                format: target_format,
                blend: Some(wgpu::BlendState::PREMULTIPLIED_ALPHA_BLENDING),
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    })
}
