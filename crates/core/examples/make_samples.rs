//! Writes the sample mesh library into `meshes/` (run from anywhere):
//!
//! ```sh
//! cargo run -p edgewise-core --example make_samples
//! ```
//!
//! Every shape is generated here, or in `mesh::generate` where tests share
//! it, so the library can be rebuilt exactly and reviewed as code. Each
//! sample is written in the format that suits it and checked (built,
//! validated, read back) before it is written. The 200k-face mesh is not a
//! file: it is `mesh::generate::torus(316, 316)`, made where it is needed.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use edgewise_core::formats::{self, Format, PlyEncoding, SaveOptions};
use edgewise_core::mesh::{Mesh, Polygons, Structure, generate};
use glam::DVec3;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if let [flag, path] = args.as_slice()
        && flag == "--large"
    {
        return write_large(Path::new(path));
    }
    if !args.is_empty() {
        return Err("usage: make_samples [--large FILE.(ply|obj|wtb|htb)]".into());
    }
    let out = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../meshes");
    for sample in samples() {
        write(&out, &sample)?;
    }
    Ok(())
}

/// The 200k-face benchmark torus, in the format `path`'s extension names
/// (binary PLY for `.ply`).
fn write_large(path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let name = path.to_string_lossy();
    let format =
        Format::from_name(&name).ok_or("the file needs a .ply, .obj, .wtb or .htb extension")?;
    let (mesh, _) = Mesh::build(&generate::torus(316, 316), Structure::HalfEdge)?;
    let options = SaveOptions {
        ply_encoding: PlyEncoding::BinaryLittleEndian,
    };
    std::fs::write(path, formats::save(&mesh, format, &options)?)?;
    println!("{name}: {} faces", mesh.face_count());
    Ok(())
}

struct Sample {
    file: &'static str,
    about: &'static str,
    mesh: Mesh,
    ply_encoding: PlyEncoding,
}

fn sample(file: &'static str, about: &'static str, polygons: &Polygons) -> Sample {
    // Half-edge keeps each face as listed when written back as polygons.
    let structure = match Format::from_name(file) {
        Some(Format::Wtb) => Structure::WingedEdge,
        _ => Structure::HalfEdge,
    };
    let mesh = match Mesh::build(polygons, structure) {
        Ok((mesh, warnings)) if warnings.is_empty() => mesh,
        Ok((_, warnings)) => panic!("{file}: {warnings:?}"),
        Err(error) => panic!("{file}: {error}"),
    };
    Sample {
        file,
        about,
        mesh,
        ply_encoding: PlyEncoding::Ascii,
    }
}

fn samples() -> Vec<Sample> {
    let quad_sphere = quad_sphere(4);
    vec![
        Sample {
            file: "tetrahedron.wtb",
            about: "The journal paper's tetrahedron (Figure 2) with its Table 2 exactly as \
                    printed: vertices A-D are 0-3, faces 1-4 are 0-3, edges a-f are 0-5.",
            mesh: Mesh::Winged(generate::table_2()),
            ply_encoding: PlyEncoding::Ascii,
        },
        sample(
            "cube.htb",
            "A cube of six squares as half-edge tables.",
            &generate::cube(),
        ),
        sample(
            "octahedron.obj",
            "A regular octahedron: every vertex has valence 4.",
            &octahedron(),
        ),
        Sample {
            ply_encoding: PlyEncoding::Ascii,
            ..sample(
                "icosahedron.ply",
                "A regular icosahedron: 20 triangles, valence 5.",
                &generate::icosphere(0),
            )
        },
        sample(
            "dodecahedron.obj",
            "A regular dodecahedron: 12 pentagons.",
            &dodecahedron(),
        ),
        sample(
            "triangular-prism.obj",
            "Two triangles and three squares.",
            &triangular_prism(),
        ),
        sample(
            "square-pyramid.obj",
            "One square and four triangles; the apex has valence 4.",
            &square_pyramid(),
        ),
        sample(
            "quad-grid.obj",
            "A 4 by 4 grid of squares with one boundary loop.",
            &generate::grid(4, 4),
        ),
        sample(
            "hexagon.obj",
            "Six triangles around a centre vertex: the half-edge explainer's example, \
             where its edge flip happens.",
            &generate::hexagon(),
        ),
        sample(
            "open-square.wtb",
            "Two triangles making a square, with the boundary as -.",
            &generate::open_square(),
        ),
        sample(
            "annulus.htb",
            "A disk with a hole: two boundary loops.",
            &annulus(16, 2),
        ),
        sample(
            "torus.obj",
            "A torus of 24 by 12 squares (genus 1).",
            &torus(24, 12),
        ),
        sample(
            "double-torus.obj",
            "A slab with two holes, made of squares (genus 2).",
            &double_torus(),
        ),
        sample(
            "sphere.obj",
            "A low-poly UV sphere of 480 triangles.",
            &uv_sphere(16, 16),
        ),
        Sample {
            ply_encoding: PlyEncoding::BinaryLittleEndian,
            ..sample(
                "icosphere-20k.ply",
                "A subdivided icosahedron of 20,480 triangles.",
                &generate::icosphere(5),
            )
        },
        sample(
            "quad-sphere.obj",
            "A cube projected onto a sphere: 96 squares.",
            &quad_sphere,
        ),
        sample(
            "quad-sphere-triangles.obj",
            "The same sphere with each square split in two: 192 triangles.",
            &triangulate(&quad_sphere),
        ),
    ]
}

fn write(dir: &Path, sample: &Sample) -> Result<(), Box<dyn std::error::Error>> {
    let format = Format::from_name(sample.file).ok_or("unknown extension")?;
    assert!(sample.mesh.validate().is_empty(), "{}", sample.file);
    let options = SaveOptions {
        ply_encoding: sample.ply_encoding,
    };
    let bytes = formats::save(&sample.mesh, format, &options)?;
    let bytes = describe(&bytes, format, sample);
    let back = formats::load(&bytes, sample.file, sample.mesh.structure())?;
    assert_eq!(back.mesh.stats(), sample.mesh.stats(), "{}", sample.file);
    std::fs::write(dir.join(sample.file), &bytes)?;
    let stats = sample.mesh.stats();
    println!(
        "{:<28} V {:>6}  E {:>6}  F {:>6}  {} bytes",
        sample.file,
        stats.vertices,
        stats.edges,
        stats.faces,
        bytes.len()
    );
    Ok(())
}

/// Splits text into lines of at most 76 characters.
fn wrap(text: &str) -> Vec<String> {
    let mut lines = vec![String::new()];
    for word in text.split(' ') {
        let line = lines.last_mut().expect("one line");
        if !line.is_empty() && line.len() + word.len() >= 76 {
            lines.push(word.to_owned());
        } else {
            if !line.is_empty() {
                line.push(' ');
            }
            line.push_str(word);
        }
    }
    lines
}

/// Puts the sample's name and purpose at the top of the file.
fn describe(bytes: &[u8], format: Format, sample: &Sample) -> Vec<u8> {
    let name = sample.file.rsplit_once('.').map_or(sample.file, |(n, _)| n);
    let lines = wrap(&format!("Edgewise sample {name}: {}", sample.about));
    match format {
        Format::Ply => {
            // Comments go after the format line.
            let text_end = bytes.iter().position(|&b| b == b'\n').unwrap_or(0);
            let second = bytes[text_end + 1..]
                .iter()
                .position(|&b| b == b'\n')
                .map_or(bytes.len(), |p| text_end + 1 + p + 1);
            let mut out = bytes[..second].to_vec();
            for line in &lines {
                out.extend_from_slice(format!("comment {line}\n").as_bytes());
            }
            out.extend_from_slice(&bytes[second..]);
            out
        }
        _ => {
            let mut out: Vec<u8> = lines
                .iter()
                .flat_map(|line| format!("# {line}\n").into_bytes())
                .collect();
            out.extend_from_slice(bytes);
            out
        }
    }
}

// ------------------------------------------------------------------ shapes

fn to_polygons(points: &[DVec3], faces: &[Vec<u32>]) -> Polygons {
    let positions = points.iter().map(|p| p.as_vec3()).collect();
    Polygons::from_faces(positions, faces)
}

/// Newell's normal of a polygon.
fn normal(points: &[DVec3], face: &[u32]) -> DVec3 {
    let mut n = DVec3::ZERO;
    for (i, &a) in face.iter().enumerate() {
        let b = face[(i + 1) % face.len()];
        let (p, q) = (points[a as usize], points[b as usize]);
        n += DVec3::new(
            (p.y - q.y) * (p.z + q.z),
            (p.z - q.z) * (p.x + q.x),
            (p.x - q.x) * (p.y + q.y),
        );
    }
    n
}

/// Lists `face` counter-clockwise seen from the side `outward` points to.
fn orient(points: &[DVec3], mut face: Vec<u32>, outward: DVec3) -> Vec<u32> {
    if normal(points, &face).dot(outward) < 0.0 {
        face.reverse();
        face.rotate_right(1);
    }
    face
}

/// The faces of the convex hull of points in convex position, coplanar
/// points merged into one polygon, each counter-clockwise from outside and
/// starting at its lowest vertex.
fn convex_hull(points: &[DVec3]) -> Vec<Vec<u32>> {
    let n = points.len();
    let mut faces: Vec<Vec<u32>> = Vec::new();
    let mut seen: Vec<Vec<u32>> = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                let plane = (points[j] - points[i]).cross(points[k] - points[i]);
                if plane.length() < 1e-9 {
                    continue;
                }
                let plane = plane.normalize();
                let side = |p: DVec3| plane.dot(p - points[i]);
                let above = points.iter().any(|&p| side(p) > 1e-7);
                let below = points.iter().any(|&p| side(p) < -1e-7);
                if above && below {
                    continue;
                }
                let outward = if above { -plane } else { plane };
                let on: Vec<u32> = (0..n as u32)
                    .filter(|&m| side(points[m as usize]).abs() <= 1e-7)
                    .collect();
                if seen.contains(&on) {
                    continue;
                }
                seen.push(on.clone());
                let centre =
                    on.iter().map(|&m| points[m as usize]).sum::<DVec3>() / on.len() as f64;
                let u = (points[on[0] as usize] - centre).normalize();
                let w = outward.cross(u);
                let mut ordered = on;
                ordered.sort_by(|&a, &b| {
                    let angle = |m: u32| {
                        let d = points[m as usize] - centre;
                        d.dot(w).atan2(d.dot(u))
                    };
                    angle(a).total_cmp(&angle(b))
                });
                let lowest = ordered
                    .iter()
                    .enumerate()
                    .min_by_key(|&(_, &v)| v)
                    .map_or(0, |(i, _)| i);
                ordered.rotate_left(lowest);
                faces.push(ordered);
            }
        }
    }
    faces
}

fn hull_polygons(points: &[DVec3]) -> Polygons {
    to_polygons(points, &convex_hull(points))
}

fn octahedron() -> Polygons {
    hull_polygons(&[
        DVec3::X,
        DVec3::NEG_X,
        DVec3::Y,
        DVec3::NEG_Y,
        DVec3::Z,
        DVec3::NEG_Z,
    ])
}

const PHI: f64 = 1.618_033_988_749_895;

fn dodecahedron() -> Polygons {
    let mut points = Vec::new();
    for x in [-1.0, 1.0] {
        for y in [-1.0, 1.0] {
            for z in [-1.0, 1.0] {
                points.push(DVec3::new(x, y, z));
            }
        }
    }
    let inverse = 1.0 / PHI;
    for a in [-inverse, inverse] {
        for b in [-PHI, PHI] {
            points.push(DVec3::new(0.0, a, b));
            points.push(DVec3::new(a, b, 0.0));
            points.push(DVec3::new(b, 0.0, a));
        }
    }
    hull_polygons(&points)
}

fn triangular_prism() -> Polygons {
    let mut points = Vec::new();
    for z in [-1.0, 1.0] {
        for k in 0..3 {
            let angle = std::f64::consts::TAU * f64::from(k) / 3.0;
            points.push(DVec3::new(angle.cos(), angle.sin(), z));
        }
    }
    hull_polygons(&points)
}

fn square_pyramid() -> Polygons {
    hull_polygons(&[
        DVec3::new(-1.0, -1.0, 0.0),
        DVec3::new(1.0, -1.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(-1.0, 1.0, 0.0),
        DVec3::new(0.0, 0.0, 1.2),
    ])
}

fn annulus(segments: u32, rings: u32) -> Polygons {
    let mut points = Vec::new();
    for r in 0..=rings {
        let radius = 1.0 + f64::from(r) / f64::from(rings);
        for s in 0..segments {
            let angle = std::f64::consts::TAU * f64::from(s) / f64::from(segments);
            points.push(DVec3::new(radius * angle.cos(), radius * angle.sin(), 0.0));
        }
    }
    let id = |s: u32, r: u32| r * segments + s % segments;
    let mut faces = Vec::new();
    for r in 0..rings {
        for s in 0..segments {
            faces.push(vec![id(s, r), id(s + 1, r), id(s + 1, r + 1), id(s, r + 1)]);
        }
    }
    to_polygons(&points, &faces)
}

fn torus(nu: u32, nv: u32) -> Polygons {
    let (major, minor) = (2.0, 0.6);
    let mut points = Vec::new();
    let mut centres = Vec::new();
    for j in 0..nv {
        let v = std::f64::consts::TAU * f64::from(j) / f64::from(nv);
        for i in 0..nu {
            let u = std::f64::consts::TAU * f64::from(i) / f64::from(nu);
            let ring = major + minor * v.cos();
            points.push(DVec3::new(ring * u.cos(), ring * u.sin(), minor * v.sin()));
            centres.push(DVec3::new(major * u.cos(), major * u.sin(), 0.0));
        }
    }
    let id = |i: u32, j: u32| (j % nv) * nu + i % nu;
    let mut faces = Vec::new();
    for j in 0..nv {
        for i in 0..nu {
            let a = id(i, j);
            let face = vec![a, id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
            faces.push(orient(
                &points,
                face,
                points[a as usize] - centres[a as usize],
            ));
        }
    }
    to_polygons(&points, &faces)
}

/// The surface of a slab of unit cubes, 5 by 3 with two holes: genus 2.
fn double_torus() -> Polygons {
    const CELLS: [&str; 3] = ["XXXXX", "X.X.X", "XXXXX"];
    let filled = |i: i32, j: i32| {
        usize::try_from(j)
            .ok()
            .and_then(|j| CELLS.get(j))
            .and_then(|row| usize::try_from(i).ok().and_then(|i| row.as_bytes().get(i)))
            == Some(&b'X')
    };
    let mut ids: HashMap<[i32; 3], u32> = HashMap::new();
    let mut points = Vec::new();
    let mut id = |p: [i32; 3]| {
        *ids.entry(p).or_insert_with(|| {
            points.push(DVec3::new(
                f64::from(p[0]),
                f64::from(p[1]),
                f64::from(p[2]),
            ));
            points.len() as u32 - 1
        })
    };
    let mut faces: Vec<(Vec<u32>, DVec3)> = Vec::new();
    for j in 0..3 {
        for i in 0..5 {
            if !filled(i, j) {
                continue;
            }
            let square = |id: &mut dyn FnMut([i32; 3]) -> u32, corners: [[i32; 3]; 4]| {
                corners.iter().map(|&c| id(c)).collect::<Vec<u32>>()
            };
            faces.push((
                square(
                    &mut id,
                    [[i, j, 1], [i + 1, j, 1], [i + 1, j + 1, 1], [i, j + 1, 1]],
                ),
                DVec3::Z,
            ));
            faces.push((
                square(
                    &mut id,
                    [[i, j, 0], [i + 1, j, 0], [i + 1, j + 1, 0], [i, j + 1, 0]],
                ),
                DVec3::NEG_Z,
            ));
            if !filled(i - 1, j) {
                faces.push((
                    square(
                        &mut id,
                        [[i, j, 0], [i, j + 1, 0], [i, j + 1, 1], [i, j, 1]],
                    ),
                    DVec3::NEG_X,
                ));
            }
            if !filled(i + 1, j) {
                faces.push((
                    square(
                        &mut id,
                        [
                            [i + 1, j, 0],
                            [i + 1, j + 1, 0],
                            [i + 1, j + 1, 1],
                            [i + 1, j, 1],
                        ],
                    ),
                    DVec3::X,
                ));
            }
            if !filled(i, j - 1) {
                faces.push((
                    square(
                        &mut id,
                        [[i, j, 0], [i + 1, j, 0], [i + 1, j, 1], [i, j, 1]],
                    ),
                    DVec3::NEG_Y,
                ));
            }
            if !filled(i, j + 1) {
                faces.push((
                    square(
                        &mut id,
                        [
                            [i, j + 1, 0],
                            [i + 1, j + 1, 0],
                            [i + 1, j + 1, 1],
                            [i, j + 1, 1],
                        ],
                    ),
                    DVec3::Y,
                ));
            }
        }
    }
    let faces: Vec<Vec<u32>> = faces
        .into_iter()
        .map(|(face, out)| orient(&points, face, out))
        .collect();
    to_polygons(&points, &faces)
}

fn uv_sphere(slices: u32, stacks: u32) -> Polygons {
    let mut points = vec![DVec3::Z];
    for k in 1..stacks {
        let polar = std::f64::consts::PI * f64::from(k) / f64::from(stacks);
        for s in 0..slices {
            let azimuth = std::f64::consts::TAU * f64::from(s) / f64::from(slices);
            points.push(DVec3::new(
                polar.sin() * azimuth.cos(),
                polar.sin() * azimuth.sin(),
                polar.cos(),
            ));
        }
    }
    points.push(DVec3::NEG_Z);
    let south = points.len() as u32 - 1;
    let ring = |k: u32, s: u32| 1 + (k - 1) * slices + s % slices;
    let mut faces = Vec::new();
    for s in 0..slices {
        faces.push(vec![0, ring(1, s), ring(1, s + 1)]);
    }
    for k in 1..stacks - 1 {
        for s in 0..slices {
            let (a, b, c, d) = (
                ring(k, s),
                ring(k + 1, s),
                ring(k + 1, s + 1),
                ring(k, s + 1),
            );
            faces.push(vec![a, b, c]);
            faces.push(vec![a, c, d]);
        }
    }
    for s in 0..slices {
        faces.push(vec![south, ring(stacks - 1, s + 1), ring(stacks - 1, s)]);
    }
    let faces: Vec<Vec<u32>> = faces
        .into_iter()
        .map(|face| {
            let outward = points[face[1] as usize];
            orient(&points, face, outward)
        })
        .collect();
    to_polygons(&points, &faces)
}

/// A cube of `n` by `n` squares per side, pushed out onto the unit sphere.
fn quad_sphere(n: i32) -> Polygons {
    let mut ids: HashMap<[i32; 3], u32> = HashMap::new();
    let mut points = Vec::new();
    let mut faces = Vec::new();
    let half = f64::from(n) / 2.0;
    for axis in 0..3 {
        for side in [0, n] {
            let outward = {
                let mut d = [0.0; 3];
                d[axis] = if side == 0 { -1.0 } else { 1.0 };
                DVec3::from(d)
            };
            for a in 0..n {
                for b in 0..n {
                    let corner = |da: i32, db: i32| {
                        let mut c = [0; 3];
                        c[axis] = side;
                        c[(axis + 1) % 3] = a + da;
                        c[(axis + 2) % 3] = b + db;
                        c
                    };
                    let face: Vec<u32> = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)]
                        .iter()
                        .map(|&c| {
                            *ids.entry(c).or_insert_with(|| {
                                let p =
                                    DVec3::new(f64::from(c[0]), f64::from(c[1]), f64::from(c[2]));
                                points.push((p - DVec3::splat(half)).normalize());
                                points.len() as u32 - 1
                            })
                        })
                        .collect();
                    faces.push((face, outward));
                }
            }
        }
    }
    let faces: Vec<Vec<u32>> = faces
        .into_iter()
        .map(|(face, out)| orient(&points, face, out))
        .collect();
    to_polygons(&points, &faces)
}

/// Splits every quad along its first diagonal.
fn triangulate(polygons: &Polygons) -> Polygons {
    let mut faces = Vec::new();
    for face in polygons.faces() {
        for k in 1..face.len() - 1 {
            faces.push(vec![face[0], face[k], face[k + 1]]);
        }
    }
    Polygons::from_faces(polygons.positions().to_vec(), faces)
}
