#!/usr/bin/env python3
"""Occlusion levels end to end: examples/showcase/occlusion-levels.hls to JSON, plotter SVG and HPGL.

usage: occlusion_levels.py HLRSCRIPT SCRIPT WORK

The expectation is computed here, not taken from hlrscript: the scene is boxes seen by an orthographic
camera, so the level of a point is the number of box faces a ray from it towards the eye crosses — 2 for
each box it passes through, 1 for the point's own box when the point lies on a face turned away. First a
JSON with --levels 16 (every hidden piece of this scene; the boxes' corners are read from it) gives each
piece's midpoint, whose counted level must be the piece's "level" (0 for visible pieces). Then the
script's own style (levels 1..3 from pen 2): the JSON's hidden strokes carry levels 1..3 in pens 2..4
(pen = 1 + level) and nothing deeper; the plotter SVG has the layers "1 black", "2 hidden 1",
"3 hidden 2", "4 hidden 3", in that order, whose paths are the JSON's strokes of that level; the HPGL
selects pens 1, 2, 3, 4 in that order.
"""
import json
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"
INK = "{http://www.inkscape.org/namespaces/inkscape}"
FAILURES = []


def fail(message):
    FAILURES.append(message)
    print("FAIL: " + message)


def run(hlrscript, script, work, *args):
    result = subprocess.run([hlrscript, script, *args], cwd=work, capture_output=True, text=True, timeout=300)
    if result.returncode != 0:
        sys.exit(f"hlrscript {' '.join(args)} failed ({result.returncode}):\n{result.stderr}")
    return result


def boxes_from(frame):
    """Each object's axis-aligned box: the extent of all its pieces (every edge is listed whole)."""
    boxes = {}
    for s in frame["segments"]:
        lo, hi = boxes.setdefault(s["object"], ([float("inf")] * 3, [float("-inf")] * 3))
        for p in s["p"]:
            for i in range(3):
                lo[i], hi[i] = min(lo[i], p[i]), max(hi[i], p[i])
    return boxes


def faces_in_front(point, toward_eye, box, eps):
    """Faces of `box` crossed by the ray point + s·toward_eye, s > 0 (slab intersection)."""
    lo, hi = box
    s0, s1 = float("-inf"), float("inf")
    for i in range(3):
        if abs(toward_eye[i]) < 1e-15:
            if point[i] < lo[i] - eps or point[i] > hi[i] + eps:
                return 0
            continue
        a, b = (lo[i] - point[i]) / toward_eye[i], (hi[i] - point[i]) / toward_eye[i]
        s0, s1 = max(s0, min(a, b)), min(s1, max(a, b))
    if s1 <= s0 + eps or s1 <= eps:
        return 0  # missed, grazed, or wholly behind the point
    return 2 if s0 > eps else 1  # passed through, or left through one face from the point on it


def check_levels_against_counting(frame):
    camera = frame["camera"]
    if camera["kind"] != "orthographic":
        fail("the example is to be seen by an orthographic camera (the counting below assumes it)")
    toward_eye = [-c for c in camera["direction"]]
    boxes = boxes_from(frame)
    size = max(max(hi[i] - lo[i] for i in range(3)) for lo, hi in boxes.values())
    eps = 1e-7 * size
    seen = set()
    for s in frame["segments"]:
        mid = [(a + b) / 2 for a, b in zip(*s["p"])]
        want = sum(faces_in_front(mid, toward_eye, box, eps) for box in boxes.values())
        got = s.get("level", 0) if s["hidden"] else 0
        if s["hidden"] and "level" not in s:
            fail(f"hidden segment of {s['object']} has no level")
        if s["hidden"] != (want > 0) or got != want:
            fail(f"{s['object']} edge {s.get('edge')} at {mid}: level {got} (hidden {s['hidden']}), "
                 f"counted {want}")
        seen.add(got)
    for level in range(0, 5):
        if level not in seen:
            fail(f"no piece at level {level}: the example should show levels 0 to 4 at least")
    return seen


def check_script_style(frame):
    levels, pens = frame.get("hidden_stroke_levels"), frame.get("hidden_stroke_pens")
    if levels is None:
        fail("the JSON has no hidden_stroke_levels")
        return
    if len(levels) != len(frame["hidden_strokes"]) or len(pens) != len(levels):
        fail("hidden_strokes, hidden_stroke_pens and hidden_stroke_levels differ in length")
    if set(levels) != {1, 2, 3}:
        fail(f"hidden strokes at levels {sorted(set(levels))}, expected 1, 2 and 3")
    for pen, level in zip(pens, levels):
        if pen != 1 + level:
            fail(f"a level-{level} stroke in pen {pen}, expected pen {1 + level}")
    # The plan draws pen by pen, so (pen, level) never goes back.
    order = list(zip(pens, levels))
    if order != sorted(order):
        fail("hidden strokes are not in pen and level order")
    for s in frame["segments"]:
        if s["hidden"] and not 1 <= s["level"] <= 3:
            fail(f"a hidden segment at level {s['level']} with levels 1..3")
    if set(frame["stroke_pens"]) != {1}:
        fail(f"visible strokes in pens {sorted(set(frame['stroke_pens']))}, expected pen 1 only")


def check_plotter_svg(path, frame):
    root = ET.parse(path).getroot()
    layers = [(g.get(INK + "label"), g) for g in root if g.tag == SVG + "g"]
    labels = [label for label, _ in layers]
    if labels != ["1 black", "2 hidden 1", "3 hidden 2", "4 hidden 3"]:
        fail(f"plotter SVG layers {labels}")
    dashes = set()
    for label, g in layers:
        m = re.fullmatch(r"(\d+) hidden (\d+)", label)
        if not m:
            continue
        level = int(m.group(2))
        dashes.add(g.get("stroke-dasharray"))
        want = sum(1 for lv in frame["hidden_stroke_levels"] if lv == level)
        if len(list(g)) != want:
            fail(f"layer '{label}' holds {len(list(g))} paths, the JSON {want} strokes of level {level}")
    if len(dashes) != 3 or None in dashes:
        fail(f"the three levels' layers should each have a dash array of their own: {dashes}")


def check_hpgl(path):
    text = open(path, encoding="ascii").read()
    pens = [int(p) for p in re.findall(r"SP(\d+)", text) if int(p) > 0]
    if pens != [1, 2, 3, 4]:
        fail(f"HPGL selects pens {pens}, expected 1, 2, 3, 4 in turn")


def main():
    hlrscript, script, work = (os.path.abspath(a) for a in sys.argv[1:4])
    os.makedirs(work, exist_ok=True)
    script = os.path.abspath(script)
    run(hlrscript, script, work, "-o", "all.json", "--levels", "16")
    seen = check_levels_against_counting(json.load(open(os.path.join(work, "all.json")))["frames"][0])
    run(hlrscript, script, work, "-o", "own.json")
    frame = json.load(open(os.path.join(work, "own.json")))["frames"][0]
    check_script_style(frame)
    run(hlrscript, script, work, "-o", "own.svg", "--svg", "plotter")
    check_plotter_svg(os.path.join(work, "own.svg"), frame)
    run(hlrscript, script, work, "-o", "own.hpgl")
    check_hpgl(os.path.join(work, "own.hpgl"))
    stats = run(hlrscript, script, work, "-o", "stats.json", "--stats").stderr
    if not re.search(r"hidden pieces by level: 1: \d+, 2: \d+, 3: \d+\n", stats):
        fail(f"--stats does not give the pieces per level:\n{stats}")
    print(f"occlusion levels: levels {sorted(seen)} as counted; SVG layers, JSON and HPGL pens agree"
          if not FAILURES else f"{len(FAILURES)} failures")
    sys.exit(1 if FAILURES else 0)


if __name__ == "__main__":
    main()
