//! Drawing egui output, paint callbacks included, into pixels on whatever
//! wgpu adapter the machine has (lavapipe on CI), with the 24-bit depth
//! attachment the 3D view's pipelines expect.

use std::sync::Arc;

use eframe::egui_wgpu::{self, RenderState, ScreenDescriptor};

/// The colour format the tests render into.
pub const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// Renders `jobs` into a fresh `screen`-sized target cleared to `clear` and
/// reads it back as tightly packed RGBA rows.
pub fn render_to_pixels(
    rs: &RenderState,
    jobs: &[egui::ClippedPrimitive],
    screen: &ScreenDescriptor,
    clear: wgpu::Color,
) -> Result<Vec<u8>, String> {
    let [width, height] = screen.size_in_pixels;
    let mut renderer = rs.renderer.write();
    let mut encoder = rs
        .device
        .create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
    let user_commands = renderer.update_buffers(&rs.device, &rs.queue, &mut encoder, jobs, screen);
    let extent = wgpu::Extent3d {
        width,
        height,
        depth_or_array_layers: 1,
    };
    let texture = |label, format, usage| {
        rs.device.create_texture(&wgpu::TextureDescriptor {
            label: Some(label),
            size: extent,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage,
            view_formats: &[],
        })
    };
    let target = texture(
        "test target",
        rs.target_format,
        wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
    );
    let depth = texture(
        "test depth",
        wgpu::TextureFormat::Depth24Plus,
        wgpu::TextureUsages::RENDER_ATTACHMENT,
    );
    let target_view = target.create_view(&wgpu::TextureViewDescriptor::default());
    let depth_view = depth.create_view(&wgpu::TextureViewDescriptor::default());
    {
        let mut pass = encoder
            .begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("test pass"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &target_view,
                    resolve_target: None,
                    depth_slice: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(clear),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth_view,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Discard,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            })
            .forget_lifetime();
        renderer.render(&mut pass, jobs, screen);
    }
    let bytes_per_row = (width * 4).div_ceil(256) * 256;
    let readback = rs.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("test readback"),
        size: u64::from(bytes_per_row * height),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    encoder.copy_texture_to_buffer(
        wgpu::TexelCopyTextureInfo {
            texture: &target,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        wgpu::TexelCopyBufferInfo {
            buffer: &readback,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(bytes_per_row),
                rows_per_image: None,
            },
        },
        extent,
    );
    rs.queue
        .submit(user_commands.into_iter().chain([encoder.finish()]));
    drop(renderer);
    let (sender, receiver) = std::sync::mpsc::channel();
    readback
        .slice(..)
        .map_async(wgpu::MapMode::Read, move |result| {
            sender.send(result).ok();
        });
    rs.device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|err| err.to_string())?;
    receiver
        .recv()
        .map_err(|err| err.to_string())?
        .map_err(|err| err.to_string())?;
    let mapped = readback
        .slice(..)
        .get_mapped_range()
        .map_err(|err| format!("{err:?}"))?;
    let mut pixels = Vec::with_capacity((width * height * 4) as usize);
    for row in 0..height {
        let start = (row * bytes_per_row) as usize;
        pixels.extend_from_slice(&mapped[start..start + (width * 4) as usize]);
    }
    Ok(pixels)
}

/// Runs `ui` for one frame on `screen` (in points) and draws it into `size`
/// pixels as eframe would, texture uploads included; returns the pixels as
/// [`render_to_pixels`] does.
pub fn draw_frame(
    rs: &RenderState,
    ctx: &egui::Context,
    screen: egui::Rect,
    size: [u32; 2],
    events: Vec<egui::Event>,
    mut ui: impl FnMut(&mut egui::Ui),
) -> Result<Vec<u8>, String> {
    let raw = egui::RawInput {
        screen_rect: Some(screen),
        events,
        ..Default::default()
    };
    let mut output = ctx.run_ui(raw, |root| ui(root));
    let jobs = ctx.tessellate(std::mem::take(&mut output.shapes), output.pixels_per_point);
    let descriptor = ScreenDescriptor {
        size_in_pixels: size,
        pixels_per_point: output.pixels_per_point,
    };
    let mut renderer = rs.renderer.write();
    for (id, deltas) in &output.textures_delta.set {
        for delta in deltas {
            renderer.update_texture(&rs.device, &rs.queue, *id, delta);
        }
    }
    drop(renderer);
    let pixels = render_to_pixels(rs, &jobs, &descriptor, wgpu::Color::BLACK)?;
    let mut renderer = rs.renderer.write();
    for id in &output.textures_delta.free {
        renderer.free_texture(id);
    }
    // Applied above; epaint panics on dropping deltas not marked handled.
    output.textures_delta.clear();
    Ok(pixels)
}

/// Set by `cargo xtask test`: a GPU test without an adapter then fails
/// instead of passing without having drawn anything.
const REQUIRE_GPU: &str = "EDGEWISE_REQUIRE_GPU";

/// A software (or any) wgpu device with WebGL2's limits, as the app gets;
/// None without an adapter, unless [`REQUIRE_GPU`] is set, which makes that
/// a failure. `WGPU_BACKEND=gl` runs the GLSL path WebGL2 also takes.
pub fn render_state() -> Option<RenderState> {
    render_state_for(FORMAT)
}

/// As [`render_state`], rendering into `format`.
pub fn render_state_for(format: wgpu::TextureFormat) -> Option<RenderState> {
    let state = adapter_render_state(format);
    assert!(
        state.is_some() || std::env::var_os(REQUIRE_GPU).is_none_or(|v| v == "0"),
        "no wgpu adapter, and {REQUIRE_GPU} is set: install mesa-vulkan-drivers (lavapipe) \
         so the rendering tests can draw"
    );
    state
}

fn adapter_render_state(format: wgpu::TextureFormat) -> Option<RenderState> {
    let instance = wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends: wgpu::Backends::from_env().unwrap_or(wgpu::Backends::VULKAN | wgpu::Backends::GL),
        ..wgpu::InstanceDescriptor::new_without_display_handle()
    });
    let adapter =
        pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
            .ok()?;
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        required_limits:
            wgpu::Limits::downlevel_webgl2_defaults().using_resolution(adapter.limits()),
        ..Default::default()
    }))
    .ok()?;
    let renderer = egui_wgpu::Renderer::new(
        &device,
        format,
        egui_wgpu::RendererOptions {
            msaa_samples: 1,
            depth_stencil_format: egui_wgpu::depth_format_from_bits(24, 0),
            dithering: false,
            predictable_texture_filtering: true,
        },
    );
    Some(RenderState {
        adapter,
        available_adapters: Vec::new(),
        instance,
        device,
        queue,
        target_format: format,
        renderer: Arc::new(egui::mutex::RwLock::new(renderer)),
    })
}
