# SPDX-License-Identifier: MIT
"""The scene compiler's choices for accuracy targets, on the lab's scenes.

For each lab scene with a LabQuality (lab.py), each target (m0plus, m4f,
rp2040) and each of its accuracy targets, host_sim --min-psnr DB --target T
chooses the methods (tools/quality) for the scene text the lab gives it; the
choice is found among the lab's rows by its method (lab.method_key) and
checked against the cheapest of the compiler's candidates the lab measured
that meets the target. The PSNR a candidate is held to is the compiler's
own: the lowest over the frames it checks (quality.c pick_frames; frame 0
alone for a still scene, where it is the lab's psnr column).

RP2040: the lab measures only the variants the firmware's images run, so a
choice is checked there against the Cortex-M0+ instructions of the same
variants (the cost model's RP2040 cycles are the M0+'s times one constant,
rho, which orders them the same); where rp2040js measured the chosen
variant, its row is marked too.
"""
import math
import os
import re
import subprocess
import tempfile

import hostsim
import lab
import scenetext

TARGETS = (("m0plus", "m0plus-qemu"), ("m4f", "m4f-qemu"), ("rp2040", "rp2040-sim"))
TARGETS_LAB = dict(TARGETS)
LIMIT = 1.10   # a choice may cost this much more than the cheapest candidate that meets the target


FRAMES = 16   # quality.c QUALITY_FRAMES


def frames_checked(n):
    """The frames tools/quality renders (quality.c pick_frames): every one up
    to FRAMES, else FRAMES evenly spaced, the first and the last among them."""
    n = max(n, 1)
    return list(range(n)) if n <= FRAMES else [i * (n - 1) // (FRAMES - 1) for i in range(FRAMES)]


def scene_frames(text):
    toks = scenetext._tokens(text)
    for i, (_, _, t) in enumerate(toks):
        if t == "frames" and i + 2 < len(toks) and toks[i + 1][2] == "=":
            return int(toks[i + 2][2])
    return 1


def choose(host_sim, text, target, db, size="240x240"):
    """host_sim's choice: {options, predicted, psnr, num_frac, candidates, rendered, report}."""
    with tempfile.TemporaryDirectory(prefix="cgfs-quality-") as tmp:
        path = os.path.join(tmp, "s.scene")
        with open(path, "w") as f:
            f.write(text)
        r = subprocess.run([host_sim, "--scene", path, "--panel", "none", "--size", size, "--min-psnr", str(db),
                            "--target", target], capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        raise RuntimeError("host_sim --min-psnr %s --target %s: %s" % (db, target, r.stderr.strip().splitlines()[-1:]))
    m = re.search(r'^quality-summary .*options="([^"]*)" numeric=(\S+) num_frac=(\d+) predicted=(\d+) psnr=(\S+) '
                  r'candidates=(\d+) rendered=(\d+)$', r.stderr, re.M)
    if not m:
        raise RuntimeError("host_sim printed no quality-summary line")
    return {"options": m.group(1), "numeric": m.group(2), "num_frac": int(m.group(3)),
            "predicted": float(m.group(4)), "psnr": math.inf if m.group(5) == "inf" else float(m.group(5)),
            "candidates": int(m.group(6)), "rendered": int(m.group(7)),
            "report": [line for line in r.stderr.splitlines() if line.startswith("quality:")]}


def allowed(key, s, qt):
    """Whether the compiler considers the method `key` for the scene text qt
    (quality.c: no change to a key the scene sets; shadows kept)."""
    opts = key.split()
    shadows = s.quality.cls == "shadows"
    if shadows and "shadows=off" in opts and "shadow_volumes=on" not in opts:
        return False
    for o in opts:
        k, v = o.split("=", 1)
        if shadows and k in ("shadows", "shadow_volumes"):
            continue
        w = scenetext.written(qt, k)
        if w is not None and w != v:
            return False
    return True


def frame_psnr(host_sim, s, text, key, cache):
    """The lowest PSNR over the frames checked of method `key` (fixed point,
    the scene's own format) against the lab's reference."""
    qt = s.quality.text(text)
    frames = frames_checked(scene_frames(text))
    vt = scenetext.apply(qt, key.split())
    ref_text = scenetext.apply(text, s.reference)
    worst = math.inf
    for f in frames:
        rk = ("ref", s.name, f)
        if rk not in cache:
            cache[rk] = hostsim.render(host_sim, ref_text, "double", frames=f + 1)[1]
        rgb = hostsim.render(host_sim, vt, "fixed", frames=f + 1)[1]
        worst = min(worst, hostsim.psnr(rgb, cache[rk]))
    return worst


def row_psnr(r):
    return math.inf if r["psnr"] in (None, "", "inf") else float(r["psnr"])


def candidates(rows, s, text, target="m0plus-qemu"):
    """The lab's rows of the methods the compiler considers for the scene on
    a target, by method key (fixed point, the scene's own format, 16 rows)."""
    qt = s.quality.text(text)
    keys = lab.variant_keys(rows, s.name)
    cands = {}
    for r in rows:
        if r["scene"] != s.name or r["target"] != target or r["numeric"] != "fixed":
            continue
        k = lab.method_key(r, s, text, keys)
        if k is not None and allowed(k, s, qt):
            cands.setdefault(k, r)
    return cands


def frames_psnr(host_sim, scenes_dir, rows):
    """{scene: {method key: lowest PSNR over the frames checked}} of the lab
    scenes that animate (a still scene's is the lab's psnr column)."""
    out, cache = {}, {}
    for s in lab.LAB:
        if not s.quality:
            continue
        with open(os.path.join(scenes_dir, s.name + ".scene")) as f:
            text = f.read()
        if scene_frames(text) > 1:
            out[s.name] = {k: frame_psnr(host_sim, s, text, k, cache) for k in sorted(candidates(rows, s, text))}
    return out


def check(host_sim, scenes_dir, rows, log=print, fpsnr=None):
    """Every choice: a list of dicts (the table of choices), with `ok` and
    `why`; sets rows' chosen_for. rows: the lab's (pareto.csv) rows; fpsnr:
    frames_psnr's (computed when not given)."""
    if fpsnr is None:
        fpsnr = frames_psnr(host_sim, scenes_dir, rows)
    for r in rows:
        r["chosen_for"] = ""
    out = []
    for s in lab.LAB:
        if not s.quality:
            continue
        with open(os.path.join(scenes_dir, s.name + ".scene")) as f:
            text = f.read()
        qt = s.quality.text(text)
        keys = lab.variant_keys(rows, s.name)
        for name, tname in TARGETS:
            cands = candidates(rows, s, text, "m0plus-qemu" if name == "rp2040" else tname)
            ps = {k: fpsnr[s.name].get(k, -math.inf) if s.name in fpsnr else row_psnr(r) for k, r in cands.items()}
            for db in s.quality.targets:
                c = choose(host_sim, qt, name, db)
                key = lab.method_key({"options": " ".join(s.quality.apply + c["options"].split()), "strip": 16,
                                      "variant": ""}, s, text, keys)
                got = cands.get(key)
                meeting = [(float(r["cost"]), k) for k, r in cands.items() if ps[k] >= db]
                best = min(meeting) if meeting else None
                e = {"scene": s.name, "target": name, "min_psnr": db, "options": c["options"],
                     "predicted": c["predicted"], "psnr": c["psnr"], "rendered": c["rendered"],
                     "candidates": c["candidates"], "measured": float(got["cost"]) if got else None,
                     "unit": "cycles" if name == "rp2040" else "instructions",
                     "best": best[0] if best else None, "best_options": best[1] if best else None}
                if name == "rp2040":
                    e["unit"] = "M0+ instructions"
                    for r in rows:
                        if r["scene"] == s.name and r["target"] == tname and \
                                lab.method_key(r, s, text, keys, board=True) == key:
                            r["chosen_for"] = (r["chosen_for"] + " %g" % db).strip()
                            e["rp2040_cycles"] = float(r["cost"])
                elif got:
                    got["chosen_for"] = (got["chosen_for"] + " %g" % db).strip()
                why = []
                if c["psnr"] < db:
                    why.append("its measured PSNR %.2f is below %g" % (c["psnr"], db))
                if not got:
                    why.append("the lab has no row of the chosen method %r" % key)
                elif best and float(got["cost"]) > LIMIT * best[0]:
                    why.append("it costs %.4g, more than %.2f x the cheapest candidate meeting %g dB (%s, %.4g)"
                               % (float(got["cost"]), LIMIT, db, best[1], best[0]))
                if got and ps[key] < db:
                    why.append("the lab measures it at %.2f dB" % ps[key])
                e["ok"], e["why"] = not why, "; ".join(why)
                out.append(e)
                if log:
                    log("quality: %s %s >= %g dB: %s, predicted %.4g, measured %s, %s%s" % (
                        s.name, name, db, c["options"] or "(as written)", c["predicted"],
                        "%.4g" % e["measured"] if e["measured"] else "-",
                        "%.1f dB" % c["psnr"] if not math.isinf(c["psnr"]) else "identical",
                        "" if e["ok"] else "  FAILS: " + e["why"]))
    return out


COLUMNS = ["scene", "target", "min_psnr", "options", "predicted", "measured", "unit", "psnr", "best", "best_options",
           "rp2040_cycles", "ok", "why"]


BEGIN = "<!-- begin choices-table (tools/quality/cost_model.py choices) -->"
END = "<!-- end choices-table -->"


def _m(x):
    return "%.3g M" % (x / 1e6) if x is not None else "-"


def doc_table(choices):
    """The table of choices of docs/charts.md ("The choices"), one row per
    scene and run of accuracy targets whose M0+ and M4F choices agree in
    every column: options, predicted and measured costs (millions of
    instructions a frame) and the compiler's measured PSNR. choices: check()'s."""
    fit = {s.name: s.quality.fit for s in lab.LAB if s.quality}
    by = {}
    for e in choices:
        by.setdefault((e["scene"], e["min_psnr"]), {})[e["target"]] = e
    rows = []
    for (scene, db), t in sorted(by.items(), key=lambda kv: (not fit[kv[0][0]], [s.name for s in lab.LAB].index(
            kv[0][0]), kv[0][1])):
        m0, m4 = t.get("m0plus"), t.get("m4f")
        if not m0 or not m4:
            continue
        if m0["options"] == m4["options"]:
            opts = "`%s`" % m0["options"] if m0["options"] else "as written"
        else:
            opts = "M0+ %s, M4F %s" % tuple("`%s`" % o if o else "as written" for o in (m0["options"], m4["options"]))
        psnr = [e["psnr"] for e in (m0, m4)]
        ps = "/".join(sorted({"identical" if math.isinf(p) else "%.1f dB" % p for p in psnr}))
        cells = [opts, "%s / %s" % (_m(m0["predicted"]), _m(m0["measured"])),
                 "%s / %s" % (_m(m4["predicted"]), _m(m4["measured"])), ps]
        name = scene if fit[scene] else scene + " (held out)"
        if rows and rows[-1][0] == name and rows[-1][2:] == cells:
            rows[-1][1].append(db)
        else:
            rows.append([name, [db]] + cells)
    out = ["| scene | target dB | chosen (M0+ and M4F) | M0+ predicted / measured | M4F predicted / measured | PSNR |",
           "|---|---|---|---|---|---|"]
    for r in rows:
        out.append("| %s | %s | %s |" % (r[0], ", ".join("%g" % d for d in r[1]), " | ".join(r[2:])))
    return "\n".join(out) + "\n"


def put_table(doc, table):
    """doc's text with the block between BEGIN and END replaced by table;
    None when the markers are not there once each, in order."""
    i, j = doc.find(BEGIN + "\n"), doc.find(END)
    if i < 0 or j < i or doc.count(BEGIN) != 1 or doc.count(END) != 1:
        return None
    return doc[:i + len(BEGIN) + 1] + table + doc[j:]
