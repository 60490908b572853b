#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Compares a screenshot (xwd, ZPixmap, 24/32 bits per pixel) with a PNG
(8-bit RGB or RGBA, as host_sim writes): the screenshot must be the PNG
scaled up by a whole factor, each channel within a tolerance.
  xwd_compare.py SHOT.xwd IMAGE.png SCALE [TOLERANCE]
Prints one line; exit 0 when they match, 1 when not."""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or ctype not in (2, 6) or interlace:
                raise ValueError("PNG not 8-bit RGB/RGBA non-interlaced")
            bpp = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = w * bpp
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
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
        rows.append([tuple(line[x * bpp:x * bpp + 3]) for x in range(w)])
        prev = line
    return w, h, rows


def read_xwd(path):
    data = open(path, "rb").read()
    f = struct.unpack(">25I", data[:100])
    hsize, fmt, w, h, order, bpp, bpl, ncolors = f[0], f[2], f[4], f[5], f[7], f[11], f[12], f[19]
    masks = f[14:17]
    if fmt != 2 or bpp not in (24, 32):
        raise ValueError("xwd not a 24/32-bit ZPixmap")
    pix = data[hsize + ncolors * 12:]
    step = bpp // 8

    def shift(m):
        s = 0
        while m and not m & 1:
            m >>= 1
            s += 1
        return s
    shifts = [shift(m) for m in masks]
    endian = "little" if order == 0 else "big"

    def at(x, y):
        o = y * bpl + x * step
        v = int.from_bytes(pix[o:o + step], endian)
        return tuple((v & m) >> s for m, s in zip(masks, shifts))
    return w, h, at


def main():
    shot, png, scale = sys.argv[1], sys.argv[2], int(sys.argv[3])
    tol = int(sys.argv[4]) if len(sys.argv) > 4 else 8
    w, h, rows = read_png(png)
    sw, sh, at = read_xwd(shot)
    if (sw, sh) != (w * scale, h * scale):
        print(f"screenshot {sw}x{sh}, expected {w * scale}x{h * scale}")
        return 1
    worst, where = 0, None
    for y in range(h):
        for x in range(w):
            want = rows[y][x]
            for dy in range(scale):
                for dx in range(scale):
                    got = at(x * scale + dx, y * scale + dy)
                    d = max(abs(a - b) for a, b in zip(got, want))
                    if d > worst:
                        worst, where = d, (x, y, got, want)
    if worst > tol:
        print(f"differs by {worst} at {where}")
        return 1
    print(f"{sw}x{sh} = {w}x{h} x{scale}, max channel difference {worst}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
