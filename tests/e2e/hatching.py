#!/usr/bin/env python3
"""End to end: hatch() through the command line and the REPL (tracker issue 36).

Boxes seen square on by orthographic cameras, so where every hatch line lies and what hides it is worked out
here by hand, not by the engine:
  - a 2-unit box hatched 0.5 apart at angle 0, seen from above: its top face carries the lines y = 0.25,
    0.75, 1.25, 1.75 (half a spacing off the multiples) from x = 0 to 2, at z = 2, and nothing else shows;
  - the same box hatched at angle 90 seen from the front, with a taller plain box in front of x 0.6 … 1.4:
    of the upright lines x = 0.25 … 1.75 only the two outside it are drawn, whole;
  - a cylinder cut by the planes z = 0.125 … 1.875: each cut's visible half runs across twelve faces and
    is planned as one stroke the cylinder's width;
and on every device the hatching keeps its pen and layer: JSON hatch_strokes and hatch_stroke_pens, the
plotter SVG layer "3 hatch", HPGL's SP3; hidden hatch pieces are never drawn, not even with --hidden
dashed. The REPL's :render writes the same hatching.

    hatching.py HLRSCRIPT WORKDIR
"""
import json
import os
import re
import subprocess
import sys

hlrscript, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
EPS = 1e-9


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def render(name, body, *args, out_ext="json"):
    script = os.path.join(work, name + ".hls")
    with open(script, "w") as f:
        f.write(body)
    out = os.path.join(work, name + "." + out_ext)
    run = subprocess.run([hlrscript, script, "-o", out, *args], capture_output=True, text=True, timeout=120)
    if run.returncode != 0:
        fail(f"{name}: exit {run.returncode}: {run.stderr}")
    return out


def hatch_segments(frame):
    return [s for s in frame["segments"] if s.get("hatch")]


def close(a, b):
    return abs(a - b) < EPS


# ---- from above: the top face's lines, exactly ----
TOP = """pen 3 (colour: "blue", width: 0.2)
draw hatch(box(2, 2, 2), 0.5, angle: 0, pen: 3)
camera top = ortho(eye: (1, 1, 10), target: (1, 1, 0), up: (0, 1, 0), height: 3)
"""
frame = json.load(open(render("top", TOP)))["frames"][0]
lines = sorted((min(s["p"][0][0], s["p"][1][0]), max(s["p"][0][0], s["p"][1][0]), s["p"][0][1], s["p"][1][1],
                s["p"][0][2], s["p"][1][2]) for s in hatch_segments(frame))
if len(lines) != 4:
    fail(f"from above: expected the top face's 4 hatch lines, got {len(lines)}: {lines}")
for (x0, x1, y0, y1, z0, z1), want_y in zip(sorted(lines, key=lambda l: l[2]), [0.25, 0.75, 1.25, 1.75]):
    if not (close(x0, 0) and close(x1, 2) and close(y0, want_y) and close(y1, want_y) and close(z0, 2)
            and close(z1, 2)):
        fail(f"from above: a hatch line from x {x0} to {x1} at y {y0}/{y1}, z {z0}/{z1}; want x 0 to 2 at "
             f"y {want_y}, z 2")
if len(frame.get("hatch_strokes", [])) != 4 or set(frame["hatch_stroke_pens"]) != {3}:
    fail(f"from above: expected 4 hatch strokes in pen 3, got {frame.get('hatch_stroke_pens')}")
if set(frame["stroke_pens"]) != {1}:
    fail(f"the box's outline should stay in pen 1, got {set(frame['stroke_pens'])}")
if any(("edge" not in s) for s in hatch_segments(frame)):
    fail("hatch segments name the edge they are a piece of")

# ---- from the front, a plain box in front: lines hidden whole or drawn whole ----
FRONT = """pen 3 (colour: "blue", width: 0.2)
draw hatch(box(2, 2, 2), 0.5, angle: 90, pen: 3)
draw box(min: (0.6, -2, -1), max: (1.4, -1, 3))
camera front = ortho(eye: (1, -10, 1), target: (1, 0, 1), height: 5)
"""
frame = json.load(open(render("front", FRONT, "--hidden", "dashed")))["frames"][0]
front = [s for s in hatch_segments(frame) if close(s["p"][0][1], 0) and close(s["p"][1][1], 0)]
others = [s for s in hatch_segments(frame) if s not in front]
if others:
    fail(f"from the front only the face y = 0 shows its hatching; {len(others)} pieces elsewhere")
xs = sorted(round(s["p"][0][0], 9) for s in front)
if xs != [0.25, 1.75]:
    fail(f"from the front: expected the upright lines x = 0.25 and 1.75 (the box in front hides 0.75 and "
         f"1.25), got x = {xs}")
for s in front:
    zs = sorted([s["p"][0][2], s["p"][1][2]])
    if not (close(zs[0], 0) and close(zs[1], 2) and close(s["p"][0][0], s["p"][1][0])):
        fail(f"from the front: the line at x = {s['p'][0][0]} should run whole from z 0 to 2, got {zs}")
if any(s["hidden"] for s in hatch_segments(frame)):
    fail("a hatch piece was drawn as a hidden line")
if not any(s["hidden"] for s in frame["segments"]):
    fail("--hidden dashed should still draw the box's hidden edges")

# ---- plotter SVG and HPGL: the hatching's own layer and pen ----
svg = open(render("front", FRONT, "--svg", "plotter", out_ext="svg")).read()
labels = re.findall(r'inkscape:label="([^"]*)"', svg)
if "3 hatch" not in labels:
    fail(f"plotter SVG: no layer '3 hatch' among {labels}")
layer = svg.split('inkscape:label="3 hatch"', 1)[1].split("</g>", 1)[0]
if layer.count("<path") != 2:
    fail(f"plotter SVG: the hatch layer should hold the 2 visible lines, holds {layer.count('<path')}")
hpgl = open(render("front", FRONT, out_ext="hpgl")).read()
if "SP3" not in hpgl:
    fail("HPGL: the hatching's pen 3 is never selected")

# ---- planes: lines that run on across faces are planned as one stroke ----
RINGS = """draw hatch(cylinder(1, 2, sides: 24), 0.25, planes: (0, 0, 1), pen: 2)
camera side = ortho(eye: (0, -10, 1), target: (0, 0, 1), height: 3)
"""
frame = json.load(open(render("rings", RINGS)))["frames"][0]
pieces = hatch_segments(frame)
heights = sorted({round(s["p"][0][2], 9) for s in pieces})
if heights != [0.125 + 0.25 * k for k in range(8)] or any(not close(s["p"][0][2], s["p"][1][2]) for s in pieces):
    fail(f"planes z = const should cut the cylinder's side at z = 0.125 ... 1.875, got {heights}")
if len(pieces) < 8 * 10:
    fail(f"each cut should cross the half of the 24 faces in view, got {len(pieces)} pieces")
if len(frame["hatch_strokes"]) != 8:
    fail(f"each cut's visible half, across 12 faces, should be one stroke: 8 strokes, got {len(frame['hatch_strokes'])}")
outline = [p[0] for stroke in frame["strokes"] for p in stroke]
for stroke in frame["hatch_strokes"]:
    width = max(p[0] for p in stroke) - min(p[0] for p in stroke)
    if abs(width - (max(outline) - min(outline))) > 0.05:
        fail(f"a cut's stroke should span the cylinder's width on the page, {max(outline) - min(outline)} mm; "
             f"spans {width} mm")

# ---- the REPL ----
out = os.path.join(work, "repl.json")
session = "draw hatch(box(2, 2, 2), 0.5, angle: 0, pen: 3)\n" \
          "camera top = ortho(eye: (1, 1, 10), target: (1, 1, 0), up: (0, 1, 0), height: 3)\n" \
          f":render {out}\n:quit\n"
run = subprocess.run([hlrscript, "repl"], input=session, capture_output=True, text=True, timeout=120)
if run.returncode != 0 or not os.path.exists(out):
    fail(f"REPL: exit {run.returncode}: {run.stderr}")
repl = json.load(open(out))["frames"][0]
if len(hatch_segments(repl)) != 4 or set(repl["hatch_stroke_pens"]) != {3}:
    fail(f"REPL: expected the 4 hatch lines in pen 3, got {len(hatch_segments(repl))}")

print("hatching: top face lines exact, hidden lines gone whole, layers and pens on every device, REPL too")
