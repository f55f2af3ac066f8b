#!/usr/bin/env python3
"""End to end: sheets of views (`view NAME = CAMERA at page (X, Y) ...`, tracker issue 41).

Boxes seen square on by orthographic cameras, so where every line lands on the page is worked out here by
hand, not by the engine:
  - a box 4 × 2 × 1 seen from the front at 10 mm per unit, its centre at page (100, 60): the rectangle
    x 80 … 120, y 55 … 65; from above at (100, 180): x 80 … 120, y 170 … 190, and the small box beside it
    x 95 … 105, y 150 … 160. Its hidden edges all lie
    under visible ones, so the engine returns hidden pieces but none is drawn (visible lines win);
  - a small box behind it, hidden in the front view: its front and back faces project to one rectangle,
    x 95 … 105, y 59 … 63, drawn once (28 mm of hidden strokes);
  - without scales, the sheet takes the largest ISO scale (1, 2, 5 × 10^k) at which each view and its label
    stay inside the margins: 20 here (worked out below);
  - a perspective view with hidden: false has no hidden pieces; --camera NAME draws one view alone;
  - the frame is drawn along the margins and each view's label under it; PDF, plotter SVG, HPGL, G-code
    and DXF are written from the same sheet;
  - a box cut in half by section(): only its cut face is hatched, in the hatch pen, and nothing of the
    removed half is drawn;
  - a dimension of the big box's length, 10 mm below the front view in pen 2: extension lines, the line
    from page (80, 75) to (120, 75), its value under the middle.

    sheets.py HLRSCRIPT WORKDIR
"""
import json
import math
import os
import subprocess
import sys

hlrscript, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
EPS = 1e-6


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(name, body, *args, out_ext="json"):
    script = os.path.join(work, name + ".hls")
    with open(script, "w") as f:
        f.write(body)
    out = os.path.join(work, name + "." + out_ext)
    r = subprocess.run([hlrscript, script, "-o", out, *args], capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        fail(f"{name}: exit {r.returncode}: {r.stderr}")
    return out, r.stderr


def on_rect(p, rect):
    x0, y0, x1, y1 = rect
    inside = x0 - EPS <= p[0] <= x1 + EPS and y0 - EPS <= p[1] <= y1 + EPS
    edge = min(abs(p[0] - x0), abs(p[0] - x1), abs(p[1] - y0), abs(p[1] - y1)) < EPS
    return inside and edge


def length(strokes):
    return sum(math.dist(s[i - 1], s[i]) for s in strokes for i in range(1, len(s)))


BOXES = """
draw box(min: (-2, -1, 0), max: (2, 1, 1))
draw box(min: (-0.5, 2, 0.2), max: (0.5, 3, 0.6))
style hidden dashed
view front = ortho(eye: (0, -10, 0.5), target: (0, 0, 0.5), height: 4) at page (100, 60) scale: 10 label: ""
camera plan = ortho(eye: (0, 0, 10), target: (0, 0, 0), up: (0, 1, 0), height: 4)
view top = plan at page (100, 180) scale: 10 label: ""
view iso = lookat(eye: (8, -6, 5), target: (0, 0, 0.5), fov: 30) at page (230, 100) scale: 10 hidden: false
"""

# ---- where the lines land ----
out, _ = run("boxes", BOXES, "--plain")
frame = json.load(open(out))["frames"][0]
if "camera" in frame or "layout" in frame:
    fail("a sheet's frame has views instead of one camera and layout")
views = frame["views"]
if [v["name"] for v in views] != ["front", "top", "iso"]:
    fail(f"views: {[v['name'] for v in views]}")
for v, at in zip(views, [(100, 60), (100, 180), (230, 100)]):
    if v["mm_per_world_unit"] != 10:
        fail(f"view {v['name']}: scale {v['mm_per_world_unit']}, wanted 10")
    if any(abs(a - b) > EPS for a, b in zip(v["layout"]["origin_mm"], at)):
        fail(f"view {v['name']}: picture origin at {v['layout']['origin_mm']}, wanted {at}")
if views[0]["label"] != "" or views[2]["label"] != "ISO":
    fail(f"labels: {[v['label'] for v in views]}")
by_view = [[s for s in frame["segments"] if s["view"] == i] for i in range(3)]
if not any(s["hidden"] for s in by_view[0]) or not any(s["hidden"] for s in by_view[1]):
    fail("the engine returns hidden pieces in the front and top views")
if any(s["hidden"] for s in by_view[2]):
    fail("the view with hidden: false has hidden pieces")

front, top, small = (80, 55, 120, 65), (80, 170, 120, 190), (95, 59, 105, 63)
small_top = (95, 150, 105, 160)  # the small box, in plain sight from above
drawn = [s for s in frame["strokes"] if all(x < 160 for x, _ in s)]  # the orthographic views, left of the iso
for s in drawn:
    for p in s:
        if not (on_rect(p, front) or on_rect(p, top) or on_rect(p, small_top)):
            fail(f"visible stroke point {p} is on no box outline")
if abs(length(drawn) - (2 * (40 + 10) + 2 * (40 + 20) + 4 * 10)) > 1e-6:
    fail(f"visible length of the three outlines: {length(drawn)}, wanted 260")
hidden = frame["hidden_strokes"]
for s in hidden:
    for p in s:
        if not on_rect(p, small):
            fail(f"hidden stroke point {p} is not on the small box's outline")
if abs(length(hidden) - 28) > 1e-6:
    fail(f"hidden length: {length(hidden)}, wanted 28 (the small box once; the big box's under its outline)")

# ---- a dimension ----
# The big box's length in the front view, 10 mm below it in pen 2: extension lines down from its bottom
# corners (page (80, 65) and (120, 65)), the dimension line at y = 75 from x 80 to 120, the value "4".
DIMENSIONED = BOXES + 'dimension from (-2, -1, 0) to (2, -1, 0) in front offset: -10 pen: 2\n'
out, _ = run("dimensioned", DIMENSIONED, "--plain")
frame = json.load(open(out))["frames"][0]
pen2 = [s for s, pen in zip(frame["strokes"], frame["stroke_pens"]) if pen == 2]
segments = [(s[i - 1], s[i]) for s in pen2 for i in range(1, len(s))]  # the plan joins lines into strokes


def covered(on, lo, hi):
    """Length of pen-2 segments lying on the line `on` (a predicate of a point) between lo and hi."""
    return sum(math.dist(a, b) for a, b in segments if on(a) and on(b))


if abs(covered(lambda p: abs(p[1] - 75) < EPS and 80 - EPS <= p[0] <= 120 + EPS, 80, 120) - 40) > 1e-6:
    fail("the dimension line from (80, 75) to (120, 75) is not drawn whole in pen 2")
for x in (80, 120):
    if abs(covered(lambda p: abs(p[0] - x) < EPS and 66.5 - EPS <= p[1] <= 77 + EPS, 66.5, 77) - 10.5) > 1e-6:
        fail(f"the extension line at x = {x} from y 66.5 to 77 is not drawn whole in pen 2")
letters = [p for s in pen2 for p in s if p[1] > 77.5]
if not letters or not all(95 < p[0] < 105 for p in letters):
    fail("the value is not written under the dimension line's middle")

# ---- an angle ----
# The front view's bottom-left corner, world (-2, -1, 0) at page (80, 65): the angle between the bottom edge
# (towards +x, page +x) and the left edge (up, page −y) is 90°, an arc of radius 8 mm about (80, 65) from
# (88, 65) to (80, 57) in pen 3, and "90°" outside it, up and to the right.
ANGLED = BOXES + 'dimension angle at (-2, -1, 0) from (2, -1, 0) to (-2, -1, 1) in front radius: 8 pen: 3\n'
out, _ = run("angled", ANGLED, "--plain")
frame = json.load(open(out))["frames"][0]
pen3 = [p for s, pen in zip(frame["strokes"], frame["stroke_pens"]) if pen == 3 for p in s]
on_arc = [p for p in pen3 if abs(math.dist(p, (80, 65)) - 8) < 1e-6]
if not any(math.dist(p, (88, 65)) < EPS for p in on_arc) or not any(math.dist(p, (80, 57)) < EPS for p in on_arc):
    fail("the angle's arc does not run from (88, 65) to (80, 57)")
if any(p[0] < 80 - EPS or p[1] > 65 + EPS for p in on_arc):
    fail("the angle's arc leaves the quarter between its legs")
outside = [p for p in pen3 if math.dist(p, (80, 65)) > 9]
if not outside or not all(p[0] > 80 and p[1] < 65 for p in outside):
    fail("the angle's value is not written outside the arc, between the legs")
if len(pen3) < 10:
    fail("the angle dimension has too few strokes for an arc, two arrowheads and '90°'")

# ---- standard views ----
# `views of PART`: third angle puts the top view above the front and the right side to its right, first
# angle the top view below and the left side to the right; one ISO scale; each column's targets share x,
# each row's y; the front view's drawing is the box's 4 × 1 face at that scale about its target.
for projection, side, top_above in (("third", "right", True), ("first", "left", False)):
    body = ('draw box(min: (0, 0, 0), max: (4, 2, 1))\npaper A4 landscape\n'
            f'views of box(min: (0, 0, 0), max: (4, 2, 1)) projection: "{projection}"\n'
            'dimension from (0, 0, 0) to (4, 0, 0) in front offset: -10 pen: 2\n')
    out, err = run("standard-" + projection, body)
    if "warning" in err:
        fail(f"{projection} angle: {err}")
    frame = json.load(open(out))["frames"][0]
    views = {v["name"]: v for v in frame["views"]}
    if sorted(views) != sorted(["front", "top", side, "iso"]):
        fail(f"{projection} angle: views {sorted(views)}")
    scales = {v["mm_per_world_unit"] for v in views.values()}
    if len(scales) != 1:
        fail(f"{projection} angle: scales {scales}")
    scale = scales.pop()
    if scale not in (1, 2, 5, 10, 20, 50, 0.5, 0.2, 0.1):
        fail(f"{projection} angle: scale {scale} is no ISO scale")
    at = {name: v["layout"]["origin_mm"] for name, v in views.items()}
    if abs(at["front"][0] - at["top"][0]) > EPS or abs(at["front"][1] - at[side][1]) > EPS:
        fail(f"{projection} angle: front {at['front']}, top {at['top']}, {side} {at[side]} do not line up")
    if (at["top"][1] < at["front"][1]) != top_above or at[side][0] <= at["front"][0]:
        fail(f"{projection} angle: top at {at['top']}, {side} at {at[side]}, front at {at['front']}")
    index = [v["name"] for v in frame["views"]].index("front")
    front_pieces = [s for s in frame["segments"] if s["view"] == index and not s["hidden"]]
    if not front_pieces:
        fail(f"{projection} angle: nothing drawn in the front view")
    pen2 = [p for st, pen in zip(frame["strokes"], frame["stroke_pens"]) if pen == 2 for p in st]
    grid = 0.0125  # planned strokes are snapped to the page's 0.025 mm grid
    if not any(abs(p[0] - (at["front"][0] - 2 * scale)) <= grid for p in pen2) or \
            not any(abs(p[0] - (at["front"][0] + 2 * scale)) <= grid for p in pen2):
        fail(f"{projection} angle: the front view's dimension does not span the box's 4 units at {scale} mm each")

# ---- the fit keeps room for dimensions ----
# One view of a 4 × 2 × 1 box fitted to an A4 sheet; a dimension 85 mm below it must still land inside the
# margins, so the fitted scale drops, and every stroke — dimension and label included — stays inside.
ALONE = ('draw box(min: (0, 0, 0), max: (4, 2, 1))\npaper A4 landscape\n'
         'view front = ortho(eye: (2, -10, 0.5), target: (2, 0, 0.5), height: 4) at page (148, 80)\n')
out, _ = run("fit-plain", ALONE, "--plain")
plain_scale = json.load(open(out))["frames"][0]["views"][0]["mm_per_world_unit"]
out, err = run("fit-dimensioned", ALONE + 'dimension from (0, 0, 0) to (4, 0, 0) in front offset: -85\n', "--plain")
frame = json.load(open(out))["frames"][0]
scale = frame["views"][0]["mm_per_world_unit"]
if not scale < plain_scale:
    fail(f"a dimension 85 mm below the view left the fitted scale at {scale} (without it {plain_scale})")
if "warning" in err:
    fail(f"the fitted sheet still warns: {err}")
for st in frame["strokes"]:
    for x, y in st:
        if not (12 - EPS <= x <= 297 - 12 + EPS and 12 - EPS <= y <= 210 - 12 + EPS):
            fail(f"stroke point ({x}, {y}) lies outside the margins at the fitted scale {scale}")

# ---- a section ----
# A 4 × 2 × 1 box cut by the plane y = 1, the half towards −y removed: the cut face is the rectangle x 0 … 4,
# z 0 … 1 at y = 1, and it alone is hatched, 0.25 apart at 45°: every hatch piece lies in it, and their
# length is the area over the spacing to within a line's length at either end (2 × √2).
SECTION = """
draw section(box(min: (0, 0, 0), max: (4, 2, 1)), (0, 1, 0), (0, -1, 0), spacing: 0.25, pen: 3)
view front = ortho(eye: (2, -10, 0.5), target: (2, 0, 0.5), height: 4) at page (100, 60) scale: 10
"""
out, _ = run("section", SECTION, "--plain")
frame = json.load(open(out))["frames"][0]
hatch = [s for s in frame["segments"] if s.get("hatch")]
if not hatch:
    fail("the section's cut face is not hatched")
for s in hatch:
    for x, y, z in s["p"]:
        if abs(y - 1) > 1e-9 or not (-1e-9 <= x <= 4 + 1e-9 and -1e-9 <= z <= 1 + 1e-9):
            fail(f"hatch point {(x, y, z)} is not on the cut face")
total = sum(math.dist(*s["p"]) for s in hatch)
if abs(total - 4 / 0.25) > 2 * math.sqrt(2):
    fail(f"hatch length {total}, wanted about {4 / 0.25}")
if set(frame["hatch_stroke_pens"]) != {3}:
    fail(f"hatch pens {set(frame['hatch_stroke_pens'])}, wanted pen 3")
# What is left: the box's front outline is now the cut face's, at y = 1, 4 × 1.
edges = [s for s in frame["segments"] if not s.get("hatch") and not s["hidden"]]
if min(min(p[1] for p in s["p"]) for s in edges) < 1 - 1e-9:
    fail("a visible edge lies in the removed half")

# ---- the fitted scale ----
# A4 landscape, 12 mm margins. front at (100, 60): 2 units right and left, 0.5 up and down from its target,
# its label 5 + 3.5·28/21 mm below: left (100 − 12)/2 = 44, down (198 − 60 − 9.67)/0.5 = 256.7. top at
# (100, 150), ±2 by ±1: left 44, down (198 − 150 − 9.67)/1 = 38.3; the two apart along y, 5 mm between:
# (90 − 5 − 9.67)/(0.5 + 1) = 50.2. Largest ISO scale ≤ 38.3: 20.
FITTED = """
draw box(min: (-2, -1, 0), max: (2, 1, 1))
view front = ortho(eye: (0, -10, 0.5), target: (0, 0, 0.5), height: 4) at page (100, 60)
view top = ortho(eye: (0, 0, 10), target: (0, 0, 0), up: (0, 1, 0), height: 4) at page (100, 150)
"""
out, _ = run("fitted", FITTED)
frame = json.load(open(out))["frames"][0]
if [v["mm_per_world_unit"] for v in frame["views"]] != [20, 20]:
    fail(f"fitted scales: {[v['mm_per_world_unit'] for v in frame['views']]}, wanted 20")
# The frame along the margins: a stroke through the corners (12, 12) and (285, 198).
corners = {(12.0, 12.0), (285.0, 12.0), (285.0, 198.0), (12.0, 198.0)}
if not any(corners <= {(round(x, 6), round(y, 6)) for x, y in s} for s in frame["strokes"]):
    fail("no stroke draws the sheet's frame along the margins")
# Labels under the views: letters below the front view's outline (y 50 … 70 at 20:1), above the top view.
below = [p for s in frame["strokes"] for p in s if 70 + 4 < p[1] < 70 + 10 and 60 < p[0] < 140]
if not below:
    fail("no label strokes under the front view")

# ---- one view alone ----
out, _ = run("alone", FITTED, "--camera", "top")
frame = json.load(open(out))["frames"][0]
if "views" in frame or "camera" not in frame:
    fail("--camera top draws that view alone, as a camera")

# ---- warnings ----
OVERLAP = FITTED.replace("at page (100, 150)", "at page (110, 65) scale: 20")
_, err = run("overlap", OVERLAP)
if "view 'top': its drawing overlaps view 'front'" not in err:
    fail(f"no overlap warning: {err}")

# ---- every device ----
for ext in ["pdf", "svg", "hpgl", "gcode", "dxf", "png"]:
    out, _ = run("boxes", BOXES, out_ext=ext)
    if os.path.getsize(out) == 0:
        fail(f"{ext}: empty")
out, _ = run("boxes-plotter", BOXES, "--svg", "plotter", out_ext="svg")
if "hidden" not in open(out).read():
    fail("plotter SVG: no hidden layer")
print("ok")
