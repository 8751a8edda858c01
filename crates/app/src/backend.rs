//! Which graphics API the 3D view ended up on.

/// The graphics backend the app is drawing with, as reported to page authors
/// and browser tests through `window.edgewise.backend`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GraphicsBackend {
    WebGpu,
    WebGl2,
    Vulkan,
    Metal,
    Dx12,
    Gl,
    /// No wgpu render state, e.g. in headless UI tests.
    None,
}

impl GraphicsBackend {
    /// Reads the backend off eframe's wgpu render state.
    pub fn from_render_state(render_state: Option<&eframe::egui_wgpu::RenderState>) -> Self {
        let Some(render_state) = render_state else {
            return Self::None;
        };
        match render_state.adapter.get_info().backend {
            wgpu::Backend::BrowserWebGpu => Self::WebGpu,
            wgpu::Backend::Gl if cfg!(target_arch = "wasm32") => Self::WebGl2,
            wgpu::Backend::Gl => Self::Gl,
            wgpu::Backend::Vulkan => Self::Vulkan,
            wgpu::Backend::Metal => Self::Metal,
            wgpu::Backend::Dx12 => Self::Dx12,
            wgpu::Backend::Noop => Self::None,
        }
    }

    /// The name used by the JavaScript API: "webgpu" or "webgl2" in a browser.
    pub fn as_str(self) -> &'static str {
        match self {
            Self::WebGpu => "webgpu",
            Self::WebGl2 => "webgl2",
            Self::Vulkan => "vulkan",
            Self::Metal => "metal",
            Self::Dx12 => "dx12",
            Self::Gl => "gl",
            Self::None => "none",
        }
    }
}
