//! `.wtb`: the winged-edge tables as written, one row per vertex, face and
//! edge (format in `docs/formats.md`).

use super::tables::table_file;
use crate::mesh::WingedEdgeMesh;
use crate::mesh::winged_edge::Vertex;
use crate::schema::Structure;

table_file!(
    WingedEdgeMesh, Winged, Edge, Vertex,
    magic: "wtb", other: "htb",
    preamble: "# Winged-edge tables (Edgewise .wtb, see docs/formats.md). Ids count from 0;\n\
               # faces are traversed clockwise seen from outside; - is the boundary.\n",
    edges: "edges" of "edge" in Structure::WingedEdge,
);
