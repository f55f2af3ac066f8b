#!/usr/bin/env python3
"""Whole runs side by side: `hlrscript mesh.hls -o mesh.pdf` against `sketch -o mesh.tex mesh.sk`.

Each mesh (an OFF file: bench/cgal_meshes.sh fetches the CGAL bunny and fandisk into bench/data/) is
written as a one-frame script importing it and as a Sketch scene of the same triangles, seen from the
same side; both commands are then run in turn, N times, and the medians compared. Sketch only orders
and paints the polygons (a plotter would still draw the hidden lines); hlrscript draws the visible lines
exactly, plans the pen and writes the PDF. Start-up is included in both.

    python3 bench/peers/whole_run.py [--runs 7] [--hlrscript build/runtime/hlrscript] mesh.off ...
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time


def read_off(path):
    """Vertices and faces of an OFF file (comments and blank lines skipped)."""
    with open(path) as f:
        words = []
        for line in f:
            line = line.split("#", 1)[0]
            words.extend(line.split())
    if not words or not words[0].endswith("OFF"):
        sys.exit(f"{path}: not an OFF file")
    words = words[1:] if words[0] == "OFF" else [words[0][3:]] + words[1:]
    nv, nf = int(words[0]), int(words[1])
    at = 3
    vertices = []
    for _ in range(nv):
        vertices.append(tuple(float(w) for w in words[at:at + 3]))
        at += 3
    faces = []
    for _ in range(nf):
        n = int(words[at])
        faces.append([int(w) for w in words[at + 1:at + 1 + n]])
        at += 1 + n
    return vertices, faces


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("meshes", nargs="+")
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--hlrscript", default="build/runtime/hlrscript")
    args = parser.parse_args()
    if not shutil.which("sketch"):
        sys.exit("sketch is not installed (apt-get install sketch)")
    hlrscript = os.path.abspath(args.hlrscript)
    print("| mesh | faces | hlrscript (median) | Sketch (median) | ours ÷ Sketch |")
    print("|---|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as work:
        for mesh in args.meshes:
            vertices, faces = read_off(mesh)
            lo = [min(v[k] for v in vertices) for k in range(3)]
            hi = [max(v[k] for v in vertices) for k in range(3)]
            centre = [(a + b) / 2 for a, b in zip(lo, hi)]
            size = max(b - a for a, b in zip(lo, hi))
            eye = [c + 0.5 * size * d for c, d in zip(centre, (1.6, -2.4, 1.2))]
            name = os.path.splitext(os.path.basename(mesh))[0]
            script = os.path.join(work, name + ".hls")
            with open(script, "w") as f:
                f.write(f'let m = import("{os.path.abspath(mesh)}")\ndraw m\n')
                f.write("camera main = lookat(eye: ({:.9g}, {:.9g}, {:.9g}), ".format(*eye))
                f.write("target: ({:.9g}, {:.9g}, {:.9g}), fov: 30)\n".format(*centre))
            scene = os.path.join(work, name + ".sk")
            with open(scene, "w") as f:
                f.write("def scene {\n")
                for face in faces:
                    f.write("  polygon" + "".join("({:.9g},{:.9g},{:.9g})".format(*vertices[v]) for v in face) + "\n")
                f.write("}\n")
                f.write("put {{ view(({:.9g},{:.9g},{:.9g}), ".format(*eye))
                f.write("({:.9g},{:.9g},{:.9g}), [0,0,1]) then perspective({:.9g}) }} {{scene}}\n".format(
                    *centre, 3 * size))
            commands = {
                # The script lives in a temporary folder; the mesh beside it must be let in.
                "ours": [hlrscript, script, "-o", os.path.join(work, name + ".pdf"),
                         "--allow-path", os.path.dirname(os.path.abspath(mesh))],
                "sketch": ["sketch", "-o", os.path.join(work, name + ".tex"), scene],
            }
            times = {k: [] for k in commands}
            for _ in range(args.runs):
                for key, command in commands.items():
                    start = time.perf_counter()
                    subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
                    times[key].append(time.perf_counter() - start)
            ours, theirs = statistics.median(times["ours"]), statistics.median(times["sketch"])
            print(f"| {name} | {len(faces)} | {ours * 1e3:.0f} ms | {theirs * 1e3:.0f} ms | {ours / theirs:.2f} |")


if __name__ == "__main__":
    main()
