//! Entry point: a desktop window natively, the page's canvas on wasm32.

#[cfg(not(target_arch = "wasm32"))]
fn main() -> eframe::Result {
    env_logger::init();
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("Edgewise")
            .with_inner_size([1280.0, 800.0]),
        depth_buffer: 24,
        ..Default::default()
    };
    eframe::run_native(
        "Edgewise",
        options,
        Box::new(|cc| {
            let mut app = edgewise_app::EdgewiseApp::new(cc);
            app.first_visit();
            Ok(Box::new(app))
        }),
    )
}

#[cfg(target_arch = "wasm32")]
fn main() {
    edgewise_app::web::start();
}
