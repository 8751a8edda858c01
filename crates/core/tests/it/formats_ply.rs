//! PLY layouts beyond what the writers produce: every scalar type for the
//! coordinates and indices, both byte orders, lists and extra properties in
//! the vertex and face elements (which take the reader's general path rather
//! than its fixed-row fast path), and extra elements before the vertices.

use edgewise_core::formats::{self, Format};
use edgewise_core::mesh::Polygons;
use glam::Vec3;

const SQUARE: [[f32; 3]; 4] = [
    [0.0, 0.0, 0.0],
    [1.0, 0.0, 0.0],
    [1.0, 1.0, 0.0],
    [0.0, 1.0, 0.0],
];
const FACES: [[u32; 3]; 2] = [[0, 1, 2], [0, 2, 3]];

fn read(bytes: &[u8]) -> Polygons {
    formats::read_polygons(bytes, Format::Ply)
        .unwrap_or_else(|e| panic!("{}", e.render("test.ply")))
}

fn assert_square(polygons: &Polygons) {
    let expected: Vec<Vec3> = SQUARE.iter().map(|&p| Vec3::from(p)).collect();
    assert_eq!(polygons.positions(), expected.as_slice());
    let faces: Vec<Vec<u32>> = polygons.faces().map(<[u32]>::to_vec).collect();
    assert_eq!(faces, FACES.iter().map(|f| f.to_vec()).collect::<Vec<_>>());
}

/// Appends `value` as the PLY type `ty` in the given byte order.
fn put(out: &mut Vec<u8>, ty: &str, value: f64, big: bool) {
    let mut bytes = match ty {
        "char" => vec![(value as i8) as u8],
        "uchar" => vec![value as u8],
        "short" => (value as i16).to_le_bytes().to_vec(),
        "ushort" => (value as u16).to_le_bytes().to_vec(),
        "int" => (value as i32).to_le_bytes().to_vec(),
        "uint" => (value as u32).to_le_bytes().to_vec(),
        "float" => (value as f32).to_le_bytes().to_vec(),
        "double" => value.to_le_bytes().to_vec(),
        other => panic!("no type {other}"),
    };
    if big {
        bytes.reverse();
    }
    out.extend(bytes);
}

#[test]
fn every_scalar_type_and_byte_order_reads_the_same_square() {
    for coordinate in [
        "char", "uchar", "short", "ushort", "int", "uint", "float", "double",
    ] {
        for (count, index) in [
            ("uchar", "int"),
            ("ushort", "uint"),
            ("int", "short"),
            ("char", "uchar"),
        ] {
            for big in [false, true] {
                let order = if big {
                    "binary_big_endian"
                } else {
                    "binary_little_endian"
                };
                let mut bytes = format!(
                    "ply\nformat {order} 1.0\nelement vertex 4\nproperty {coordinate} x\n\
                     property {coordinate} y\nproperty {coordinate} z\nelement face 2\n\
                     property list {count} {index} vertex_indices\nend_header\n"
                )
                .into_bytes();
                for p in SQUARE {
                    for c in p {
                        put(&mut bytes, coordinate, f64::from(c), big);
                    }
                }
                for f in FACES {
                    put(&mut bytes, count, 3.0, big);
                    for v in f {
                        put(&mut bytes, index, f64::from(v), big);
                    }
                }
                assert_square(&read(&bytes));
            }
        }
    }
}

#[test]
fn extra_properties_lists_and_elements_are_skipped() {
    for big in [false, true] {
        let order = if big {
            "binary_big_endian"
        } else {
            "binary_little_endian"
        };
        let mut bytes = format!(
            "ply\nformat {order} 1.0\ncomment extra element first, lists in the vertices\n\
             element material 2\nproperty uchar red\nproperty list uchar float weights\n\
             element vertex 4\nproperty double z_scale\nproperty float x\nproperty list ushort int tags\n\
             property float y\nproperty float z\nproperty uchar alpha\n\
             element face 2\nproperty short flags\nproperty list uchar uint vertex_index\n\
             property list uchar float texcoord\nend_header\n"
        )
        .into_bytes();
        for _ in 0..2 {
            put(&mut bytes, "uchar", 255.0, big);
            put(&mut bytes, "uchar", 2.0, big);
            put(&mut bytes, "float", 0.5, big);
            put(&mut bytes, "float", 0.25, big);
        }
        for (i, p) in SQUARE.iter().enumerate() {
            put(&mut bytes, "double", 9.0, big);
            put(&mut bytes, "float", f64::from(p[0]), big);
            put(&mut bytes, "ushort", i as f64, big);
            for _ in 0..i {
                put(&mut bytes, "int", 7.0, big);
            }
            put(&mut bytes, "float", f64::from(p[1]), big);
            put(&mut bytes, "float", f64::from(p[2]), big);
            put(&mut bytes, "uchar", 128.0, big);
        }
        for f in FACES {
            put(&mut bytes, "short", -1.0, big);
            put(&mut bytes, "uchar", 3.0, big);
            for v in f {
                put(&mut bytes, "uint", f64::from(v), big);
            }
            put(&mut bytes, "uchar", 2.0, big);
            put(&mut bytes, "float", 0.0, big);
            put(&mut bytes, "float", 1.0, big);
        }
        assert_square(&read(&bytes));
        let loaded = formats::load(&bytes, "x.ply", edgewise_core::mesh::Structure::HalfEdge)
            .expect("loads");
        assert_eq!(loaded.warnings.len(), 1);
        assert_eq!(
            loaded.warnings[0].render("x.ply"),
            "x.ply:4: the 2 rows of element \"material\" are skipped; only vertex and face make the mesh"
        );
    }
    let ascii = "ply\r\nformat ascii 1.0\r\nelement vertex 4\r\nproperty float x\r\nproperty list uchar int tags\r\n\
                 property float y\r\nproperty float z\r\nproperty float nx\r\nelement face 2\r\n\
                 property list uchar int vertex_indices\r\nproperty uchar flags\r\nend_header\r\n\
                 0 0 0 0 1\r\n1 2 5 6 0 0 1\r\n\r\n1 0 1 0 1\r\n0 1 7 1 0 0\r\n3 0 1 2 9\r\n3 0 2 3 9\r\n";
    assert_square(&read(ascii.as_bytes()));
}
