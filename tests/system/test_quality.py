#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Methods chosen for an accuracy target (tools/quality; docs/scene-format.md,
"quality").

- the cost model tools/quality/cost_model.def is the one
  tools/quality/cost_model.py makes of the committed lab rows
  (tests/data/quality/lab.json, written by `make charts` as
  out/charts/quality-lab.json);
- on the held-out lab scenes (LabQuality fit = False: one or two per class,
  ray tracer with and without reflections, rasterizer lit and textured),
  which the model is not fitted on, the model orders the candidates as the
  lab measures them on the M0+ and M4F (no two it orders by more than
  cost_model.ORDER_GAP measured the other way by more than that), and every
  predicted cost is within cost_model.COST_BOUND[class] of the measured one
  (tools/quality/cost_model.py validate);
- the ray tracer's unit of work is each candidate's own rays (primary,
  reflected and shadow, x objects): the fixture's work is what host renders
  of its rows' variants give now (cost_model.py work), and the compiler's
  prediction of a ray-traced choice is the model's of that candidate's own
  work;
- for each lab scene (the held-out ones too), target (m0plus, m4f, rp2040)
  and accuracy target of tools/charts/lab.py, the choice meets the target on its own measured image,
  is a variant the lab measured, and costs at most 10 % more than the
  cheapest of the compiler's candidates the lab measured that meets it
  (tools/charts/quality.py; RP2040: the Cortex-M0+ instructions of the same
  variants);
- docs/charts.md's table of choices is the one these choices make
  (`make choices-table`);
- a choice meets its target on the image rendered with it, measured here
  against the double build's exact render (every frame the compiler checks);
- options the scene sets and --numeric stay as given;
- scenec compiles the choice (the emitted options), and host_sim renders the
  same image with the block as with the chosen options written;
- bad input: the scene format's one-line error and exit status 2, no output.
The lab's choices run on HOST_SIM (the optimised build, as make charts), the
rest on ASAN_HOST_SIM (default HOST_SIM).
usage: test_quality.py HOST_SIM SCENEC [ASAN_HOST_SIM]
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "tools", "charts"))
sys.path.insert(0, os.path.join(ROOT, "tools", "quality"))
import cost_model  # noqa: E402
import hostsim  # noqa: E402
import quality  # noqa: E402
import scenetext  # noqa: E402

BALL = os.path.join(ROOT, "tests", "data", "quality", "ball.scene")
FIXTURE = os.path.join(ROOT, "tests", "data", "quality", "lab.json")


def report(name, ok, why=""):
    print("%s %s%s" % ("PASS" if ok else "FAIL", name, "" if ok else ": " + why))


def run(cmd):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=600)


def summary(err):
    m = re.search(r'^quality-summary .*options="([^"]*)" numeric=(\S+) .* psnr=(\S+) ', err, re.M)
    return (m.group(1), m.group(2), math.inf if m.group(3) == "inf" else float(m.group(3))) if m else None


def no_block(text):
    return re.sub(r"^quality \{[^}]*\}\n", "", text, flags=re.M)


def main():
    if len(sys.argv) not in (3, 4):
        print("usage: test_quality.py HOST_SIM SCENEC [ASAN_HOST_SIM]", file=sys.stderr)
        return 2
    host_sim, scenec = sys.argv[1], sys.argv[2]
    lab_host_sim = host_sim
    os.chdir(ROOT)

    r = run([sys.executable, "tools/quality/cost_model.py", "model", "--fixture", FIXTURE,
             "--check", "tools/quality/cost_model.def"])
    report("quality_cost_model_from_fixture", r.returncode == 0, (r.stdout + r.stderr).strip())

    with open(FIXTURE) as f:
        fx = json.load(f)
    held = {}
    for e in cost_model.validate(fx, "firmware/scenes", log=None):
        if e["how"] == "held out":
            held.setdefault((e["scene"], e["target"]), []).append(e)
    classes = {fx["scenes"][sc]["class"] for sc, _ in held}
    report("quality_held_out_classes", {"rt", "rt-reflective", "lit", "textured"} <= classes,
           "held-out scenes' classes: %s" % sorted(classes))
    for (sc, t), es in sorted(held.items()):
        bad = [e for e in es if not e["ok"]]
        report("quality_held_out_%s_%s" % (re.sub(r"\W", "_", sc), t), len(es) >= 3 and not bad,
               "%d methods; " % len(es) + "; ".join("%s predicted %.4g, measured %.4g, measured dearer than %s" % (
                   e["method"] or "(as written)", e["predicted"], e["measured"], e["inversions"]) for e in bad))
    choices = cost_model.fixture_choices(fx, lab_host_sim, "firmware/scenes")
    for e in choices:
        report("quality_choice_%s_%s_%g" % (re.sub(r"\W", "_", e["scene"]), e["target"], e["min_psnr"]), e["ok"],
               e["why"])
    # docs/charts.md's table of choices is these choices' (make choices-table)
    with open("docs/charts.md") as f:
        doc = f.read()
    new = quality.put_table(doc, quality.doc_table(choices))
    report("quality_choices_table_current", new == doc,
           "docs/charts.md's table of choices differs from the fixture's choices (make choices-table)" if new
           else "docs/charts.md has no choices-table block")

    # the fixture's work, scenes' and ray-traced rows', recomputed from host renders
    with open(FIXTURE) as f:
        fresh = json.load(f)
    stored = json.loads(json.dumps(fresh))
    cost_model.add_work(lab_host_sim, "firmware/scenes", fresh)
    stale = ["%s %s %s %r: %s, now %s" % (a["scene"], a["target"], a["numeric"], a["options"], a.get("work"), b["work"])
             for a, b in zip(stored["rows"], fresh["rows"]) if a.get("work") != b["work"]]
    stale += ["%s: %s, now %s" % (n, i["work"], fresh["scenes"][n]["work"]) for n, i in stored["scenes"].items()
              if i["work"] != fresh["scenes"][n]["work"]]
    own = sum(1 for r in fresh["rows"] if r["work"])
    report("quality_fixture_work_current", not stale and own > 0,
           "%d ray-traced rows with work; differs from host renders (make cost-model-refit): %s" % (own, stale[:3]))
    # a ray-traced choice's prediction (host_sim) is the model's of the candidate's own work
    labs = {s.name: s for s in cost_model.lab.LAB}
    preds = {(e["scene"], e["target"], e["method"]): e["predicted"] for es in held.values() for e in es}
    checked = []
    for e in choices:
        s = labs[e["scene"]]
        if s.quality.cls not in cost_model.OWN_WORK or e["target"] == "rp2040" or s.quality.fit:
            continue
        with open("firmware/scenes/%s.scene" % s.name) as f:
            text = f.read()
        key = cost_model.lab.method_key({"options": " ".join(s.quality.apply + e["options"].split()), "strip": 16,
                                         "variant": ""}, s, text, fx["scenes"][s.name]["keys"])
        p = preds.get((s.name, e["target"], key))
        checked.append((s.name, e["target"], key, e["predicted"], p))
    bad = [c for c in checked if c[4] is None or abs(c[3] / c[4] - 1) > 1e-3]
    report("quality_own_work_predictions", len(checked) >= 6 and not bad,
           "%d choices; host_sim's prediction against the model's: %s" % (len(checked), bad[:3]))

    host_sim = sys.argv[3] if len(sys.argv) == 4 else host_sim
    with tempfile.TemporaryDirectory(prefix="cgfs-test-quality-") as tmp:
        with open(BALL) as f:
            ball = f.read()
        # the block's choice, its own image against double exact
        r = run([host_sim, "--scene", BALL, "--panel", "none", "--size", "240x240",
                 "--out-rgb888", os.path.join(tmp, "b.ppm")])
        s = summary(r.stderr)
        ok = r.returncode == 0 and s is not None
        report("quality_block_renders", ok, r.stderr.strip()[-300:])
        if ok:
            ref = hostsim.render(host_sim, scenetext.apply(no_block(ball), ["adaptive_subsample=0", "subsample=1"]),
                                 "double")[1]
            got = hostsim._read_ppm(os.path.join(tmp, "b.ppm"))
            p = hostsim.psnr(got, ref)
            report("quality_block_meets_target", p >= 50, "%.2f dB < 50" % p)
            # the same image as the scene with the chosen options written, which prints no choice
            chosen = scenetext.apply(no_block(ball), s[0].split())
            path = os.path.join(tmp, "chosen.scene")
            with open(path, "w") as f:
                f.write(chosen)
            r2 = run([host_sim, "--scene", path, "--panel", "none", "--size", "240x240",
                      "--out-rgb888", os.path.join(tmp, "c.ppm")])
            same = r2.returncode == 0 and hostsim._read_ppm(os.path.join(tmp, "c.ppm")) == got
            report("quality_block_is_the_choice", same and "quality" not in r2.stderr, r2.stderr[-200:])
            # scenec compiles the choice, for the block's target (rp2040)
            outc = os.path.join(tmp, "ball.c")
            r3 = run([scenec, "-o", outc, BALL])
            ok3 = r3.returncode == 0 and summary(r3.stdout) and summary(r3.stdout)[0] == s[0]
            if ok3:
                with open(outc) as f:
                    c = f.read()
                for o in s[0].split():
                    k, v = o.split("=")
                    ok3 = ok3 and re.search(r"\.%s = %s\b" % (k, v), c) is not None
                ok3 = ok3 and "the quality block at" in r3.stdout and "RP2040" in r3.stdout
            report("quality_scenec_compiles_the_choice", bool(ok3), (r3.stdout + r3.stderr)[-300:])

            # the work memory measured on the target for the scene as written does not hold the
            # chosen methods': this host's (an upper bound) instead
            r4 = run([scenec, "--target-work", "1000:1000", "-o", outc, BALL])
            with open(outc[:-1] + "h") as f:
                h = f.read()
            ok4 = r4.returncode == 0 and "instead of --target-work" in r4.stdout and \
                re.search(r"WORK_SIZE +1000\b", h) is None
            report("quality_scenec_work_of_the_choice", ok4, (r4.stdout + r4.stderr)[-300:])

        # every frame meets the target: the textured cube's choice for 32 dB on the M0+ (perspective_step
        # = 8 measures 32.04 dB on frame 3 but 31.55 on frame 2), the lit cube's, Phong shaded, for 45 dB
        # (fast Phong measures 46.04 dB on frame 3 but 41.30 on frame 7)
        for name, db, ref in (("bench/cube-textured", 32, ["perspective_step=1"]),
                              ("bench/cube-gouraud", 45, ["perspective_step=1", "lighting=exact"])):
            text = open("firmware/scenes/%s.scene" % name).read()
            if name == "bench/cube-gouraud":
                text = scenetext.apply(text, ["shading=phong"])
            c = quality.choose(host_sim, text, "m0plus", db)
            vt = scenetext.apply(text, c["options"].split())
            rt = scenetext.apply(text, ref)
            n = quality.scene_frames(text)
            ps = [hostsim.psnr(hostsim.render(host_sim, vt, "fixed", frames=f + 1)[1],
                               hostsim.render(host_sim, rt, "double", frames=f + 1)[1]) for f in range(n)]
            report("quality_every_frame_meets_target_%s" % re.sub(r"\W", "_", name), min(ps) >= db,
                   "%s: %.2f dB on frame %d" % (c["options"], min(ps), ps.index(min(ps))))

        # a key the scene sets stays; --numeric stays
        rt05 = scenetext.apply(open("firmware/scenes/book/raytracer-05.scene").read(), ["adaptive_subsample=2"])
        path = os.path.join(tmp, "rt05.scene")
        with open(path, "w") as f:
            f.write(rt05)
        r = run([host_sim, "--scene", path, "--panel", "none", "--size", "240x240", "--min-psnr", "55",
                 "--target", "m4f"])
        s = summary(r.stderr)
        report("quality_keeps_scene_option", r.returncode == 0 and s and "adaptive_subsample" not in s[0]
               and "kept as the scene sets it: adaptive_subsample" in r.stderr, r.stderr[-300:])
        r = run([host_sim, "--scene", "firmware/scenes/book/raytracer-02.scene", "--panel", "none", "--size",
                 "240x240", "--numeric", "float", "--min-psnr", "45", "--target", "m4f"])
        s = summary(r.stderr)
        report("quality_keeps_numeric", r.returncode == 0 and s and s[1] == "float" and s[2] >= 45, r.stderr[-300:])

        # no target: no choice
        r = run([host_sim, "--scene", "firmware/scenes/book/raytracer-02.scene", "--panel", "none", "--size",
                 "64x64", "--stats"])
        report("quality_none_without_target", r.returncode == 0 and "quality" not in r.stderr + r.stdout,
               r.stderr[-200:])

        # bad input
        cases = [("psnr = 50", "psnr = fifty", "quality psnr must be a number"),
                 ("target = rp2040", "target = rp2400", "quality target: unknown value 'rp2400'"),
                 ("psnr = 50", "psnr = 500", "quality psnr must be in 1 .. 200"),
                 ("psnr = 50 target = rp2040", "target = rp2040", "quality: missing 'psnr'"),
                 ("psnr = 50", "psnr = 50 speed = 3", "speed")]
        for i, (old, new, want) in enumerate(cases):
            path = os.path.join(tmp, "bad%d.scene" % i)
            with open(path, "w") as f:
                f.write(ball.replace(old, new))
            r = run([host_sim, "--scene", path, "--panel", "none"])
            line = r.stderr.strip()
            ok = r.returncode == 2 and re.match(r"^%s:8:\d+: error: .*%s" % (re.escape(path), re.escape(want)), line)
            outc = os.path.join(tmp, "bad%d.c" % i)
            r2 = run([scenec, "-o", outc, path])
            ok = ok and r2.returncode == 2 and r2.stderr.strip() == line and not os.path.exists(outc)
            report("quality_bad_block_%d" % i, bool(ok), line + " | " + r2.stderr.strip())
        r = run([host_sim, "--scene", BALL, "--panel", "none", "--min-psnr", "abc"])
        report("quality_bad_min_psnr", r.returncode == 2 and "bad --min-psnr 'abc'" in r.stderr, r.stderr)
        r = run([host_sim, "--scene", BALL, "--panel", "none", "--target", "m5"])
        report("quality_bad_target", r.returncode == 2 and "unknown --target 'm5'" in r.stderr, r.stderr)
        r = run([host_sim, "--scene", "firmware/scenes/book/raytracer-02.scene", "--panel", "none", "--target", "m4f"])
        report("quality_target_needs_psnr", r.returncode == 2 and "--target needs --min-psnr" in r.stderr, r.stderr)
        outc = os.path.join(tmp, "none.c")
        r = run([scenec, "--target", "stm32f411", "--min-psnr", "40", "-o", outc, BALL])
        report("quality_scenec_no_model", r.returncode == 2 and "no cost model for --target stm32f411" in r.stderr
               and not os.path.exists(outc), r.stderr)
        path = os.path.join(tmp, "unreachable.scene")
        with open(path, "w") as f:
            f.write(ball.replace("psnr = 50", "psnr = 150"))
        r = run([host_sim, "--scene", path, "--panel", "none", "--size", "120x120"])
        report("quality_unreachable", r.returncode == 2 and re.search(r":8:1: error: no method reaches 150.0 dB on "
                                                                      r"rp2040: the most accurate", r.stderr),
               r.stderr[-300:])
    return 0


if __name__ == "__main__":
    sys.exit(main())
