//! Pictures of the whole app, 3D view included, compared with the PNGs in
//! tests/snapshots/ (`UPDATE_SNAPSHOTS=1` rewrites them after a deliberate
//! change; a failed comparison leaves `*.new.png` and `*.diff.png` beside
//! them).
//!
//! kittest's own wgpu renderer draws without a depth buffer, which the 3D
//! view's paint callback needs, so these tests render through
//! [`DepthRenderer`]: the same `egui_wgpu` renderer with the `Depth24Plus`
//! attachment the app gets from eframe. Without a wgpu adapter (no GPU and
//! no lavapipe) the tests say so and pass.

#![allow(clippy::unwrap_used)]

use std::sync::Arc;

use edgewise_app::{
    EdgewiseApp,
    selection::{ElementKind, ElementRef},
};
use edgewise_core::mesh::Structure;
use eframe::egui_wgpu::{self, RenderState, ScreenDescriptor};
use egui_kittest::{Harness, SnapshotOptions, TestRenderer, kittest::Queryable as _};

const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// Lavapipe and the text rasteriser are deterministic on one machine; the
/// threshold absorbs small differences between Mesa versions.
fn options() -> SnapshotOptions {
    SnapshotOptions::new().threshold(1.5).max_failed_pixels(400)
}

/// A software (or any) wgpu device with WebGL2's limits, as the app gets.
fn render_state() -> Option<RenderState> {
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
        FORMAT,
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
        target_format: FORMAT,
        renderer: Arc::new(egui::mutex::RwLock::new(renderer)),
    })
}

/// Renders egui output, paint callbacks included, into an image.
struct DepthRenderer {
    state: RenderState,
}

impl TestRenderer for DepthRenderer {
    fn setup_eframe(&self, cc: &mut eframe::CreationContext<'_>, frame: &mut eframe::Frame) {
        cc.wgpu_render_state = Some(self.state.clone());
        frame.wgpu_render_state = Some(self.state.clone());
    }

    fn handle_delta(&mut self, delta: &mut egui::TexturesDelta) {
        let rs = &self.state;
        let mut renderer = rs.renderer.write();
        for (id, images) in std::mem::take(&mut delta.set) {
            for image in images {
                renderer.update_texture(&rs.device, &rs.queue, id, &image);
            }
        }
        for id in std::mem::take(&mut delta.free) {
            renderer.free_texture(&id);
        }
    }

    fn render(
        &mut self,
        ctx: &egui::Context,
        output: &egui::FullOutput,
    ) -> Result<image::RgbaImage, String> {
        let rs = &self.state;
        let ppp = ctx.pixels_per_point();
        let size = ctx.content_rect().size() * ppp;
        let (width, height) = (size.x.round() as u32, size.y.round() as u32);
        let screen = ScreenDescriptor {
            size_in_pixels: [width, height],
            pixels_per_point: ppp,
        };
        let jobs = ctx.tessellate(output.shapes.clone(), ppp);
        let mut renderer = rs.renderer.write();
        let mut encoder = rs
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
        let user_commands =
            renderer.update_buffers(&rs.device, &rs.queue, &mut encoder, &jobs, &screen);
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
            "snapshot",
            FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        );
        let depth = texture(
            "snapshot depth",
            wgpu::TextureFormat::Depth24Plus,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        );
        let target_view = target.create_view(&wgpu::TextureViewDescriptor::default());
        let depth_view = depth.create_view(&wgpu::TextureViewDescriptor::default());
        {
            let mut pass = encoder
                .begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some("snapshot"),
                    color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                        view: &target_view,
                        resolve_target: None,
                        depth_slice: None,
                        ops: wgpu::Operations {
                            load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
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
            renderer.render(&mut pass, &jobs, &screen);
        }
        let bytes_per_row = (width * 4).div_ceil(256) * 256;
        let readback = rs.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("snapshot readback"),
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
        readback
            .slice(..)
            .map_async(wgpu::MapMode::Read, |result| result.unwrap());
        rs.device
            .poll(wgpu::PollType::wait_indefinitely())
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
        image::RgbaImage::from_raw(width, height, pixels)
            .ok_or_else(|| "the readback has the wrong size".to_owned())
    }
}

/// The app in a window of `size` points at `pixels_per_point`, drawing its
/// 3D view; None without a wgpu adapter.
fn harness(size: egui::Vec2, pixels_per_point: f32) -> Option<Harness<'static, EdgewiseApp>> {
    let Some(state) = render_state() else {
        eprintln!("no wgpu adapter (install mesa-vulkan-drivers): snapshots skipped");
        return None;
    };
    Some(
        Harness::builder()
            .with_size(size)
            .with_pixels_per_point(pixels_per_point)
            .renderer(DepthRenderer { state })
            .build_eframe(|cc| EdgewiseApp::new(cc)),
    )
}

#[test]
fn tetrahedron_winged_edge_with_edge_0_selected_light() {
    let Some(mut harness) = harness(egui::vec2(1280.0, 800.0), 1.0) else {
        return;
    };
    let app = harness.state_mut();
    app.load_sample("tetrahedron", Some(Structure::WingedEdge))
        .unwrap();
    app.select(Some(ElementRef {
        kind: ElementKind::Edge,
        id: 0,
    }))
    .unwrap();
    harness.run();
    harness.snapshot_options("tetrahedron-winged-edge0-light", &options());
}

#[test]
fn cube_half_edge_dark_at_lecture_hall_scale() {
    let Some(mut harness) = harness(egui::vec2(1280.0, 720.0), 1.5) else {
        return;
    };
    harness.get_by_label("Dark theme").click();
    harness.run();
    let app = harness.state_mut();
    app.load_sample("cube", Some(Structure::HalfEdge)).unwrap();
    app.select(Some(ElementRef {
        kind: ElementKind::Face,
        id: 2,
    }))
    .unwrap();
    harness.run();
    harness.snapshot_options("cube-half-edge-face2-dark-lecture", &options());
}

/// The OBJ editor after a good square and then a face naming a missing
/// vertex: the square stays in the view, the bad line is marked.
fn obj_editor_with_an_error(dark: bool, name: &str) {
    let Some(mut harness) = harness(egui::vec2(1280.0, 800.0), 1.0) else {
        return;
    };
    if dark {
        harness.get_by_label("Dark theme").click();
        harness.run();
    }
    harness.get_by_label("OBJ editor").click();
    harness.run();
    let editor = harness.get_by_role(egui::accesskit::Role::MultilineTextInput);
    editor.focus();
    editor.type_text(
        "# a square, then a broken triangle\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n",
    );
    harness.run_steps(60);
    let editor = harness.get_by_role(egui::accesskit::Role::MultilineTextInput);
    editor.type_text("f 1 2 17\n");
    harness.run_steps(60);
    let state = harness.state().state();
    assert_eq!(state.counts.faces, 1, "the square stays");
    assert_eq!(state.diagnostics.len(), 1);
    harness.snapshot_options(name, &options());
}

#[test]
fn obj_editor_with_an_inline_error_light() {
    obj_editor_with_an_error(false, "obj-editor-error-light");
}

#[test]
fn obj_editor_with_an_inline_error_dark() {
    obj_editor_with_an_error(true, "obj-editor-error-dark");
}

#[test]
fn structure_dialog() {
    let Some(mut harness) = harness(egui::vec2(1280.0, 800.0), 1.0) else {
        return;
    };
    harness.state_mut().load_sample("octahedron", None).unwrap();
    harness
        .state_mut()
        .open_file(
            "quad.obj",
            b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n".to_vec(),
        )
        .unwrap();
    harness.run();
    harness.snapshot_options("structure-dialog", &options());
}
