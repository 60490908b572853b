#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Prints docs/rasterizer.md's mesh table from results.jsonl: the trefoil-knot
scenes of firmware/scenes/bench/ (tools/bench/bench_scene.c), millions of
instructions a frame and instructions a triangle on the emulated Cortex-M0+
and M4F, fixed and float (qemu instruction counts, not cycles), with the PSNR
of the M0+ fixed and float images against double exact (tools/bench/accuracy.py:
of the last frame they render, whose checksum the rows carry).

Usage: mesh_table.py [build/bench/results.jsonl]
"""
import json
import sys

TARGETS = [("m0plus-qemu", "fixed"), ("m0plus-qemu", "float"), ("m4f-qemu", "fixed"), ("m4f-qemu", "float")]


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "build/bench/results.jsonl"
    rows = {}
    with open(path) as fh:
        for line in fh:
            r = json.loads(line)
            if not r.get("what", "").startswith("scene:bench/knot-") or r.get("variant") != "default":
                continue
            rows.setdefault(r["what"], {})[(r["target"], r["numeric"], r["per"])] = r
    if not rows:
        sys.exit("mesh_table.py: no knot rows in %s (make bench)" % path)
    print("| scene | M0+ fixed | M0+ float | M4F fixed | M4F float | PSNR fixed / float |")
    print("|---|---|---|---|---|---|")
    for what in sorted(rows, key=lambda w: (int(w.split("-")[1][:-1]), w)):
        v = rows[what]
        cells = []
        for t, n in TARGETS:
            f, tri = v.get((t, n, "frame")), v.get((t, n, "triangle"))
            cells.append("%.1f M / %.0f" % (f["instructions"] / 1e6, tri["instructions"]) if f and tri else "")
        ps = []
        for n in ("fixed", "float"):
            r = v.get(("m0plus-qemu", n, "frame"))
            ps.append("—" if not r or "psnr" not in r else ("exact" if r["psnr"] is None else "%.1f" % r["psnr"]))
        acc = "%s / %s" % (ps[0], ps[1]) + (" dB" if any(p[0].isdigit() for p in ps) else "")
        print("| %s | %s | %s |" % (what.replace("scene:", ""), " | ".join(cells), acc))


if __name__ == "__main__":
    main()
