#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Adds size and accuracy fields to the scene lines of results.jsonl.

Every `scene:NAME` measurement gets `width` and `height` (from a `@WxH` suffix
of the name, else the 240x240 panel size the benchmarks render at) and, when
firmware/scenes/NAME.scene exists, the accuracy of that scene in that numeric
mode against the double build of the same scene at the same size:
`psnr` (dB, null when identical), `ssim`, `max_err`, `pct_diff`, from
`host_sim --compare double`. Accuracy is of the scene as written (its own
options), stated in `accuracy_of`; a variant named KEY=VALUE (a rasterizer
method, e.g. perspective_step=32 or lighting=vertex) is measured on the scene
with that option set (in the scene's rasterizer or raytracer block; several
options joined by commas, KEY=VALUE,KEY=VALUE, are all set). A line that
names its image's `num_frac` (bench_raytracer's) is measured at that
format, so the accuracy is that of the image whose cost it states. A
variant named *_pass measures one pass of the progressive display, not an
image: it gets no accuracy. The reference is always the double build's
exact method (host_sim --compare). The file is rewritten atomically.
usage: accuracy.py RESULTS.jsonl HOST_SIM [SCENES_DIR]
"""
import json
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "charts"))
from stability import host_sim_compare  # noqa: E402


def set_option(text, opt):
    """The scene text with `KEY = VALUE` set: replaced where the key is
    written, else added to the rasterizer (or raytracer) block."""
    k, _, v = opt.partition("=")
    if re.search(r"^\s*%s\s*=" % k, text, re.M):
        return re.sub(r"^(\s*%s\s*=\s*)\S+" % k, r"\g<1>%s" % v, text, count=1, flags=re.M)
    block = "raytracer" if re.search(r"^renderer\s*=\s*raytracer", text, re.M) else "rasterizer"
    if re.search(r"^%s\s*\{" % block, text, re.M):
        return re.sub(r"^(%s\s*\{)" % block, r"\1 %s = %s" % (k, v), text, count=1, flags=re.M)
    return text + "\n%s { %s = %s }\n" % (block, k, v)


def compare_variant(host_sim, path, numeric, w, h, opt, num_frac=None):
    """host_sim --compare double of the scene, with `KEY = VALUE` added to
    its rasterizer (or raytracer) block when opt is given; fixed point at
    num_frac when given (the format the measured image was built at), else
    at the scene's own."""
    size = "%dx%d" % (w, h)
    if not opt:
        return host_sim_compare(host_sim, path, numeric, size, num_frac)
    with open(path) as f:
        text = f.read()
    for one in opt.split(","):
        text = set_option(text, one)
    # next to the scene: the files it names (textures, meshes) are relative to it
    fd, tmp = tempfile.mkstemp(prefix=".accuracy-", suffix=".scene", dir=os.path.dirname(os.path.abspath(path)))
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        return host_sim_compare(host_sim, tmp, numeric, size, num_frac)
    finally:
        os.unlink(tmp)


def main():
    results, host_sim = sys.argv[1], sys.argv[2]
    scenes = sys.argv[3] if len(sys.argv) > 3 else "firmware/scenes"
    with open(results) as f:
        lines = [json.loads(l) for l in f if l.strip()]
    cache = {}
    for l in lines:
        what = l.get("what", "")
        if not what.startswith("scene:"):
            continue
        name = what[len("scene:"):]
        m = re.search(r"@(\d+)x(\d+)$", name)
        if m:
            name = name[:m.start()]
        l.setdefault("width", int(m.group(1)) if m else 240)
        l.setdefault("height", int(m.group(2)) if m else 240)
        path = os.path.join(scenes, name + ".scene")
        numeric = l.get("numeric", "fixed")
        if not os.path.exists(path) or numeric not in ("fixed", "float", "double"):
            continue
        variant = l.get("variant", "default")
        if variant.endswith("_pass"):
            continue
        opt = variant if re.match(r"^[a-z_]+=[a-z0-9_]+(,[a-z_]+=[a-z0-9_]+)*$", variant) else None
        frac = l.get("num_frac") if numeric == "fixed" else None
        key = (path, numeric, l["width"], l["height"], opt, frac)
        if key not in cache:
            try:
                cache[key] = compare_variant(host_sim, path, numeric, l["width"], l["height"], opt, frac)
            except RuntimeError as e:
                print("accuracy: %s: %s" % (path, e), file=sys.stderr)
                cache[key] = None
        s = cache[key]
        if s is None:
            continue
        for k in ("psnr", "ssim", "max_err", "pct_diff"):
            l[k] = s.get(k)
        l["accuracy_of"] = ("scene with %s, vs double exact" % opt) if opt else "scene as written, vs double exact"
    tmp = results + ".tmp"
    with open(tmp, "w") as f:
        for l in lines:
            f.write(json.dumps(l) + "\n")
    os.replace(tmp, results)
    print("accuracy: %d scene measurements, %d scene/mode/size renders compared" %
          (sum(1 for l in lines if l.get("what", "").startswith("scene:")), len(cache)))


if __name__ == "__main__":
    main()
