//! The top-level eframe application.

use crate::{GraphicsBackend, state::AppState};

/// The Edgewise application.
pub struct EdgewiseApp {
    backend: GraphicsBackend,
    frames: u64,
}

impl EdgewiseApp {
    /// Creates the app from eframe's creation context.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        Self::with_backend(GraphicsBackend::from_render_state(
            cc.wgpu_render_state.as_ref(),
        ))
    }

    /// Creates the app for a known backend (UI tests run without a GPU).
    pub fn with_backend(backend: GraphicsBackend) -> Self {
        Self { backend, frames: 0 }
    }

    /// The graphics backend in use.
    pub fn backend(&self) -> GraphicsBackend {
        self.backend
    }

    /// A snapshot of the observable state.
    pub fn state(&self) -> AppState {
        AppState {
            version: edgewise_core::VERSION,
            backend: self.backend.as_str(),
            frames: self.frames,
        }
    }

    fn top_bar_ui(ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.heading("Edgewise");
            ui.separator();
            ui.label("winged-edge and half-edge meshes, table by table");
        });
    }

    fn central_ui(&self, ui: &mut egui::Ui) {
        ui.centered_and_justified(|ui| {
            ui.label(format!(
                "Edgewise {} is running on {}.",
                edgewise_core::VERSION,
                self.backend.as_str()
            ));
        });
    }
}

impl eframe::App for EdgewiseApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.frames += 1;
        egui::Panel::top("top_bar").show(ui, Self::top_bar_ui);
        egui::CentralPanel::default().show(ui, |ui| self.central_ui(ui));
    }

    #[cfg(target_arch = "wasm32")]
    fn as_any_mut(&mut self) -> Option<&mut dyn std::any::Any> {
        Some(&mut *self)
    }
}
