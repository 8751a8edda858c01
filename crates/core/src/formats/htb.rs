//! `.htb`: the half-edge tables as written, one row per vertex, face and
//! half-edge (format in `docs/formats.md`).

use super::tables::table_file;
use crate::mesh::HalfEdgeMesh;
use crate::mesh::half_edge::Vertex;
use crate::schema::Structure;

table_file!(
    HalfEdgeMesh, Half, HalfEdge, Vertex,
    magic: "htb", other: "wtb",
    preamble: "# Half-edge tables (Edgewise .htb, see docs/formats.md). Ids count from 0;\n\
               # successors go counter-clockwise around their face; a vertex's incident\n\
               # half-edge ends at it; - is the boundary.\n",
    edges: "halfedges" of "half-edge" in Structure::HalfEdge,
);
