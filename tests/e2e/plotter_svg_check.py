#!/usr/bin/env python3
"""Checks a plotter SVG (--svg plotter) against the JSON of the same frame, with readers of our own and
Inkscape's.

usage: plotter_svg_check.py FRAME.svg FRAME.json

- Read as XML (Python's parser, not ours): the root is sized in mm with a matching viewBox; it holds only
  a <title> and layers (<g inkscape:groupmode="layer">), each labelled "N ..." with N its pen, in pen order
  with a pen's hidden layer after its visible one and its hatch layer ("N hatch") last; a layer holds only
  <path>s, unfilled, stroked.
- The paths, read back in id order (s0, s1, ...: the planned order) and split by layer, equal the JSON's
  `strokes`, `hidden_strokes` and `hatch_strokes` point for point (to 0.001 mm) with the JSON's pens, and within each layer
  they come in planned order.
- `inkscape --query-all` lists every layer and path, and each path's box is the stroke's box grown by
  half the pen's width (round caps), at 96 px per inch (a dashed one's lies within it).
"""
import json
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"
INK = "{http://www.inkscape.org/namespaces/inkscape}"
PX_PER_MM = 96 / 25.4


def fail(message):
    print(f"plotter_svg_check: {sys.argv[1]}: {message}", file=sys.stderr)
    sys.exit(1)


def mm(attr):
    m = re.fullmatch(r"([0-9.]+)mm", attr or "")
    if not m:
        fail(f"size '{attr}' is not in mm")
    return float(m.group(1))


def points_of(d):
    m = re.fullmatch(r"M ([-0-9.]+,[-0-9.]+)(?: L((?: [-0-9.]+,[-0-9.]+)+))?", d)
    if not m:
        fail(f"path data '{d[:60]}' is not 'M x,y L x,y ...'")
    pairs = [m.group(1)] + (m.group(2).split() if m.group(2) else [])
    return [tuple(float(v) for v in p.split(",")) for p in pairs]


def same_points(a, b):
    return len(a) == len(b) and all(abs(p[0] - q[0]) <= 1e-3 and abs(p[1] - q[1]) <= 1e-3 for p, q in zip(a, b))


def main():
    svg_path, json_path = sys.argv[1], sys.argv[2]
    root = ET.parse(svg_path).getroot()
    frame = json.load(open(json_path))["frames"][0]
    page = json.load(open(json_path))["page"]

    if root.tag != SVG + "svg":
        fail("the root is not <svg>")
    width, height = mm(root.get("width")), mm(root.get("height"))
    if abs(width - page["width_mm"]) > 1e-3 or abs(height - page["height_mm"]) > 1e-3:
        fail(f"page {width} x {height} mm, the JSON says {page['width_mm']} x {page['height_mm']}")
    if [float(v) for v in root.get("viewBox").split()] != [0, 0, width, height]:
        fail(f"viewBox '{root.get('viewBox')}' does not match the size")

    paths = {}  # index → (pen, kind, points, width, level); kind 0 visible, 1 hidden, 2 hatch
    layer_keys = []
    for child in root:
        if child.tag == SVG + "title":
            continue
        if child.tag != SVG + "g" or child.get(INK + "groupmode") != "layer":
            fail(f"<{child.tag}> at the top level is not a layer")
        label = child.get(INK + "label") or ""
        m = re.fullmatch(r"(\d+) (.+)", label)
        if not m:
            fail(f"layer label '{label}' does not start with its pen number")
        # "N hidden", or by occlusion level "N hidden K"; "N hatch"; else "N colour"
        level_match = re.fullmatch(r"hidden(?: (\d+))?", m.group(2))
        pen, kind = int(m.group(1)), 1 if level_match else (2 if m.group(2) == "hatch" else 0)
        level = int(level_match.group(1)) if level_match and level_match.group(1) else 0
        layer_keys.append((pen, kind, level))
        if child.get("fill") != "none" or not child.get("stroke") or not child.get("stroke-width"):
            fail(f"layer '{label}' is not stroke-only")
        last = -1
        for path in child:
            if path.tag != SVG + "path":
                fail(f"layer '{label}' holds <{path.tag}>")
            if path.get("fill") not in (None, "none"):
                fail(f"a path of layer '{label}' is filled")
            index = int(re.fullmatch(r"s(\d+)", path.get("id")).group(1))
            if index <= last:
                fail(f"layer '{label}': path s{index} after s{last}, not in planned order")
            last = index
            paths[index] = (pen, kind, points_of(path.get("d")), float(child.get("stroke-width")), level)
    if layer_keys != sorted(layer_keys) or len(set(layer_keys)) != len(layer_keys):
        fail(f"layers {layer_keys} are not one per pen and layer, in pen order")

    visible = [p for _, p in sorted(paths.items()) if p[1] == 0]
    hidden = [p for _, p in sorted(paths.items()) if p[1] == 1]
    hatch = [p for _, p in sorted(paths.items()) if p[1] == 2]
    hidden_levels = frame.get("hidden_stroke_levels", [0] * len(frame.get("hidden_strokes", [])))
    for name, got, strokes, pens, levels in (
            ("strokes", visible, frame["strokes"], frame["stroke_pens"], [0] * len(frame["strokes"])),
            ("hidden_strokes", hidden, frame.get("hidden_strokes", []), frame.get("hidden_stroke_pens", []),
             hidden_levels),
            ("hatch_strokes", hatch, frame.get("hatch_strokes", []), frame.get("hatch_stroke_pens", []),
             [0] * len(frame.get("hatch_strokes", [])))):
        if len(got) != len(strokes):
            fail(f"{len(got)} paths, the JSON has {len(strokes)} {name}")
        for k, (path, stroke, pen, level) in enumerate(zip(got, strokes, pens, levels)):
            if path[0] != pen:
                fail(f"{name}[{k}] is pen {pen}, its path is in pen {path[0]}'s layer")
            if path[4] != level:
                fail(f"{name}[{k}] is at level {level}, its path in a layer of level {path[4]}")
            if not same_points(path[2], [tuple(p) for p in stroke]):
                fail(f"{name}[{k}] differs from its path: {stroke[:3]}... vs {path[2][:3]}...")

    listed = {}
    out = subprocess.run(["inkscape", "--query-all", svg_path], capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        parts = line.split(",")
        if len(parts) == 5:
            listed[parts[0]] = [float(v) for v in parts[1:]]
    for pen, kind, level in layer_keys:
        suffix = {0: "", 1: "-hidden", 2: "-hatch"}[kind]
        if f"layer-{pen}{suffix}{f'-{level}' if level else ''}" not in listed:
            fail(f"Inkscape does not list the layer of pen {pen}")
    for index, (_, kind, points, width, _) in paths.items():
        box = listed.get(f"s{index}")
        if box is None:
            fail(f"Inkscape does not list path s{index}")
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        want = [(min(xs) - width / 2) * PX_PER_MM, (min(ys) - width / 2) * PX_PER_MM,
                (max(xs) - min(xs) + width) * PX_PER_MM, (max(ys) - min(ys) + width) * PX_PER_MM]
        if kind == 1:  # dashed: the dashes may stop short of the ends, never beyond them
            inside = (box[0] >= want[0] - 0.05 and box[1] >= want[1] - 0.05 and
                      box[0] + box[2] <= want[0] + want[2] + 0.05 and box[1] + box[3] <= want[1] + want[3] + 0.05)
            if not inside:
                fail(f"Inkscape's box of dashed s{index} is {box}, beyond {want}")
        elif any(abs(a - b) > 0.05 for a, b in zip(box, want)):
            fail(f"Inkscape's box of s{index} is {box}, expected {want}")
    print(f"{svg_path}: {len(layer_keys)} layers, {len(visible)} visible, {len(hidden)} hidden and {len(hatch)} "
          "hatch paths agree")


if __name__ == "__main__":
    main()
