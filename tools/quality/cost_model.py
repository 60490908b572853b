#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The scene compiler's cost model (tools/quality/cost_model.def) from the
speed/accuracy lab's measurements (`make charts`, out/charts/pareto.csv).

  cost_model.py fixture --pareto out/charts/pareto.csv --host-sim build/host_sim --out tests/data/quality/lab.json
      the lab's rows the model and its test need, and each lab scene's work
      (host_sim --stats of the scene text the compiler chooses for, in each
      numeric mode: every ray the ray tracer traces (primary, reflected and
      shadow rays) x objects, pixels written for the rasterizer, the mean
      over the frames tools/quality checks), each ray-traced row's own work
      (its variant's render: `work`), and for a scene that animates each
      candidate's lowest PSNR over those frames
  cost_model.py measure --host-sim build/host_sim --out tests/data/quality/lab.json
        [--only SCENE,... [--numeric MODE,...] [--no-rp2040]]
      the lab's variants measured on the emulators (make cost-model), into
      the fixture; --only: those scenes' alone, replacing their rows of each
      target and mode measured, every other row kept
  cost_model.py work --fixture tests/data/quality/lab.json --host-sim build/host_sim
      the same work figures for the fixture's stored rows, written into it
      (host renders only: no emulator runs; after a change to what a unit
      of work counts)
  cost_model.py model --fixture tests/data/quality/lab.json [--write tools/quality/cost_model.def | --check FILE]
      the model from the fixture: written, or compared with FILE (exit 1
      when it differs)

The model (docs/scene-format.md, "quality"): a scene's class (ray tracer with
or without reflections; rasterizer lit, textured with power-of-two textures,
textured with others, with chapter 15's shadows) has a base method (the
lab's plain variant of its scene: fast Phong, N = 16, nearest filtering, the
scene's map; every pixel for the ray tracer); the predicted cost of method m on target T in
numeric mode n is

    per_work[T, class, n] x work(scene, n) x factor[T, class, n, m]

per_work: the base method's cost a frame over its work, the geometric mean
over the lab's scenes of that class; factor: the method's cost over the
base method's on the same scene, target and mode, geometric mean over the
lab's scenes of that class. The ray tracer's classes (OWN_WORK) take each
candidate's own work instead of the scene's: the rays of its own render
(primary, reflected and shadow rays, x objects), so that what a method
leaves out (reflections, pixels it interpolates) is counted, not guessed.
Their per_work is the base method's cost over its own work (every pixel
traced), and a method's factor is instead its work beyond its rays, per
pixel: (its cost / per_work - its work) / pixels, the arithmetic mean over
the lab's scenes of that class (the adaptive methods' interpolation and
tests, which their rays do not count; negative where a ray costs less than
the base method's do on average). Predicted:

    per_work[T, class, n] x (work(candidate, n) + factor x pixels)

at least a tenth of per_work x work(candidate, n). RP2040 cycles: the Cortex-M0+ factors, and
per_work the M0+'s times rho, the geometric mean of RP2040 cycles over M0+
instructions of the lab's variants measured on both (rp2040js runs the
firmware's own images, SPI and XIP cache included).
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "charts"))
import lab  # noqa: E402
import quality  # noqa: E402
import scenetext  # noqa: E402

TARGETS = {"m0plus-qemu": "m0plus", "m4f-qemu": "m4f", "rp2040-sim": "rp2040"}
COLS = ["scene", "variant", "target", "cost", "psnr", "unit", "numeric", "format", "options", "strip"]
# Classes whose unit of work is each candidate's own render's (quality.c: the
# ray tracer's candidates are all rendered before they are ordered): the
# fixture's rows of their scenes carry it (`work`).
OWN_WORK = ("rt", "rt-reflective")
# The lab's render size (scene_work: host_sim --size): the pixels of a
# factor of an OWN_WORK class.
PIXELS = 240 * 240
# A held-out scene's predictions (cost_model.py validate). What decides the
# choice is the order of the candidates' costs (the scene's work and the
# class's cost per unit of work scale them all alike): two candidates the
# model orders by more than ORDER_GAP are measured in that order, or within
# ORDER_GAP of each other. The costs themselves (error = predicted /
# measured - 1) are held within COST_BOUND[class] either way: the reach of a
# model whose unit of work is pixels written or rays x objects alone (the
# lights, specular highlights, triangle counts and shadow rays of a scene are
# not in it; docs/charts.md, "Held-out scenes").
ORDER_GAP = 1.25
COST_BOUND = {"rt": 2.0, "rt-reflective": 2.0, "lit": 8.0, "textured": 3.0}


def scene_work(host_sim, text, numeric):
    """Mean work a frame over the frames checked (quality.c render_text):
    the ray tracer's rays (primary and reflected) and shadow rays x objects,
    else the pixels written."""
    toks = scenetext._tokens(text)
    objs = sum(len(scenetext._blocks(toks, k)) for k in ("sphere", "plane", "triangle"))
    with tempfile.TemporaryDirectory(prefix="cgfs-quality-") as tmp:
        path = os.path.join(tmp, "s.scene")
        with open(path, "w") as f:
            f.write(text)
        frames = quality.scene_frames(text)
        r = subprocess.run([host_sim, "--scene", path, "--panel", "none", "--size", "240x240", "--stats",
                            "--numeric", numeric, "--frames", str(frames)], capture_output=True, text=True, check=True)
    stats = [json.loads(line) for line in r.stdout.splitlines() if line.startswith("{")]
    pick = quality.frames_checked(frames)
    ws = []
    for st in stats:
        if st["frame"] in pick:
            rays = st["rays"] + st["shadow_rays"]
            ws.append(rays * max(objs, 1) if rays else st["pixels_written"])
    return sum(ws) / len(ws)


def make_fixture(args):
    with open(args.pareto) as f:
        rows = list(csv.DictReader(f))
    write_fixture(args, rows)


def measure(args):
    """The lab's variants the model and its checks use, measured (lab.Lab,
    quality_only: the emulators, each run cached under BUILD/charts/cache),
    into the fixture. --only: those lab scenes' variants alone (and
    --numeric's modes, without the RP2040 runs with --no-rp2040), each
    (scene, target, numeric mode) measured replacing the --out fixture's
    rows of it, every other row kept."""
    only = [n for n in args.only.split(",") if n] if args.only else None
    names = [s.name for s in lab.LAB if s.quality]
    if only and any(n not in names for n in only):
        raise SystemExit("cost_model: --only %s: not a lab scene with a cost model (%s)" % (
            ",".join(n for n in only if n not in names), ", ".join(names)))
    L = lab.Lab(args.host_sim, args.build, jobs=args.jobs, make=args.make, rp2040=not args.no_rp2040)
    rows = L.run(args.scenes, only=only, quality_only=True,
                 numerics=args.numeric.split(",") if args.numeric else None)
    cell = lambda k, v: ("inf" if k.startswith("psnr") else "") if v is None else str(v)  # noqa: E731 (charts.cell)
    rows = [{k: cell(k, r.get(k)) for k in COLS} for r in rows]
    if only:
        with open(args.out) as f:
            stored = json.load(f)["rows"]
        got = {(r["scene"], r["target"], r["numeric"]) for r in rows}
        rows = [{k: r[k] for k in COLS} for r in stored if (r["scene"], r["target"], r["numeric"]) not in got] + rows
        rows.sort(key=lambda r: names.index(r["scene"]) if r["scene"] in names else len(names))
        print("cost_model: %d rows measured, %d kept from %s" % (sum(1 for r in rows if (
            r["scene"], r["target"], r["numeric"]) in got), sum(1 for r in rows if (
                r["scene"], r["target"], r["numeric"]) not in got), args.out))
    write_fixture(args, rows)


def add_work(host_sim, scenes_dir, out):
    """Each lab scene's work (out["scenes"][name]["work"], by numeric mode)
    and each row's own work (`work`: the variant the compiler would render
    for it, in its numeric mode; OWN_WORK classes' rows, "" otherwise)."""
    rows = out["rows"]
    texts = {}
    for s in lab.LAB:
        if not s.quality:
            continue
        with open(os.path.join(scenes_dir, s.name + ".scene")) as f:
            texts[s.name] = f.read()
        qt = s.quality.text(texts[s.name])
        modes = ("fixed", "float", "double") if s.quality.fit else ("fixed",)
        work = {n: scene_work(host_sim, qt, n) for n in modes}
        info = out["scenes"].setdefault(s.name, {})
        info.update({"class": s.quality.cls, "work": work, "keys": lab.variant_keys(rows, s.name),
                     "fit": s.quality.fit})
    labs = {s.name: s for s in lab.LAB}
    cache = {}
    for r in rows:
        s = labs.get(r["scene"])
        r["work"] = ""
        if not s or not s.quality or s.quality.cls not in OWN_WORK or r["target"] == "rp2040-sim":
            continue
        k = lab.method_key(r, s, texts[s.name], out["scenes"][s.name]["keys"])
        if k is None:
            continue
        if (s.name, k, r["numeric"]) not in cache:
            vt = scenetext.apply(s.quality.text(texts[s.name]), k.split())
            cache[(s.name, k, r["numeric"])] = scene_work(host_sim, vt, r["numeric"])
        r["work"] = "%.10g" % cache[(s.name, k, r["numeric"])]


def write_fixture(args, rows):
    labs = {s.name: s for s in lab.LAB}
    rows = [{k: r[k] for k in COLS} for r in rows if lab.quality_row(r, labs.get(r["scene"]))]
    out = {"scenes": {}, "rows": rows}
    add_work(args.host_sim, args.scenes, out)
    for name, ps in quality.frames_psnr(args.host_sim, args.scenes, rows).items():
        out["scenes"][name]["psnr_frames"] = {k: round(v, 3) for k, v in ps.items()}
    save_fixture(out, args.out)


def refresh_work(args):
    """The work of the fixture's stored rows and scenes, recomputed (host renders only)."""
    with open(args.fixture) as f:
        out = json.load(f)
    add_work(args.host_sim, args.scenes, out)
    save_fixture(out, args.fixture)


def save_fixture(out, path):
    with open(path + ".tmp", "w") as f:
        json.dump(out, f, indent=0, sort_keys=True)
        f.write("\n")
    os.replace(path + ".tmp", path)
    print("cost_model: %d rows, %d scenes -> %s" % (len(out["rows"]), len(out["scenes"]), path))


def gmean(xs):
    return math.exp(sum(math.log(x) for x in xs) / len(xs))


def keyed_rows(fx, scenes_dir):
    """(scene, target, numeric, method key) -> cost, for the rows the model
    uses; and (scene, numeric, method key) -> the row's own work (OWN_WORK
    classes), in fx["own_work"]."""
    by = {}
    own = fx.setdefault("own_work", {})
    texts = {}
    for s in lab.LAB:
        with open(os.path.join(scenes_dir, s.name + ".scene")) as f:
            texts[s.name] = f.read()
    labs = {s.name: s for s in lab.LAB}
    for r in fx["rows"]:
        s = labs.get(r["scene"])
        if not s or r["target"] == "rp2040-sim":
            continue
        k = lab.method_key(r, s, texts[s.name], fx["scenes"][s.name]["keys"])
        if k is None:
            continue
        by.setdefault((r["scene"], TARGETS[r["target"]], r["numeric"], k), float(r["cost"]))
        if r.get("work"):
            own.setdefault((r["scene"], r["numeric"], k), float(r["work"]))
    return by, texts


def base_key(s, text, keys):
    """The class's base method (LabQuality.base) as a method key."""
    return lab.method_key({"options": " ".join(s.quality.apply + s.quality.base), "strip": 16, "variant": ""}, s,
                          text, keys)


def rho(fx, by, texts):
    """RP2040 cycles over M0+ instructions of the variants measured on both."""
    labs = {s.name: s for s in lab.LAB}
    rs = []
    for r in fx["rows"]:
        if r["target"] != "rp2040-sim":
            continue
        m0 = [o for o in fx["rows"] if o["scene"] == r["scene"] and o["target"] == "m0plus-qemu"
              and o["numeric"] == "fixed" and o["options"] == r["options"] and int(o["strip"]) == 16
              and " Q" not in o["variant"]]
        if m0:
            rs.append(float(r["cost"]) / float(m0[0]["cost"]))
    del labs, by, texts
    return gmean(rs), len(rs)


def fit(fx, by, texts, scenes):
    """The model's terms fitted on `scenes` (names): base {(target, class,
    numeric): [per_work of each scene]}, meth {(target, class, numeric,
    method key): [factor of each scene]}."""
    labs = {s.name: s for s in lab.LAB}
    base, meth = {}, {}
    for (scene, t, n, k), cost in sorted(by.items()):
        if scene not in scenes:
            continue
        s = labs[scene]
        info = fx["scenes"][scene]
        bk = base_key(s, texts[scene], info["keys"])
        b = by.get((scene, t, n, bk))
        if b is None:
            continue
        cls = info["class"]
        if cls in OWN_WORK:
            # per its own work: the base method's, and each method's over it
            wb, wk = own_work(fx, scene, n, bk), own_work(fx, scene, n, k)
            if k == bk:
                base.setdefault((t, cls, n), []).append(b / wb)
            meth.setdefault((t, cls, n, k), []).append(0.0 if k == bk else (cost * wb / b - wk) / PIXELS)
            continue
        if k == bk:
            base.setdefault((t, cls, n), []).append(b / info["work"][n])
        meth.setdefault((t, cls, n, k), []).append(cost / b)
    return base, meth


def own_work(fx, scene, numeric, key):
    """The work of a ray-traced row's own render (the fixture's `work`)."""
    w = fx["own_work"].get((scene, numeric, key))
    if w is None:
        raise SystemExit("cost_model: %s, %s, %r: no work of its own in the fixture (cost_model.py work)" %
                         (scene, numeric, key or "(as written)"))
    return w


def fitted(fx):
    """The scenes the model is fitted on (not held out)."""
    return {n for n, i in fx["scenes"].items() if i.get("fit", True)}


# Textured classes: a pixel's lighting is not in their unit of work, so a
# scene shaded otherwise than the class's fitted scenes has the lit class's
# per-pixel lighting added (or taken out) a unit of work, whatever the
# method: the lit class's cost per unit of work times (its factor for the
# scene's shading - its factor for the class's; no shading counts as flat,
# whose lighting is per triangle).
SHADED_CLASSES = ("textured", "textured-npot")


def shading_of(text):
    return scenetext.written(text, "shading") or "none"


def class_shading(fx, texts, scenes):
    """{class: the shading its scenes among `scenes` write} of the textured
    classes whose scenes agree."""
    seen = {}
    for name in scenes:
        cls = fx["scenes"][name]["class"]
        if cls in SHADED_CLASSES:
            seen.setdefault(cls, set()).add(shading_of(texts[name]))
    return {c: next(iter(v)) for c, v in seen.items() if len(v) == 1}


def lighting(base, meth, shade, t, cls, n, shading):
    """What a unit of work costs more (or less) for the scene's shading
    (quality.c lighting_per_work)."""
    cs = shade.get(cls)
    if cls not in SHADED_CLASSES or cs is None or cs == shading or (t, "lit", n) not in base:
        return 0.0
    lit = ("m0plus" if t == "rp2040" else t, "lit", n)
    f = {s: meth.get(lit + ("shading=%s" % ("flat" if s == "none" else s),)) for s in (shading, cs)}
    if None in f.values():
        return 0.0
    return gmean(base[(t, "lit", n)]) * (gmean(f[shading]) - gmean(f[cs]))


def term(cls, xs):
    """A model term of the lab scenes' values xs: the geometric mean, or the
    arithmetic one of an OWN_WORK class's factors (work a pixel, of either
    sign)."""
    return sum(xs) / len(xs) if cls in OWN_WORK else gmean(xs)


def predicted(base, meth, shade, t, cls, n, shading, work, factor, pixels=PIXELS):
    """A method's predicted cost (quality.c): (the class's cost per unit of
    work x the method's factor + lighting) x work, at least a tenth of the
    first term; OWN_WORK classes: the class's cost per unit of work x (the
    candidate's work + factor x pixels), at least a tenth of per_work x
    work."""
    if cls in OWN_WORK:
        return gmean(base[(t, cls, n)]) * max(work + factor * pixels, 0.1 * work)
    pw = gmean(base[(t, cls, n)]) * factor
    return max(pw + lighting(base, meth, shade, t, cls, n, shading), 0.1 * pw) * work


def model(fx, scenes_dir):
    by, texts = keyed_rows(fx, scenes_dir)
    base, meth = fit(fx, by, texts, fitted(fx))
    shade = class_shading(fx, texts, fitted(fx))
    r, nr = rho(fx, by, texts)
    lines = ["/* SPDX-License-Identifier: MIT */",
             "/* cost_model.def — the scene compiler's cost model (tools/quality/quality.h), written by",
             " *   tools/quality/cost_model.py model --fixture tests/data/quality/lab.json --write tools/quality/cost_model.def",
             " * from the lab's measurements (make charts). Do not edit.",
             " *",
             " * QUALITY_BASE(target, class, numeric, per_work, scenes): instructions (rp2040: cycles) a frame",
             " *   of the class's base method per unit of work (ray tracer: its rays, primary, reflected and",
             " *   shadow, x objects; rasterizer: pixels written), the geometric mean over `scenes` lab scenes;",
             " *   rp2040: the M0+'s times rho = %.4f (%d variants measured on both)." % (r, nr),
             " * QUALITY_METHOD(target, class, numeric, options, factor, scenes): a candidate method, its cost",
             " *   over the base method's (geometric mean over `scenes` lab scenes); the RP2040 takes the M0+'s.",
             " *   QUALITY_OWN_WORK classes: its work beyond its own render's rays, a pixel (arithmetic mean).",
             " * QUALITY_SHADING(class, shading): the shading the class's lab scenes write (textured classes:",
             " *   a scene shaded otherwise has the lit class's per-pixel lighting added or taken out, whatever",
             " *   the method).",
             " * QUALITY_OWN_WORK(class): a class whose candidates are each rendered first and predicted from",
             " *   their own work: per_work x (the candidate's work + factor x its pixels), at least a tenth of",
             " *   per_work x its work.",
             " */",
             "#ifndef QUALITY_BASE", "#define QUALITY_BASE(target, cls, numeric, per_work, scenes)", "#endif",
             "#ifndef QUALITY_METHOD", "#define QUALITY_METHOD(target, cls, numeric, options, factor, scenes)",
             "#endif", "#ifndef QUALITY_SHADING", "#define QUALITY_SHADING(cls, shading)", "#endif",
             "#ifndef QUALITY_OWN_WORK", "#define QUALITY_OWN_WORK(cls)", "#endif", ""]
    for (t, cls, n), xs in sorted(base.items()):
        lines.append('QUALITY_BASE("%s", "%s", "%s", %.6g, %d)' % (t, cls, n, gmean(xs), len(xs)))
        if t == "m0plus" and n == "fixed":
            lines.append('QUALITY_BASE("rp2040", "%s", "%s", %.6g, %d)' % (cls, n, gmean(xs) * r, len(xs)))
    lines.append("")
    for (t, cls, n, k), xs in sorted(meth.items()):
        lines.append('QUALITY_METHOD("%s", "%s", "%s", "%s", %.6g, %d)' % (t, cls, n, k, term(cls, xs), len(xs)))
    lines.append("")
    for cls in OWN_WORK:
        lines.append('QUALITY_OWN_WORK("%s")' % cls)
    lines.append("")
    for cls, sh in sorted(shade.items()):
        lines.append('QUALITY_SHADING("%s", "%s")' % (cls, sh))
    lines += ["", "#undef QUALITY_BASE", "#undef QUALITY_METHOD", "#undef QUALITY_SHADING", "#undef QUALITY_OWN_WORK",
              ""]
    return "\n".join(lines)


def predictions(fx, by, texts, scene, base, meth, shade):
    """{(target, method key): (predicted, measured, factor predicted,
    factor measured)} of a scene's fixed-point rows on the M0+ and M4F, from
    the terms base, meth (fit's)."""
    labs = {s.name: s for s in lab.LAB}
    info = fx["scenes"][scene]
    cls, n = info["class"], "fixed"
    bk = base_key(labs[scene], texts[scene], info["keys"])
    out = {}
    for (sc, t, nn, k), cost in sorted(by.items()):
        if sc != scene or nn != n or (t, cls, n) not in base or (t, cls, n, k) not in meth:
            continue
        b = by.get((scene, t, n, bk))
        f = term(cls, meth[(t, cls, n, k)])
        work = own_work(fx, scene, n, k) if cls in OWN_WORK else info["work"][n]
        p = predicted(base, meth, shade, t, cls, n, shading_of(texts[scene]), work, f)
        if cls in OWN_WORK:
            # the method's work (its rays and the factor's) from the fitted
            # factor over that from this scene's own: 1 for the base method
            fm = (cost * own_work(fx, scene, n, bk) / b - work) / PIXELS if b else None
            out[(t, k)] = (p, cost, work + f * PIXELS, work + fm * PIXELS if fm is not None else None)
        else:
            out[(t, k)] = (p, cost, f, cost / b if b else None)
    return out


def validate(fx, scenes_dir, log=print):
    """The model's predictions on the scenes it is not fitted on: each held-out
    scene from the committed model (fitted on the others), and every scene
    of a class with two or more from the model fitted on its class's other
    scenes (leave one out). A list of dicts (scene, target, method, predicted,
    measured, error = predicted / measured - 1, factor_error, how, ok)."""
    by, texts = keyed_rows(fx, scenes_dir)
    fit_on = fitted(fx)
    base, meth = fit(fx, by, texts, fit_on)
    out = []
    labs = {s.name for s in lab.LAB}
    for scene, info in sorted(fx["scenes"].items()):
        if scene not in labs:
            continue
        runs = []
        if scene not in fit_on:
            runs.append(("held out", base, meth, class_shading(fx, texts, fit_on)))
        others = {o for o, i in fx["scenes"].items() if o != scene and i["class"] == info["class"]}
        if others:
            # the class's other scenes, and the lit class (whose lighting a textured one borrows) as fitted
            b, m = fit(fx, by, texts, others | {o for o in fit_on if fx["scenes"][o]["class"] == "lit"})
            runs.append(("leave one out", b, m, class_shading(fx, texts, others)))
        for how, b, m, sh in runs:
            ps = predictions(fx, by, texts, scene, b, m, sh)
            for (t, k), (pred, meas, fp, fm) in sorted(ps.items()):
                e = {"scene": scene, "class": info["class"], "how": how, "target": t, "method": k,
                     "predicted": pred, "measured": meas, "error": pred / meas - 1,
                     "factor_error": fp / fm - 1 if fm else None}
                cb = COST_BOUND.get(info["class"], 2.0)
                e["ok"] = how != "held out" or 1 / cb <= pred / meas <= cb
                # the order: no candidate predicted cheaper by more than ORDER_GAP is measured dearer by more
                e["inversions"] = sorted(k2 for (t2, k2), (p2, m2, _, _) in ps.items() if t2 == t and
                                         pred * ORDER_GAP < p2 and meas > m2 * ORDER_GAP)
                e["ok"] = e["ok"] and (how != "held out" or not e["inversions"])
                out.append(e)
    if log:
        log("cost_model: predictions on scenes the model is not fitted on (error = predicted / measured - 1; "
            "factor: the method's cost over the base method's); held out: no two candidates ordered by more than "
            "x%.2f measured the other way by more than x%.2f, every cost within %s" % (
                ORDER_GAP, ORDER_GAP, ", ".join("x%g (%s)" % (b, c) for c, b in sorted(COST_BOUND.items()))))
        groups = {}
        for e in out:
            groups.setdefault((e["how"], e["scene"], e["target"]), []).append(e)
        for (how, scene, t), es in sorted(groups.items()):
            worst = max(es, key=lambda e: abs(math.log(1 + e["error"])))
            fe = [e for e in es if e["factor_error"] is not None]
            wf = max(fe, key=lambda e: abs(math.log(1 + e["factor_error"]))) if fe else None
            base_e = [e for e in es if e["factor_error"] is not None and abs(e["factor_error"]) < 1e-12]
            inv = sum(len(e["inversions"]) for e in es)
            log("  %-13s %-21s %-6s %2d methods: base %+6.1f %%, worst %+6.1f %% (%s), worst factor %s, %d "
                "inversions%s" % (
                how, scene, t, len(es), 100 * base_e[0]["error"] if base_e else float("nan"), 100 * worst["error"],
                worst["method"] or "(as written)",
                "%+.1f %% (%s)" % (100 * wf["factor_error"], wf["method"] or "(as written)") if wf else "-", inv,
                "" if all(e["ok"] for e in es) else "  OUT OF BOUNDS"))
    return out


def fixture_choices(fx, host_sim, scenes):
    """quality.check's choices on the fixture's rows, each animated scene held
    to its stored lowest PSNR over the frames the compiler checks."""
    fpsnr = {n: s["psnr_frames"] for n, s in fx["scenes"].items() if "psnr_frames" in s}
    return quality.check(host_sim, scenes, fx["rows"], log=None, fpsnr=fpsnr)


def choices_table(args):
    """Writes (or checks) the table of choices in a document: the block
    between quality.BEGIN and quality.END."""
    with open(args.fixture) as f:
        fx = json.load(f)
    table = quality.doc_table(fixture_choices(fx, args.host_sim, args.scenes))
    doc = args.write or args.check
    if not doc:
        sys.stdout.write(table)
        return 0
    with open(doc) as f:
        old = f.read()
    new = quality.put_table(old, table)
    if new is None:
        print("cost_model: %s: no single %r ... %r block" % (doc, quality.BEGIN, quality.END), file=sys.stderr)
        return 1
    if args.check:
        if new != old:
            print("cost_model: %s: the table of choices differs from the fixture's (make choices-table)" % doc)
            return 1
        print("cost_model: %s: the table of choices matches %s" % (doc, args.fixture))
        return 0
    with open(doc + ".tmp", "w") as f:
        f.write(new)
    os.replace(doc + ".tmp", doc)
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    a = sub.add_parser("fixture")
    a.add_argument("--pareto", required=True)
    a.add_argument("--host-sim", required=True)
    a.add_argument("--scenes", default="firmware/scenes")
    a.add_argument("--out", required=True)
    m = sub.add_parser("measure")
    m.add_argument("--host-sim", required=True)
    m.add_argument("--build", default="build")
    m.add_argument("--scenes", default="firmware/scenes")
    m.add_argument("--jobs", type=int, default=2)
    m.add_argument("--make", default="make")
    m.add_argument("--out", required=True)
    m.add_argument("--numeric", default="", help="only these numeric modes (comma-separated; default: all)")
    m.add_argument("--only", default="", help="only these lab scenes (comma-separated), the --out fixture's other "
                   "rows kept")
    m.add_argument("--no-rp2040", action="store_true", help="no RP2040 runs (with --only: its rows kept)")
    v = sub.add_parser("validate")
    v.add_argument("--fixture", required=True)
    v.add_argument("--scenes", default="firmware/scenes")
    v.add_argument("--csv")
    w = sub.add_parser("work")
    w.add_argument("--fixture", required=True)
    w.add_argument("--host-sim", required=True)
    w.add_argument("--scenes", default="firmware/scenes")
    c = sub.add_parser("choices", help="the table of choices of docs/charts.md from the fixture's rows")
    c.add_argument("--fixture", required=True)
    c.add_argument("--host-sim", required=True)
    c.add_argument("--scenes", default="firmware/scenes")
    g = c.add_mutually_exclusive_group()
    g.add_argument("--write", metavar="DOC")
    g.add_argument("--check", metavar="DOC")
    b = sub.add_parser("model")
    b.add_argument("--fixture", required=True)
    b.add_argument("--scenes", default="firmware/scenes")
    g = b.add_mutually_exclusive_group()
    g.add_argument("--write")
    g.add_argument("--check")
    args = ap.parse_args()
    if args.cmd == "fixture":
        return make_fixture(args)
    if args.cmd == "measure":
        return measure(args)
    if args.cmd == "work":
        return refresh_work(args)
    if args.cmd == "choices":
        return choices_table(args)
    with open(args.fixture) as f:
        fx = json.load(f)
    if args.cmd == "validate":
        es = validate(fx, args.scenes)
        if args.csv:
            with open(args.csv, "w", newline="") as f:
                w = csv.DictWriter(f, ["scene", "class", "how", "target", "method", "predicted", "measured", "error",
                                       "factor_error", "inversions", "ok"])
                w.writeheader()
                w.writerows(es)
        bad = [e for e in es if not e["ok"]]
        print("cost_model: %d held-out predictions, %d out of bounds" %
              (sum(1 for e in es if e["how"] == "held out"), len(bad)))
        return 1 if bad else 0
    text = model(fx, args.scenes)
    if args.write:
        with open(args.write + ".tmp", "w") as f:
            f.write(text)
        os.replace(args.write + ".tmp", args.write)
    elif args.check:
        with open(args.check) as f:
            if f.read() != text:
                print("cost_model: %s differs from the model of %s (tools/quality/cost_model.py model --fixture %s "
                      "--write %s)" % (args.check, args.fixture, args.fixture, args.check))
                return 1
        print("cost_model: %s matches %s" % (args.check, args.fixture))
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
