#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""obj_torus.py — a torus as a Wavefront OBJ file, to load large models.

RINGS x SIDES quads, each written as two triangles: RINGS * SIDES vertices
(`v`), (RINGS + 1) * (SIDES + 1) texture coordinates (`vt`, the seams
doubled) and one unit normal per vertex (`vn`); 2 * RINGS * SIDES faces
`f v/vt/vn` with the front faces clockwise seen from outside, as the scene
notation's triangles. 128 x 64: 8192 vertices, 16384 triangles.

    obj_torus.py RINGS SIDES OUT.obj
"""
import math
import sys


def main(argv):
    if len(argv) != 4:
        sys.stderr.write("usage: obj_torus.py RINGS SIDES OUT.obj\n")
        return 2
    rings, sides = int(argv[1]), int(argv[2])
    big, small = 2.0, 0.6
    out = ["# torus, %d x %d quads (tests/support/obj_torus.py)" % (rings, sides)]
    normals = []
    for i in range(rings):
        a = 2 * math.pi * i / rings
        for j in range(sides):
            b = 2 * math.pi * j / sides
            n = (math.cos(a) * math.cos(b), math.sin(b), math.sin(a) * math.cos(b))
            out.append("v %.5f %.5f %.5f" % (math.cos(a) * big + small * n[0], small * n[1],
                                             math.sin(a) * big + small * n[2]))
            normals.append("vn %.5f %.5f %.5f" % n)
    for i in range(rings + 1):
        for j in range(sides + 1):
            out.append("vt %.5f %.5f" % (i / rings, j / sides))
    out += normals

    def corner(i, j):
        v = (i % rings) * sides + (j % sides) + 1
        return "%d/%d/%d" % (v, i * (sides + 1) + j + 1, v)
    for i in range(rings):
        for j in range(sides):
            a, b, c, d = corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1)
            out.append("f %s %s %s" % (a, d, c))
            out.append("f %s %s %s" % (a, c, b))
    with open(argv[3], "w", newline="\n") as f:
        f.write("\n".join(out) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
