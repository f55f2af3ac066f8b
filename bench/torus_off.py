#!/usr/bin/env python3
"""Writes a closed torus mesh as an OFF file, for the 10^6-face import runs of issue 17 (bench/README.md):
MAJOR × MINOR vertices, each grid cell two triangles (or one quad with --quads; rounded to 6 decimals,
most quads are then no longer exactly planar and the importer splits them).

usage: torus_off.py MAJOR MINOR [--quads] > torus.off
"""
import math
import sys


def main():
    major, minor = int(sys.argv[1]), int(sys.argv[2])
    quads = "--quads" in sys.argv[3:]
    big, small = 3.0, 1.2
    out = sys.stdout
    cells = major * minor
    out.write(f"OFF\n{cells} {cells if quads else 2 * cells} 0\n")
    for i in range(major):
        a = 2 * math.pi * i / major
        for j in range(minor):
            b = 2 * math.pi * j / minor
            r = big + small * math.cos(b)
            out.write(f"{r * math.cos(a):.6f} {r * math.sin(a):.6f} {small * math.sin(b):.6f}\n")
    for i in range(major):
        for j in range(minor):
            p, q = i * minor + j, ((i + 1) % major) * minor + j
            p1, q1 = i * minor + (j + 1) % minor, ((i + 1) % major) * minor + (j + 1) % minor
            if quads:
                out.write(f"4 {p} {q} {q1} {p1}\n")
            else:
                out.write(f"3 {p} {q} {q1}\n3 {p} {q1} {p1}\n")


if __name__ == "__main__":
    main()
