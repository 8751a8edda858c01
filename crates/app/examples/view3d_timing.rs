//! Reports what the 3D view costs on the 20k- and 200k-face tori (and the
//! 1M-face one with `--large`): the mesh and its view geometry,
//! `set_geometry` (the scene and picking structure alone, then with the GPU
//! instance buffers), two frames drawn and read back, frames drawn while the
//! camera orbits, and the UI pass alone (headless, the camera turning every
//! frame so nothing is reused).
//!
//! `cargo run --release -p edgewise-app --example view3d_timing [-- --large]`
//!
//! The GPU rows need a wgpu adapter (lavapipe will do, slowly); without one
//! they are left out.

use std::time::{Duration, Instant};

use edgewise_core::mesh::{Mesh, Structure, generate};
use edgewise_pictures::geometry::MeshGeometry;
use edgewise_pictures::options::{DrawIds, ViewOptions};
use edgewise_pictures::styles::SceneStyles;
use edgewise_renderer::view3d::View3d;
use eframe::egui_wgpu::RenderState;

// The render tests' offscreen drawing, so a frame here costs what theirs do.
#[path = "../tests/it/support/gpu.rs"]
mod gpu;

/// The window, in pixels and points.
const SIZE: [u32; 2] = [900, 640];

/// Frames drawn while the camera orbits.
const ORBIT_FRAMES: u32 = 20;

/// A row label and its figure; None where it needs the GPU and there is none.
type Row = (&'static str, Option<Duration>);

fn main() {
    let gpu = gpu::render_state();
    match &gpu {
        Some(rs) => println!("GPU rows on {}", rs.adapter.get_info().name),
        None => println!("no wgpu adapter: GPU rows left out"),
    }
    let mut tori = vec![("20k faces", 100, 100), ("200k faces", 400, 250)];
    if std::env::args().any(|arg| arg == "--large") {
        tori.push(("1M faces", 1000, 500));
    }
    let mut columns = Vec::new();
    for &(_, nu, nv) in &tori {
        match measure(nu, nv, gpu.as_ref()) {
            Ok(rows) => columns.push(rows),
            Err(message) => {
                eprintln!("torus {nu}×{nv}: {message}");
                return;
            }
        }
    }
    print!("{:<44}", "torus");
    for &(name, _, _) in &tori {
        print!("{name:>14}");
    }
    println!();
    for (i, &(label, _)) in columns[0].iter().enumerate() {
        print!("{label:<44}");
        for column in &columns {
            match column[i].1 {
                Some(time) => print!("{:>11.3} ms", time.as_secs_f64() * 1e3),
                None => print!("{:>14}", "-"),
            }
        }
        println!();
    }
}

fn time<T>(f: impl FnOnce() -> T) -> (T, Duration) {
    let start = Instant::now();
    let value = f();
    (value, start.elapsed())
}

fn measure(nu: u32, nv: u32, gpu: Option<&RenderState>) -> Result<Vec<Row>, String> {
    let polygons = generate::torus(nu, nv);
    let (built, build) = time(|| Mesh::build(&polygons, Structure::HalfEdge));
    let (mesh, _) = built.map_err(|error| error.to_string())?;
    let (geometry, from_mesh) = time(|| MeshGeometry::from_mesh(&mesh));
    let styles = SceneStyles {
        generation: 1,
        ..SceneStyles::default()
    };
    let always = ViewOptions {
        draw_ids: DrawIds::Always,
        ..ViewOptions::default()
    };
    let screen =
        egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(SIZE[0] as f32, SIZE[1] as f32));

    let (mut with_gpu, mut drawn, mut orbit) = (None, [None, None], None);
    if let Some(rs) = gpu {
        let mut view = View3d::new(Some(rs));
        let copy = geometry.clone();
        with_gpu = Some(time(|| view.set_geometry(copy, true)).1);
        let ctx = egui::Context::default();
        for (options, slot) in [ViewOptions::default(), always.clone()]
            .iter()
            .zip(&mut drawn)
        {
            // The first frame uploads the buffers and frames the mesh.
            let (result, took) = time(|| {
                for _ in 0..2 {
                    gpu::draw_frame(rs, &ctx, screen, SIZE, Vec::new(), |ui| {
                        view.ui(ui, &styles, options);
                    })?;
                }
                Ok::<_, String>(())
            });
            result?;
            *slot = Some(took);
        }
        // Orbiting: each frame turns the camera, is drawn and is waited for
        // (read back), as a frame the page presents is.
        let (result, took) = time(|| {
            for _ in 0..ORBIT_FRAMES {
                let mut camera = view.camera();
                camera.yaw += 0.05;
                view.set_camera(camera);
                gpu::draw_frame(rs, &ctx, screen, SIZE, Vec::new(), |ui| {
                    view.ui(ui, &styles, &ViewOptions::default());
                })?;
            }
            Ok::<_, String>(())
        });
        result?;
        orbit = Some(took / ORBIT_FRAMES);
    }

    let mut headless = View3d::new(None);
    let headless_set = time(|| headless.set_geometry(geometry, true)).1;
    let ctx = egui::Context::default();
    let mut passes = Vec::new();
    for (options, count, hover) in [
        (ViewOptions::default(), 1, false),
        (ViewOptions::default(), 10, false),
        (always, 10, false),
        (ViewOptions::default(), 10, true),
    ] {
        let took = time(|| {
            for i in 0..count {
                let mut camera = headless.camera();
                camera.yaw += 0.01;
                headless.set_camera(camera);
                let events = if hover {
                    let at = egui::pos2(450.0 + i as f32 * 7.0, 300.0);
                    vec![egui::Event::PointerMoved(at)]
                } else {
                    Vec::new()
                };
                let raw = egui::RawInput {
                    screen_rect: Some(screen),
                    events,
                    ..Default::default()
                };
                ctx.run_ui(raw, |ui| {
                    headless.ui(ui, &styles, &options);
                })
                .drop_without_applying_deltas();
            }
        })
        .1;
        passes.push(Some(took / count));
    }

    Ok(vec![
        ("build the half-edge mesh", Some(build)),
        ("MeshGeometry::from_mesh", Some(from_mesh)),
        (
            "set_geometry headless (scene, picking BVH)",
            Some(headless_set),
        ),
        ("set_geometry with GPU buffers", with_gpu),
        ("two frames drawn, highlighted ids", drawn[0]),
        ("two frames drawn, all ids", drawn[1]),
        ("orbiting, per frame drawn and read back", orbit),
        ("UI pass: first frame", passes[0]),
        ("UI pass per frame: highlighted ids", passes[1]),
        ("UI pass per frame: all ids", passes[2]),
        ("UI pass per frame: hover picking", passes[3]),
    ])
}
