#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Runs emulated-MCU benchmark images in qemu-system-arm and records results.

Each image is $(BUILD)/bench/<target>/<mode>/<name>.elf, target m0plus-qemu
(mps2-an385, code built for cortex-m0plus) or m4f-qemu (mps2-an386,
cortex-m4 with the FPU). qemu runs with -icount shift=0,align=off (one
instruction = 1 ns of virtual time) and semihosting; the image prints
    BENCH <what> <numeric> <variant> <milli-instructions> <per>
lines, each turned into one JSON line of the results file; a line
    BENCHX key=value ...
right after one adds fields to it, integers where the value is one
(pixels=, frames=, frame_checksum=, ...), else strings (scene=, options=,
which may be empty: tools/bench/bench.h). Lines of the same (target, what,
numeric, variant) already in the file are replaced.

  run.py [--out FILE] [--timeout S] IMAGE.elf...   benchmark
  run.py --smoke IMAGE.elf                           boot test: passes the
      image's PASS/FAIL lines through (tests/support/run.sh), bounded by --timeout
"""
import argparse
import json
import os
import subprocess
import sys

MACHINES = {"m0plus-qemu": "mps2-an385", "m4f-qemu": "mps2-an386"}


def qemu_cmd(target, elf):
    return ["qemu-system-arm", "-M", MACHINES[target], "-nographic", "-monitor", "none",
            "-serial", "null", "-icount", "shift=0,align=off",
            "-semihosting-config", "enable=on,target=native", "-kernel", elf]


def target_of(elf):
    parts = os.path.normpath(elf).split(os.sep)
    for p in parts:
        if p in MACHINES:
            return p
    raise SystemExit(f"run.py: {elf}: path names no target ({', '.join(MACHINES)})")


def run_image(elf, timeout):
    target = target_of(elf)
    try:
        p = subprocess.run(qemu_cmd(target, elf), capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return target, None, f"timed out after {timeout} s"
    except FileNotFoundError:
        return target, None, "qemu-system-arm not found (make deps-bench: tools/deps.sh bench)"
    # semihosting output may arrive on either stream
    p.stdout = (p.stdout or "") + (p.stderr or "")
    return target, p, None


def parse(target, elf, out):
    recs = []
    for line in out.splitlines():
        f = line.split()
        if f and f[0] == "BENCHX" and recs:
            # extra fields of the line before: BENCHX key=value ...
            for kv in f[1:]:
                k, eq, v = kv.partition("=")
                if k and eq:
                    recs[-1][k] = int(v) if v.lstrip("-").isdigit() else v
            continue
        if len(f) != 6 or f[0] != "BENCH":
            continue
        _, what, numeric, variant, milli, per = f
        if what.startswith("op:calibration"):
            continue  # checked inside the image; not a result
        recs.append({"target": target, "what": what, "numeric": numeric, "variant": variant,
                     "instructions": round(int(milli) / 1000.0, 3), "per": per,
                     "image": os.path.basename(elf)})
    return recs


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("images", nargs="+")
    ap.add_argument("--out", default="build/bench/results.jsonl")
    ap.add_argument("--timeout", type=float, default=600)
    ap.add_argument("--smoke", action="store_true")
    a = ap.parse_args()

    if a.smoke:
        a.timeout = min(a.timeout, 30)
        ok = True
        for elf in a.images:
            target, p, err = run_image(elf, a.timeout)
            name = f"bench_smoke_{target}"
            if err:
                print(f"FAIL {name}: {err}")
                ok = False
                continue
            sys.stdout.write(p.stdout)
            if p.returncode != 0 or "PASS " not in p.stdout:
                print(f"FAIL {name}: qemu exit status {p.returncode}")
                ok = False
            else:
                recs = parse(target, elf, p.stdout)
                print(f"PASS {name}" if recs else f"FAIL {name}: no BENCH line")
                ok = ok and bool(recs)
        return 0 if ok else 1

    new = []
    for elf in a.images:
        target, p, err = run_image(elf, a.timeout)
        if err or p.returncode != 0:
            print(f"run.py: {elf}: {err or 'exit status %d' % p.returncode}", file=sys.stderr)
            if p is not None:
                sys.stderr.write(p.stdout[-2000:])
            return 1
        recs = parse(target, elf, p.stdout)
        print(f"{elf}: {len(recs)} measurements")
        new += recs
    keys = {(r["target"], r["what"], r["numeric"], r["variant"]) for r in new}
    old = []
    if os.path.exists(a.out):
        with open(a.out) as fh:
            for line in fh:
                try:
                    r = json.loads(line)
                except ValueError:
                    continue
                if (r.get("target"), r.get("what"), r.get("numeric"), r.get("variant")) not in keys:
                    old.append(line.rstrip("\n"))
    os.makedirs(os.path.dirname(a.out) or ".", exist_ok=True)
    with open(a.out, "w") as fh:
        for line in old:
            fh.write(line + "\n")
        for r in new:
            fh.write(json.dumps(r) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
