#!/usr/bin/env python3
"""Compares two PNG pictures of the same drawing within a tolerance: same size, and at most MAX_SHARE of
the pixels differing by more than 48 in a channel of RGBA (a grey picture is read as RGB with three equal
channels, one without alpha as opaque, so a grey file and a colour one of the same drawing compare) (antialiasing may differ in the last bits between
library versions; a moved line does not pass). A small PNG reader of our own (8-bit grey, grey+alpha,
RGB or RGBA, not interlaced — what cairo writes), so the tests need no imaging library.

usage: png_diff.py EXPECTED.png ACTUAL.png [MAX_SHARE=0.002]
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, chunks = 8, {}
    idat = b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            chunks["IHDR"] = body
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", chunks["IHDR"])
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(colour)
    if depth != 8 or channels is None or interlace:
        raise ValueError(f"{path}: unsupported PNG (depth {depth}, colour type {colour}, interlace {interlace})")
    raw = zlib.decompress(idat)
    stride = w * channels
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return w, h, channels, rows


def rgba_rows(w, channels, rows):
    """Each row as RGBA bytes."""
    out = []
    for row in rows:
        if channels == 4:
            out.append(row)
            continue
        rgba = bytearray(4 * w)
        for x in range(w):
            p = row[x * channels:(x + 1) * channels]
            if channels == 1:
                rgba[4 * x:4 * x + 4] = bytes((p[0], p[0], p[0], 255))
            elif channels == 2:
                rgba[4 * x:4 * x + 4] = bytes((p[0], p[0], p[0], p[1]))
            else:
                rgba[4 * x:4 * x + 4] = bytes((p[0], p[1], p[2], 255))
        out.append(bytes(rgba))
    return out


def main():
    expected, actual = read_png(sys.argv[1]), read_png(sys.argv[2])
    max_share = float(sys.argv[3]) if len(sys.argv) > 3 else 0.002
    if expected[:2] != actual[:2]:
        sys.exit(f"{sys.argv[2]}: {actual[0]}x{actual[1]} pixels, expected {expected[0]}x{expected[1]}")
    w, h, n = expected[0], expected[1], 4
    if expected[2:] == actual[2:]:
        return
    expected = (w, h, n, rgba_rows(w, expected[2], expected[3]))
    actual = (w, h, n, rgba_rows(w, actual[2], actual[3]))
    differing = 0
    for row_e, row_a in zip(expected[3], actual[3]):
        for x in range(w):
            if any(abs(row_e[x * n + k] - row_a[x * n + k]) > 48 for k in range(n)):
                differing += 1
    share = differing / (w * h)
    if share > max_share:
        sys.exit(f"{sys.argv[2]} differs from {sys.argv[1]} in {differing} pixels ({share:.3%}): "
                 "regenerate the pictures (scripts/docs-images.sh) if the change is meant")


if __name__ == "__main__":
    main()
