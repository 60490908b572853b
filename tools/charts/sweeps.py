# SPDX-License-Identifier: MIT
"""The stability sweeps: where each method fails, and the pins that hold
those boundaries in place.

Each sweep renders the scenes of tools/scene/gen_sweep.py along one
parameter, for a few series (a method, a number format, a bit depth), with
host_sim at a small size, and measures each point against a reference. A
point holds when its measure is on the right side of the sweep's threshold;
the boundary of a series is the first swept value where it fails after
holding (and, for a series that fails from the start, the first where it
holds). PINS are the points on either side of each boundary as measured
today: tests/system/test_stability.py renders exactly those points and
fails when one of them changes side, i.e. when a boundary moves; make
charts draws the whole sweep and says when a boundary no longer sits between
its pins. Plain Python and host_sim only (the tests run without matplotlib),
except subpixel_range, whose measure is the fast path's cost on the emulated
Cortex-M0+ (qemu, through tools/charts/lab.py).
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "scene"))
import gen_sweep  # noqa: E402
import hostsim  # noqa: E402


def geo(lo, hi, per_octave):
    """lo, lo*2^(1/n), ... up to hi, rounded to 4 significant digits."""
    out, k = [], 0
    while True:
        v = float("%.4g" % (lo * 2 ** (k / per_octave)))
        if v > hi * 1.0001:
            return out
        out.append(v)
        k += 1


class Series:
    """One curve: generator keywords, numeric mode, NUM_FRAC (None: the
    scene's own format), frames rendered."""

    def __init__(self, label, kw=None, numeric="fixed", frac=None):
        self.label, self.kw, self.numeric, self.frac = label, dict(kw or {}), numeric, frac


class Sweep:
    """name: stability-NAME; gen: gen_sweep function name; xs: the values;
    series; measure(sweep, series, x) -> dict with the measure `metric`;
    holds(value) -> bool; pins: {series label: [(x, holds?), ...]}."""

    def __init__(self, name, title, xlabel, gen, xs, series, metric, ylabel, holds, threshold, pins,
                 size="120x120", logx=True, note=""):
        # size: the render size of every point; None: x is the render size
        self.name, self.title, self.xlabel, self.gen, self.xs = name, title, xlabel, gen, xs
        self.series, self.metric, self.ylabel, self.holds = series, metric, ylabel, holds
        self.threshold, self.pins, self.size, self.logx, self.note = threshold, pins, size, logx, note

    def scene(self, s, x, **over):
        kw = dict(s.kw)
        kw.update(over)
        return gen_sweep.SWEEPS[self.gen]("%.10g" % x if isinstance(x, float) else str(x), **kw)


# ---- the measures -----------------------------------------------------------
def bleed(sw, s, x, lab=None):
    """Share (%) of pixels where the near (red) square, which covers the
    view, is not what shows: the far one shows through, or neither passed
    the depth test."""
    raw, rgb, st = hostsim.render(sw.host_sim, sw.scene(s, x), s.numeric, sw.size, s.frac)
    lost = sum(1 for i in range(0, len(rgb), 3) if not (rgb[i] > 128 and rgb[i + 2] < 128))
    return {"bleed": 100.0 * lost * 3 / len(rgb), "num_frac": st["num_frac"], "saturations": st["saturations"]}


def against(ref_kw=None, ref_x=None, frames=False, max_err=False):
    """A measure against the double build of the same point (with ref_kw
    changed in the reference, or at ref_x instead of x): within1 (%), psnr,
    with max_err the largest error off the silhouettes (8-bit levels)."""
    def m(sw, s, x, lab=None):
        n = int(x) if frames else 1
        size = sw.size or "%dx%d" % (int(x), int(x))
        raw, rgb, st = hostsim.render(sw.host_sim, sw.scene(s, x), s.numeric, size, s.frac, frames=n)
        rx = x if ref_x is None else ref_x
        kw = dict(s.kw)
        kw.update(ref_kw or {})
        key = (sw.name, rx, tuple(sorted(kw.items())), n, size)
        if key not in sw.refs:
            sw.refs[key] = hostsim.render(sw.host_sim, sw.scene(s, rx, **(ref_kw or {})), "double", size,
                                          frames=n)
        rraw, rrgb, _ = sw.refs[key]
        p = hostsim.psnr(rgb, rrgb)
        return {"within1": 100.0 * hostsim.within1(raw, rraw), "psnr": None if math.isinf(p) else round(p, 2),
                "num_frac": st["num_frac"], "saturations": st["saturations"]} | (
                    {"max_err": interior_max_err(rgb, rrgb, int(size.split("x")[0]))} if max_err else {})
    return m


def interior_max_err(rgb, ref, w):
    """Largest channel error (8-bit) over the pixels whose 3x3 neighbourhood
    in the reference has no background (black) pixel: off the silhouettes,
    where a pixel's coverage may differ between builds."""
    n = len(ref) // 3
    h = n // w
    bg = [ref[3 * i] == 0 and ref[3 * i + 1] == 0 and ref[3 * i + 2] == 0 for i in range(n)]
    worst = 0
    for y in range(1, h - 1):
        for x in range(1, w - 1):
            if any(bg[(y + dy) * w + x + dx] for dy in (-1, 0, 1) for dx in (-1, 0, 1)):
                continue
            i = 3 * (y * w + x)
            e = max(abs(rgb[i] - ref[i]), abs(rgb[i + 1] - ref[i + 1]), abs(rgb[i + 2] - ref[i + 2]))
            if e > worst:
                worst = e
    return worst


def cost_per_pixel(sw, s, x, lab):
    """Instructions per drawn pixel on the emulated Cortex-M0+ (fixed point,
    the scene's own format), from tools/charts/lab.py's cached runs."""
    text = sw.scene(s, x)
    _, _, st = hostsim.render(sw.host_sim, text, "fixed", "%dx%d" % (int(x), int(x)))
    mode = "fixed%d" % st["num_frac"]
    lab.build_elves([("m0plus-qemu", mode)], quiet=True)
    c = lab.cost("m0plus-qemu", mode, text, 16, size=(int(x), int(x)))
    if "error" in c:
        raise hostsim.RenderError(c["error"])
    return {"per_pixel": round((c["init"] + c["total"]) / max(1, c["pixels"]), 1), "pixels": c["pixels"],
            "num_frac": st["num_frac"], "saturations": st["saturations"]}


def psnr_or_inf(v):
    return math.inf if v is None else v


# ---- the sweeps ----------------------------------------------------------------
SWEEPS = [
    Sweep("depth", "Depth precision against depth range: squares 0.01 apart at distance z (near plane 1)",
          "distance z of the near square (depth range z / near)", "depth",
          geo(3, 100000, 4),
          [Series("16-bit", {"depth_bits": "16"}), Series("32-bit", {"depth_bits": "32"}),
           Series("auto (the parser's choice)", {})],
          "bleed", "near square lost: the far one or nothing shows (% of pixels)", lambda v: v == 0, 0,
          {"16-bit": [(20.18, True), (24.0, False)], "32-bit": [(5166.0, True), (6144.0, False)],
           "auto (the parser's choice)": [(20.18, True), (24.0, True), (57.08, True), (67.88, True),
                                          (5166.0, True), (6144.0, False)]},
          size="32x32", note="fails where any pixel of the near square is lost"),
    Sweep("slope", "Perspective step N against the slope of a textured wall (nearest, 120x120)",
          "angle of the wall from facing the camera (degrees)", "slope", list(range(0, 90, 5)),
          [Series("N = 8", {"perspective_step": "8"}), Series("N = 16", {"perspective_step": "16"}),
           Series("N = 32", {"perspective_step": "32"}), Series("uv = linear (affine)", {"uv": "linear"})],
          "within1", "pixels within one RGB565 level of double, N = 1 (%)", lambda v: v >= 99.0, 99.0,
          {"N = 8": [(50, True), (55, False)], "N = 16": [(35, True), (40, False)],
           "N = 32": [(10, True), (15, False)], "uv = linear (affine)": [(0, True), (5, False)]},
          logx=False),
    Sweep("subpixel", "Sub-pixel bits against screen size: a fan of 48 slivers",
          "render size (pixels a side)", "subpixel", [30, 45, 60, 90, 120, 180, 240, 360, 480, 720, 960],
          [Series("%d bits" % b, {"subpixel_bits": str(b)}) for b in (1, 2, 3, 4, 6)],
          "within1", "pixels within one level of double at 8 bits (%)", lambda v: v >= 99.9, 99.9,
          {"3 bits": [(360, False), (480, True)], "4 bits": [(180, False), (240, True)],
           "6 bits": [(60, False), (90, True)]},
          note="the size is the render size; the same scene", size=None),
    Sweep("subpixel-range", "The fast path's range: sub-pixel bits against screen size (one triangle, M0+)",
          "render size (pixels a side)", "subpixel_range",
          [32, 48, 64, 72, 80, 96, 128, 192, 256, 288, 320, 384, 512, 768, 1024, 1152, 1280],
          [Series("%d bits" % b, {"subpixel_bits": str(b)}) for b in (4, 6, 8)],
          "per_pixel", "M0+ instructions per drawn pixel (qemu)", lambda v: v < 500, 500,
          {"8 bits": [(64, True), (72, False)], "6 bits": [(256, True), (288, False)],
           "4 bits": [(1024, True), (1152, False)]},
          note="fails where the triangle leaves the span loops for the exact filler"),
    Sweep("raster-scale", "Fixed format against scene scale: raster-11 scaled by k (viewport too)",
          "scale k", "raster_scale", [2.0 ** e for e in range(-9, 10)] + [1000.0],
          [Series("fixed, own format", {}), Series("Q19.12", {}, "fixed", 12), Series("Q15.16", {}, "fixed", 16),
           Series("Q11.20", {}, "fixed", 20), Series("float", {}, "float"), Series("double", {}, "double")],
          "psnr", "PSNR vs double at k = 1 (dB; identical at 99)", lambda v: psnr_or_inf(v) >= 40, 40,
          {"fixed, own format": [(1 / 64, False), (1 / 32, True), (1000, True)],
           "Q15.16": [(1 / 32, False), (1 / 16, True), (1000, True)],
           "Q19.12": [(1 / 8, False), (1 / 4, True), (256, True), (512, False)],
           "double": [(1 / 512, True), (1000, True)]}),
    Sweep("rotation", "Accumulated rotation: a cube turning 7.3 degrees a frame, the last frame",
          "frames", "rotation", [1, 10, 100, 300, 1000, 2000, 3000, 5000, 7000, 10000],
          [Series("own format", {}), Series("Q19.12", {}, "fixed", 12), Series("Q17.14", {}, "fixed", 14),
           Series("Q15.16", {}, "fixed", 16), Series("Q11.20", {}, "fixed", 20)],
          "within1", "pixels within one level of double, same frame (%)", lambda v: v >= 99.9, 99.9,
          {"Q19.12": [(1000, True), (2000, False)], "Q17.14": [(7000, True), (10000, False)],
           "own format": [(10000, True)]}),
    Sweep("specular", "Specular exponent against the power's error (highlight kept the same size)",
          "specular exponent e", "specular", [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 3000, 5000, 7000, 10000],
          [Series("fast Phong, fixed", {"lighting": "fast"}), Series("fast Phong, float", {"lighting": "fast"}, "float"),
           Series("exact Phong, fixed", {"lighting": "exact"}), Series("exact Phong, float", {"lighting": "exact"}, "float"),
           Series("ray tracer, fixed", {"renderer": "raytracer"})],
          "max_err", "largest error vs double exact off the silhouette (8-bit levels)", lambda v: v <= 8, 8,
          {"fast Phong, fixed": [(100, True), (200, False)], "fast Phong, float": [(100, True), (200, False)],
           "exact Phong, fixed": [(3000, True), (5000, False)], "ray tracer, fixed": [(3000, True), (5000, False)],
           "exact Phong, float": [(10000, True)]}),
    Sweep("near", "Near-plane distance: two cubes at z = 3.5 … 5.5, viewport d x d at d",
          "near plane d", "near", [0.001, 0.002, 0.005, 0.01, 0.02, 0.03, 0.05, 0.1, 0.2, 0.5, 1, 2, 3, 3.5],
          [Series("16-bit depth", {"depth_bits": "16"}), Series("32-bit depth", {"depth_bits": "32"}),
           Series("auto (the parser's choice)", {})],
          "within1", "pixels within one level of double, 32-bit depth (%)", lambda v: v >= 99.9, 99.9,
          {"16-bit depth": [(0.02, False), (0.03, True)], "auto (the parser's choice)": [(0.001, True)]}),
    Sweep("rt-scale", "The ray tracer's sphere test against scene scale k (about the camera)",
          "scale k", "rt_scale", [1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096],
          [Series("fixed Q15.16, book quadratic", {"formulation": "book"}, "fixed", 16),
           Series("fixed, robust (own format)", {"formulation": "robust"}),
           Series("float, book quadratic", {"formulation": "book"}, "float"),
           Series("float, robust", {"formulation": "robust"}, "float")],
          "psnr", "PSNR vs double, same k (dB; identical at 99)", lambda v: psnr_or_inf(v) >= 45, 45,
          {"fixed Q15.16, book quadratic": [(2, True), (4, False), (64, False)],
           "fixed, robust (own format)": [(1, True), (16, True), (256, True), (2048, True), (4096, True)],
           "float, book quadratic": [(256, True), (512, False)]},
          size="80x80"),
    Sweep("triangle-size", "Tiny and huge triangles: a fan of slivers scaled about the view's centre",
          "scale of the fan (1: 95 % of the half view)", "triangle_size",
          [1e-4, 1e-3, 1e-2, 0.1, 1, 10, 100, 300, 1000, 2000, 3000, 5000, 10000, 30000],
          [Series("fixed, own format", {}), Series("float", {}, "float")],
          "within1", "pixels within one level of double (%)", lambda v: v >= 99.9, 99.9,
          {"fixed, own format": [(1000, True), (2000, False), (30000, False)], "float": [(30000, True)]}),
]

MEASURES = {"depth": bleed, "slope": against(ref_kw={"perspective_step": "1", "uv": "perspective"}),
            "subpixel": against(ref_kw={"subpixel_bits": "8"}), "subpixel-range": cost_per_pixel,
            "raster-scale": against(ref_x=1.0), "rotation": against(frames=True), "specular": None,
            "near": against(ref_kw={"depth_bits": "32"}), "triangle-size": against(), "rt-scale": against()}


def _specular(sw, s, x, lab=None):
    return against(ref_kw={"lighting": "exact", "renderer": s.kw.get("renderer", "rasterizer")},
                   max_err=True)(sw, s, x)


MEASURES["specular"] = _specular


def by_name(name):
    for sw in SWEEPS:
        if sw.name == name:
            return sw
    raise KeyError(name)


def series_of(sw, label):
    for s in sw.series:
        if s.label == label:
            return s
    raise KeyError(label)


def measure(host_sim, sw, s, x, lab=None):
    """The sweep's measure at one point: (value, row fields); value None when
    host_sim refused the point (row field error), inf for identical images."""
    sw.host_sim = host_sim
    if not hasattr(sw, "refs"):
        sw.refs = {}
    try:
        r = MEASURES[sw.name](sw, s, x, lab)
    except hostsim.RenderError as e:
        return None, {"error": str(e)}
    return psnr_or_inf(r[sw.metric]) if sw.metric == "psnr" else r[sw.metric], r


def boundaries(sw, rows):
    """The swept values where a series changes from holding to failing or back."""
    out = {}
    for s in sw.series:
        pts = [r for r in rows if r["series"] == s.label and r["holds"] != ""]
        found = []
        for a, b in zip(pts, pts[1:]):
            if a["holds"] != b["holds"]:
                found.append((a["x"], b["x"], "fails" if a["holds"] else "holds"))
        out[s.label] = found
    return out


def run(host_sim, sw, lab=None, log=print):
    """Every point of a sweep: rows of dicts (series, x, holds, boundary, metric fields)."""
    rows = []
    for s in sw.series:
        prev = None
        for x in sw.xs:
            v, r = measure(host_sim, sw, s, x, lab)
            row = {"series": s.label, "x": x, "value": "" if v is None else "inf" if v == math.inf else v}
            row.update(r)
            row["holds"] = "" if "error" in r else int(bool(sw.holds(v)))
            row["boundary"] = int(prev is not None and row["holds"] != "" and row["holds"] != prev)
            if row["holds"] != "":
                prev = row["holds"]
            rows.append(row)
    for label, pins in sw.pins.items():
        for x, want in pins:
            got = [r for r in rows if r["series"] == label and r["x"] == x]
            if not got or got[0]["holds"] == "" or bool(got[0]["holds"]) != want:
                log("charts: stability-%s: %s at %g %s, pinned to %s: the boundary moved (update the pin in "
                    "tools/charts/sweeps.py and docs/charts.md)" % (sw.name, label, x,
                                                                   "is refused" if not got or got[0]["holds"] == ""
                                                                   else "holds" if got[0]["holds"] else "fails",
                                                                   "hold" if want else "fail"))
    return rows
