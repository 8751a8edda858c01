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
