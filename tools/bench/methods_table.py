#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Prints docs/rasterizer.md's table of the rasterizer's methods from
results.jsonl: instructions per drawn pixel (the whole frame included,
averaged over the scene's frames) of each tools/bench/bench_scene.c variant of
the bench scenes on the emulated Cortex-M0+ and M4F, fixed and float (qemu
instruction counts, not cycles), with the PSNR of the M0+ fixed image against
double exact (tools/bench/accuracy.py: of the frame whose checksum the row
carries, the last one the image rendered). bench/empty has no drawn pixels:
its row is millions of instructions a frame. A variant that renders the
default's frame at the default's cost is left out.

Usage: methods_table.py [build/bench/results.jsonl]
"""
import json
import re
import sys

TARGETS = [("m0plus-qemu", "fixed"), ("m0plus-qemu", "float"), ("m4f-qemu", "fixed"), ("m4f-qemu", "float")]
# (scene, what its default, the scene as written, does)
SCENES = [("bench/cube-textured", "fast, perspective_step = 16"),
          ("bench/cube-bilinear", "fast, bilinear, perspective_step = 16"),
          ("bench/cube-gouraud", "fast, perspective_step = 16"),
          ("bench/cube-flat", "fast"),
          ("bench/phong", "fast Phong, perspective_step = 16"),
          ("bench/empty", "(background only)")]


def method(variant, default):
    """A variant's name (KEY=VALUE[,KEY=VALUE]) in the docs' words."""
    if variant == "default":
        return default
    words = ", ".join(kv.replace("=", " = ") for kv in variant.split(","))
    return words + " (exact path)" if variant == "perspective_step=1" else words


def order(variant):
    """The default first, then by name with numbers in numeric order, the exact path last."""
    return (variant != "default", variant == "perspective_step=1",
            [int(p) if p.isdigit() else p for p in re.split(r"(\d+)", variant)])


def same(a, b):
    """A variant that renders the default's frame at the default's cost says nothing new."""
    return (a is not None and b is not None and a.get("frame_checksum") is not None and
            a.get("frame_checksum") == b.get("frame_checksum") and a["instructions"] == b["instructions"])


def psnr(r):
    if r is None or "psnr" not in r:
        return "—"
    return "exact" if r["psnr"] is None else "%.1f dB" % r["psnr"]


def table(rows):
    """rows: results.jsonl's records. Returns the table's lines."""
    by = {}
    for r in rows:
        if r.get("image", "").startswith("scene-") and r.get("what", "").startswith("scene:bench/"):
            by.setdefault((r["what"][6:], r["variant"]), {})[(r["target"], r["numeric"], r["per"])] = r
    out = ["| scene | method | M0+ fixed | M0+ float (soft) | M4F fixed | M4F float | PSNR (fixed) |",
           "|---|---|---|---|---|---|---|"]
    for scene, default in SCENES:
        variants = [v for (s, v) in by if s == scene]
        base = by.get((scene, "default"), {}).get(TARGETS[0] + ("frame",))
        for variant in sorted(variants, key=order):
            v = by[(scene, variant)]
            own = v.get(TARGETS[0] + ("frame",))
            if variant != "default" and same(own, base):
                continue
            if scene == "bench/empty":
                cells = ["%.3f M a frame" % (v[t + ("frame",)]["instructions"] / 1e6) if t + ("frame",) in v else ""
                         for t in TARGETS]
            else:
                cells = ["%.1f" % v[t + ("pixel",)]["instructions"] if t + ("pixel",) in v else "—"
                         for t in TARGETS]
            first = TARGETS[0] + ("pixel" if scene != "bench/empty" else "frame",)
            out.append("| %s | %s | %s | %s |" % (scene, method(variant, default), " | ".join(cells),
                                                 psnr(v.get(first))))
    if len(out) == 2:
        raise ValueError("no bench scene rows (make bench)")
    return out


def main(argv):
    path = argv[0] if argv else "build/bench/results.jsonl"
    with open(path) as fh:
        rows = [json.loads(line) for line in fh if line.strip()]
    try:
        print("\n".join(table(rows)))
    except ValueError as e:
        sys.exit("methods_table.py: %s in %s" % (e, path))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
