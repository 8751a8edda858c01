//! The PLY and OBJ readers against the crates the issue suggested, on the
//! ~200k-face benchmark torus (316×316 vertices, 199,712 triangles, written
//! by our own writers): binary little-endian PLY (3.8 MB), ASCII PLY and
//! OBJ. Each reader produces the same thing, a `Polygons` list ready for the
//! mesh builder, so the figures compare like with like:
//!
//! - ply-rs-bw is driven through its fastest path (typed `PropertyAccess`
//!   setters that fill our own structs, with `BeginList::Fill` for the index
//!   lists), not its `DefaultElement` hash maps;
//! - tobj runs with `triangulate: false` (polygons kept) and no features.
//!
//! `load` then adds the mesh build, for the full time to open a file.
//!
//! Run: `cargo bench -p edgewise-core --bench formats`.

use std::hint::black_box;
use std::io::Cursor;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use edgewise_core::formats::{self, Format, PlyEncoding, SaveOptions};
use edgewise_core::mesh::{Mesh, Polygons, Structure, generate};
use glam::Vec3;
use ply_rs_bw::parser::{Parser, Reader};
use ply_rs_bw::ply::{BeginList, PropertyAccess, PropertyAccessResult};

#[derive(Default)]
struct PlyVertex([f32; 3]);

impl PropertyAccess for PlyVertex {
    fn new() -> Self {
        Self::default()
    }

    fn set_float(&mut self, name: &str, value: f32) -> PropertyAccessResult {
        match name {
            "x" => self.0[0] = value,
            "y" => self.0[1] = value,
            "z" => self.0[2] = value,
            _ => return PropertyAccessResult::Ignored,
        }
        PropertyAccessResult::Set
    }
}

#[derive(Default)]
struct PlyFace(Vec<i32>);

impl PropertyAccess for PlyFace {
    fn new() -> Self {
        Self::default()
    }

    fn begin_list_int(&mut self, name: &str, _len: usize) -> BeginList<'_, i32> {
        match name {
            "vertex_indices" | "vertex_index" => BeginList::Fill(&mut self.0),
            _ => BeginList::UnsupportedType,
        }
    }
}

/// Reads a PLY with ply-rs-bw into the same `Polygons` our reader gives.
fn ply_rs_bw_polygons(bytes: &[u8]) -> Polygons {
    let mut reader = Reader::new(Cursor::new(bytes));
    let vertex_parser = Parser::<PlyVertex>::new();
    let face_parser = Parser::<PlyFace>::new();
    let header = vertex_parser.read_header(&mut reader).expect("header");
    let mut vertices = Vec::new();
    let mut faces = Vec::new();
    for element in header.elements.values() {
        match element.name.as_str() {
            "vertex" => {
                vertices = vertex_parser
                    .read_payload_for_element(&mut reader, element, &header)
                    .expect("vertices");
            }
            "face" => {
                faces = face_parser
                    .read_payload_for_element(&mut reader, element, &header)
                    .expect("faces");
            }
            _ => {}
        }
    }
    let corners = faces.iter().map(|f| f.0.len()).sum();
    let mut polygons = Polygons::with_capacity(vertices.len(), faces.len(), corners);
    for v in &vertices {
        polygons.push_vertex(Vec3::from(v.0));
    }
    let mut face = Vec::new();
    for f in &faces {
        face.clear();
        face.extend(f.0.iter().map(|&i| i as u32));
        polygons.push_face(&face);
    }
    polygons
}

/// Reads an OBJ with tobj (polygons kept, groups merged) into `Polygons`.
fn tobj_polygons(bytes: &[u8]) -> Polygons {
    let options = tobj::LoadOptions {
        single_index: false,
        triangulate: false,
        ignore_points: true,
        ignore_lines: true,
    };
    let (models, _) = tobj::load_obj_buf(&mut Cursor::new(bytes), &options, |_| {
        Err(tobj::LoadError::OpenFileFailed)
    })
    .expect("tobj reads it");
    let mut polygons = Polygons::new();
    for model in &models {
        let mesh = &model.mesh;
        let base = polygons.vertex_count() as u32;
        for p in mesh.positions.chunks_exact(3) {
            polygons.push_vertex(Vec3::new(p[0], p[1], p[2]));
        }
        let mut face = Vec::new();
        let mut start = 0;
        let arities: Vec<u32> = if mesh.face_arities.is_empty() {
            vec![3; mesh.indices.len() / 3]
        } else {
            mesh.face_arities.clone()
        };
        for arity in arities {
            let end = start + arity as usize;
            face.clear();
            face.extend(mesh.indices[start..end].iter().map(|&i| base + i));
            polygons.push_face(&face);
            start = end;
        }
    }
    polygons
}

fn formats(c: &mut Criterion) {
    let (mesh, _) = Mesh::build(&generate::torus(316, 316), Structure::HalfEdge).expect("builds");
    let save = |format, ply_encoding| {
        formats::save(&mesh, format, &SaveOptions { ply_encoding }).expect("saves")
    };
    let binary = save(Format::Ply, PlyEncoding::BinaryLittleEndian);
    let ascii = save(Format::Ply, PlyEncoding::Ascii);
    let obj = save(Format::Obj, PlyEncoding::Ascii);
    let faces = mesh.face_count() as u64;

    // The readers agree before anything is timed (OBJ faces also carry their
    // source lines, so compare positions and faces).
    let same =
        |a: &Polygons, b: &Polygons| a.positions() == b.positions() && a.faces().eq(b.faces());
    let ours = formats::read_polygons(&binary, Format::Ply).expect("reads");
    assert!(
        same(&ours, &ply_rs_bw_polygons(&binary)),
        "binary PLY readers differ"
    );
    assert!(
        same(&ours, &ply_rs_bw_polygons(&ascii)),
        "ASCII PLY readers differ"
    );
    let obj_polygons = formats::read_polygons(&obj, Format::Obj).expect("reads");
    assert!(same(&ours, &obj_polygons), "OBJ and PLY differ");
    let theirs = tobj_polygons(&obj);
    if !same(&ours, &theirs) {
        // tobj renumbers vertices per model in order of use; the counts and
        // face sizes still have to agree.
        assert_eq!(
            (
                theirs.vertex_count(),
                theirs.face_count(),
                theirs.corner_count()
            ),
            (ours.vertex_count(), ours.face_count(), ours.corner_count()),
            "tobj reads something else"
        );
        eprintln!(
            "note: tobj numbers the vertices differently (positions equal: {}, faces equal: {})",
            ours.positions() == theirs.positions(),
            ours.faces().eq(theirs.faces())
        );
    }

    for (label, bytes, format) in [
        ("ply_binary_200k", &binary, Format::Ply),
        ("ply_ascii_200k", &ascii, Format::Ply),
        ("obj_200k", &obj, Format::Obj),
    ] {
        let mut group = c.benchmark_group(label);
        group.sample_size(20);
        group.throughput(Throughput::Elements(faces));
        group.bench_function("edgewise", |b| {
            b.iter(|| formats::read_polygons(black_box(bytes), format));
        });
        match format {
            Format::Ply => group.bench_function("ply-rs-bw", |b| {
                b.iter(|| ply_rs_bw_polygons(black_box(bytes)));
            }),
            _ => group.bench_function("tobj", |b| b.iter(|| tobj_polygons(black_box(bytes)))),
        };
        group.bench_function("edgewise_load_half_edge", |b| {
            b.iter(|| formats::load_as(black_box(bytes), format, Structure::HalfEdge));
        });
        group.finish();
    }
}

criterion_group!(benches, formats);
criterion_main!(benches);
