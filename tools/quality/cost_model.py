#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The scene compiler's cost model (tools/quality/cost_model.def) from the
speed/accuracy lab's measurements (`make charts`, out/charts/pareto.csv).

  cost_model.py fixture --pareto out/charts/pareto.csv --host-sim build/host_sim --out tests/data/quality/lab.json
      the lab's rows the model and its test need, and each lab scene's work
      (host_sim --stats of the scene text the compiler chooses for, in each
      numeric mode: rays x objects for the ray tracer, pixels written for
      the rasterizer, the mean over the frames tools/quality checks), and for
      a scene that animates each candidate's lowest PSNR over those frames
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
lab's scenes of that class. RP2040 cycles: the Cortex-M0+ factors, and
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
COLS = ["scene", "variant", "target", "cost", "psnr", "frontier", "unit", "numeric", "format", "options", "strip"]


def scene_work(host_sim, text, numeric):
    """Mean work a frame over the frames checked (quality.c render_text)."""
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
            ws.append(st["rays"] * max(objs, 1) if st["rays"] else st["pixels_written"])
    return sum(ws) / len(ws)


def make_fixture(args):
    with open(args.pareto) as f:
        rows = [{k: r[k] for k in COLS} for r in csv.DictReader(f)]
    out = {"scenes": {}, "rows": rows}
    for s in lab.LAB:
        with open(os.path.join(args.scenes, s.name + ".scene")) as f:
            text = f.read()
        qt = s.quality.text(text)
        work = {n: scene_work(args.host_sim, qt, n) for n in ("fixed", "float", "double")}
        out["scenes"][s.name] = {"class": s.quality.cls, "work": work, "keys": lab.variant_keys(rows, s.name)}
    for name, ps in quality.frames_psnr(args.host_sim, args.scenes, rows).items():
        out["scenes"][name]["psnr_frames"] = {k: round(v, 3) for k, v in ps.items()}
    with open(args.out + ".tmp", "w") as f:
        json.dump(out, f, indent=0, sort_keys=True)
        f.write("\n")
    os.replace(args.out + ".tmp", args.out)
    print("cost_model: %d rows, %d scenes -> %s" % (len(rows), len(out["scenes"]), args.out))


def gmean(xs):
    return math.exp(sum(math.log(x) for x in xs) / len(xs))


def keyed_rows(fx, scenes_dir):
    """(scene, target, numeric, method key) -> cost, for the rows the model uses."""
    by = {}
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


def model(fx, scenes_dir):
    by, texts = keyed_rows(fx, scenes_dir)
    labs = {s.name: s for s in lab.LAB}
    base, meth = {}, {}
    for (scene, t, n, k), cost in sorted(by.items()):
        s = labs[scene]
        info = fx["scenes"][scene]
        bk = base_key(s, texts[scene], info["keys"])
        b = by.get((scene, t, n, bk))
        if b is None:
            continue
        cls = info["class"]
        if k == bk:
            base.setdefault((t, cls, n), []).append(b / info["work"][n])
        meth.setdefault((t, cls, n, k), []).append(cost / b)
    r, nr = rho(fx, by, texts)
    lines = ["/* SPDX-License-Identifier: MIT */",
             "/* cost_model.def — the scene compiler's cost model (tools/quality/quality.h), written by",
             " *   tools/quality/cost_model.py model --fixture tests/data/quality/lab.json --write tools/quality/cost_model.def",
             " * from the lab's measurements (make charts). Do not edit.",
             " *",
             " * QUALITY_BASE(target, class, numeric, per_work, scenes): instructions (rp2040: cycles) a frame",
             " *   of the class's base method per unit of work (rays x objects; pixels written), the geometric",
             " *   mean over `scenes` lab scenes; rp2040: the M0+'s times rho = %.4f (%d variants measured on both)." % (r, nr),
             " * QUALITY_METHOD(target, class, numeric, options, factor, scenes): a candidate method, its cost",
             " *   over the base method's (geometric mean over `scenes` lab scenes); the RP2040 takes the M0+'s.",
             " */",
             "#ifndef QUALITY_BASE", "#define QUALITY_BASE(target, cls, numeric, per_work, scenes)", "#endif",
             "#ifndef QUALITY_METHOD", "#define QUALITY_METHOD(target, cls, numeric, options, factor, scenes)",
             "#endif", ""]
    for (t, cls, n), xs in sorted(base.items()):
        lines.append('QUALITY_BASE("%s", "%s", "%s", %.6g, %d)' % (t, cls, n, gmean(xs), len(xs)))
        if t == "m0plus" and n == "fixed":
            lines.append('QUALITY_BASE("rp2040", "%s", "%s", %.6g, %d)' % (cls, n, gmean(xs) * r, len(xs)))
    lines.append("")
    for (t, cls, n, k), xs in sorted(meth.items()):
        lines.append('QUALITY_METHOD("%s", "%s", "%s", "%s", %.6g, %d)' % (t, cls, n, k, gmean(xs), len(xs)))
    lines += ["", "#undef QUALITY_BASE", "#undef QUALITY_METHOD", ""]
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    a = sub.add_parser("fixture")
    a.add_argument("--pareto", required=True)
    a.add_argument("--host-sim", required=True)
    a.add_argument("--scenes", default="firmware/scenes")
    a.add_argument("--out", required=True)
    b = sub.add_parser("model")
    b.add_argument("--fixture", required=True)
    b.add_argument("--scenes", default="firmware/scenes")
    g = b.add_mutually_exclusive_group()
    g.add_argument("--write")
    g.add_argument("--check")
    args = ap.parse_args()
    if args.cmd == "fixture":
        return make_fixture(args)
    with open(args.fixture) as f:
        fx = json.load(f)
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
