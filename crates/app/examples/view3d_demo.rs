//! A window with only the 3D view and its options, for trying the view by
//! hand: `cargo run -p edgewise-app --example view3d_demo [torus|cube|grid] [--half]`.
//!
//! Clicking an element highlights it yellow and labels it; hovering shows
//! the preview. The side panel holds the view options.

use edgewise_core::mesh::{Mesh, Polygons, Structure, generate};
use edgewise_core::schema::{ElementKind, ElementRef};
use edgewise_pictures::geometry::MeshGeometry;
use edgewise_pictures::options::{DrawIds, PickFilter, ViewOptions};
use edgewise_pictures::styles::{ElementStyle, Pointer, SceneStyles};
use edgewise_renderer::view3d::View3d;
use egui::Color32;

struct Demo {
    view: View3d,
    geometry: MeshGeometry,
    styles: SceneStyles,
    options: ViewOptions,
    selected: Option<ElementRef>,
    hovered: Option<ElementRef>,
}

fn polygons(name: &str) -> Polygons {
    match name {
        "cube" => generate::cube(),
        "grid" => {
            // Bumped out of its plane, so the view has some depth to show.
            let mut grid = generate::grid(4, 3);
            for p in grid.positions_mut() {
                p.z = ((p.x + p.y) * 0.7).sin() * 0.3;
            }
            grid
        }
        "torus200k" => generate::torus(400, 250),
        "torus20k" => generate::torus(100, 100),
        _ => generate::torus(24, 12),
    }
}

impl Demo {
    fn new(cc: &eframe::CreationContext<'_>) -> Self {
        let args: Vec<String> = std::env::args().skip(1).collect();
        let name = args
            .iter()
            .find(|a| !a.starts_with("--"))
            .map_or("torus", String::as_str);
        let structure = if args.iter().any(|a| a == "--half") {
            Structure::HalfEdge
        } else {
            Structure::WingedEdge
        };
        let geometry = match Mesh::build(&polygons(name), structure) {
            Ok((mesh, _)) => MeshGeometry::from_mesh(&mesh),
            Err(error) => {
                eprintln!("cannot build {name}: {error}");
                MeshGeometry::default()
            }
        };
        let mut view = View3d::new(cc.wgpu_render_state.as_ref());
        view.set_geometry(geometry.clone(), true);
        let mut demo = Self {
            view,
            geometry,
            styles: SceneStyles::default(),
            options: ViewOptions::default(),
            selected: None,
            hovered: None,
        };
        demo.restyle();
        demo
    }

    fn restyle(&mut self) {
        let generation = self.styles.generation + 1;
        let mut styles = SceneStyles {
            generation,
            ..SceneStyles::default()
        };
        if let Some(pick) = self.selected {
            styles.elements.insert(
                pick,
                ElementStyle {
                    colour: Some(Color32::from_rgb(232, 196, 40)),
                    faded: false,
                    label: Some(format!("{}: picked", pick.id)),
                },
            );
            styles.pointers.push(Pointer {
                target: pick,
                colour: Color32::from_rgb(80, 180, 230),
            });
        }
        self.styles = styles;
    }

    fn options_ui(&mut self, ui: &mut egui::Ui) {
        let o = &mut self.options;
        ui.heading("View options");
        egui::ComboBox::from_label("Draw ids")
            .selected_text(format!("{:?}", o.draw_ids))
            .show_ui(ui, |ui| {
                for ids in [DrawIds::Highlighted, DrawIds::Always, DrawIds::Never] {
                    ui.selectable_value(&mut o.draw_ids, ids, format!("{ids:?}"));
                }
            });
        ui.add(egui::Slider::new(&mut o.mesh_scale, 0.2..=4.0).text("Mesh scale"));
        ui.add(egui::Slider::new(&mut o.label_scale, 0.5..=3.0).text("Label scale"));
        ui.checkbox(&mut o.show_axes, "Axes");
        ui.checkbox(&mut o.show_orientation, "Face orientation");
        ui.checkbox(&mut o.solid_faces, "Solid faces");
        ui.checkbox(&mut o.dark, "Dark");
        egui::ComboBox::from_label("Pickable")
            .selected_text(format!("{:?}", o.pickable))
            .show_ui(ui, |ui| {
                for filter in [
                    PickFilter::All,
                    PickFilter::Only(ElementKind::Vertex),
                    PickFilter::Only(ElementKind::Edge),
                    PickFilter::Only(ElementKind::Face),
                ] {
                    ui.selectable_value(&mut o.pickable, filter, format!("{filter:?}"));
                }
            });
        ui.separator();
        if ui.button("Frame all").clicked() {
            self.view.frame_all();
        }
        ui.label(format!("selected: {:?}", self.selected));
        ui.label(format!("hovered: {:?}", self.hovered));
        ui.label(format!(
            "{} vertices, {} arrows, {} faces",
            self.geometry.positions.len(),
            self.geometry.edges.len(),
            self.geometry.faces.len()
        ));
        let dt = ui.input(|i| i.unstable_dt);
        ui.label(format!("frame: {:.1} ms", dt * 1000.0));
    }
}

impl eframe::App for Demo {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        egui::Panel::left("options").show(ui, |ui| self.options_ui(ui));
        egui::CentralPanel::default()
            .frame(egui::Frame::NONE)
            .show(ui, |ui| {
                let response = self.view.ui(ui, &self.styles, &self.options);
                self.hovered = response.hovered;
                if let Some(pick) = response.clicked {
                    self.selected = Some(pick);
                    self.restyle();
                } else if response.background_clicked {
                    self.selected = None;
                    self.restyle();
                }
            });
    }
}

fn main() -> eframe::Result {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("Edgewise 3D view")
            .with_inner_size([1100.0, 750.0]),
        depth_buffer: edgewise_renderer::view3d::DEPTH_BITS,
        ..Default::default()
    };
    eframe::run_native(
        "view3d demo",
        options,
        Box::new(|cc| Ok(Box::new(Demo::new(cc)))),
    )
}
