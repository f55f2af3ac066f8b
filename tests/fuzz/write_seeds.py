#!/usr/bin/env python3
"""Writes the binary seeds of tests/fuzz/corpus/: engine/ (the layout fuzz_engine.cpp decodes) and
stl_binary/ (triangles as fuzz_stl_binary.cpp takes them). Run from anywhere; rewrites those seeds."""
import pathlib
import struct

CORPUS = pathlib.Path(__file__).resolve().parent / "corpus"


def s8(value):
    """A coordinate: fuzz_engine reads signed bytes × 0.5."""
    b = round(value * 2)
    assert -128 <= b <= 127
    return b & 0xFF


def solid(vertices, faces, lines=(), options=0, turn=0):
    out = [(len(vertices) - 3) % 14, options, turn]
    for v in vertices:
        out += [s8(c) for c in v]
    out.append(len(faces) + len(lines))
    for f in faces:
        out.append(len(f) - 3)  # kind 0: a face without hole
        out += f
    for a, b in lines:
        out += [0xC0, a, b]  # kind 3: a line
    return out


def box(x0, y0, z0, x1, y1, z1, options=0, turn=0):
    v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    f = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    return solid(v, f, options=options, turn=turn)


def l_block(options=0):
    """An L-shaped prism: the L (x 0..4, y 0..3, notch from (2, 1.5)) extruded 0..2 in z, with a marking
    across its top face."""
    ring = [(0, 0), (4, 0), (4, 1.5), (2, 1.5), (2, 3), (0, 3)]
    v = [(x, y, 0) for x, y in ring] + [(x, y, 2) for x, y in ring]
    f = [[5, 4, 3, 2, 1, 0], [6, 7, 8, 9, 10, 11]]
    f += [[i, (i + 1) % 6, (i + 1) % 6 + 6, i + 6] for i in range(6)]
    return solid(v, f, lines=[(6, 8)], options=options)


def scene(flags, eye, target, up, lens, solids):
    out = [flags] + [s8(c) for c in eye] + [s8(c) for c in target] + [up, lens, len(solids) - 1]
    for s in solids:
        out += s
    return bytes(out)


def write(directory, name, data):
    path = CORPUS / directory / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)


# Engine: perspective and orthographic views, hidden pieces, frames and every pen order.
write("engine", "cube", scene(0x80, (6, -5, 4), (0.5, 0.5, 0.5), 0, 55, [box(0, 0, 0, 1, 1, 1)]))
write("engine", "cube-ortho-hidden", scene(0x13, (6, -5, 4), (0.5, 0.5, 0.5), 0, 8, [box(0, 0, 0, 1, 1, 1)]))
write("engine", "l-block", scene(0xA2, (10, -8, 7), (2, 1.5, 1), 0, 50, [l_block()]))
write("engine", "l-block-mirrored-greedy", scene(0x40, (-10, -8, 7), (-2, 1.5, 1), 0, 50,
                                                  [l_block(options=1)]))
write("engine", "two-boxes-overlapping", scene(0x82, (12, -9, 8), (1.5, 1, 1), 0, 45,
                                               [box(0, 0, 0, 2, 2, 2), box(1, 0.5, 0.5, 3.5, 1.5, 1.5)]))
write("engine", "two-boxes-touching-framed", scene(0xA0, (10, 7, 6), (1, 1, 1), 0, 60,
                                                   [box(0, 0, 0, 2, 2, 2), box(2, 0, 0, 4, 2, 1)]))
write("engine", "box-in-box-no-intersections", scene(0x86, (9, -9, 9), (0, 0, 0), 0, 45,
                                                     [box(-2, -2, -2, 2, 2, 2), box(-1, -1, -1, 1, 1, 1)]))
# A box turned by 1/64 of a turn about z (turn byte: axis 0, step 1) through a box on the grid.
write("engine", "two-boxes-one-turned", scene(0x82, (12, -9, 8), (1.5, 1, 1), 0, 45,
                                              [box(0, 0, 0, 2, 2, 2), box(1, 0.5, 0.5, 3.5, 1.5, 1.5, turn=4)]))
# A square plate with a square hole (kind 2) and a marking across it.
plate = [8 - 3, 0, 0] + [s8(c) for v in [(0, 0, 0), (4, 0, 0), (4, 4, 0), (0, 4, 0),
                                      (1, 1, 0), (1, 3, 0), (3, 3, 0), (3, 1, 0)] for c in v]
plate += [2, 0x80 | 1, 0, 1, 2, 3, 1, 4, 5, 6, 7, 0xC0, 0, 2]
write("engine", "plate-with-hole", scene(0x82, (2, -6, 8), (2, 2, 0), 0, 60, [plate]))

# Binary STL: triangles of 50 bytes (normal, three corners, attribute count).
def triangles(tris):
    out = b""
    for t in tris:
        out += struct.pack("<3f", 0, 0, 0)
        for p in t:
            out += struct.pack("<3f", *p)
        out += b"\0\0"
    return out


tetra = [[(0, 0, 0), (0, 1, 0), (1, 0, 0)], [(0, 0, 0), (1, 0, 0), (0, 0, 1)],
         [(0, 0, 0), (0, 0, 1), (0, 1, 0)], [(1, 0, 0), (0, 1, 0), (0, 0, 1)]]
write("stl_binary", "tetra", triangles(tetra))
quads = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
cube_v = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
cube = [[cube_v[q[0]], cube_v[q[i]], cube_v[q[i + 1]]] for q in quads for i in (1, 2)]
write("stl_binary", "cube", triangles(cube))
write("stl_binary", "broken-nan-corner", triangles([[(0, 0, 0), (float("nan"), 1, 0), (1, 0, 0)]]))
write("stl_binary", "broken-open-and-degenerate", triangles(cube[:5] + [[(0, 0, 0), (0, 0, 0), (1, 1, 1)]]))
