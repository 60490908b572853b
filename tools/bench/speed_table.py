#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Prints the README's speed table from results.jsonl: millions of
instructions a frame (qemu instruction counts, not cycles) of the book's
heaviest scenes on the emulated Cortex-M0+ and M4F, fixed and float, 240x240
in 16-row strips (tools/bench/bench_raytracer.c and bench_raster.c), and the
same scene on the emulated RP2040 (tools/rp2040sim: cycles at 133 MHz, one
core, SPI included, 8-row strips at the board image's format), with the
frame rate and, for the ray tracer, when its preview reaches the panel.

Usage: speed_table.py [build/bench/results.jsonl]
"""
import json
import sys

TARGETS = [("m0plus-qemu", "fixed"), ("m0plus-qemu", "float"), ("m4f-qemu", "fixed"), ("m4f-qemu", "float")]
# (label, what, image, variant, the RP2040 row's scene or None, show the M0+ fixed PSNR)
ROWS = [("raytracer-05 (16-row strips)", "scene:book/raytracer-05", "raytracer.elf", "strip16",
         "scene:book/raytracer-05", False),
        ("raytracer-05, `adaptive_subsample = 4`", "scene:book/raytracer-05", "raytracer.elf",
         "adaptive_subsample=4", "scene:bench/raytracer-05-adaptive", True),
        ("raytracer-05, `adaptive_subsample = 4`, `adaptive_threshold = 7`", "scene:book/raytracer-05",
         "raytracer.elf", "adaptive_subsample=4,adaptive_threshold=7", None, True),
        ("raytracer-02 (16-row strips)", "scene:book/raytracer-02", "raytracer.elf", "strip16",
         "scene:book/raytracer-02", False),
        ("raster-11, Phong, book path (16-row strips)", "scene:book/raster-11", "raster.elf", "book",
         "scene:book/raster-11", False),
        ("raster-13, textured, book path (16-row strips)", "scene:book/raster-13", "raster.elf", "book",
         None, False)]


def rp2040(r):
    if r is None:
        return "—"
    q = " at Q%d.%d" % (31 - r["num_frac"], r["num_frac"]) if r.get("num_frac") else ""
    cell = "%.0f M cycles%s, %.2f fps" % (r["cycles"] / 1e6, q, r["fps"])
    if r.get("first_image_us"):
        cell += " (preview after %.2f s)" % (r["first_image_us"] / 1e6)
    return cell


def main(argv):
    path = argv[0] if argv else "build/bench/results.jsonl"
    with open(path) as fh:
        rows = [json.loads(line) for line in fh if line.strip()]
    qemu, board = {}, {}
    for r in rows:
        if r.get("per") != "frame":
            continue
        if r.get("target") == "rp2040-sim" and r.get("variant") == "single-core" and r.get("width", 240) == 240:
            board[r["what"]] = r
        elif r.get("target") in ("m0plus-qemu", "m4f-qemu"):
            qemu[(r["what"], r.get("image"), r["variant"], r["target"], r["numeric"])] = r
    print("| scene | Cortex-M0+ fixed | Cortex-M0+ float (soft) | Cortex-M4F fixed | Cortex-M4F float (FPU) "
          "| RP2040 (emulated), fixed |")
    print("|---|---|---|---|---|---|")
    for label, what, image, variant, rp, show in ROWS:
        cells = [qemu.get((what, image, variant) + t) for t in TARGETS]
        if cells[0] is None:
            sys.exit("speed_table.py: no %s `%s` row of %s in %s (make bench)" % (what, variant, image, path))
        if show and cells[0].get("psnr") is not None:
            label += " (%.1f dB)" % cells[0]["psnr"]
        text = ["%.0f M instr." % (c["instructions"] / 1e6) if c else "—" for c in cells]
        print("| %s | %s | %s |" % (label, " | ".join(text), rp2040(board.get(rp)) if rp else "—"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
