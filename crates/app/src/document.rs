//! One open mesh: its structure, where it came from, and what is selected.

use edgewise_core::{
    formats::{self, FormatError, Loaded},
    mesh::{Mesh, Structure},
};

use crate::selection::{self, ElementKind, ElementRef, Highlight};

/// A mesh open in the app with its selection.
pub struct Document {
    /// The file or sample name, shown in the title and used for saving.
    pub name: String,
    mesh: Mesh,
    /// What the loader kept but noticed (unused vertices, ignored lines).
    pub warnings: Vec<String>,
    selection: Option<ElementRef>,
    highlights: Vec<Highlight>,
    /// Increases whenever the mesh or the selection changes, so views
    /// re-derive colours and labels only then.
    generation: u64,
}

impl Document {
    /// Reads a mesh file of any format. `name` decides the format by its
    /// extension, or the content does when it has none (pasted text). The
    /// message names `name:line:column` for each problem.
    pub fn load(bytes: &[u8], name: &str, structure: Structure) -> Result<Self, String> {
        Self::parse(bytes, name, structure).map_err(|err| err.render(name).trim_end().to_owned())
    }

    /// [`Self::load`] with the problems and their places kept, for editors
    /// that mark them in the text.
    pub fn parse(bytes: &[u8], name: &str, structure: Structure) -> Result<Self, FormatError> {
        let Loaded { mesh, warnings, .. } = formats::load(bytes, name, structure)?;
        Ok(Self {
            name: name.to_owned(),
            mesh,
            warnings: warnings.iter().map(ToString::to_string).collect(),
            selection: None,
            highlights: Vec::new(),
            generation: 0,
        })
    }

    /// Builds a mesh from polygons (a generated sample).
    pub fn from_polygons(
        name: &str,
        polygons: &edgewise_core::mesh::Polygons,
        structure: Structure,
    ) -> Result<Self, String> {
        let (mesh, warnings) =
            Mesh::build(polygons, structure).map_err(|err| format!("{name}: {err}"))?;
        Ok(Self {
            name: name.to_owned(),
            mesh,
            warnings: warnings.iter().map(ToString::to_string).collect(),
            selection: None,
            highlights: Vec::new(),
            generation: 0,
        })
    }

    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    pub fn structure(&self) -> Structure {
        self.mesh.structure()
    }

    pub fn selection(&self) -> Option<ElementRef> {
        self.selection
    }

    /// The selected element and everything it references, with roles.
    pub fn highlights(&self) -> &[Highlight] {
        &self.highlights
    }

    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// Selects `element` (or clears the selection), refusing ids the mesh lacks.
    pub fn select(&mut self, element: Option<ElementRef>) -> Result<(), String> {
        if let Some(element) = element
            && !element.exists_in(&self.mesh)
        {
            let count = match element.kind {
                ElementKind::Vertex => self.mesh.vertex_count(),
                ElementKind::Edge => self.mesh.edge_row_count(),
                ElementKind::Face => self.mesh.face_count(),
            };
            return Err(format!(
                "there is no {} {} (this mesh has {count}, numbered from 0)",
                element.kind.title().to_lowercase(),
                element.id
            ));
        }
        self.selection = element;
        self.highlights = element
            .map(|element| selection::highlights(&self.mesh, element))
            .unwrap_or_default();
        self.generation += 1;
        Ok(())
    }

    /// Converts the mesh to `structure`, keeping the selection where it maps:
    /// vertices and faces keep their ids; a winged edge maps to the first of
    /// its two half-edges, and a half-edge to the winged edge it belongs to.
    pub fn switch_structure(&mut self, structure: Structure) -> Result<(), String> {
        if structure == self.structure() {
            return Ok(());
        }
        let selection = self.selection;
        let (mesh, mapped) = match &self.mesh {
            Mesh::Winged(m) => {
                let (he, correspondence) = m
                    .to_half_edge_with_correspondence()
                    .map_err(|err| err.to_string())?;
                let mapped = selection.and_then(|s| match s.kind {
                    ElementKind::Edge => correspondence
                        .half_edges(edgewise_core::mesh::EdgeId::new(s.id))
                        .map(|(h, _)| ElementRef::half_edge(h)),
                    _ => Some(s),
                });
                (Mesh::Half(he), mapped)
            }
            Mesh::Half(m) => {
                let (we, correspondence) = m
                    .to_winged_edge_with_correspondence()
                    .map_err(|err| err.to_string())?;
                let mapped = selection.and_then(|s| match s.kind {
                    ElementKind::Edge => correspondence
                        .edge(edgewise_core::mesh::HalfEdgeId::new(s.id))
                        .map(ElementRef::edge),
                    _ => Some(s),
                });
                (Mesh::Winged(we), mapped)
            }
        };
        self.mesh = mesh;
        self.select(mapped)
    }
}
