#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""test_symbols.py — every external symbol of the renderer core has its
layer's prefix, so an embedder's own draw_line or compute_lighting links.

The core's objects (one numeric mode a directory, as the build leaves them:
BUILD/host/MODE/firmware/core/**.o) are listed with nm; each symbol they
define with external linkage must start with one of PREFIXES:

    num_ wnum_          the numeric layer (num.h, num/)
    v3_ m3_ m4_ rgb_    vectors, matrices, colours (num.h)
    mip_                texture levels (mipmap.h)
    ras_ raster_        the rasterizer (raster.h, raster/)
    rt_                 the ray tracer (raytracer.h, rt/)
    render_             the dispatcher (render.h)
    scene_              the data model (scene.h)

The book's names stay in the comments (ras_draw_line is the book's
DrawLine). Prints one PASS/FAIL line per mode.

Usage: test_symbols.py BUILD [MODE ...]   (default modes: fixed float double)
       test_symbols.py --self-test
"""
import os
import re
import subprocess
import sys

PREFIXES = ("num_", "wnum_", "v3_", "m3_", "m4_", "rgb_", "mip_", "ras_", "raster_", "rt_", "render_",
            "scene_")
CORE = os.path.join("firmware", "core")


def objects(build, mode):
    top = os.path.join(build, "host", mode, CORE)
    found = []
    for d, _, files in os.walk(top):
        found += [os.path.join(d, f) for f in files if f.endswith(".o")]
    return sorted(found)


def defined_externals(nm_output):
    """Names of the symbols nm -g --defined-only lists."""
    names = []
    for line in nm_output.splitlines():
        parts = line.split()
        if len(parts) == 3 and re.fullmatch(r"[A-Za-z]", parts[1]):
            names.append(parts[2])
    return names


def offenders(names):
    return sorted({n for n in names if not n.startswith(PREFIXES)})


def check(build, mode, expect):
    objs = objects(build, mode)
    if len(objs) < expect:
        return "FAIL core_symbols_prefixed_%s: %d core objects under %s, expected %d (build them first)" % (
            mode, len(objs), os.path.join(build, "host", mode, CORE), expect)
    out = subprocess.run(["nm", "-g", "--defined-only"] + objs, capture_output=True, text=True, check=True).stdout
    bad = offenders(defined_externals(out))
    if bad:
        return "FAIL core_symbols_prefixed_%s: without a layer prefix: %s" % (mode, " ".join(bad))
    return "PASS core_symbols_prefixed_%s (%d objects)" % (mode, len(objs))


def self_test():
    sample = ("0000000000000000 T num_add\n0000000000000010 T draw_line\n                 U memset\n"
              "0000000000000020 D ras_spec\n0000000000000000 B v3\n")
    got = offenders(defined_externals(sample))
    if got == ["draw_line", "v3"]:
        print("PASS core_symbols_self_test")
        return 0
    print("FAIL core_symbols_self_test: found %r" % got)
    return 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) < 2:
        print("usage: test_symbols.py BUILD [MODE ...]", file=sys.stderr)
        return 2
    build = sys.argv[1]
    modes = sys.argv[2:] or ["fixed", "float", "double"]
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    expect = sum(1 for d, _, fs in os.walk(os.path.join(root, CORE)) for f in fs if f.endswith(".c"))
    failed = self_test()
    for m in modes:
        line = check(build, m, expect)
        print(line)
        failed += line.startswith("FAIL")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
