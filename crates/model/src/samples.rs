//! The sample meshes of meshes/, built into the app so each is one click
//! away. The two largest are generated instead of shipped: the 200k-face
//! torus for scale, and icosphere-20k (the same ids and positions as its file).

use edgewise_core::mesh::{Structure, generate};

use crate::document::{Document, structure_for};

/// Where a sample's data comes from.
pub enum SampleData {
    /// A file from meshes/, read by its extension.
    File {
        file_name: &'static str,
        bytes: &'static [u8],
    },
    /// A torus grid of `nu` × `nv` vertices, generated on demand (too big to ship).
    Torus { nu: u32, nv: u32 },
    /// `mesh::generate::icosphere(levels)`, identical to its file in meshes/
    /// but generated: 140 KB less to download.
    Icosphere {
        file_name: &'static str,
        levels: u32,
    },
}

/// One sample mesh.
pub struct Sample {
    /// The name used by the menu and `loadSample`: the file stem.
    pub name: &'static str,
    pub data: SampleData,
}

impl Sample {
    const fn file(name: &'static str, file_name: &'static str, bytes: &'static [u8]) -> Self {
        Self {
            name,
            data: SampleData::File { file_name, bytes },
        }
    }
}

/// Every sample, in menu order.
pub const SAMPLES: &[Sample] = &[
    Sample::file(
        "annulus",
        "annulus.htb",
        include_bytes!("../../../meshes/annulus.htb"),
    ),
    Sample::file(
        "cube",
        "cube.htb",
        include_bytes!("../../../meshes/cube.htb"),
    ),
    Sample::file(
        "dodecahedron",
        "dodecahedron.obj",
        include_bytes!("../../../meshes/dodecahedron.obj"),
    ),
    Sample::file(
        "double-torus",
        "double-torus.obj",
        include_bytes!("../../../meshes/double-torus.obj"),
    ),
    Sample::file(
        "hexagon",
        "hexagon.obj",
        include_bytes!("../../../meshes/hexagon.obj"),
    ),
    Sample::file(
        "icosahedron",
        "icosahedron.ply",
        include_bytes!("../../../meshes/icosahedron.ply"),
    ),
    Sample {
        name: "icosphere-20k",
        data: SampleData::Icosphere {
            file_name: "icosphere-20k.ply",
            levels: 5,
        },
    },
    Sample::file(
        "octahedron",
        "octahedron.obj",
        include_bytes!("../../../meshes/octahedron.obj"),
    ),
    Sample::file(
        "open-square",
        "open-square.wtb",
        include_bytes!("../../../meshes/open-square.wtb"),
    ),
    Sample::file(
        "quad-grid",
        "quad-grid.obj",
        include_bytes!("../../../meshes/quad-grid.obj"),
    ),
    Sample::file(
        "quad-sphere-triangles",
        "quad-sphere-triangles.obj",
        include_bytes!("../../../meshes/quad-sphere-triangles.obj"),
    ),
    Sample::file(
        "quad-sphere",
        "quad-sphere.obj",
        include_bytes!("../../../meshes/quad-sphere.obj"),
    ),
    Sample::file(
        "sphere",
        "sphere.obj",
        include_bytes!("../../../meshes/sphere.obj"),
    ),
    Sample::file(
        "square-pyramid",
        "square-pyramid.obj",
        include_bytes!("../../../meshes/square-pyramid.obj"),
    ),
    Sample::file(
        "tetrahedron",
        "tetrahedron.wtb",
        include_bytes!("../../../meshes/tetrahedron.wtb"),
    ),
    Sample::file(
        "torus",
        "torus.obj",
        include_bytes!("../../../meshes/torus.obj"),
    ),
    Sample::file(
        "triangular-prism",
        "triangular-prism.obj",
        include_bytes!("../../../meshes/triangular-prism.obj"),
    ),
    Sample {
        name: "torus-200k",
        data: SampleData::Torus { nu: 316, nv: 316 },
    },
];

/// The sample called `name`.
pub fn find(name: &str) -> Option<&'static Sample> {
    SAMPLES.iter().find(|s| s.name == name)
}

/// Opens the sample called `name` as `structure`; with none, a table file
/// opens as the structure it stores and the others as `fallback`.
pub fn open(
    name: &str,
    structure: Option<Structure>,
    fallback: Structure,
) -> Result<Document, String> {
    let Some(sample) = find(name) else {
        let names: Vec<&str> = SAMPLES.iter().map(|s| s.name).collect();
        return Err(format!(
            "there is no sample called '{name}'; the samples are: {}",
            names.join(", ")
        ));
    };
    let structure = match &sample.data {
        SampleData::File { file_name, .. } | SampleData::Icosphere { file_name, .. } => {
            structure.unwrap_or_else(|| structure_for(file_name, fallback))
        }
        SampleData::Torus { .. } => structure.unwrap_or(fallback),
    };
    let loaded = match &sample.data {
        SampleData::File { file_name, bytes } => Document::load(bytes, file_name, structure),
        SampleData::Torus { nu, nv } => {
            Document::from_polygons(sample.name, &generate::torus(*nu, *nv), structure)
        }
        SampleData::Icosphere { file_name, levels } => {
            Document::from_polygons(file_name, &generate::icosphere(*levels), structure)
        }
    };
    loaded.map(|mut document| {
        document.sample = Some(sample.name.to_owned());
        document
    })
}
