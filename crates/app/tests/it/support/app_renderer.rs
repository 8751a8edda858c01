//! The renderer every app harness uses for snapshots.

use eframe::egui_wgpu::{RenderState, ScreenDescriptor};
use egui_kittest::TestRenderer;

use super::gpu::{render_state, render_to_pixels};

/// Renders the app's egui output, paint callbacks included, into an image
/// as eframe draws it: the frame cleared to [`edgewise_app::backdrop`] (panels
/// draw no fill of their own) and with the `Depth24Plus` attachment the 3D
/// view's pipelines need.
pub struct AppRenderer {
    state: Option<RenderState>,
}

impl AppRenderer {
    /// Hands `state` to the app, whose 3D view draws with it.
    pub fn drawing_3d(state: RenderState) -> Self {
        Self { state: Some(state) }
    }

    /// For an app without a 3D view: the adapter is found at the first
    /// snapshot, so harnesses that take none need no GPU.
    pub fn lazy() -> Self {
        Self { state: None }
    }

    fn state(&mut self) -> Result<&RenderState, String> {
        if self.state.is_none() {
            self.state = render_state();
        }
        self.state
            .as_ref()
            .ok_or_else(|| "no wgpu adapter (install mesa-vulkan-drivers)".to_owned())
    }
}

impl TestRenderer for AppRenderer {
    fn setup_eframe(&self, cc: &mut eframe::CreationContext<'_>, frame: &mut eframe::Frame) {
        cc.wgpu_render_state.clone_from(&self.state);
        frame.wgpu_render_state.clone_from(&self.state);
    }

    fn handle_delta(&mut self, delta: &mut egui::TexturesDelta) {
        let Ok(rs) = self.state() else {
            return;
        };
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
        let rs = self.state()?;
        let ppp = ctx.pixels_per_point();
        let size = ctx.content_rect().size() * ppp;
        let (width, height) = (size.x.round() as u32, size.y.round() as u32);
        let screen = ScreenDescriptor {
            size_in_pixels: [width, height],
            pixels_per_point: ppp,
        };
        let jobs = ctx.tessellate(output.shapes.clone(), ppp);
        let [r, g, b, a] =
            edgewise_app::visuals::backdrop(ctx.global_style().visuals.dark_mode).map(f64::from);
        let clear = wgpu::Color { r, g, b, a };
        let pixels = render_to_pixels(rs, &jobs, &screen, clear)?;
        image::RgbaImage::from_raw(width, height, pixels)
            .ok_or_else(|| "the readback has the wrong size".to_owned())
    }
}
