#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""gen_mesh.py — the benchmark meshes of firmware/scenes/bench/ as Wavefront OBJ.

A trefoil knot swept by a tube whose radius ripples along and around it, so
the mesh is closed, hides part of itself (depth test and culling both
matter) and has triangles of many sizes and shapes, as a scanned model
does. RINGS x SIDES quads, each split into two triangles; per-vertex unit
normals (`vn`, averaged over the faces around each vertex) and texture
coordinates (`vt`, u along the knot, v around the tube). Every number is
printed with a fixed number of decimals, so the files are reproducible
byte for byte (tests/system/test_meshes.sh regenerates and compares them):
    knot-4k.obj   gen_mesh.py 64 32
    knot-16k.obj  gen_mesh.py --no-uv 128 64

    gen_mesh.py [--no-uv] RINGS SIDES OUT.obj

--no-uv leaves the texture coordinates out (corners v//vn).
"""
import math
import sys


def knot(t):
    """Trefoil centre line at parameter t (radius about 3)."""
    return (math.sin(t) + 2.0 * math.sin(2.0 * t),
            math.cos(t) - 2.0 * math.cos(2.0 * t),
            -math.sin(3.0 * t))


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(a):
    n = math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])
    return (a[0] / n, a[1] / n, a[2] / n) if n > 0 else (0.0, 0.0, 1.0)


def mesh(rings, sides):
    verts = []
    for i in range(rings):
        t = 2.0 * math.pi * i / rings
        c = knot(t)
        tang = unit(sub(knot(t + 1e-4), knot(t - 1e-4)))
        # a frame around the tangent from a fixed helper axis (the knot's
        # tangent is never parallel to this one)
        helper = (0.3, 0.4, 0.866)
        nrm = unit(cross(tang, helper))
        bin_ = cross(tang, nrm)
        for j in range(sides):
            a = 2.0 * math.pi * j / sides
            r = 0.55 + 0.12 * math.sin(5.0 * t) * math.cos(3.0 * a) + 0.05 * math.sin(17.0 * t + 2.0 * a)
            d = (math.cos(a) * nrm[0] + math.sin(a) * bin_[0],
                 math.cos(a) * nrm[1] + math.sin(a) * bin_[1],
                 math.cos(a) * nrm[2] + math.sin(a) * bin_[2])
            verts.append((c[0] + r * d[0], c[1] + r * d[1], c[2] + r * d[2]))
    tris = []
    for i in range(rings):
        for j in range(sides):
            a = i * sides + j
            b = ((i + 1) % rings) * sides + j
            c = ((i + 1) % rings) * sides + (j + 1) % sides
            d = i * sides + (j + 1) % sides
            tris.append((a, b, c))
            tris.append((a, c, d))
    return verts, tris


def main(argv):
    uv = "--no-uv" not in argv
    argv = [a for a in argv if a != "--no-uv"]
    if len(argv) != 4:
        sys.stderr.write("usage: gen_mesh.py [--no-uv] RINGS SIDES OUT.obj\n")
        return 2
    rings, sides = int(argv[1]), int(argv[2])
    verts, tris = mesh(rings, sides)
    # the winding that faces outward is the one whose normal points away
    # from the tube's centre line; flip every triangle if the first does not
    acc = [[0.0, 0.0, 0.0] for _ in verts]
    for t in tris:
        n = cross(sub(verts[t[1]], verts[t[0]]), sub(verts[t[2]], verts[t[0]]))
        for k in t:
            for c in range(3):
                acc[k][c] += n[c]
    centre0 = knot(0.0)
    if sum((verts[0][c] - centre0[c]) * acc[0][c] for c in range(3)) > 0:
        tris = [(t[0], t[2], t[1]) for t in tris]
        acc = [[-x for x in a] for a in acc]
    with open(argv[3], "w", newline="\n") as f:
        f.write("# trefoil knot tube, %d x %d quads, %d vertices, %d triangles (tools/bench/gen_mesh.py)\n"
                % (rings, sides, len(verts), len(tris)))
        f.write("o knot\n")
        for v in verts:
            f.write("v %.4f %.4f %.4f\n" % v)
        if uv:
            for i in range(rings + 1):
                for j in range(sides + 1):
                    f.write("vt %.4f %.4f\n" % (i / rings, j / sides))
        for a in acc:
            n = unit(a)
            f.write("vn %.4f %.4f %.4f\n" % n)

        def corner(k, tri_i, tri_j):
            i, j = divmod(k, sides)
            # texture seam: the last ring and side wrap to u = 1, v = 1
            ui = i if not (i == 0 and tri_i == rings - 1) else rings
            vj = j if not (j == 0 and tri_j == sides - 1) else sides
            if not uv:
                return "%d//%d" % (k + 1, k + 1)
            return "%d/%d/%d" % (k + 1, ui * (sides + 1) + vj + 1, k + 1)
        for n, t in enumerate(tris):
            q = n // 2
            ti, tj = divmod(q, sides)
            f.write("f %s %s %s\n" % tuple(corner(k, ti, tj) for k in t))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
