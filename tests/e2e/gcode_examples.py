#!/usr/bin/env python3
"""The G-code device against an independent reader, on every example.

    gcode_examples.py HLRSCRIPT EXAMPLES_DIR WORK_DIR EXAMPLE.hls...

For each example (its first frame only, to stay quick) hlrscript writes G-code for the grbl-servo profile
and hlrscript.lines/1 JSON. A small G-code interpreter written here, knowing nothing of the device's code,
replays the program (G21, G90, G0, G1, G4, M0, M2, M3 S and Z pen moves) and checks that
  - every move stays inside the profile's work area,
  - the pen state is right: no G0 with the pen down, no G1 in X/Y with the pen up, M0 and M2 with the
    pen up, a feed set before the first G1, and the program ends at the origin with M2,
  - the segments drawn, with their pens, are the JSON strokes' segments mapped by the origin corner
    (bottom-left: machine (x, page height - y)), within 0.002 mm.
Both files come from the same pen plan settings (the 0.025 mm grid), so the same segments are drawn; the
order differs (G-code starts from the machine's origin), so they are compared as multisets.
A few examples also run with grbl-z, and one small script with a declared top-left plotter.
"""
import json
import math
import os
import re
import subprocess
import sys
from collections import Counter

TOL = 0.002
GRID = 0.025  # the planning grid: both files' points lie on it, so keys built from it are stable

# The built-in profiles' numbers as documented (core/device/plotters/gcode_profile.cpp, LANGUAGE_SPEC.md).
PROFILES = {
    "grbl-servo": {"mode": "servo", "up": 30.0, "down": 60.0, "w": 420.0, "h": 297.0, "origin": "bottom-left"},
    "grbl-z": {"mode": "z", "up": 5.0, "down": 0.0, "w": 420.0, "h": 297.0, "origin": "bottom-left"},
}


class GcodeError(Exception):
    pass


WORD = re.compile(r"([A-Z])([-+]?\d+(?:\.\d+)?)")


def replay(text, profile):
    """The drawn segments [(pen, (x0, y0), (x1, y1))] of a G-code program, checking it on the way."""
    pen_up = None  # unknown until the program sets it
    pen = 1  # the program starts with pen 1 in the holder
    wanted_pen = None  # from the last "(change to pen N, then resume)" comment
    units = absolute = feed_set = False
    x = y = 0.0
    ended = False
    segments = []
    w, h = profile["w"], profile["h"]
    for number, raw in enumerate(text.split("\n"), 1):
        where = f"line {number}: {raw!r}"
        if ended and raw.strip():
            raise GcodeError(f"{where}: text after M2")
        comments = re.findall(r"\(([^()]*)\)", raw)
        code = re.sub(r"\([^()]*\)", "", raw).strip()
        if "(" in code or ")" in code:
            raise GcodeError(f"{where}: unbalanced comment")
        for c in comments:
            m = re.fullmatch(r"change to pen (\d+), then resume", c)
            if m:
                wanted_pen = int(m.group(1))
        if not code:
            continue
        words = WORD.findall(code)
        if "".join(a + b for a, b in words) != code.replace(" ", ""):
            raise GcodeError(f"{where}: not a sequence of G-code words")
        letters = [a for a, _ in words]
        if len(set(letters)) != len(letters):
            raise GcodeError(f"{where}: a word given twice")
        p = {a: float(b) for a, b in words}
        command = words[0][0] + str(int(float(words[0][1])))
        if command == "G21":
            units = True
            continue
        if command == "G90":
            absolute = True
            continue
        if not (units and absolute):
            raise GcodeError(f"{where}: a command before G21 and G90")
        if command == "M3":
            if profile["mode"] != "servo" or "S" not in p:
                raise GcodeError(f"{where}: M3 S is the servo profile's pen move")
            if p["S"] == profile["up"]:
                pen_up = True
            elif p["S"] == profile["down"]:
                pen_up = False
            else:
                raise GcodeError(f"{where}: S is neither the pen-up nor the pen-down value")
        elif command in ("G0", "G1") and "Z" in p:
            if profile["mode"] != "z" or "X" in p or "Y" in p:
                raise GcodeError(f"{where}: a Z move must be alone, and only for a Z pen")
            if command == "G0" and p["Z"] == profile["up"]:
                pen_up = True
            elif command == "G1" and p["Z"] == profile["down"] and "F" in p:
                pen_up = False
            else:
                raise GcodeError(f"{where}: a Z move that is neither pen up (G0) nor pen down (G1 with F)")
        elif command in ("G0", "G1"):
            if "X" not in p or "Y" not in p:
                raise GcodeError(f"{where}: a move without X and Y")
            nx, ny = p["X"], p["Y"]
            if not (0 <= nx <= w and 0 <= ny <= h):
                raise GcodeError(f"{where}: outside the {w} x {h} mm work area")
            if command == "G0":
                if pen_up is not True:
                    raise GcodeError(f"{where}: G0 with the pen down (or not yet lifted)")
            else:
                if pen_up is not False:
                    raise GcodeError(f"{where}: G1 drawing with the pen up")
                feed_set = feed_set or "F" in p
                if not feed_set:
                    raise GcodeError(f"{where}: G1 before any feed")
                segments.append((pen, (x, y), (nx, ny)))
            x, y = nx, ny
        elif command == "G4":
            if not (p.get("P", -1) > 0):
                raise GcodeError(f"{where}: G4 needs P seconds above 0")
        elif command == "M0":
            if pen_up is not True or wanted_pen is None:
                raise GcodeError(f"{where}: M0 with the pen down or without naming the next pen")
            pen, wanted_pen = wanted_pen, None
        elif command == "M2":
            if pen_up is not True or (x, y) != (0.0, 0.0):
                raise GcodeError(f"{where}: the program must end with the pen up at the origin")
            ended = True
        else:
            raise GcodeError(f"{where}: unexpected command {command}")
    # A servo pen whose up value is above its down value would be lowered by M2 (it stops the PWM): such
    # a program ends with the pen up at the origin and no M2.
    reversed_servo = profile["mode"] == "servo" and profile["up"] > profile["down"]
    if not ended and not (reversed_servo and pen_up is True and (x, y) == (0.0, 0.0)):
        raise GcodeError("the program does not end with M2")
    if ended and reversed_servo:
        raise GcodeError("M2 would turn this servo to S0 and lower the pen")
    return segments


def key(pen, a, b):
    ka = (round(a[0] / GRID), round(a[1] / GRID))
    kb = (round(b[0] / GRID), round(b[1] / GRID))
    return (pen,) + (ka + kb if ka <= kb else kb + ka)


def json_segments(doc, origin):
    page_h = doc["page"]["height_mm"]
    frame = doc["frames"][0]
    out = []
    # The hidden layer (style hidden dashed, drawn whole with --dash solid) and the hatching are drawn like any
    # stroke, with their pens.
    strokes = frame["strokes"] + frame.get("hidden_strokes", []) + frame.get("hatch_strokes", [])
    pens = frame["stroke_pens"] + frame.get("hidden_stroke_pens", []) + frame.get("hatch_stroke_pens", [])
    if len(strokes) != len(pens):
        raise GcodeError("the JSON has a pen for each stroke")
    for pts, pen in zip(strokes, pens):
        m = [(x, page_h - y) if origin == "bottom-left" else (x, y) for x, y in pts]
        out += [(pen, m[i - 1], m[i]) for i in range(1, len(m))]
    return out


def merge_collinear(segs):
    """Segments of one pen that continue one another in a straight line through a point no other segment
    of that pen touches, as one: two plans on different grids may keep or drop such a point (where a closed
    stroke starts, or a node snapped on one grid only). Each point is judged by its own two segments as
    given, on the grid's whole numbers both files' points share, so the answer does not depend on the order
    the files list their segments in."""
    segs = [(pen, tuple(a), tuple(b)) for pen, a, b in segs if math.dist(a, b) > TOL]

    def node(pen, p):
        return (pen, round(p[0] / GRID), round(p[1] / GRID))

    at = {}
    for i, (pen, a, b) in enumerate(segs):
        at.setdefault(node(pen, a), []).append(i)
        at.setdefault(node(pen, b), []).append(i)
    # The points a straight line runs through: exactly two segments end there, in line and onward.
    through = {}
    for n, ends in at.items():
        if len(ends) != 2 or ends[0] == ends[1]:
            continue
        i, j = ends
        pen, a, b = segs[i]
        _, c, d = segs[j]
        if node(pen, a) == n:
            a, b = b, a
        if node(pen, d) == n:
            c, d = d, c
        ga, gb, gc, gd = ([round(q / GRID) for q in p] for p in (a, b, c, d))
        u, v = (gb[0] - ga[0], gb[1] - ga[1]), (gd[0] - gc[0], gd[1] - gc[1])
        lu, lv = math.hypot(*u), math.hypot(*v)
        if abs(u[0] * v[1] - u[1] * v[0]) <= TOL / GRID * max(lu, lv) and u[0] * v[0] + u[1] * v[1] > 0:
            through[n] = (i, j)
    # Chains of segments joined at such points become one segment from end to end (a closed chain stays).
    seen, out = set(), []
    for start in range(len(segs)):
        if start in seen:
            continue
        pen = segs[start][0]
        chain, chain_ends, closed = [start], [], False
        seen.add(start)
        for end in (segs[start][1], segs[start][2]):
            k, p = start, end
            while node(pen, p) in through:
                i, j = through[node(pen, p)]
                k2 = j if i == k else i
                if k2 == start or k2 in seen:
                    closed = True
                    break
                seen.add(k2)
                chain.append(k2)
                _, a, b = segs[k2]
                p = b if node(pen, a) == node(pen, p) else a
                k = k2
            chain_ends.append(p)
        if closed or node(pen, chain_ends[0]) == node(pen, chain_ends[1]):
            out += [segs[k] for k in chain]
        else:
            out.append((pen, chain_ends[0], chain_ends[1]))
    return out


def split_at_nodes(segs):
    """Each segment cut where another segment of its pen ends on it: a line one plan draws through a
    T-junction and the other stops and restarts at is the same line."""
    cell = 1.0
    nodes = {}
    for pen, a, b in segs:
        for p in (a, b):
            nodes.setdefault((pen, math.floor(p[0] / cell), math.floor(p[1] / cell)), set()).add(p)
    out = []
    for pen, a, b in segs:
        length = math.dist(a, b)
        u = ((b[0] - a[0]) / length, (b[1] - a[1]) / length)
        cuts = {}
        x0, x1 = sorted((a[0], b[0]))
        y0, y1 = sorted((a[1], b[1]))
        ga, gb = [round(q / GRID) for q in a], [round(q / GRID) for q in b]
        glen = math.hypot(gb[0] - ga[0], gb[1] - ga[1])
        for i in range(math.floor((x0 - TOL) / cell), math.floor((x1 + TOL) / cell) + 1):
            for j in range(math.floor((y0 - TOL) / cell), math.floor((y1 + TOL) / cell) + 1):
                for p in nodes.get((pen, i, j), ()):
                    t = (p[0] - a[0]) * u[0] + (p[1] - a[1]) * u[1]
                    # Off the line, decided on the grid's whole numbers (the same answer for both files).
                    gp = [round(q / GRID) for q in p]
                    cross = (gp[0] - ga[0]) * (gb[1] - ga[1]) - (gp[1] - ga[1]) * (gb[0] - ga[0])
                    off = abs(cross) / glen * GRID if glen > 0 else math.inf
                    if TOL < t < length - TOL and off <= TOL + 1e-12:
                        cuts.setdefault(round(t / GRID), p)  # the node itself: it lies on both files' grid
        points = [a] + [cuts[k] for k in sorted(cuts)] + [b]
        out += [(pen, points[i - 1], points[i]) for i in range(1, len(points))]
    return out


def compare(name, gcode_segs, json_segs):
    gcode_segs = split_at_nodes(merge_collinear(gcode_segs))
    json_segs = split_at_nodes(merge_collinear(json_segs))

    def index(segs):
        d = {}
        for pen, a, b in segs:
            if math.dist(a, b) <= TOL:  # a dot: no segment to compare
                continue
            d.setdefault(key(pen, a, b), []).append((a, b))
        return d

    g, j = index(gcode_segs), index(json_segs)
    gc = Counter({k: len(v) for k, v in g.items()})
    jc = Counter({k: len(v) for k, v in j.items()})
    if gc != jc:
        missing, extra = jc - gc, gc - jc
        raise GcodeError(
            f"{name}: drawn segments differ from the JSON strokes: {sum(missing.values())} missing "
            f"(e.g. {list(missing)[:2]}), {sum(extra.values())} extra (e.g. {list(extra)[:2]})"
        )
    for k, segs in g.items():  # same keys: check the coordinates themselves within the tolerance
        for (a, b), (c, d) in zip(sorted(segs), sorted(sorted(s) for s in j[k])):
            ends = sorted([a, b])
            if max(math.dist(ends[0], c), math.dist(ends[1], d)) > TOL:
                raise GcodeError(f"{name}: segment {a}-{b} is more than {TOL} mm from the JSON's {c}-{d}")
    return sum(gc.values())


def run(hlrscript, args):
    r = subprocess.run([hlrscript] + args, capture_output=True, text=True, timeout=300)
    if r.returncode != 0:
        raise GcodeError(f"hlrscript {' '.join(args)} failed ({r.returncode}): {r.stderr.strip()}")


def check(hlrscript, script, work, name, profile_name, profile, extra=()):
    gcode = os.path.join(work, name + ".gcode")
    js = os.path.join(work, name + ".json")
    # --plain: the drawing itself. The caption's letters are planned from each device's home, and where
    # strokes of neighbouring letters overlap the two plans may split them differently; caption() checks them.
    common = [script, "--frames", "0", "--plain"] + list(extra)
    # --dash solid: the hidden layer whole, so that its segments match JSON's too (the dashes plotters draw
    # by default are checked in tests/runtime/pipeline/plotter_hidden_lines_test.cpp).
    run(hlrscript, common + ["-o", gcode, "--dash", "solid"] + (["--plotter", profile_name] if profile_name else []))
    run(hlrscript, common + ["-o", js])
    with open(gcode) as f:
        text = f.read()
    with open(js) as f:
        doc = json.load(f)
    if doc["format"] != "hlrscript.lines/1":
        raise GcodeError(f"{name}: not hlrscript.lines/1 JSON")
    try:
        segs = replay(text, profile)
    except GcodeError as e:
        raise GcodeError(f"{name}.gcode: {e}")
    n = compare(name, segs, json_segments(doc, profile["origin"]))
    if n == 0:
        raise GcodeError(f"{name}: nothing drawn")
    print(f"ok {name}: {n} segments, {profile_name or 'the declared plotter'}")


def caption(hlrscript, script, work, profile):
    """The caption: G-code draws it in single strokes (pen 1), in the bottom margin below the drawing, and
    nothing else changes: every segment of the plain file is drawn again."""
    plain, with_caption = os.path.join(work, "plain.gcode"), os.path.join(work, "caption.gcode")
    run(hlrscript, [script, "--frames", "0", "--plain", "-o", plain])
    run(hlrscript, [script, "--frames", "0", "-o", with_caption])
    segs = {}
    for path in (plain, with_caption):
        with open(path) as f:
            segs[path] = Counter((pen, a, b) if a <= b else (pen, b, a) for pen, a, b in replay(f.read(), profile))
    added = segs[with_caption] - segs[plain]
    if segs[plain] - segs[with_caption]:
        raise GcodeError("caption: the drawing changed when the caption was added")
    if len(added) < 20:
        raise GcodeError(f"caption: only {len(added)} segments of letters")
    margin = 12  # the default, bottom-left origin: the band below the drawing is y < 12 mm
    for pen, a, b in added:
        if pen != 1 or max(a[1], b[1]) >= margin or min(a[1], b[1]) < 0:
            raise GcodeError(f"caption: a segment {a}-{b} in pen {pen} outside the bottom margin")
    print(f"ok caption: {sum(added.values())} single-stroke segments in the bottom margin")


TOP_LEFT = """plotter desk { base: "grbl-servo", origin: "top-left", width: 300, height: 220, up: 40, down: 90 }
output "unused.gcode" plotter desk
draw cube(1)
draw cube(0.5) at translate(1.5, 0, 0) pen 2
camera main = lookat(eye: (4, -5, 3), target: (0.5, 0.5, 0.5))
"""


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    hlrscript, examples, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    failures = []
    for i, example in enumerate(sys.argv[4:]):
        name = example.replace("/", ".").removesuffix(".hls")
        script = os.path.join(examples, example)
        jobs = [(name, "grbl-servo")] + ([(name + ".z", "grbl-z")] if i < 2 else [])
        for label, profile in jobs:
            try:
                check(hlrscript, script, work, label, profile, PROFILES[profile])
            except GcodeError as e:
                failures.append(str(e))
                print("FAIL", e)
    # A declared top-left plotter with two pens: y kept as on the page, one M0 pause for pen 2.
    script = os.path.join(work, "top_left.hls")
    with open(script, "w") as f:
        f.write(TOP_LEFT)
    top_left = {"mode": "servo", "up": 40.0, "down": 90.0, "w": 300.0, "h": 220.0, "origin": "top-left"}
    try:
        check(hlrscript, script, work, "top_left", None, top_left)
    except GcodeError as e:
        failures.append(str(e))
        print("FAIL", e)
    # The same with the servo turned the other way (up S90, down S40): no M2 at the end.
    with open(script, "w") as f:
        f.write(TOP_LEFT.replace("up: 40, down: 90", "up: 90, down: 40"))
    try:
        check(hlrscript, script, work, "reversed_servo", None, dict(top_left, up=90.0, down=40.0))
    except GcodeError as e:
        failures.append(str(e))
        print("FAIL", e)
    try:
        caption(hlrscript, os.path.join(examples, "showcase/gear.hls"), work, PROFILES["grbl-servo"])
    except GcodeError as e:
        failures.append(str(e))
        print("FAIL", e)
    if failures:
        sys.exit(f"{len(failures)} failure(s)")


if __name__ == "__main__":
    main()
