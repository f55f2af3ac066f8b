#!/usr/bin/env python3
"""DXF read back by ezdxf (Debian's python3-ezdxf, not our code) against the JSON of the same frame.

usage: dxf_check.py HLRSCRIPT WORKDIR SCRIPT...

For each script: `hlrscript SCRIPT -o x.dxf` and `-o x.json`, then
  - ezdxf reads the file as DXF R12 (AC1009) in millimetres ($INSUNITS 4), auditing it without errors;
  - its entities, in file order, split by layer kind (PENn, PENn_HIDDEN[_K], PENn_HATCH), are the JSON's
    `strokes`, `hidden_strokes` and `hatch_strokes` in order, point for point to 0.0001 mm once DXF's y (up,
    from the page's bottom) is turned back into the page's (down, from the top), each on its pen's layer;
  - each layer's colour is (within 12 RGB units) the AutoCAD colour index nearest its pen's colour, as
    ezdxf's palette has it (pen
    colours read from the script's `pen N (colour: ...)` lines, the carousel's for the rest);
  - hidden layers use a dashed linetype (dash then gap, as ezdxf compiles it), visible and hatch layers a
    continuous one.
"""
import json
import math
import os
import re
import subprocess
import sys

import ezdxf
from ezdxf import colors

CAROUSEL = {1: (0, 0, 0), 2: (255, 0, 0), 3: (0, 255, 0), 4: (0, 0, 255), 5: (0, 255, 255), 6: (255, 0, 255),
            7: (204, 153, 0), 8: (0, 0, 0)}
NAMED = {"black": (0, 0, 0), "white": (255, 255, 255), "red": (255, 0, 0), "green": (0, 128, 0), "blue": (0, 0, 255),
         "cyan": (0, 255, 255), "magenta": (255, 0, 255), "yellow": (255, 255, 0), "orange": (255, 165, 0),
         "grey": (128, 128, 128), "gray": (128, 128, 128), "brown": (165, 42, 42), "purple": (128, 0, 128)}


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def pen_colours(script):
    pens = dict(CAROUSEL)
    for n, colour in re.findall(r'^pen (\d+) \(colour: "([^"]+)"', open(script).read(), re.M):
        c = colour.lower()
        if c.startswith("#"):
            pens[int(n)] = tuple(int(c[1 + 2 * i:3 + 2 * i], 16) for i in range(3))
        else:
            pens[int(n)] = NAMED[c]
    return pens


def nearest_distance(rgb):
    def dist(i):
        ref = (0, 0, 0) if i == 7 else colors.aci2rgb(i)  # 7 is black on paper
        return math.dist(rgb, ref)
    return dist, min(dist(i) for i in range(1, 256))


def check(hlrscript, work, script):
    name = os.path.splitext(os.path.basename(script))[0]
    out = {}
    for ext in ("dxf", "json"):
        out[ext] = os.path.join(work, f"{name}.{ext}")
        # --plain: no caption, which DXF would draw in single strokes and JSON does not list.
        run = subprocess.run([hlrscript, script, "-o", out[ext], "--plain"], capture_output=True, text=True, timeout=300,
                             cwd=os.path.dirname(script))
        if run.returncode != 0:
            fail(f"{name}: -o .{ext}: exit {run.returncode}: {run.stderr}")
    doc = ezdxf.readfile(out["dxf"])
    if doc.dxfversion != "AC1009":
        fail(f"{name}: DXF version {doc.dxfversion}, expected AC1009 (R12)")
    if doc.header.get("$INSUNITS") != 4:
        fail(f"{name}: $INSUNITS {doc.header.get('$INSUNITS')}, expected 4 (millimetres)")
    auditor = doc.audit()
    if auditor.has_errors:
        fail(f"{name}: ezdxf's audit finds errors: {[str(e.message) for e in auditor.errors][:3]}")
    doc_json = json.load(open(out["json"]))
    frame = doc_json["frames"][0]
    height = doc_json["page"]["height_mm"]

    got = {"": [], "_HIDDEN": [], "_HATCH": []}
    for e in doc.modelspace():
        m = re.fullmatch(r"PEN(\d+)(_HIDDEN|_HATCH)?(?:_(\d+))?", e.dxf.layer)
        if not m:
            fail(f"{name}: an entity on layer '{e.dxf.layer}'")
        if e.dxftype() == "LINE":
            points = [e.dxf.start, e.dxf.end]
        elif e.dxftype() == "POLYLINE":
            points = list(e.points())
            if e.is_closed:
                points.append(points[0])
        else:
            fail(f"{name}: a {e.dxftype()} entity")
        got[m.group(2) or ""].append((int(m.group(1)), int(m.group(3) or 1), [(p[0], height - p[1]) for p in points]))

    for kind, strokes, pens in (("", frame["strokes"], frame["stroke_pens"]),
                                ("_HIDDEN", frame.get("hidden_strokes", []), frame.get("hidden_stroke_pens", [])),
                                ("_HATCH", frame.get("hatch_strokes", []), frame.get("hatch_stroke_pens", []))):
        entities = got[kind]
        if len(entities) != len(strokes):
            fail(f"{name}: {len(entities)} entities on the PENn{kind} layers, the JSON has {len(strokes)} strokes")
        levels = frame.get("hidden_stroke_levels", [1] * len(strokes)) if kind == "_HIDDEN" else [1] * len(strokes)
        for k, ((pen, level, points), stroke, want_pen, want_level) in enumerate(zip(entities, strokes, pens, levels)):
            if pen != want_pen or level != max(want_level, 1):
                fail(f"{name}: stroke {k}{kind} is pen {want_pen} level {want_level}, on a layer of pen {pen} level {level}")
            if len(points) != len(stroke) or any(math.dist(a, b) > 1.5e-4 for a, b in zip(points, stroke)):
                fail(f"{name}: stroke {k}{kind} differs: {stroke[:3]}... vs {points[:3]}...")

    pens = pen_colours(script)
    for layer in doc.layers:
        m = re.fullmatch(r"PEN(\d+)(_HIDDEN|_HATCH)?(?:_(\d+))?", layer.dxf.name)
        if not m:
            continue
        dist, best = nearest_distance(pens[int(m.group(1))])
        # Within 12 RGB units of the nearest: our palette is the index's regular construction (index_colours in
        # dxf_device.cpp), AutoCAD's own table (ezdxf's) strays from it in a few dark half-saturated entries.
        if dist(layer.dxf.color) > best + 12:
            fail(f"{name}: layer {layer.dxf.name} has colour {layer.dxf.color}, not the nearest to pen "
                 f"{m.group(1)}'s {pens[int(m.group(1))]}")
        pattern = doc.linetypes.get(layer.dxf.linetype).pattern_tags.compile()  # (dash, gap, ...) in mm
        if m.group(2) == "_HIDDEN":
            if len(pattern) != 2 or not (pattern[0] > 0 and pattern[1] > 0):
                fail(f"{name}: hidden layer {layer.dxf.name} has linetype {layer.dxf.linetype}, pattern {pattern}")
        elif pattern:
            fail(f"{name}: layer {layer.dxf.name} is not continuous: {layer.dxf.linetype}, pattern {pattern}")
    counts = {k or "visible": len(v) for k, v in got.items()}
    print(f"{name}.dxf: {counts} entities agree with the JSON; layers {[l.dxf.name for l in doc.layers]}")


def main():
    hlrscript, work, scripts = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3:]
    os.makedirs(work, exist_ok=True)
    for script in scripts:
        check(hlrscript, work, os.path.abspath(script))


if __name__ == "__main__":
    main()
