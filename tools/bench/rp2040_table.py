#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Prints docs/firmware.md's table of frame rates on the emulated board from
the rows `make bench-rp2040` appends to results.jsonl (target rp2040-sim,
240x240): per scene, one core and two cores, the frame's cycles (from its
begin line to its last pixel) and its rate (fps: from its begin line to the
next frame's), or for a ray-traced benchmark frame its time in seconds; the
XIP cache misses and the cycles waiting on the UART of the two-core frame;
the PSNR against double exact of the frame the board showed (the two-core
image's, tools/bench/accuracy.py: of the frame whose checksum the row
carries, the first of an averaged run).

Usage: rp2040_table.py [build/bench/results.jsonl]
"""
import json
import sys

SCENES = [("book/raytracer-02", ""), ("book/raster-11", ""), ("bench/cube-textured", ""),
          ("bench/cube-gouraud", ""), ("bench/cube-flat", ""), ("book/raytracer-05", ""),
          ("bench/raytracer-05-adaptive", " (`adaptive_subsample = 4`, 59.2 dB)"),
          ("bench/knot-4k-gouraud", " (`cgfs-mesh`, `RP2040_RAM_TEXT=raster`, Q12.19)"),
          ("bench/knot-4k-flat", " (the same)"), ("bench/knot-4k-textured", " (the same)"),
          ("builtin/pattern", " (`cgfs`)")]
SECONDS = {"book/raytracer-05", "bench/raytracer-05-adaptive"}


def cell(r, scene, first):
    if r is None:
        return ""
    m = r["cycles"] / 1e6
    cyc = f"{m:.1f} M" if m >= 100 else f"{m:.3f} M" if m < 10 else f"{m:.2f} M"
    if first:
        cyc += " cycles"
    if scene in SECONDS:
        return f"{cyc}, {r['us'] / 1e6:.2f} s"
    fps = r["fps"]
    return f"{cyc}, {fps:.3f} fps" if fps < 1 else f"{cyc}, {fps:.1f} fps" if fps >= 10 else f"{cyc}, {fps:.2f} fps"


def main(argv):
    path = argv[0] if argv else "build/bench/results.jsonl"
    rows = {}
    te = {}
    with open(path) as fh:
        for line in fh:
            r = json.loads(line)
            if r.get("target") == "rp2040-sim" and r.get("variant") == "two-core-te":
                te[r["what"]] = r
            if (r.get("target") == "rp2040-sim" and r.get("width", 240) == 240 and
                    r.get("variant") in ("single-core", "two-core")):
                rows[(r["what"], r["cores"] if r["variant"] != "single-core" else 1)] = r
    print("| scene | one core | two cores | XIP misses (two cores) | UART wait (two cores) | PSNR |")
    print("|---|---|---|---|---|---|")
    first = True
    for scene, note in SCENES:
        one, two = rows.get((f"scene:{scene}", 1)), rows.get((f"scene:{scene}", 2))
        if one is None and two is None:
            continue
        xip = f"{two['xip_misses']:,}" if two and two.get("xip_misses", 0) >= 100 else ""
        wait = two.get("uart_stall_cycles") if two else None
        wait = "" if wait is None else "0" if wait == 0 else f"{wait / 1e6:.2f} M cycles"
        shown = two if two is not None and "psnr" in two else one
        psnr = "" if shown is None or "psnr" not in shown else "exact" if shown["psnr"] is None else \
            f"{shown['psnr']:.1f} dB"
        print(f"| {scene}{note} | {cell(one, scene, first)} | {cell(two, scene, False)} | {xip} | {wait} | {psnr} |")
        first = False
    # the cubes against the panel's scan: frames sent, shown whole, torn
    cubes = [s for s, _ in SCENES if s.startswith("bench/cube-")]
    if any(rows.get((f"scene:{s}", 2), {}).get("shown_fps") is not None for s in cubes):
        print()
        print("| scene (two cores, 60 Hz scan) | sent / shown whole, torn | with TE (`cgfs-cube-te`) |")
        print("|---|---|---|")
        for s in cubes:
            cells = []
            for r in (rows.get((f"scene:{s}", 2)), te.get(f"scene:{s}")):
                cells.append("" if not r or r.get("shown_fps") is None else
                             f"{r['fps']:.1f} / {r['shown_fps']:.1f} fps, {r['torn_frames']} of {r['frames']}")
            print(f"| {s} | {cells[0]} | {cells[1]} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
