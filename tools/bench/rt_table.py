#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Prints docs/raytracer.md's speed table from results.jsonl: millions of
instructions a frame of each bench_raytracer variant on the emulated
Cortex-M0+ and M4F, fixed and float (qemu instruction counts, not cycles),
with the PSNR of the fixed and float images against double exact
(tools/bench/accuracy.py), and the ray-traced scenes on the emulated RP2040
(cycles and frame time, one and two cores).

Usage: rt_table.py [--summary] [build/bench/results.jsonl]
  --summary  the README's table instead: the book's two ray-traced scenes and
             raytracer-05's adaptive option, millions of instructions a frame
             and PSNR against double per target and numeric mode
"""
import json
import sys

TARGETS = [("m0plus-qemu", "fixed"), ("m0plus-qemu", "float"), ("m4f-qemu", "fixed"), ("m4f-qemu", "float")]
RP_SCENES = [("scene:book/raytracer-05", "raytracer-05 (exact)"),
             ("scene:bench/raytracer-05-adaptive", "raytracer-05, `adaptive_subsample = 4`"),
             ("scene:book/raytracer-02", "raytracer-02")]


def load(path):
    rows = []
    with open(path) as fh:
        for line in fh:
            rows.append(json.loads(line))
    return rows


def frame_rows(rows):
    """(what, variant) -> {(target, numeric): row} of bench_raytracer's frames."""
    out = {}
    for r in rows:
        if r.get("image") != "raytracer.elf" or r.get("per") != "frame":
            continue
        out.setdefault((r["what"], r["variant"]), {})[(r["target"], r["numeric"])] = r
    return out


def psnr(r):
    if not r or "psnr" not in r:
        return None
    return "exact" if r["psnr"] is None else "%.1f" % r["psnr"]


SUMMARY = [(("scene:book/raytracer-02", "strip16"), "raytracer-02"),
           (("scene:book/raytracer-05", "strip16"), "raytracer-05"),
           (("scene:book/raytracer-05", "adaptive_subsample=4"), "raytracer-05, `adaptive_subsample = 4`")]


def summary(fr):
    print("| ray-traced scene (240x240) | M0+ fixed | M0+ float | M4F fixed | M4F float |")
    print("|---|---|---|---|---|")
    for key, name in SUMMARY:
        v = fr.get(key)
        if v is None:
            sys.exit("rt_table.py: no %s `%s` rows (make bench)" % key)
        cells = []
        for t in TARGETS:
            r = v.get(t)
            p = psnr(r)
            cells.append("" if r is None else "%.0f M" % (r["instructions"] / 1e6) + ("" if not p else ", exact" if p == "exact" else ", %s dB" % p))
        print("| %s | %s |" % (name, " | ".join(cells)))
    return 0


def main():
    args = sys.argv[1:]
    short = "--summary" in args
    args = [a for a in args if a != "--summary"]
    rows = load(args[0] if args else "build/bench/results.jsonl")
    fr = frame_rows(rows)
    if not fr:
        sys.exit("rt_table.py: no bench_raytracer rows (make bench)")
    if short:
        return summary(fr)
    print("| scene, variant | M0+ fixed | M0+ float | M4F fixed | M4F float | PSNR fixed / float |")
    print("|---|---|---|---|---|---|")
    for (what, variant), v in fr.items():
        cells = ["%.0f" % (v[t]["instructions"] / 1e6) if t in v else "" for t in TARGETS]
        pf, pl = psnr(v.get(TARGETS[0])), psnr(v.get(TARGETS[1]))
        acc = "%s / %s dB" % (pf, pl) if pf and pl else "—"
        print("| %s `%s` | %s | %s |" % (what.replace("scene:", ""), variant, " | ".join(cells), acc))
    print()
    print("| scene (RP2040, 133 MHz) | one core | two cores |")
    print("|---|---|---|")
    for what, name in RP_SCENES:
        cells = []
        for cores in (1, 2):
            r = [x for x in rows if x.get("target") == "rp2040-sim" and x.get("what") == what and
                 x.get("cores") == cores and x.get("per") == "frame"]
            cells.append("%.1f M cycles, %.2f s" % (r[0]["cycles"] / 1e6, r[0]["us"] / 1e6) if r else "—")
        print("| %s | %s |" % (name, " | ".join(cells)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
