#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora: OUT/{obj,off,ply,stl,scene,svg,strokes}/.

Meshes: the first vertices of each shared OBJ model (../shared/models) with the faces
among them, written in every format (ASCII and binary PLY and STL), plus the start of
each OBJ file as it is (comments, normals, texture coordinates) and the header of each
PLY model with a few of its vertices and a triangle strip. Scenes: scenes/*.json. SVG:
the drawings of scenes/drawn, each cut to its first elements. Stroke files and styles:
the stroke files of scenes/drawn, each cut to its first strokes, and the style files
(STYLES_DIR/strokes/*.json, scenes/styles/*.json). Also every file of the
malformed-input corpus (tests/corpus/, not its fuzz/ folder) of a matching folder or
extension. Each seed is at most MAX_BYTES.

Usage: make_seeds.py MODELS_DIR SCENES_DIR STYLES_DIR CORPUS_DIR OUT
"""
import pathlib
import shutil
import struct
import sys

MAX_BYTES = 4096
VERTICES = 24  # from the start of each model: a patch small enough for MAX_BYTES


def small_patch(obj_text):
    """The first VERTICES vertices and the triangles (fan-split faces) among them."""
    vertices, triangles = [], []
    for line in obj_text.splitlines():
        words = line.split()
        if words[:1] == ["v"] and len(vertices) < VERTICES:
            vertices.append(tuple(float(w) for w in words[1:4]))
        elif words[:1] == ["f"]:
            corners = [int(w.split("/")[0]) - 1 for w in words[1:]]
            if all(0 <= c < len(vertices) for c in corners):
                triangles += [(corners[0], corners[k], corners[k + 1]) for k in range(1, len(corners) - 1)]
    return vertices, triangles


def normal(vertices, t):
    a, b, c = (vertices[i] for i in t)
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def mesh_files(vertices, triangles):
    """(extension suffix, bytes) of the patch in each format."""
    vs = "".join(f"{x} {y} {z}\n" for x, y, z in vertices)
    obj = "".join(f"v {x} {y} {z}\n" for x, y, z in vertices) + "".join(
        f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in triangles)
    off = f"OFF\n{len(vertices)} {len(triangles)} 0\n" + vs + "".join(f"3 {a} {b} {c}\n" for a, b, c in triangles)

    def ply_header(fmt):
        return (f"ply\nformat {fmt} 1.0\nelement vertex {len(vertices)}\nproperty float x\nproperty float y\n"
                f"property float z\nelement face {len(triangles)}\nproperty list uchar int vertex_indices\n"
                "end_header\n").encode()

    ply_ascii = ply_header("ascii") + (vs + "".join(f"3 {a} {b} {c}\n" for a, b, c in triangles)).encode()
    ply_binary = ply_header("binary_little_endian") + b"".join(struct.pack("<3f", *v) for v in vertices) + b"".join(
        struct.pack("<B3i", 3, *t) for t in triangles)
    stl_ascii = "solid patch\n" + "".join(
        "facet normal {} {} {}\nouter loop\n".format(*normal(vertices, t)) +
        "".join("vertex {} {} {}\n".format(*vertices[i]) for i in t) + "endloop\nendfacet\n"
        for t in triangles) + "endsolid patch\n"
    stl_binary = b"patch".ljust(80, b"\0") + struct.pack("<I", len(triangles)) + b"".join(
        struct.pack("<3f", *normal(vertices, t)) + b"".join(struct.pack("<3f", *vertices[i]) for i in t) + b"\0\0"
        for t in triangles)
    return [("obj", ".obj", obj.encode()), ("off", ".off", off.encode()), ("ply", "-ascii.ply", ply_ascii),
            ("ply", "-binary.ply", ply_binary), ("stl", "-ascii.stl", stl_ascii.encode()),
            ("stl", "-binary.stl", stl_binary)]


def ply_with_strip(ply_bytes):
    """A binary PLY model's header, its counts cut to a few vertices and one strip of them."""
    header, _, _ = ply_bytes.partition(b"end_header\n")
    lines = header.decode("ascii").splitlines()
    vertices = 6
    for i, line in enumerate(lines):
        if line.startswith("element vertex"):
            lines[i] = f"element vertex {vertices}"
    strip = list(range(vertices)) + [-1, 0, 2, 4]
    body = b"".join(struct.pack("<3f", k, k % 2, 0) for k in range(vertices))
    body += struct.pack("<i", len(strip)) + struct.pack(f"<{len(strip)}i", *strip)
    return ("\n".join(lines) + "\nend_header\n").encode() + body


def first_lines(data):
    """The start of a text file, cut at the last whole line within MAX_BYTES."""
    head = data[:MAX_BYTES]
    return head[:head.rfind(b"\n") + 1]


def head_closed(data, item_end, closing):
    """The whole file when it fits MAX_BYTES; else its first items, up to the last `item_end`
    that leaves room for `closing`, then `closing`: a drawing's first elements, a stroke
    file's first strokes."""
    if len(data) <= MAX_BYTES:
        return data
    head = data[:MAX_BYTES - len(closing)]
    return head[:head.rfind(item_end) + len(item_end)] + closing


# The seed folder of a corpus file: by its folder, else by its extension.
CORPUS_FOLDERS = {"scene": "scene", "svg": "svg", "strokes": "strokes", "style": "strokes"}


def main(models, scenes, styles, corpus, out):
    seeds = {fmt: {} for fmt in ("obj", "off", "ply", "stl", "scene", "svg", "strokes")}  # format -> {name: bytes}
    for path in sorted(models.glob("*.obj")):
        data = path.read_bytes()
        seeds["obj"][f"{path.stem}-head.obj"] = first_lines(data)
        for fmt, suffix, content in mesh_files(*small_patch(data.decode())):
            seeds[fmt][path.stem + suffix] = content
    for path in sorted(models.glob("*.ply")):
        seeds["ply"][f"{path.stem}-strip.ply"] = ply_with_strip(path.read_bytes())
    for path in sorted(scenes.glob("*.json")):
        seeds["scene"][path.name] = path.read_bytes()
    for path in sorted((scenes / "drawn").glob("*.svg")):
        seeds["svg"][path.name] = head_closed(path.read_bytes(), b"/>\n", b"</svg>\n")
    for path in sorted((scenes / "drawn").glob("*.strokes.json")):
        seeds["strokes"][path.name] = head_closed(path.read_bytes(), b"}", b"\n ]\n}\n")
    for path in sorted((styles / "strokes").glob("*.json")) + sorted((scenes / "styles").glob("*.json")):
        seeds["strokes"]["style-" + path.name] = path.read_bytes()
    for path in sorted(corpus.rglob("*")):
        parts = path.relative_to(corpus).parts
        fmt = CORPUS_FOLDERS.get(parts[0], path.suffix[1:])
        if path.is_file() and "fuzz" not in parts and fmt in seeds:
            seeds[fmt]["corpus-" + "-".join(parts)] = path.read_bytes()
    for fmt, files in seeds.items():
        folder = out / fmt
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir(parents=True)
        for name, content in files.items():
            if len(content) <= MAX_BYTES:
                (folder / name).write_bytes(content)
        print(f"make_seeds: {len(list(folder.iterdir()))} {fmt} seeds in {folder}")


if __name__ == "__main__":
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    main(*(pathlib.Path(a) for a in sys.argv[1:]))
