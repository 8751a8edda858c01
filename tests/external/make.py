"""Writes mesh files with other tools, to check that Edgewise reads them.

Run by hand, not by CI; the outputs are committed beside this script:

    python3 -m venv /tmp/venv && /tmp/venv/bin/pip install trimesh meshio plyfile numpy
    /tmp/venv/bin/python tests/external/make.py

Each file is listed in expected.txt with the vertex, edge and face counts the
writer put in it (edges counted here from the faces), which
crates/core/tests/formats_external.rs checks after loading. A file with a
vertex where separate fans of faces meet still lists the file's counts; the
test names such files and expects one vertex more per extra fan.
"""

import os

import meshio
import numpy as np
import plyfile
import trimesh

HERE = os.path.dirname(os.path.abspath(__file__))


def counts(faces):
    """Vertices used, distinct undirected edges and faces of a face list."""
    edges = set()
    used = set()
    for face in faces:
        used.update(int(v) for v in face)
        for a, b in zip(face, list(face[1:]) + [face[0]]):
            edges.add((min(int(a), int(b)), max(int(a), int(b))))
    return len(used), len(edges), len(faces)


expected = []


def record(name, vertex_count, faces):
    _, e, f = counts(faces)
    expected.append(f"{name} {vertex_count} {e} {f}")


# trimesh: binary little-endian PLY (its default) and OBJ with normals
# (faces written as v//vn).
sphere = trimesh.creation.icosphere(subdivisions=2)
sphere.export(os.path.join(HERE, "trimesh-icosphere.ply"))
record("trimesh-icosphere.ply", len(sphere.vertices), sphere.faces.tolist())

# trimesh: the same icosphere with four faces removed, two holes of two
# adjacent faces each that touch at exactly one vertex (no shared edge), so
# that vertex joins two fans of faces. Taking the first such two pairs in
# order of face numbers keeps the choice deterministic.
def touching_holes(mesh):
    pairs = sorted(tuple(sorted(map(int, p))) for p in mesh.face_adjacency)

    def corners(pair):
        return set(int(v) for f in pair for v in mesh.faces[f])

    def edges(pair):
        return {frozenset((int(a), int(b))) for f in pair
                for a, b in zip(mesh.faces[f], np.roll(mesh.faces[f], -1))}

    for i, first in enumerate(pairs):
        for second in pairs[i + 1:]:
            if set(first) & set(second):
                continue
            if len(corners(first) & corners(second)) == 1 and not edges(first) & edges(second):
                return list(first) + list(second)
    raise SystemExit("no two holes touch at one vertex")


removed = touching_holes(sphere)
holed = trimesh.Trimesh(
    vertices=sphere.vertices, faces=np.delete(sphere.faces, removed, axis=0), process=False
)
holed.export(os.path.join(HERE, "trimesh-icosphere-touching-holes.ply"))
record("trimesh-icosphere-touching-holes.ply", len(holed.vertices), holed.faces.tolist())

box = trimesh.creation.box()
with open(os.path.join(HERE, "trimesh-box.obj"), "w") as out:
    out.write(trimesh.exchange.obj.export_obj(box, include_normals=True))
record("trimesh-box.obj", len(box.vertices), box.faces.tolist())
torus = trimesh.creation.torus(major_radius=2.0, minor_radius=0.5, major_sections=24, minor_sections=12)
torus.export(os.path.join(HERE, "trimesh-torus.ply"), encoding="ascii")
record("trimesh-torus.ply", len(torus.vertices), torus.faces.tolist())

# meshio: a cube of quads plus a square pyramid's triangles glued on top,
# as ASCII PLY and as OBJ, with triangle and quad cells in one file.
points = np.array(
    [[x, y, z] for z in (0.0, 1.0) for y in (0.0, 1.0) for x in (0.0, 1.0)] + [[0.5, 0.5, 1.8]]
)
quads = np.array([[0, 2, 3, 1], [0, 1, 5, 4], [1, 3, 7, 5], [3, 2, 6, 7], [2, 0, 4, 6]])
triangles = np.array([[4, 5, 8], [5, 7, 8], [7, 6, 8], [6, 4, 8]])
house = meshio.Mesh(points, [("triangle", triangles), ("quad", quads)])
meshio.write(os.path.join(HERE, "meshio-house.ply"), house, binary=False)
record("meshio-house.ply", len(points), triangles.tolist() + quads.tolist())
meshio.write(os.path.join(HERE, "meshio-house.obj"), house)
record("meshio-house.obj", len(points), triangles.tolist() + quads.tolist())

# plyfile: big-endian binary with double coordinates, normals and colours,
# a face list named vertex_index with uint count and uint indices, and an
# extra "edge" element, all of which must be skipped.
octa_points = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
octa_faces = [
    [0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4],
    [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5],
]
vertex = np.array(
    [(x, y, z, x, y, z, 200, 100, 50) for (x, y, z) in octa_points],
    dtype=[("x", "f8"), ("y", "f8"), ("z", "f8"), ("nx", "f4"), ("ny", "f4"), ("nz", "f4"),
           ("red", "u1"), ("green", "u1"), ("blue", "u1")],
)
face = np.empty(len(octa_faces), dtype=[("vertex_index", "O"), ("flags", "i2")])
face["vertex_index"] = [np.array(f, dtype="u4") for f in octa_faces]
face["flags"] = 7
edge = np.array([(0, 1), (2, 3)], dtype=[("vertex1", "i4"), ("vertex2", "i4")])
plyfile.PlyData(
    [
        plyfile.PlyElement.describe(vertex, "vertex"),
        plyfile.PlyElement.describe(face, "face", len_types={"vertex_index": "u4"},
                                    val_types={"vertex_index": "u4"}),
        plyfile.PlyElement.describe(edge, "edge"),
    ],
    byte_order=">",
).write(os.path.join(HERE, "plyfile-octahedron.ply"))
record("plyfile-octahedron.ply", len(octa_points), octa_faces)

with open(os.path.join(HERE, "expected.txt"), "w") as out:
    out.write("# file vertices edges faces (written by make.py)\n")
    out.write("\n".join(expected) + "\n")
