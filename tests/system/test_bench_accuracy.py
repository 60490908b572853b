#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Every benchmark row's accuracy is that of its own image.

tools/bench/accuracy.py gives a scene row of results.jsonl the PSNR of the
frame its image rendered: the image states the frame's checksum and its
configuration (tools/bench/bench.h), host_sim renders that configuration,
and the two checksums must agree. With HOST_SIM alone, the rules on rows
made here (host_sim's own checksums standing in for an image's): a row
measured on its own frame, a variant named otherwise than KEY=VALUE, a
scene's last frame of several; the emulated RP2040's rows (their frame, the first of an
averaged run; none for a built-in pattern); and the rows that must get no
accuracy (the checksum of another variant's frame, no checksum, no options, a stale PSNR
of an earlier run), accuracy.py then exiting 1. With benchmark images, each
runs in qemu through tools/bench/run.py and accuracy.py, and every row must
carry a frame_checksum, and every row that states its options a PSNR
measured on a frame of that checksum.
usage: test_bench_accuracy.py HOST_SIM [IMAGE.elf ...]
"""
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
ACCURACY = os.path.join(ROOT, "tools", "bench", "accuracy.py")
RUN = os.path.join(ROOT, "tools", "bench", "run.py")
SCENES = os.path.join(ROOT, "firmware", "scenes")
failed = 0


def check(ok, name, why=""):
    global failed
    print("PASS %s" % name if ok else "FAIL %s: %s" % (name, why))
    failed += not ok


def host_checksum(host_sim, scene, size, frames=1, num_frac=None, options=None):
    """host_sim's checksum of the last of `frames` frames of a scene file."""
    cmd = [host_sim, "--scene", os.path.join(SCENES, scene + ".scene"), "--panel", "none", "--size", size,
           "--frames", str(frames), "--stats"]
    if num_frac:
        cmd += ["--num-frac", str(num_frac)]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    if r.returncode != 0:
        raise RuntimeError("host_sim %s: %s" % (scene, r.stderr.strip()))
    return json.loads(r.stdout.strip().splitlines()[-1])["checksum"]


def accuracy(path, host_sim):
    r = subprocess.run([sys.executable, ACCURACY, path, host_sim, SCENES], capture_output=True, text=True,
                       timeout=600)
    with open(path) as f:
        rows = [json.loads(l) for l in f if l.strip()]
    return r, rows


def own_frame(r):
    """Why row r's accuracy is not that of its own frame ("" when it is)."""
    if "psnr" not in r:
        return "no psnr" + (" (%s)" % r["accuracy_error"] if "accuracy_error" in r else "")
    if not isinstance(r.get("frame_checksum"), int):
        return "a psnr but no frame_checksum"
    if r.get("accuracy_checksum") != r["frame_checksum"]:
        return "psnr of frame %s, the image rendered %s" % (r.get("accuracy_checksum"), r["frame_checksum"])
    return ""


def row(variant, scene, options, checksum, size=(48, 48), frames=1, **extra):
    r = {"target": "m0plus-qemu", "what": "scene:" + scene, "numeric": "fixed", "variant": variant,
         "instructions": 1.0, "per": "frame", "image": "test.elf", "scene": scene, "width": size[0],
         "height": size[1], "strip_rows": 16, "frames": frames, "num_frac": 16}
    if options is not None:
        r["options"] = options
    if checksum is not None:
        r["frame_checksum"] = checksum
    r.update(extra)
    return r


def board(variant, scene, checksum, frame=0, **extra):
    r = {"target": "rp2040-sim", "what": "scene:" + scene, "numeric": "fixed", "variant": variant, "cores": 2,
         "frame": frame, "width": 48, "height": 48, "cycles": 1, "per": "frame", "num_frac": 16,
         "frame_checksum": checksum}
    r.update(extra)
    return r


def rules(host_sim, tmp):
    """accuracy.py on rows made here."""
    r11 = host_checksum(host_sim, "book/raster-11", "48x48", num_frac=16)
    r05 = host_checksum(host_sim, "book/raytracer-05", "48x48", num_frac=16)
    cube0 = host_checksum(host_sim, "bench/cube-flat", "48x48", num_frac=16)
    cube2 = host_checksum(host_sim, "bench/cube-flat", "48x48", frames=3, num_frac=16)
    check(cube0 != cube2, "bench_accuracy_frames_differ", "frames 0 and 2 of cube-flat have one checksum")
    rows = [
        row("book", "book/raster-11", "", r11),
        # the book path's frame given for the default path: not its own
        row("default", "book/raster-11", "book_exact=off,truncate=off,clip=split", r11, psnr=33.67,
            accuracy_of="stale"),
        row("strip8", "book/raster-11", "", None, psnr=33.67),
        row("coarse_pass", "book/raytracer-05", None, r05, psnr=69.36),
        # not KEY=VALUE: measured by its options (shadow rays' shortcuts change no pixel)
        row("shadow_any_hit+cache", "book/raytracer-05", "shadow_any_hit=on,shadow_cache=on", r05),
        row("default", "bench/cube-flat", "", cube2, frames=3),
        row("perspective_step=8", "bench/cube-flat", "perspective_step=8", cube0, frames=3),
        {"target": "m0plus-qemu", "what": "op:num_mul", "numeric": "fixed", "variant": "x", "instructions": 9.0,
         "per": "op"},
        # the emulated RP2040's rows (rp2040sim --json): the scene as written up to the row's frame
        board("two-core", "bench/cube-flat", cube0, frames=10),
        board("single-core", "bench/cube-flat", cube2, frame=2),
        board("two-core-te", "bench/cube-flat", cube2),
        board("two-core", "builtin/pattern", 12345),
    ]
    path = os.path.join(tmp, "rules.jsonl")
    with open(path, "w") as f:
        f.writelines(json.dumps(r) + "\n" for r in rows)
    p, got = accuracy(path, host_sim)
    by = {(r["what"], r["variant"]): r for r in got}
    check(len(got) == len(rows), "bench_accuracy_keeps_rows", "%d rows, wrote %d" % (len(rows), len(got)))
    check(p.returncode == 1, "bench_accuracy_mismatch_exit_1", "exit %d: %s" % (p.returncode, p.stderr.strip()))
    for key in [("scene:book/raster-11", "book"), ("scene:book/raytracer-05", "shadow_any_hit+cache"),
                ("scene:bench/cube-flat", "default")]:
        why = own_frame(by[key])
        check(not why, "bench_accuracy_own_%s" % key[1].replace("+", "_"), why)
    d = by[("scene:book/raster-11", "default")]
    check("psnr" not in d and "accuracy_of" not in d and "another frame" in d.get("accuracy_error", ""),
          "bench_accuracy_other_frame_refused", json.dumps(d))
    check("default" in p.stderr and "another frame" in p.stderr, "bench_accuracy_other_frame_named",
          p.stderr.strip())
    s = by[("scene:book/raster-11", "strip8")]
    check("psnr" not in s and "frame_checksum" in s.get("accuracy_error", ""), "bench_accuracy_no_checksum_refused",
          json.dumps(s))
    c = by[("scene:book/raytracer-05", "coarse_pass")]
    check("psnr" not in c and "accuracy_error" not in c, "bench_accuracy_no_options_no_accuracy", json.dumps(c))
    f0 = by[("scene:bench/cube-flat", "perspective_step=8")]
    check("psnr" not in f0, "bench_accuracy_last_frame_only", json.dumps(f0))
    check("frame 2 " in by[("scene:bench/cube-flat", "default")].get("accuracy_of", ""),
          "bench_accuracy_of_names_frame", by[("scene:bench/cube-flat", "default")].get("accuracy_of"))
    check(by[("op:num_mul", "x")] == rows[-5], "bench_accuracy_op_rows_untouched", json.dumps(by[("op:num_mul", "x")]))
    # a board row averaged over 10 frames is its first frame's (frame 0), not the 10th
    b = by[("scene:bench/cube-flat", "two-core")]
    check(not own_frame(b) and "frame 0 " in b.get("accuracy_of", ""), "bench_accuracy_board_first_frame",
          json.dumps(b))
    b = by[("scene:bench/cube-flat", "single-core")]
    check(not own_frame(b) and "frame 2 " in b.get("accuracy_of", ""), "bench_accuracy_board_frame", json.dumps(b))
    b = by[("scene:bench/cube-flat", "two-core-te")]
    check("psnr" not in b and "another frame" in b.get("accuracy_error", ""), "bench_accuracy_board_other_frame",
          json.dumps(b))
    b = by[("scene:builtin/pattern", "two-core")]
    check("psnr" not in b and "accuracy_error" not in b, "bench_accuracy_board_no_scene_file", json.dumps(b))

    # only rows measured on their own frames: exit 0
    good = [r for r in got if "accuracy_error" not in r]
    with open(path, "w") as f:
        f.writelines(json.dumps(r) + "\n" for r in good)
    p, again = accuracy(path, host_sim)
    check(p.returncode == 0 and all(not own_frame(r) for r in again if "options" in r or "psnr" in r),
          "bench_accuracy_all_own_exit_0", "exit %d: %s" % (p.returncode, p.stderr.strip()))

    # bad input: one line, exit status 1, no traceback
    p = subprocess.run([sys.executable, ACCURACY, os.path.join(tmp, "none.jsonl"), host_sim], capture_output=True,
                       text=True)
    check(p.returncode == 1 and len(p.stderr.strip().splitlines()) == 1 and "Traceback" not in p.stderr,
          "bench_accuracy_missing_file", "exit %d: %s" % (p.returncode, p.stderr.strip()))
    p = subprocess.run([sys.executable, ACCURACY, path, os.path.join(tmp, "no_host_sim")], capture_output=True,
                       text=True)
    check(p.returncode == 1 and len(p.stderr.strip().splitlines()) == 1 and "Traceback" not in p.stderr,
          "bench_accuracy_missing_host_sim", "exit %d: %s" % (p.returncode, p.stderr.strip()))


def images(host_sim, elves, tmp):
    """The images through run.py and accuracy.py."""
    path = os.path.join(tmp, "results.jsonl")
    r = subprocess.run([sys.executable, RUN, "--out", path, "--timeout", "300"] + elves, capture_output=True,
                       text=True)
    if r.returncode != 0:
        check(False, "bench_accuracy_images_run", (r.stderr.strip().splitlines() or ["exit %d" % r.returncode])[-1])
        return
    p, rows = accuracy(path, host_sim)
    check(p.returncode == 0, "bench_accuracy_images_exit_0", "exit %d: %s" % (p.returncode, p.stderr.strip()))
    scene_rows = [x for x in rows if x["what"].startswith("scene:")]
    check(bool(scene_rows), "bench_accuracy_images_rows", "no scene rows")
    for x in scene_rows:
        name = "bench_accuracy_image_%s_%s_%s_%s_%s" % (x["image"].replace(".elf", ""), x["what"][6:], x["numeric"],
                                                        x["variant"], x["per"])
        name = "".join(ch if ch.isalnum() or ch == "_" else "_" for ch in name)
        if not isinstance(x.get("frame_checksum"), int):
            check(False, name, "no frame_checksum")
        elif "options" not in x:
            # no configuration of a scene file (a pass of the progressive display)
            check(x["variant"].endswith("_pass") and "psnr" not in x, name, "states no options")
        else:
            why = own_frame(x)
            check(not why, name, why)


def main():
    if len(sys.argv) < 2:
        print("usage: test_bench_accuracy.py HOST_SIM [IMAGE.elf ...]", file=sys.stderr)
        return 2
    host_sim, elves = sys.argv[1], sys.argv[2:]
    with tempfile.TemporaryDirectory(prefix="test_bench_accuracy.") as tmp:
        if elves:
            images(host_sim, elves, tmp)
        else:
            rules(host_sim, tmp)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
