//! One open mesh: its structure, where it came from, and what is selected.

use edgewise_core::schema::{Column, ElementKind, ElementRef, Records as _, RecordsMut as _};
use edgewise_core::{
    formats::{self, Format, FormatError, Loaded},
    mesh::{
        EdgeCorrespondence, EdgeId, Edit as _, FaceId, HalfEdgeId, Mesh, Renumbering, Structure,
        VertexId,
    },
};

use glam::Vec3;

use crate::selection::{self, Highlight};

/// A mesh open in the app with its selection. Cloned whole into the undo
/// history, so that an undo gives back the tables byte for byte.
#[derive(Clone)]
pub struct Document {
    /// The file or sample name, shown in the title and used for saving.
    pub name: String,
    mesh: Mesh,
    /// What the loader kept but noticed (unused vertices, ignored lines).
    pub warnings: Vec<String>,
    selection: Option<ElementRef>,
    highlights: Vec<Highlight>,
    /// A fresh number ([`next_stamp`]) whenever the mesh or the selection
    /// changes, so views re-derive colours and labels only then. Numbers
    /// are never reused, across documents too: a new or restored document
    /// never passes for the one a view last drew.
    generation: u64,
    /// See [`Self::mesh_id`].
    mesh_id: u64,
    /// The built-in sample this mesh is, as loaded (not converted since), so
    /// a shared link can name it instead of carrying its text.
    pub sample: Option<String>,
}

impl Document {
    /// Reads a mesh file of any format. `name` decides the format by its
    /// extension, or the content does when it has none (pasted text). The
    /// message names `name:line:column` for each problem.
    pub fn load(bytes: &[u8], name: &str, structure: Structure) -> Result<Self, String> {
        Self::parse(bytes, name, structure).map_err(|err| err.render(name).trim_end().to_owned())
    }

    /// Opens a table file for diagnosis: kept as written even if its tables
    /// break the structure's rules (see [`formats::load_for_diagnosis`]).
    pub fn load_for_diagnosis(
        bytes: &[u8],
        name: &str,
        structure: Structure,
    ) -> Result<Self, String> {
        let Loaded { mesh, warnings, .. } = formats::load_for_diagnosis(bytes, name, structure)
            .map_err(|err| err.render(name).trim_end().to_owned())?;
        let warnings = warnings
            .iter()
            .map(|warning| format!("{name}:{warning}"))
            .collect();
        Ok(Self::new(name, mesh, warnings))
    }

    /// [`Self::load`] with the problems and their places kept, for editors
    /// that mark them in the text.
    pub fn parse(bytes: &[u8], name: &str, structure: Structure) -> Result<Self, FormatError> {
        let Loaded { mesh, warnings, .. } = formats::load(bytes, name, structure)?;
        Ok(Self::new(
            name,
            mesh,
            warnings.iter().map(ToString::to_string).collect(),
        ))
    }

    /// A freshly opened mesh: nothing selected, a new mesh id.
    fn new(name: &str, mesh: Mesh, warnings: Vec<String>) -> Self {
        Self {
            name: name.to_owned(),
            mesh,
            warnings,
            selection: None,
            highlights: Vec::new(),
            generation: next_stamp(),
            mesh_id: next_stamp(),
            sample: None,
        }
    }

    /// Builds a mesh from polygons (a generated sample).
    pub fn from_polygons(
        name: &str,
        polygons: &edgewise_core::mesh::Polygons,
        structure: Structure,
    ) -> Result<Self, String> {
        let (mesh, warnings) =
            Mesh::build(polygons, structure).map_err(|err| format!("{name}: {err}"))?;
        Ok(Self::new(
            name,
            mesh,
            warnings.iter().map(ToString::to_string).collect(),
        ))
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
            && !self.mesh.contains(element)
        {
            let count = self.mesh.count(element.kind);
            return Err(format!(
                "there is no {element} (this mesh has {count}, numbered from 0)"
            ));
        }
        self.selection = element;
        self.highlights = element
            .map(|element| selection::highlights(&self.mesh, element))
            .unwrap_or_default();
        self.generation = next_stamp();
        Ok(())
    }

    /// Converts the mesh to `structure`, keeping the selection where it maps:
    /// vertices and faces keep their ids; a winged edge maps to the first of
    /// its two half-edges, and a half-edge to the winged edge it belongs to.
    pub fn switch_structure(&mut self, structure: Structure) -> Result<(), String> {
        if structure == self.structure() {
            return Ok(());
        }
        let (mesh, correspondence) = convert(&self.mesh)?;
        let mapped = self
            .selection
            .and_then(|s| map_element(s, self.structure(), &correspondence));
        self.mesh = mesh;
        self.mesh_id = next_stamp();
        self.sample = None;
        self.select(mapped)
    }

    /// The same mesh in the other structure, with the selection mapped, and
    /// how their edges correspond (for side-by-side views).
    pub fn twin(&self) -> Result<(Document, EdgeCorrespondence), String> {
        let (mesh, correspondence) = convert(&self.mesh)?;
        let mut twin = Document::new(&self.name, mesh, Vec::new());
        let mapped = self
            .selection
            .and_then(|s| map_element(s, self.structure(), &correspondence));
        twin.select(mapped)?;
        Ok((twin, correspondence))
    }

    /// Moves the mesh through an editing trace's changes, from the state
    /// after `from` of them to the state after `to`. The selection is kept
    /// if its element still exists.
    pub fn seek(
        &mut self,
        trace: &edgewise_core::lang::Trace,
        from: usize,
        to: usize,
    ) -> Result<(), String> {
        let result = trace
            .seek(&mut self.mesh, from, to)
            .map_err(|error| format!("the trace could not be replayed: {error}"));
        // `sample` stays: the trace still starts from it.
        self.mesh_id = next_stamp();
        let selection = self.selection.filter(|&s| self.mesh.contains(s));
        self.select(selection)?;
        result
    }

    /// Replaces the mesh with one derived from it (an edit's result or what
    /// it replaced), keeping the name; gives back the document as it was,
    /// for the undo history.
    pub fn replace_mesh(&mut self, mesh: Mesh) -> Document {
        let before = Document {
            name: self.name.clone(),
            mesh: std::mem::replace(&mut self.mesh, mesh),
            warnings: self.warnings.clone(),
            selection: self.selection,
            highlights: self.highlights.clone(),
            generation: self.generation,
            mesh_id: self.mesh_id,
            sample: self.sample.clone(),
        };
        self.changed();
        before
    }

    /// A copy of this document showing `mesh` instead: what it was before
    /// an editing trace that has since changed it.
    pub fn with_mesh(&self, mesh: Mesh) -> Document {
        let mut copy = Document::new(&self.name, mesh, self.warnings.clone());
        copy.sample.clone_from(&self.sample);
        let selection = self.selection.filter(|&s| copy.mesh.contains(s));
        let _kept = copy.select(selection);
        copy
    }

    /// Writes one reference by hand (a table cell): `target` must name a
    /// live row of the kind the column holds, or be `None` where the
    /// column may be empty.
    pub fn set_reference(
        &mut self,
        element: ElementRef,
        column: Column,
        target: Option<ElementRef>,
    ) -> Result<(), String> {
        if !self.mesh.contains(element) {
            return Err(self.missing(element));
        }
        if let Some(target) = target
            && !self.mesh.contains(target)
        {
            return Err(self.missing(target));
        }
        self.mesh
            .set_reference(element, column, target)
            .map_err(|error| error.to_string())?;
        self.changed();
        Ok(())
    }

    /// A document of a mesh made here (an exercise's instance), nothing
    /// selected.
    pub fn from_mesh(name: &str, mesh: Mesh) -> Self {
        Self::new(name, mesh, Vec::new())
    }

    /// Appends an empty row to one table, by hand: its references are unset
    /// until written, and a vertex sits at the origin.
    pub fn add_row(&mut self, kind: ElementKind) -> Result<ElementRef, String> {
        let row = self
            .mesh
            .push_row(kind)
            .map_err(|error| error.to_string())?;
        self.changed();
        Ok(row)
    }

    /// Marks a row deleted, by hand; it keeps its number until the ids are
    /// compacted.
    pub fn delete_row(&mut self, element: ElementRef) -> Result<(), String> {
        if !self.mesh.contains(element) {
            return Err(self.missing(element));
        }
        self.mesh
            .set_deleted(element, true)
            .map_err(|error| error.to_string())?;
        self.changed();
        Ok(())
    }

    /// Moves a vertex, by hand (a typed position).
    pub fn set_position(&mut self, vertex: VertexId, position: Vec3) -> Result<(), String> {
        let element = ElementRef::from(vertex);
        if !self.mesh.contains(element) {
            return Err(self.missing(element));
        }
        self.mesh
            .set_position(vertex, position)
            .map_err(|error| error.to_string())?;
        self.changed();
        Ok(())
    }

    /// Drops the deleted rows and renumbers the rest in order; gives the
    /// old-to-new mapping. The selection follows its element.
    pub fn compact(&mut self) -> Renumbering {
        let renumbering = self.mesh.compact();
        let selection = self.selection.and_then(|s| renumbering.get(s));
        self.mesh_id = next_stamp();
        self.sample = None;
        let _kept = self.select(selection);
        renumbering
    }

    /// Why `element` names no row: past the table, or deleted.
    fn missing(&self, element: ElementRef) -> String {
        let count = self.mesh.count(element.kind);
        if (element.id as usize) < count {
            format!("{element} was deleted")
        } else {
            format!("there is no {element} (this mesh has {count}, numbered from 0)")
        }
    }

    /// After the mesh changed: a new mesh id, no longer the sample, and the
    /// selection kept if its element still exists.
    fn changed(&mut self) {
        self.mesh_id = next_stamp();
        self.sample = None;
        let selection = self.selection.filter(|&s| self.mesh.contains(s));
        // The selection was just checked against the new mesh.
        let _kept = self.select(selection);
    }

    /// Identifies the mesh itself: it changes when the mesh is replaced or
    /// converted, not when the selection changes.
    pub fn mesh_id(&self) -> u64 {
        self.mesh_id
    }
}

/// The mesh in the other structure, with its edge correspondence.
fn convert(mesh: &Mesh) -> Result<(Mesh, EdgeCorrespondence), String> {
    match mesh {
        Mesh::Winged(m) => m
            .to_half_edge_with_correspondence()
            .map(|(he, c)| (Mesh::Half(he), c))
            .map_err(|err| err.to_string()),
        Mesh::Half(m) => m
            .to_winged_edge_with_correspondence()
            .map(|(we, c)| (Mesh::Winged(we), c))
            .map_err(|err| err.to_string()),
    }
}

/// An element of a mesh in structure `from`, in the converted mesh: vertices
/// and faces keep their ids; a winged edge maps to its first half-edge, a
/// half-edge to its winged edge.
pub fn map_element(
    element: ElementRef,
    from: Structure,
    correspondence: &EdgeCorrespondence,
) -> Option<ElementRef> {
    match (element.kind, from) {
        (ElementKind::Edge, Structure::WingedEdge) => correspondence
            .half_edges(EdgeId::new(element.id))
            .map(|(h, _)| ElementRef::half_edge(h)),
        (ElementKind::Edge, Structure::HalfEdge) => correspondence
            .edge(HalfEdgeId::new(element.id))
            .map(ElementRef::edge),
        (ElementKind::Vertex, _) => correspondence
            .vertex(VertexId::new(element.id))
            .map(ElementRef::vertex),
        (ElementKind::Face, _) => correspondence
            .face(FaceId::new(element.id))
            .map(ElementRef::face),
    }
}

/// A number never handed out before in this process: mesh ids and
/// generations.
fn next_stamp() -> u64 {
    use std::sync::atomic::{AtomicU64, Ordering};
    static NEXT: AtomicU64 = AtomicU64::new(1);
    NEXT.fetch_add(1, Ordering::Relaxed)
}

/// The structure chosen when Edgewise starts, which a PLY or OBJ builds as
/// until the user picks another: the journal's first, the winged edge.
pub const FIRST_STRUCTURE: Structure = Structure::WingedEdge;

/// The structure a file called `name` opens as: a table file's own, else
/// `fallback` (PLY and OBJ, as the structure chosen in the top bar).
pub fn structure_for(name: &str, fallback: Structure) -> Structure {
    Format::from_name(name)
        .and_then(Format::native_structure)
        .unwrap_or(fallback)
}

/// `name` without its extension if it has a mesh format's extension
/// ("cube.htb" → "cube"; "torus-200k" stays).
pub fn mesh_stem(name: &str) -> &str {
    match name.rsplit_once('.') {
        Some((stem, _)) if !stem.is_empty() && Format::from_name(name).is_some() => stem,
        _ => name,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stem_drops_only_mesh_extensions() {
        assert_eq!(mesh_stem("cube.htb"), "cube");
        assert_eq!(mesh_stem("my.mesh.obj"), "my.mesh");
        assert_eq!(mesh_stem("torus-200k"), "torus-200k");
        assert_eq!(mesh_stem("notes.txt"), "notes.txt");
        assert_eq!(mesh_stem(".obj"), ".obj");
    }

    use edgewise_core::mesh::generate;

    fn tetrahedron() -> Document {
        Document::from_polygons("t", &generate::tetrahedron(), Structure::WingedEdge)
            .expect("the tetrahedron builds")
    }

    /// The views redraw colours when the generation differs from the one
    /// they drew: a new document, or one back from the history, must never
    /// pass for the document they last drew.
    #[test]
    fn generations_are_never_reused_and_a_copy_keeps_its_own() {
        let mut first = tetrahedron();
        let second = tetrahedron();
        assert_ne!(first.generation(), second.generation());
        let kept = first.clone();
        first
            .select(Some(ElementRef::vertex(VertexId::new(1))))
            .expect("vertex 1 exists");
        assert_ne!(first.generation(), kept.generation());
        assert_ne!(first.generation(), second.generation());
        let before = first.replace_mesh(second.mesh().clone());
        assert_ne!(first.generation(), before.generation());
        assert_eq!(
            first.selection(),
            Some(ElementRef::vertex(VertexId::new(1))),
            "the selection is kept where its element exists"
        );
    }
}
