#!/usr/bin/env python3
"""Writes a script of general code, for the parse-speed goal of issue 17 (≥ 10 MB/s, bench/README.md):
N statements mixing `let` of vectors, `def` in the expression form, list comprehensions, transform chains,
`if`/`else` blocks and string interpolation, with comments; it evaluates without errors.

usage: general_script.py N > general.hls      (60 000 statements ≈ 4.4 MB)
"""
import random
import sys


def main():
    n = int(sys.argv[1])
    rng = random.Random(3)
    out = sys.stdout
    out.write("camera c = lookat(eye: (40, 30, 20), target: (0, 0, 0))\n")
    for i in range(n):
        kind = i % 4
        if kind == 0:
            out.write(f"let v{i} = ({rng.uniform(-9, 9):.3f}, {rng.uniform(-9, 9):.3f}, 2 * {i % 7} + 1)  # point {i}\n")
        elif kind == 1:
            out.write(f"def f{i}(a, b = 2) = a * b + sin(a * 30) - max(a, {i % 13})\n")
        elif kind == 2:
            out.write(f"let s{i} = [x * 2 for x in 0..{i % 9 + 1} if x % 2 == 0]\n")
        else:
            out.write(f"let t{i} = translate({i % 5}, 0, 1) then rotate(z: {i % 90}) then scale(1.5)\n")
            out.write(f"if {i % 3} > 1 {{ let q{i} = \"n {{{i}:04}}\" }} else {{ let q{i} = f{i - 2}({i % 4}) }}\n")
    out.write("draw box(1, 1, 1)\n")


if __name__ == "__main__":
    main()
