//! The statistics window: the counts and invariants of the open mesh (V, E,
//! F, V − E + F, genus, boundary loops, components) and the warnings its
//! build gave, each row explained, so Euler's formula can be checked on any
//! mesh without the command line.

use edgewise_core::mesh::MeshStats;

use super::EdgewiseApp;

/// Components listed one by one before "and N more".
const LISTED: usize = 8;

impl EdgewiseApp {
    pub(super) fn statistics_window_ui(&mut self, ctx: &egui::Context) {
        if !self.show_statistics {
            return;
        }
        let mut open = true;
        let tab = &self.tabs[self.active_tab];
        let stats = tab.stats();
        let warnings = tab
            .document
            .as_ref()
            .map(|doc| (doc.name.clone(), doc.warnings.clone()));
        egui::Window::new("Statistics")
            .open(&mut open)
            .resizable(false)
            .collapsible(false)
            .show(ctx, |ui| match (stats, warnings) {
                (Some(stats), Some((name, warnings))) => {
                    ui.strong(name);
                    statistics_grid_ui(ui, &stats);
                    warnings_ui(ui, &warnings);
                }
                _ => {
                    ui.weak("Open a mesh to see its statistics.");
                }
            });
        self.show_statistics = open;
    }
}

fn statistics_grid_ui(ui: &mut egui::Ui, stats: &MeshStats) {
    let row = |ui: &mut egui::Ui, name: &str, value: String, why: &str| {
        ui.label(name).on_hover_text(why);
        ui.monospace(value);
        ui.end_row();
    };
    egui::Grid::new("statistics")
        .num_columns(2)
        .striped(true)
        .show(ui, |ui| {
            row(ui, "Vertices (V)", stats.vertices.to_string(), "Rows of the vertex table.");
            row(ui, "Edges (E)", stats.edges.to_string(), "Edges: a winged edge, or a half-edge and its pair.");
            row(ui, "Faces (F)", stats.faces.to_string(), "Rows of the face table.");
            row(ui, "Half-edges", stats.half_edges.to_string(), "2E: the rows of a half-edge table (a winged-edge mesh would have as many).");
            row(
                ui,
                "V − E + F",
                stats.euler_characteristic.to_string(),
                "The Euler characteristic: 2 − 2·genus − boundary loops for one connected surface.",
            );
            row(ui, "Boundary loops", stats.boundary_loops.to_string(), "Holes: cycles of half-edges without a face.");
            row(ui, "Components", stats.components.len().to_string(), "Connected pieces (an isolated vertex is one).");
            for (index, component) in stats.components.iter().take(LISTED).enumerate() {
                let genus = component.genus.map_or_else(
                    || "open (has a boundary)".to_owned(),
                    |g| format!("genus {g}"),
                );
                row(
                    ui,
                    &format!("  component {}", index + 1),
                    format!(
                        "V {} E {} F {}, χ {}, {genus}",
                        component.vertices,
                        component.edges,
                        component.faces,
                        component.euler_characteristic
                    ),
                    &format!(
                        "The piece holding vertex {}. Genus is the number of handles of a closed surface: (2 − χ) / 2.",
                        component.first_vertex.index()
                    ),
                );
            }
            if stats.components.len() > LISTED {
                ui.weak(format!("… and {} more", stats.components.len() - LISTED));
                ui.end_row();
            }
        });
}

fn warnings_ui(ui: &mut egui::Ui, warnings: &[String]) {
    ui.separator();
    if warnings.is_empty() {
        ui.weak("The build gave no warnings.");
        return;
    }
    ui.label(format!(
        "{} warning{} from the build:",
        warnings.len(),
        if warnings.len() == 1 { "" } else { "s" }
    ));
    egui::ScrollArea::vertical()
        .max_height(160.0)
        .show(ui, |ui| {
            for warning in warnings {
                ui.label(egui::RichText::new(warning).small());
            }
        });
}
