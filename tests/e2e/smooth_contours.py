#!/usr/bin/env python3
"""End to end: contours: "smooth" through the command line (tracker issue 36).

A sphere seen from outside, alone: drawn with its edges (the default) its outline is made of Smooth mesh
edges, every segment naming an "edge"; drawn with contours: "smooth" every segment names the "contour"
face it crosses, the pieces meet end to end in one closed loop (each end shared by exactly two pieces, on
the device grid), and they lie between the mesh's inscribed radius and the sphere's from the centre of the
picture — computed here from the camera the JSON reports, not from the engine.

    smooth_contours.py HLRSCRIPT WORKDIR
"""
import json
import math
import os
import subprocess
import sys

hlrscript, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
SLICES, STACKS = 48, 24


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def render(contours):
    script = os.path.join(work, f"sphere-{contours}.hls")
    with open(script, "w") as f:
        f.write(f'draw sphere(1, slices: {SLICES}, stacks: {STACKS}, contours: "{contours}")\n')
        f.write("camera c = lookat(eye: (4, -3, 2), target: (0, 0, 0), fov: 35)\n")
    out = os.path.join(work, f"sphere-{contours}.json")
    run = subprocess.run([hlrscript, script, "-o", out], capture_output=True, text=True)
    if run.returncode != 0:
        fail(f"{contours}: exit {run.returncode}: {run.stderr}")
    with open(out) as f:
        return json.load(f)["frames"][0]


edges = render("edges")
if not edges["segments"] or any("edge" not in s for s in edges["segments"]):
    fail('contours: "edges" should draw mesh edges only')

smooth = render("smooth")
segments = smooth["segments"]
if len(segments) < SLICES:
    fail(f"expected a contour of at least {SLICES} pieces, got {len(segments)}")
if any("contour" not in s or "edge" in s for s in segments):
    fail('contours: "smooth" should draw contour pieces only')

# One closed loop: every end shared by exactly two pieces (ends compared to 1e-9).
ends = {}
for i, s in enumerate(segments):
    for p in s["p"]:
        ends.setdefault(tuple(round(c * 1e9) for c in p), []).append(i)
if any(len(v) != 2 for v in ends.values()):
    fail(f"{sum(len(v) != 2 for v in ends.values())} ends are not met by exactly one other piece")
seen, stack = set(), [0]
while stack:
    i = stack.pop()
    if i in seen:
        continue
    seen.add(i)
    for p in segments[i]["p"]:
        stack.extend(ends[tuple(round(c * 1e9) for c in p)])
if len(seen) != len(segments):
    fail(f"the contour is {len(segments)} pieces but one loop holds {len(seen)}")
if len(smooth["strokes"]) != 1:
    fail(f"the planned contour should be one stroke, got {len(smooth['strokes'])}")

# Between the inscribed radius and the sphere's: the distance from the centre to the sight line through
# each point, which is what the outline's radius is, seen from the eye.
eye = (4.0, -3.0, 2.0)
d_eye = math.sqrt(sum(c * c for c in eye))
inscribed = math.cos(math.pi / STACKS) * math.cos(math.pi / SLICES)
for s in segments:
    for p in s["p"]:
        ray = [p[k] - eye[k] for k in range(3)]
        to_centre = [-eye[k] for k in range(3)]
        cross = [ray[1] * to_centre[2] - ray[2] * to_centre[1], ray[2] * to_centre[0] - ray[0] * to_centre[2],
                 ray[0] * to_centre[1] - ray[1] * to_centre[0]]
        dist = math.sqrt(sum(c * c for c in cross)) / math.sqrt(sum(c * c for c in ray))
        if not (inscribed - 1e-9 <= dist <= 1 + 1e-9):
            fail(f"contour point {p} is {dist} from the centre's sight line, outside [{inscribed}, 1]")
print(f"ok: {len(edges['segments'])} edge pieces; {len(segments)} contour pieces in one closed stroke")
