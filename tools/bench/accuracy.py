#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Adds size and accuracy fields to the scene lines of results.jsonl.

Every `scene:NAME` measurement gets `width` and `height` (as its image
states them, else from a `@WxH` suffix of the name, else the 240x240 panel
size the benchmarks render at). A row whose image states what it rendered
(tools/bench/bench.h, bench_frame_line: `scene`, `options`, `width`,
`height`, `strip_rows`, `frames`, `num_frac` and `frame_checksum`, the
checksum of the last frame it rendered) gets the accuracy of exactly that
frame against the double build: host_sim renders firmware/scenes/SCENE.scene
with the row's options set (KEY=VALUE of the scene's rasterizer or raytracer
block, texture.KEY=VALUE on every texture; comma-separated), at its size,
strips and frames, in its numeric mode and (fixed point) its format, with
--compare double --stats, and its checksum of the frame it compared must be
the row's frame_checksum. Then the row gets `psnr` (dB, null when
identical), `ssim`, `max_err`, `pct_diff`, `accuracy_checksum` (the
checksum of the frame host_sim compared: equal to frame_checksum) and
`accuracy_of` (what was compared). The reference is always the double
build's exact methods (host_sim --compare).

A row whose image rendered another frame than host_sim's (the checksums
differ) gets no accuracy and `accuracy_error` instead, as does a row that
states options but no checksum; each is named on stderr and the exit status
is 1 (after the file is written). A row that states no options (a pass of
the progressive display) gets no accuracy. A row of the emulated RP2040
(tools/rp2040sim --json) whose `what` is a scene file gets the accuracy of
that scene as written at the row's format, up to its `frame` (with
--average, the run's first frame), checked against its frame_checksum the
same way.
Accuracy fields from an earlier run are dropped first. The file is
rewritten atomically.
usage: accuracy.py RESULTS.jsonl HOST_SIM [SCENES_DIR]
"""
import json
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "charts"))
from stability import host_sim_compare  # noqa: E402

FIELDS = ("psnr", "ssim", "max_err", "pct_diff")
ADDED = FIELDS + ("accuracy_of", "accuracy_checksum", "accuracy_error")


def block_span(text, name):
    """(start, end) of the text inside `name { ... }` at the start of a
    line (braces nested), or None."""
    m = re.search(r"^%s\s*\{" % name, text, re.M)
    if not m:
        return None
    depth, i = 1, m.end()
    while i < len(text) and depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    if depth:
        raise ValueError("%s block not closed" % name)
    return m.end(), i - 1


def set_in(body, key, value):
    """A block's text with `key = value` set: every setting of key taken out,
    the new one put first."""
    body = re.sub(r"(?<![\w.])%s\s*=\s*[^\s}]+" % re.escape(key), "", body)
    return " %s = %s %s" % (key, value, body)


def set_option(text, opt):
    """The scene text with one option set: KEY=VALUE in the renderer's block
    (rasterizer or raytracer, added when the scene has none), or
    texture.KEY=VALUE in every texture."""
    k, eq, v = opt.partition("=")
    if not eq or not re.match(r"^[a-z_.]+$", k) or not re.match(r"^[A-Za-z0-9_.+-]+$", v):
        raise ValueError("option '%s' is not KEY=VALUE" % opt)
    if k.startswith("texture."):
        key = k[len("texture."):]
        n = [0]

        def one(m):
            n[0] += 1
            return m.group(1) + set_in(m.group(2), key, v) + "}"
        text = re.sub(r"^(\s*texture\s*\{)([^{}]*)\}", one, text, flags=re.M)
        if not n[0]:
            raise ValueError("option '%s': the scene has no texture" % opt)
        return text
    block = "raytracer" if re.search(r"^renderer\s*=\s*raytracer", text, re.M) else "rasterizer"
    span = block_span(text, block)
    if span is None:
        return text + "\n%s { %s = %s }\n" % (block, k, v)
    a, b = span
    return text[:a] + set_in(text[a:b], k, v) + text[b:]


def compare_variant(host_sim, path, numeric, w, h, options, num_frac=None, frames=None, strip_rows=None):
    """host_sim --compare double --stats of the scene with `options` (a
    comma-separated KEY=VALUE list; "" the scene as written): the last
    frame's object."""
    size = "%dx%d" % (w, h)
    if not options:
        return host_sim_compare(host_sim, path, numeric, size, num_frac, frames, strip_rows)
    with open(path) as f:
        text = f.read()
    for one in options.split(","):
        text = set_option(text, one)
    # next to the scene: the files it names (textures, meshes) are relative to it
    fd, tmp = tempfile.mkstemp(prefix=".accuracy-", suffix=".scene", dir=os.path.dirname(os.path.abspath(path)))
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        return host_sim_compare(host_sim, tmp, numeric, size, num_frac, frames, strip_rows)
    finally:
        os.unlink(tmp)


def row_name(l):
    return "%s %s %s %s %s" % (l.get("target"), l.get("what"), l.get("numeric"), l.get("variant"), l.get("per"))


def board_spec(l, scenes):
    """What an emulated RP2040 row (tools/rp2040sim --json) showed, when its
    scene is a scene file: the scene as written (the board images compile
    their scenes as written), up to the row's frame (with --average the
    run's first, the one without the fps overlay). None: no accuracy."""
    if l.get("target") != "rp2040-sim" or "frame_checksum" not in l:
        return None
    scene = l["what"][len("scene:"):]
    if not os.path.exists(os.path.join(scenes, scene + ".scene")):
        return None
    return {"scene": scene, "options": "", "frames": int(l.get("frame", 0)) + 1, "width": l["width"],
            "height": l["height"]}


def describe(l, frames):
    opts = l["options"]
    return "%s %s, frame %d at %dx%d, vs double exact" % (
        l["scene"], "with " + opts if opts else "as written", frames - 1, l["width"], l["height"])


def add_accuracy(lines, host_sim, scenes, log=print):
    """Adds the accuracy fields to lines (dicts) in place. Returns (rows
    measured, host_sim renders, [errors])."""
    cache, errors, measured = {}, [], 0
    for l in lines:
        what = l.get("what", "")
        if not what.startswith("scene:"):
            continue
        for k in ADDED:
            l.pop(k, None)
        m = re.search(r"@(\d+)x(\d+)$", what)
        l.setdefault("width", int(m.group(1)) if m else 240)
        l.setdefault("height", int(m.group(2)) if m else 240)
        spec = board_spec(l, scenes) if "options" not in l else l
        if spec is None:
            continue
        numeric = l.get("numeric", "fixed")
        err = None
        if not isinstance(l.get("frame_checksum"), int):
            err = "no frame_checksum: the frame it rendered is not known"
        elif not isinstance(spec.get("scene"), str) or not spec["scene"]:
            err = "no scene"
        elif numeric not in ("fixed", "float", "double"):
            err = "numeric mode '%s' has no host build" % numeric
        path = os.path.join(scenes, str(spec.get("scene")) + ".scene")
        if not err and not os.path.exists(path):
            err = "%s: no such scene file" % path
        if err:
            l["accuracy_error"] = err
            errors.append("%s: %s" % (row_name(l), err))
            continue
        frames = spec.get("frames") or 1
        frac = l.get("num_frac") if numeric == "fixed" else None
        key = (path, numeric, l["width"], l["height"], spec["options"], frac, frames, spec.get("strip_rows"))
        if key not in cache:
            try:
                cache[key] = compare_variant(host_sim, path, numeric, l["width"], l["height"], spec["options"], frac,
                                             frames, spec.get("strip_rows"))
            except (RuntimeError, ValueError, OSError) as e:
                cache[key] = str(e) or type(e).__name__
        s = cache[key]
        if isinstance(s, str):
            err = "host_sim: %s" % s
        elif s.get("checksum") != l["frame_checksum"]:
            err = "host_sim rendered another frame (checksum %s, the image's %d): %s" % (
                s.get("checksum"), l["frame_checksum"], describe(spec, frames))
        if err:
            l["accuracy_error"] = err
            errors.append("%s: %s" % (row_name(l), err))
            continue
        for k in FIELDS:
            l[k] = s.get(k)
        l["accuracy_checksum"] = s["checksum"]
        l["accuracy_of"] = describe(spec, frames)
        measured += 1
    return measured, len(cache), errors


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: accuracy.py RESULTS.jsonl HOST_SIM [SCENES_DIR]")
    results, host_sim = sys.argv[1], sys.argv[2]
    scenes = sys.argv[3] if len(sys.argv) > 3 else "firmware/scenes"
    if not (os.path.isfile(host_sim) and os.access(host_sim, os.X_OK)):
        sys.exit("accuracy.py: %s: no such program (make build/host_sim)" % host_sim)
    try:
        with open(results) as f:
            lines = [json.loads(l) for l in f if l.strip()]
    except (OSError, ValueError) as e:
        sys.exit("accuracy.py: %s: %s" % (results, e))
    if not all(isinstance(l, dict) for l in lines):
        sys.exit("accuracy.py: %s: a line is not a JSON object" % results)
    measured, renders, errors = add_accuracy(lines, host_sim, scenes)
    fd, tmp = tempfile.mkstemp(prefix=".accuracy-", suffix=".jsonl", dir=os.path.dirname(os.path.abspath(results)))
    try:
        with os.fdopen(fd, "w") as f:
            for l in lines:
                f.write(json.dumps(l) + "\n")
        os.replace(tmp, results)
    except BaseException:
        os.unlink(tmp)
        raise
    scene_rows = sum(1 for l in lines if l.get("what", "").startswith("scene:"))
    print("accuracy: %d of %d scene measurements measured on their own frame, %d host_sim renders" %
          (measured, scene_rows, renders))
    for e in errors:
        print("accuracy: %s" % e, file=sys.stderr)
    if errors:
        print("accuracy: %d rows without accuracy (accuracy_error)" % len(errors), file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
