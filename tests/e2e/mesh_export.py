#!/usr/bin/env python3
"""End to end: mesh export (`-o NAME.off|.obj|.stl`, tracker issue 41).

Every file is read back by the small parsers below, not by the code that wrote it:
  - tutorial step 14's slotted and drilled block (a difference of boxes and a 40-sided cylinder) and the
    bracket sheet: closed and consistently oriented (every edge used once each way), enclosed volume equal
    to the analytic value worked out here, in OFF, OBJ and STL alike;
  - a box placed by translate(): its bounds are the world coordinates, not the object's;
  - an animation to '-o m-{frame}.off' writes one file per frame, each box where that frame puts it; to
    one '.stl' it is a usage error (64) that writes nothing;
  - a drilled, pocketed block exported to OFF and imported again draws the same visible lines as the
    original from the same camera (the round trip through another tool's file);
  - a script without a camera exports its mesh (a picture from it is still an error);
  - an output naming the script's own imported mesh is refused.

    mesh_export.py HLRSCRIPT WORKDIR EXAMPLES_DIR
"""
import json
import math
import os
import struct
import subprocess
import sys

hlrscript, work, examples = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(script, out, *args, expect=0):
    r = subprocess.run([hlrscript, script, "-o", out, *args], capture_output=True, text=True, timeout=300)
    if r.returncode != expect:
        fail(f"{script} -o {out}: exit {r.returncode} (expected {expect}): {r.stderr}")
    return r


def write_script(name, body):
    path = os.path.join(work, name + ".hls")
    with open(path, "w") as f:
        f.write(body)
    return path


def read_off(path):
    with open(path) as f:
        lines = [ln for ln in f.read().split("\n") if ln.strip() and not ln.startswith("#")]
    if lines[0] != "OFF":
        fail(f"{path}: first line {lines[0]!r}")
    nv, nf, _ = map(int, lines[1].split())
    points = [tuple(map(float, ln.split())) for ln in lines[2:2 + nv]]
    faces = []
    for ln in lines[2 + nv:2 + nv + nf]:
        v = list(map(int, ln.split()))
        if v[0] != len(v) - 1:
            fail(f"{path}: face line {ln!r}")
        faces.append(v[1:])
    return points, faces


def read_obj(path):
    points, faces, objects = [], [], []
    with open(path) as f:
        for ln in f:
            t = ln.split()
            if not t:
                continue
            if t[0] == "v":
                points.append(tuple(map(float, t[1:4])))
            elif t[0] == "f":
                faces.append([int(k.split("/")[0]) - 1 for k in t[1:]])
            elif t[0] == "o":
                objects.append(t[1])
    return points, faces, objects


def read_stl(path):
    data = open(path, "rb").read()
    if data[:5] == b"solid":
        fail(f"{path}: a binary STL must not start with 'solid'")
    (n,) = struct.unpack_from("<I", data, 80)
    if len(data) != 84 + 50 * n:
        fail(f"{path}: {len(data)} bytes for {n} triangles")
    index, points, faces = {}, [], []
    for t in range(n):
        vals = struct.unpack_from("<12f", data, 84 + 50 * t)
        normal, corners = vals[:3], [vals[3 + 3 * c:6 + 3 * c] for c in range(3)]
        face = []
        for c in corners:
            if c not in index:
                index[c] = len(points)
                points.append(c)
            face.append(index[c])
        a, b, c = (points[k] for k in face)
        cr = cross(sub(b, a), sub(c, a))
        if dot(cr, normal) <= 0:
            fail(f"{path}: triangle {t} winds against its normal")
        faces.append(face)
    return points, faces


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def check_closed(path, faces):
    directed = {}
    for f in faces:
        for i in range(len(f)):
            e = (f[i], f[(i + 1) % len(f)])
            directed[e] = directed.get(e, 0) + 1
    for (a, b), n in directed.items():
        if n != 1 or directed.get((b, a)) != 1:
            fail(f"{path}: edge {a}-{b} is used {n} times one way, {directed.get((b, a), 0)} the other")


def fan_area_and_volume(points, faces):
    # Polygons may be concave (OFF, OBJ): the fan's signed volumes still sum to the enclosed volume.
    v = 0.0
    for f in faces:
        for i in range(1, len(f) - 1):
            v += dot(points[f[0]], cross(points[f[i]], points[f[i + 1]])) / 6
    return v


def check_volume(path, points, faces, expected, rel):
    v = fan_area_and_volume(points, faces)
    if abs(v - expected) > rel * expected:
        fail(f"{path}: volume {v}, expected {expected}")


# ---- tutorial step 14: 60 × 40 × 20 block, a 20 × 40 × 10 slot, a Ø12 40-sided hole below the slot ------
ngon = 40 / 2 * 6 ** 2 * math.sin(2 * math.pi / 40)  # the inscribed 40-gon of radius 6
step14 = os.path.join(examples, "tutorial", "14-sheets.hls")
expected14 = 60 * 40 * 20 - 20 * 40 * 10 - ngon * 10
for ext in ("off", "obj", "stl"):
    out = os.path.join(work, "step14." + ext)
    run(step14, out)
    if ext == "off":
        pts, fs = read_off(out)
    elif ext == "obj":
        pts, fs, objs = read_obj(out)
        if objs != ["difference"]:  # a solid is named after what made it, as in JSON's segments
            fail(f"{out}: objects {objs}, expected ['difference']")
    else:
        pts, fs = read_stl(out)
    check_closed(out, fs)
    check_volume(out, pts, fs, expected14, 1e-9 if ext != "stl" else 1e-6)

# ---- the bracket sheet: every solid closed ---------------------------------------------------------------
bracket = os.path.join(examples, "sheets", "bracket.hls")
out = os.path.join(work, "bracket.obj")
run(bracket, out)
pts, fs, objs = read_obj(out)
if not objs:
    fail(f"{out}: no objects")
check_closed(out, fs)
if fan_area_and_volume(pts, fs) <= 0:
    fail(f"{out}: the bracket encloses no volume")

# ---- a sheet of views: its mesh, and no warnings about a page a mesh file does not draw ----------------
views = os.path.join(examples, "sheets", "standard-views.hls")
out = os.path.join(work, "standard-views.stl")
r = run(views, out)
if "warning" in r.stderr:
    fail(f"{out}: warnings about the sheet's views for a mesh file: {r.stderr!r}")
pts, fs = read_stl(out)
check_closed(out, fs)

# ---- world coordinates -------------------------------------------------------------------------------
placed = write_script("placed", """
draw place(box(min: (0, 0, 0), max: (1, 2, 3)), translate(10, 20, 30))
camera main = lookat(eye: (30, -20, 50), target: (10, 20, 30))
""")
out = os.path.join(work, "placed.off")
run(placed, out)
pts, fs = read_off(out)
lo = [min(p[i] for p in pts) for i in range(3)]
hi = [max(p[i] for p in pts) for i in range(3)]
if lo != [10, 20, 30] or hi != [11, 22, 33]:
    fail(f"{out}: bounds {lo} .. {hi}, expected the box moved to (10, 20, 30) .. (11, 22, 33)")
check_volume(out, pts, fs, 6, 1e-12)

# ---- sequences: one file per frame -------------------------------------------------------------------
moving = write_script("moving", """
animate frames 3 fps 1
draw place(box(min: (0, 0, 0), max: (1, 1, 1)), translate(5 * frame, 0, 0))
camera main = lookat(eye: (5, -20, 10), target: (5, 0, 0))
""")
run(moving, os.path.join(work, "m-{frame}.off"))
for k in range(3):
    out = os.path.join(work, f"m-{k}.off")
    pts, fs = read_off(out)
    if min(p[0] for p in pts) != 5 * k or max(p[0] for p in pts) != 5 * k + 1:
        fail(f"{out}: x from {min(p[0] for p in pts)}, expected {5 * k}")
single = os.path.join(work, "all-frames.stl")
r = run(moving, single, expect=64)
if os.path.exists(single) or "{frame" not in r.stderr:
    fail(f"several frames to one STL: {r.stderr!r}, file written: {os.path.exists(single)}")

# ---- round trip: export, import, the same drawing ------------------------------------------------------
camera = 'camera main = lookat(eye: (70, -55, 60), target: (30, 20, 10), fov: 40)\n'
original = write_script("drilled", """
let part = difference(box(min: (0, 0, 0), max: (60, 40, 20)), box(min: (10, 10, 12), max: (35, 30, 21)),
                      box(min: (45, 15, -1), max: (52, 25, 21)))
draw part
""" + camera)
exported = os.path.join(work, "drilled.off")
run(original, exported)
pts, fs = read_off(exported)
check_closed(exported, fs)
check_volume(exported, pts, fs, 60 * 40 * 20 - 25 * 20 * 8 - 7 * 10 * 20, 1e-12)
again = write_script("drilled-again", 'draw import("drilled.off")\n' + camera)


def visible_pieces(script):
    out = script[:-4] + ".json"
    run(script, out, "--json", "segments")
    doc = json.load(open(out))
    pieces = []
    for s in doc["frames"][0]["segments"]:
        if s.get("hidden"):
            continue
        a, b = (tuple(round(c, 6) for c in p) for p in s["p"])
        pieces.append((min(a, b), max(a, b)))
    return pieces


def total(pieces):
    return sum(math.dist(a, b) for a, b in pieces)


first, second = visible_pieces(original), visible_pieces(again)
if abs(total(first) - total(second)) > 1e-6 * total(first):
    fail(f"round trip: {total(first)} of visible lines drawn, {total(second)} after export and import")
if len(first) != len(second):
    fail(f"round trip: {len(first)} visible pieces, {len(second)} after export and import")

# ---- no camera: a mesh file needs none, a picture still does ------------------------------------------
nocam = write_script("no-camera", "draw box(min: (0, 0, 0), max: (2, 3, 4))\n")
out = os.path.join(work, "no-camera.obj")
run(nocam, out)
pts, fs, objs = read_obj(out)
check_closed(out, fs)
check_volume(out, pts, fs, 24, 1e-12)
r = run(nocam, os.path.join(work, "no-camera.pdf"), expect=65)
if "camera" not in r.stderr or os.path.exists(os.path.join(work, "no-camera.pdf")):
    fail(f"a PDF without a camera: {r.stderr!r}")

# ---- an output may not overwrite an input ------------------------------------------------------------
r = run(again, exported, expect=64)
if "input" not in r.stderr:
    fail(f"overwriting the imported mesh: {r.stderr!r}")
print("ok")
