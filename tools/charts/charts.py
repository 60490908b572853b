#!/usr/bin/env python3
"""Speed-vs-accuracy and numeric-stability charts (make charts).

speed_vs_accuracy: every scene measured by `make bench` (instructions per
frame on the emulated Cortex-M0+ and Cortex-M4F, fixed and float) against
its accuracy versus the double build of the same scene (PSNR from
host_sim --compare double at the same size).

stability_scale: the ray tracer's sphere test where methods fail. A scene
whose geometry is multiplied by k (camera at the origin, so the exact image
does not change with k) is rendered for k = 1 … 4096 in fixed and float,
with the book's quadratic and with the robust formulation, and compared with
the double build. The book's formulation in Q15.16 breaks once k·|CO| and
r² leave the number format; the robust one holds.

Writes out/charts/<name>.png, .svg and .csv.
"""
import argparse
import csv
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from stability import host_sim_compare, scaled_scene  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def write_outputs(fig, rows, header, outdir, name):
    os.makedirs(outdir, exist_ok=True)
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(outdir, "%s.%s" % (name, ext)), dpi=110, bbox_inches="tight")
    with open(os.path.join(outdir, name + ".csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
    plt.close(fig)
    print("charts: %s/%s.{png,svg,csv} (%d rows)" % (outdir, name, len(rows)))


DEFAULT_VARIANTS = ("default", "strip16", "plain", "")


def speed_vs_accuracy(results, host_sim, scenes_dir, outdir):
    lines = []
    if os.path.exists(results):
        with open(results) as f:
            lines = [json.loads(l) for l in f if l.strip()]
    # one measurement per (target, scene, numeric): the scene's default variant
    pick = {}
    for l in lines:
        what = l.get("what", "")
        if not what.startswith("scene:") or l.get("per") != "frame":
            continue
        if l.get("target") not in ("m0plus-qemu", "m4f-qemu", "rp2040-sim"):
            continue
        name = what[len("scene:"):]
        if not os.path.exists(os.path.join(scenes_dir, name + ".scene")):
            continue
        key = (l["target"], name, l.get("numeric", "fixed"))
        variant = l.get("variant", "")
        if key not in pick or (variant in DEFAULT_VARIANTS and pick[key].get("variant") not in DEFAULT_VARIANTS):
            pick[key] = l
    rows, acc = [], {}
    for (target, name, numeric), l in sorted(pick.items()):
        size = "%dx%d" % (l.get("width", 240), l.get("height", 240))
        if (name, numeric, size) not in acc:
            s = host_sim_compare(host_sim, os.path.join(scenes_dir, name + ".scene"), numeric, size)
            acc[(name, numeric, size)] = s
        s = acc[(name, numeric, size)]
        cost = l.get("instructions", l.get("cycles"))
        unit = "instructions" if "instructions" in l else "cycles"
        psnr = s.get("psnr")
        rows.append([target, name, numeric, size, cost, unit,
                     "inf" if psnr is None else psnr, s.get("ssim"), s.get("max_err"), s.get("pct_diff")])
    fig, ax = plt.subplots(figsize=(8, 5.5))
    markers = {"m0plus-qemu": "o", "m4f-qemu": "s", "rp2040-sim": "^"}
    colours = {"fixed": "tab:blue", "float": "tab:orange", "double": "tab:green"}
    for r in rows:
        psnr = 99.0 if r[6] == "inf" else float(r[6])
        ax.scatter(float(r[4]), psnr, marker=markers.get(r[0], "x"), color=colours.get(r[2], "k"))
        ax.annotate(r[1].split("/")[-1], (float(r[4]), psnr), fontsize=6, xytext=(3, 2),
                    textcoords="offset points")
    for t, m in markers.items():
        ax.scatter([], [], marker=m, color="grey", label=t)
    for n, c in colours.items():
        ax.scatter([], [], marker="o", color=c, label=n)
    ax.set_xscale("log")
    ax.set_xlabel("instructions per frame (qemu, -icount) / cycles (rp2040-sim)")
    ax.set_ylabel("PSNR vs double build (dB; identical plotted at 99)")
    ax.set_title("Speed against accuracy, 240x240")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    if not rows:
        ax.text(0.5, 0.5, "no scene measurements: run `make bench` first", ha="center",
                transform=ax.transAxes)
    write_outputs(fig, rows, ["target", "scene", "numeric", "size", "cost", "unit", "psnr", "ssim",
                              "max_err", "pct_diff"], outdir, "speed_vs_accuracy")


def stability(host_sim, outdir, size):
    ks = [1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for form in ("book", "robust"):
            for k in ks:
                # the ground sphere keeps the book's 5000/k ratio up to the format's limit
                text = scaled_scene(k, form)
                path = os.path.join(tmp, "k%d-%s.scene" % (k, form))
                with open(path, "w") as f:
                    f.write(text)
                for numeric in ("fixed", "float"):
                    try:
                        # fixed point in Q15.16 throughout (the chart's question)
                        s = host_sim_compare(host_sim, path, numeric, size, 16)
                        psnr = s.get("psnr")
                        rows.append([form, numeric, k, "inf" if psnr is None else psnr,
                                     s.get("pct_within2"), s.get("saturations"), ""])
                    except RuntimeError as e:
                        rows.append([form, numeric, k, "", "", "", str(e).splitlines()[-1][:120]])
    fig, ax = plt.subplots(figsize=(8, 5))
    for form, style in (("book", "--"), ("robust", "-")):
        for numeric, colour in (("fixed", "tab:blue"), ("float", "tab:orange")):
            pts = [(r[2], 99.0 if r[3] == "inf" else float(r[3])) for r in rows
                   if r[0] == form and r[1] == numeric and r[3] != ""]
            if pts:
                ax.plot([p[0] for p in pts], [p[1] for p in pts], style, marker="o", color=colour,
                        label="%s, %s" % (numeric, form))
    ax.axhline(45, color="grey", lw=0.8, ls=":")
    ax.set_xscale("log", base=2)
    ax.set_xlabel("scene scale k (positions and radii multiplied by k)")
    ax.set_ylabel("PSNR vs double build (dB; identical at 99)")
    ax.set_title("Ray-sphere test stability with scene scale, %s" % size)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    write_outputs(fig, rows, ["formulation", "numeric", "k", "psnr", "pct_within2", "saturations",
                              "error"], outdir, "stability_scale")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--results", default="build/bench/results.jsonl")
    ap.add_argument("--host-sim", default="build/host_sim")
    ap.add_argument("--scenes", default="firmware/scenes")
    ap.add_argument("--out", default="out/charts")
    ap.add_argument("--size", default="120x120", help="render size of the stability sweep")
    a = ap.parse_args()
    if not os.path.exists(a.host_sim):
        sys.exit("charts: %s is missing (run make first)" % a.host_sim)
    speed_vs_accuracy(a.results, a.host_sim, a.scenes, a.out)
    stability(a.host_sim, a.out, a.size)


if __name__ == "__main__":
    main()
