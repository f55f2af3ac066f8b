#!/usr/bin/env python3
"""Blender's Line Art as a measured peer (tracker issue 36): times and disagreement, one markdown table.

For each scene — a one-frame script that draws `import("MESH.off")` through a `lookat(eye, target, fov:)`
camera (bench/data/fandisk.hls, bench/data/bunny.hls), or a bare OFF file, then seen as peers_bench sees
mesh files (orbit_view: 2.2 bounding-box diagonals from the centre, azimuth 30°, elevation 25°, fov 40°) —
it runs, in turn, `--rounds` times:

  1. `blender -b --factory-startup --python blender_lineart.py -- MESH ... --runs 0` — the whole Blender
     process timed from outside: start-up, reading the OFF, building the mesh, one Line Art evaluation,
     writing the strokes;
  2. `hlrscript SCRIPT -o OUT.pdf` — our whole run (reading, importing, hidden lines, pen plan, PDF);
  3. `blender ... --runs N` — Line Art's evaluation alone, timed inside Blender (blender_lineart.py:
     the modifier switched off and on, the view layer updated, N times; the median).

then `lineart_compare` on the strokes of the last run (our drawing, the oracle, our hidden-line time), and
prints medians. Needs `blender` (bench/peers/setup.sh), a built `hlrscript` and `lineart_compare`.

    python3 bench/peers/lineart_run.py [--rounds 5] [--runs 5] [--samples 20000] \
        [--build /tmp/peers-build] bench/data/fandisk.hls bench/data/bunny.hls
"""
import argparse
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
NUMBER = r"\s*(-?[0-9.eE+-]+)\s*"
VECTOR = r"\(" + NUMBER + "," + NUMBER + "," + NUMBER + r"\)"


def read_off_vertices(path):
    with open(path) as f:
        words = []
        for line in f:
            words.extend(line.split("#", 1)[0].split())
    words = words[1:] if words[0] == "OFF" else [words[0][3:]] + words[1:]
    nv, nf = int(words[0]), int(words[1])
    return [tuple(float(w) for w in words[3 + 3 * i:6 + 3 * i]) for i in range(nv)], nf


def scene_from_script(path):
    """The mesh and the lookat camera of a one-frame script like bench/data/bunny.hls."""
    text = open(path).read()
    mesh = re.search(r'import\(\s*"([^"]+)"', text)
    cam = re.search(r"lookat\(\s*(?:eye:\s*)?" + VECTOR + r"\s*,\s*(?:target:\s*)?" + VECTOR +
                    r"\s*,\s*fov:" + NUMBER + r"\)", text)
    if not mesh or not cam:
        sys.exit(f"{path}: expected import(\"MESH\") and lookat((eye), (target), fov: F)")
    values = [float(v) for v in cam.groups()]
    return {"name": os.path.splitext(os.path.basename(path))[0],
            "mesh": os.path.join(os.path.dirname(os.path.abspath(path)), mesh.group(1)),
            "script": os.path.abspath(path), "eye": values[0:3], "target": values[3:6], "fov": values[6]}


def scene_from_mesh(path, work):
    """A bare mesh, seen as peers_bench sees mesh files (bench_scenes.hpp orbit_view), with its script."""
    vertices, _ = read_off_vertices(path)
    lo = [min(v[k] for v in vertices) for k in range(3)]
    hi = [max(v[k] for v in vertices) for k in range(3)]
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    dist = 2.2 * math.dist(lo, hi)
    az, el = math.radians(30), math.radians(25)
    direction = (math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el))
    eye = [c + dist * d for c, d in zip(centre, direction)]
    name = os.path.splitext(os.path.basename(path))[0] + "-orbit"
    script = os.path.join(work, name + ".hls")
    with open(script, "w") as f:
        f.write(f'draw import("{os.path.abspath(path)}")\n')
        f.write("camera c = lookat(({:.17g}, {:.17g}, {:.17g}), ".format(*eye))
        f.write("({:.17g}, {:.17g}, {:.17g}), fov: 40)\n".format(*centre))
    return {"name": name, "mesh": os.path.abspath(path), "script": script, "eye": eye, "target": centre,
            "fov": 40.0}


def timed(command):
    start = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    elapsed = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"failed ({done.returncode}): {' '.join(command)}\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    return elapsed


def fmt_s(s):
    return f"{s * 1e3:.0f} ms" if s < 10 else f"{s:.1f} s"


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scenes", nargs="+", help="SCRIPT.hls (import + lookat) or MESH.off")
    p.add_argument("--rounds", type=int, default=5, help="whole runs of each command, in turn")
    p.add_argument("--runs", type=int, default=5, help="Line Art evaluations per timing process, our renders")
    p.add_argument("--samples", type=int, default=10000, help="points judged by the oracle per figure")
    p.add_argument("--build", default="/tmp/peers-build", help="the build folder (hlrscript, lineart_compare)")
    p.add_argument("--blender", default="blender")
    p.add_argument("--keep", help="leave the strokes and comparison JSON in this folder")
    args = p.parse_args()
    if not shutil.which(args.blender):
        sys.exit("blender is not installed (bench/peers/setup.sh)")
    hlrscript = os.path.join(args.build, "runtime", "hlrscript")
    compare = os.path.join(args.build, "bench", "peers", "lineart_compare")
    for tool in (hlrscript, compare):
        if not os.access(tool, os.X_OK):
            sys.exit(f"{tool} is not built (ninja -C {args.build} hlrscript hlrscript-engine lineart_compare)")
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        work = args.keep or tmp
        os.makedirs(work, exist_ok=True)
        for arg in args.scenes:
            s = scene_from_script(arg) if arg.endswith(".hls") else scene_from_mesh(arg, work)
            camera = ["--eye", *map(str, s["eye"]), "--target", *map(str, s["target"]), "--fov", str(s["fov"])]
            strokes = os.path.join(work, s["name"] + ".lineart.json")
            blender = [args.blender, "-b", "--factory-startup", "--python", os.path.join(HERE, "blender_lineart.py"),
                       "--", s["mesh"], *camera, "--out", strokes]
            ours = [hlrscript, s["script"], "-o", os.path.join(work, s["name"] + ".pdf"),
                    "--allow-path", os.path.dirname(s["mesh"])]
            whole_blender, whole_ours, first_eval, evals = [], [], [], []
            for r in range(args.rounds):
                whole_blender.append(timed(blender + ["--runs", "0"]))
                first_eval.append(json.load(open(strokes))["timing"]["first_evaluation_s"])
                whole_ours.append(timed(ours))
                timed(blender + ["--runs", str(args.runs)])
                evals.extend(json.load(open(strokes))["timing"]["lineart_s"])
                print(f"{s['name']} round {r + 1}/{args.rounds}: blender {whole_blender[-1]:.2f} s, "
                      f"hlrscript {whole_ours[-1]:.3f} s, Line Art evaluation {statistics.median(evals[-args.runs:]):.3f} s",
                      file=sys.stderr, flush=True)
            out = subprocess.run([compare, s["mesh"], "--strokes", strokes, *camera, "--runs", str(args.runs),
                                  "--samples", str(args.samples), "--json"],
                                 stdout=subprocess.PIPE, text=True, check=True).stdout
            c = json.loads(out)
            if args.keep:
                with open(os.path.join(work, s["name"] + ".compare.json"), "w") as f:
                    f.write(out)
            rows.append((s, c, statistics.median(whole_blender), statistics.median(whole_ours),
                         statistics.median(first_eval), statistics.median(evals), len(evals)))
    print("| scene | faces | Blender whole process | Line Art evaluation (first / re-evaluated) | hlrscript whole run "
          "| our hidden lines (all cores / 1 thread) | hlrscript ÷ Line Art evaluation | hlrscript ÷ Blender process "
          "| our hidden lines ÷ Line Art evaluation |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for s, c, wb, wo, fe, ev, n in rows:
        o = c["ours"]
        print(f"| {s['name']} | {c['faces']} | {fmt_s(wb)} | {fmt_s(fe)} / {fmt_s(ev)} | {fmt_s(wo)} "
              f"| {o['hlr_fresh_all_threads_s'] * 1e3:.0f} / {o['hlr_fresh_one_thread_s'] * 1e3:.0f} ms "
              f"| {wo / ev:.3f}× | {wo / wb:.3f}× | {o['hlr_fresh_all_threads_s'] / ev:.4f}× |")
    print()
    print("| scene | visible length: ours / Line Art | Line Art strokes | Line Art false-visible | ours false-visible "
          "| Line Art misses of ours (10⁻³ / 10⁻⁴) | Line Art draws not in ours (10⁻³ / 10⁻⁴) "
          "| of the oracle's visible edges: Line Art misses (10⁻³ / 10⁻⁴) | ours misses (10⁻³ / 10⁻⁴) "
          "| Line Art on edges we call Flat |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    pct = lambda v: f"{100 * v:.3f} %"
    for s, c, *_ in rows:
        o, la, m3, m4 = c["ours"], c["lineart"], c["missing"]["1e-03"], c["missing"]["1e-04"]
        print(f"| {s['name']} | {o['visible_length']:.3f} / {la['visible_length']:.3f} | {la['strokes']} "
              f"| {pct(la['false_visible'])} | {pct(o['false_visible'])} "
              f"| {pct(m3['lineart_vs_ours'])} / {pct(m4['lineart_vs_ours'])} "
              f"| {pct(m3['lineart_not_in_ours'])} / {pct(m4['lineart_not_in_ours'])} "
              f"| {pct(m3['lineart_vs_oracle'])} / {pct(m4['lineart_vs_oracle'])} "
              f"| {pct(m3['ours_vs_oracle'])} / {pct(m4['ours_vs_oracle'])} "
              f"| {pct(la['share_on_flat_edges'])} |")
    print()
    for s, c, *_ in rows:
        print(f"{s['name']}: eye {s['eye']}, target {s['target']}, fov {s['fov']}; picture extent "
              f"{c['picture_extent']:.4f}; bbox ours {[round(v, 4) for v in c['ours']['bbox']]}, Line Art "
              f"{[round(v, 4) for v in c['lineart']['bbox']]}; oracle: {c['oracle']['edge_samples_visible']} of "
              f"{c['oracle']['edge_samples']} edge samples visible, ambiguous: Line Art "
              f"{c['lineart']['false_visible_ambiguous']}, ours {c['ours']['false_visible_ambiguous']}, edges "
              f"{c['oracle']['edge_samples_ambiguous']}; Line Art on no mesh edge {pct(c['lineart']['share_on_no_edge'])}")


if __name__ == "__main__":
    main()
