#!/usr/bin/env python3
"""Writes a generated city as an hlrscript script, the way another program would: N random boxes, each
a `solid` block of 8 vertices and 6 faces with literal coordinates, then a `draw` of each, and an
oblique perspective camera over the whole city (issue 17's scale benchmark, bench/scale_bench.sh).

usage: city_script.py BOXES [SEED] > city.hls
"""
import math
import random
import sys


def main():
    boxes = int(sys.argv[1])
    rng = random.Random(int(sys.argv[2]) if len(sys.argv) > 2 else 17)
    side = math.ceil(math.sqrt(boxes))
    pitch = 10.0  # one box per 10 × 10 lot
    out = sys.stdout
    out.write(f"# A generated city of {boxes} boxes (bench/city_script.py {boxes}).\n")
    for i in range(boxes):
        row, col = divmod(i, side)
        w, d = rng.uniform(4, 8), rng.uniform(4, 8)
        h = rng.uniform(3, 30)
        x = col * pitch + rng.uniform(0, pitch - w)
        y = row * pitch + rng.uniform(0, pitch - d)
        x1, y1 = x + w, y + d
        out.write(f"solid b{i} {{\n")
        for name, (vx, vy, vz) in zip("abcdefgh", [(x, y, 0), (x1, y, 0), (x1, y1, 0), (x, y1, 0),
                                                 (x, y, h), (x1, y, h), (x1, y1, h), (x, y1, h)]):
            out.write(f"  vertex {name} = ({vx:.3f}, {vy:.3f}, {vz:.3f})\n")
        out.write("  face a d c b\n  face e f g h\n  face a b f e\n  face b c g f\n  face c d h g\n  face d a e h\n}\n")
        out.write(f"draw b{i}\n")
    extent = side * pitch
    c = extent / 2
    out.write(f"camera over = lookat(eye: ({c - 0.9 * extent:.1f}, {c - 1.3 * extent:.1f}, {0.7 * extent:.1f}), "
              f"target: ({c:.1f}, {c:.1f}, 0), fov: 50)\n")


if __name__ == "__main__":
    main()
