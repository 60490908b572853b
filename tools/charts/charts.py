#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Speed-against-accuracy and numeric-stability charts (make charts).

pareto: the lab (tools/charts/lab.py): every variant of each lab scene, its
cost on each emulated target against its accuracy versus the double build's
exact render, the Pareto frontier marked, and the variant the scene compiler
chooses for each of the scene's accuracy targets (tools/charts/quality.py;
column chosen_for, a star on the chart). out/charts/pareto.csv,
pareto-<scene>.{png,svg}, quality.csv (the table of choices) and
quality-lab.json (tools/quality/cost_model.py's fixture, compared with
tests/data/quality/lab.json).

formats: every scene of firmware/scenes at every fixed-point format Q19.12 …
Q11.20 against the double build, the format the scene analysis chooses
marked (formats.csv, formats.{png,svg}).

stability-<name>: the sweeps of tools/charts/sweeps.py, each with the
boundary where its method fails (stability-<name>.{csv,png,svg}).

usage: charts.py [--only pareto,formats,stability] [--jobs N] [--lab-scenes A,B]
"""
import argparse
import csv
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hostsim  # noqa: E402
import lab  # noqa: E402
import quality  # noqa: E402
import sweeps  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TARGET_NAMES = {"m0plus-qemu": "Cortex-M0+ (qemu, instructions)", "m4f-qemu": "Cortex-M4F (qemu, instructions)",
                "rp2040-sim": "RP2040 (rp2040js, cycles)"}
NUM_COLOURS = {"fixed": "tab:blue", "float": "tab:orange", "double": "tab:green"}
IDENTICAL = 99.0   # where an identical image is drawn


def save(fig, outdir, name):
    os.makedirs(outdir, exist_ok=True)
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(outdir, "%s.%s" % (name, ext)), dpi=110, bbox_inches="tight")
    plt.close(fig)


def write_csv(outdir, name, header, rows):
    os.makedirs(outdir, exist_ok=True)
    path = os.path.join(outdir, name + ".csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        for r in rows:
            w.writerow([cell(h, r.get(h)) for h in header] if isinstance(r, dict) else r)
    print("charts: %s (%d rows)" % (path, len(rows)))


def cell(column, v):
    """A CSV cell: PSNR of identical images is inf, other missing values empty."""
    if v is None:
        return "inf" if column.startswith("psnr") else ""
    return v


def plot_psnr(p):
    return IDENTICAL if p is None else min(float(p), IDENTICAL)


def frontier_steps(front):
    """The staircase through frontier points sorted by cost: (xs, ys) for ax.plot."""
    xs, ys = [], []
    for r in front:
        if xs:
            xs.append(r["cost"])
            ys.append(ys[-1])
        xs.append(r["cost"])
        ys.append(plot_psnr(r["psnr"]))
    return xs, ys


def pareto(a, outdir):
    L = lab.Lab(a.host_sim, a.build, a.jobs, rp2040=not a.no_rp2040, make=a.make)
    rows = L.run(a.scenes, a.lab_scenes.split(",") if a.lab_scenes else None)
    rows.sort(key=lambda r: (r["scene"], lab.TARGETS.index(r["target"]), r["cost"]))
    choices = quality_choices(a, outdir, rows)
    write_csv(outdir, "pareto", lab.COLUMNS + ["chosen_for"], rows)
    for scene in sorted({r["scene"] for r in rows}):
        rs = [r for r in rows if r["scene"] == scene]
        targets = [t for t in lab.TARGETS if any(r["target"] == t for r in rs)]
        fig, axes = plt.subplots(1, len(targets), figsize=(6.2 * len(targets), 5.0), squeeze=False)
        longest = 0
        for ax, t in zip(axes[0], targets):
            pts = [r for r in rs if r["target"] == t]
            for r in pts:
                ax.scatter(r["cost"], plot_psnr(r["psnr"]), s=30 if r["frontier"] else 18,
                           color=NUM_COLOURS[r["numeric"]], edgecolors="k" if r["frontier"] else "none",
                           zorder=3, alpha=1 if r["frontier"] else 0.5)
            front = sorted((r for r in pts if r["frontier"]), key=lambda r: r["cost"])
            ax.plot(*frontier_steps(front), color="crimson", lw=1.2, zorder=2, label="Pareto frontier")
            lines = []
            for k, r in enumerate(front, 1):
                ax.annotate(str(k), (r["cost"], plot_psnr(r["psnr"])), fontsize=7.5, xytext=(3, 3),
                            textcoords="offset points", color="crimson", weight="bold")
                lines.append("%d  %s: %.4g M, %s" % (k, r["variant"], r["cost"] / 1e6,
                                                     "identical" if r["psnr"] is None else "%.1f dB" % r["psnr"]))
            # the frontier of the methods the scene compiler considers (fixed point in the
            # scene's own format, 16-row strips: tools/charts/quality.py)
            cq = quality_frontier(a, scene, t, rows)
            if cq:
                ax.plot(*frontier_steps(cq), color="k", lw=0.9, ls="--", zorder=2)
            for r in pts:
                if r.get("chosen_for"):
                    ax.scatter(r["cost"], plot_psnr(r["psnr"]), s=160, marker="*", facecolors="none",
                               edgecolors="k", linewidths=1.1, zorder=5)
                    ax.annotate(">= " + " / ".join(r["chosen_for"].split()) + " dB", (r["cost"], plot_psnr(r["psnr"])),
                                fontsize=7, xytext=(4, -10), textcoords="offset points", color="k")
            chosen = [c for c in choices if c["scene"] == scene and quality.TARGETS_LAB.get(c["target"]) == t]
            if chosen:
                lines.append("")
                lines += ["* %s >= %g dB: %s" % (c["target"], c["min_psnr"], c["options"] or "as written")
                          for c in chosen]
            longest = max(longest, len(lines))
            ax.text(0.0, -0.19, "\n".join(lines), transform=ax.transAxes, va="top", ha="left", fontsize=7,
                    family="monospace", color="crimson")
            ax.set_xscale("log")
            ax.set_xlabel(("cycles" if t == "rp2040-sim" else "instructions") + " per frame")
            ax.set_title(TARGET_NAMES[t], fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
        axes[0][0].set_ylabel("PSNR vs double exact (dB; identical at %g)" % IDENTICAL)
        for n, c in NUM_COLOURS.items():
            axes[0][0].scatter([], [], color=c, label=n)
        axes[0][0].plot([], [], color="k", lw=0.9, ls="--", label="frontier of the compiler's candidates")
        axes[0][0].scatter([], [], s=160, marker="*", facecolors="none", edgecolors="k",
                           label="the compiler's choice (>= target dB)")
        axes[0][0].legend(fontsize=7, loc="lower right")
        fig.suptitle("%s, %dx%d: cost against accuracy of every variant; numbered: the Pareto frontier; "
                     "star: the scene compiler's choice for an accuracy target"
                     % ((scene,) + lab.SIZE), fontsize=11)
        fig.subplots_adjust(bottom=0.16 + 0.03 * longest)
        save(fig, outdir, "pareto-" + scene.replace("/", "-"))
    return rows


def quality_frontier(a, scene, target, rows):
    """The frontier of the scene compiler's candidates on a target, by cost
    (the RP2040's: none, its rows are the firmware images')."""
    s = next((x for x in lab.LAB if x.name == scene and x.quality), None)
    if s is None or target == "rp2040-sim" or a.lab_scenes:
        return []
    with open(os.path.join(a.scenes, scene + ".scene")) as f:
        text = f.read()
    cands = list(quality.candidates(rows, s, text, target).values())
    return sorted((r for r in cands if not any(o["cost"] < r["cost"] and lab.psnr_value(o["psnr"]) >=
                                                lab.psnr_value(r["psnr"]) for o in cands)), key=lambda r: r["cost"])


def quality_choices(a, outdir, rows):
    """The scene compiler's choices for the lab scenes' accuracy targets
    (tools/charts/quality.py): chosen_for on rows, quality.csv, and the cost
    model's fixture from this run (quality-lab.json)."""
    if a.lab_scenes:
        for r in rows:
            r["chosen_for"] = ""
        return []
    fx = os.path.join(outdir, "quality-lab.json")
    os.makedirs(outdir, exist_ok=True)
    write_csv(outdir, "pareto", lab.COLUMNS, rows)
    cm = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "quality", "cost_model.py")
    r = subprocess.run([sys.executable, cm, "fixture", "--pareto", os.path.join(outdir, "pareto.csv"), "--host-sim",
                        a.host_sim, "--scenes", a.scenes, "--out", fx])
    if r.returncode == 0:
        # the model's predictions on the held-out scenes, from this run's rows
        subprocess.run([sys.executable, cm, "validate", "--fixture", fx, "--scenes", a.scenes, "--csv",
                        os.path.join(outdir, "cost-model-validate.csv")])
        same = subprocess.run(["cmp", "-s", fx, "tests/data/quality/lab.json"]).returncode == 0
        print("charts: %s %s tests/data/quality/lab.json%s" % (
            fx, "matches" if same else "differs from",
            "" if same else " (the committed cost model's data: cp %s tests/data/quality/lab.json, then "
            "tools/quality/cost_model.py model --fixture tests/data/quality/lab.json --write "
            "tools/quality/cost_model.def and make again)" % fx))
    choices = quality.check(a.host_sim, a.scenes, rows)
    write_csv(outdir, "quality", quality.COLUMNS, choices)
    bad = [c for c in choices if not c["ok"]]
    print("charts: the scene compiler's choices: %d of %d within %.0f %% of the cheapest candidate that meets the "
          "target" % (len(choices) - len(bad), len(choices), 100 * (quality.LIMIT - 1)))
    return choices


def formats(a, outdir):
    """Every scene at every format against double; the chosen one marked."""
    rows = []
    names = []
    for root, _, files in os.walk(a.scenes):
        for f in files:
            if f.endswith(".scene"):
                names.append(os.path.relpath(os.path.join(root, f), a.scenes)[:-6])
    for name in sorted(names):
        with open(os.path.join(a.scenes, name + ".scene")) as f:
            text = f.read()
        try:
            _, ref_rgb, _ = hostsim.render(a.host_sim, text, "double", "240x240")
            _, _, st = hostsim.render(a.host_sim, text, "fixed", "240x240")
            chosen = st["num_frac"]
        except hostsim.RenderError as e:
            print("charts: formats: %s: %s" % (name, e))
            continue
        for frac in lab.FRACS:
            try:
                raw, rgb, st = hostsim.render(a.host_sim, text, "fixed", "240x240", frac)
                p = hostsim.psnr(rgb, ref_rgb)
                rows.append([name, lab.qfmt(frac), frac, int(frac == chosen),
                             "finer" if frac > chosen else "coarser" if frac < chosen else "chosen",
                             "inf" if math.isinf(p) else round(p, 2), st["saturations"], ""])
            except hostsim.RenderError as e:
                rows.append([name, lab.qfmt(frac), frac, 0, "finer" if frac > chosen else "coarser", "", "", str(e)[-100:]])
    write_csv(outdir, "formats", ["scene", "format", "num_frac", "chosen", "relation", "psnr", "saturations",
                                  "error"], rows)
    scenes = sorted({r[0] for r in rows})
    cols = 6
    nrow = (len(scenes) + cols - 1) // cols
    fig, axes = plt.subplots(nrow, cols, figsize=(2.6 * cols, 2.1 * nrow), sharex=True, sharey=True, squeeze=False)
    for i, sc in enumerate(scenes):
        ax = axes[i // cols][i % cols]
        pts = [(r[2], plot_psnr(None if r[5] == "inf" else r[5]), r[3]) for r in rows if r[0] == sc and r[5] != ""]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "-", color="tab:blue", lw=1, marker=".", ms=4)
        for p in pts:
            if p[2]:
                ax.scatter([p[0]], [p[1]], s=70, facecolors="none", edgecolors="crimson", linewidths=1.6, zorder=4)
        refused = [r[2] for r in rows if r[0] == sc and r[5] == ""]
        for f in refused:
            ax.axvspan(f - 0.5, f + 0.5, color="grey", alpha=0.15, lw=0)
        ax.set_title(sc, fontsize=7.5)
        ax.grid(True, alpha=0.3)
        ax.set_ylim(20, 102)
    for j in range(len(scenes), nrow * cols):
        axes[j // cols][j % cols].axis("off")
    for ax in axes[-1]:
        ax.set_xticks([12, 14, 16, 18, 20])
        ax.set_xticklabels(["Q19.12", "Q17.14", "Q15.16", "Q13.18", "Q11.20"], fontsize=6.5)
    fig.suptitle("Every scene at every fixed-point format, 240x240: PSNR against double (identical at %g); "
                 "ring: the format the scene analysis chooses; grey: formats the scene does not load in" % IDENTICAL,
                 fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    save(fig, outdir, "formats")


SWEEP_FIELDS = ["within1", "psnr", "max_err", "bleed", "per_pixel", "pixels", "num_frac", "saturations", "error"]


def stability(a, outdir):
    L = None
    for sw in sweeps.SWEEPS:
        if a.sweeps and sw.name not in a.sweeps.split(","):
            continue
        if sw.metric == "per_pixel":
            if L is None:
                L = lab.Lab(a.host_sim, a.build, a.jobs, rp2040=False, make=a.make)
        print("charts: sweep %s (%d series x %d points)" % (sw.name, len(sw.series), len(sw.xs)))
        rows = sweeps.run(a.host_sim, sw, L)
        fields = [f for f in SWEEP_FIELDS if any(f in r for r in rows)]
        header = ["series", "x", "value", "holds", "boundary"] + fields
        write_csv(outdir, "stability-" + sw.name, header, [[cell("psnr" if h == "value" and sw.metric == "psnr" else h,
                                                                  r.get(h)) for h in header] for r in rows])
        fig, ax = plt.subplots(figsize=(8.5, 5.2))
        cmap = plt.get_cmap("tab10")
        styles = ["-", "--", "-.", ":", (0, (5, 1)), (0, (3, 1, 1, 1))]
        for i, s in enumerate(sw.series):
            pts = [r for r in rows if r["series"] == s.label and r["holds"] != ""]
            ys = [plot_psnr(r["value"]) if sw.metric == "psnr" else r["value"] for r in pts]
            ax.plot([r["x"] for r in pts], ys, linestyle=styles[i % len(styles)], marker="o", ms=3.5 - 0.4 * i,
                    lw=2.2 - 0.3 * i, color=cmap(i), label=s.label)
            for r, y in zip(pts, ys):
                if r["boundary"]:
                    ax.scatter([r["x"]], [y], s=110, facecolors="none", edgecolors=cmap(i), linewidths=1.5, zorder=4)
        ax.axhline(sw.threshold, color="grey", lw=0.9, ls=":", label="threshold (%g)" % sw.threshold)
        if sw.logx:
            ax.set_xscale("log")
        if sw.metric == "per_pixel":
            ax.set_yscale("log")
        ax.set_xlabel(sw.xlabel)
        ax.set_ylabel(sw.ylabel)
        ax.set_title(sw.title + ("\nringed: the first point past a boundary" + ("; " + sw.note if sw.note else "")),
                     fontsize=9.5)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
        save(fig, outdir, "stability-" + sw.name)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--host-sim", default="build/host_sim")
    ap.add_argument("--build", default="build")
    ap.add_argument("--scenes", default="firmware/scenes")
    ap.add_argument("--out", default="out/charts")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", default="pareto,formats,stability")
    ap.add_argument("--lab-scenes", default="")
    ap.add_argument("--no-rp2040", action="store_true")
    ap.add_argument("--make", default="make")
    ap.add_argument("--sweeps", default="", help="only these sweeps (comma-separated names)")
    a = ap.parse_args()
    only = a.only.split(",")
    bad = [o for o in only if o not in ("pareto", "formats", "stability")]
    if bad:
        print("charts: --only %s: expected pareto, formats or stability" % ",".join(bad), file=sys.stderr)
        return 2
    unknown = [n for n in a.lab_scenes.split(",") if n and n not in [s.name for s in lab.LAB]]
    unknown += [n for n in a.sweeps.split(",") if n and n not in [s.name for s in sweeps.SWEEPS]]
    if unknown:
        print("charts: %s: not a lab scene (%s) or sweep (%s)" % (unknown[0], ", ".join(s.name for s in lab.LAB),
              ", ".join(s.name for s in sweeps.SWEEPS)), file=sys.stderr)
        return 2
    if not os.path.exists(a.host_sim):
        print("charts: %s is missing (run make first)" % a.host_sim, file=sys.stderr)
        return 2
    if "pareto" in only:
        pareto(a, a.out)
    if "formats" in only:
        formats(a, a.out)
    if "stability" in only:
        stability(a, a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
