#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""test_includes.py — the include graph follows the layers.

Every quoted #include of every C source and header is resolved to the
directory that holds it (the including file's own directory first, then the
path from the top of the tree, then any directory with a file of that name;
names found nowhere are generated files and are skipped) and checked against
LAYERS: a directory may include only from the directories listed for it.

    firmware/core      the renderer: nothing above it (inside it, see below)
    hal                the DCS layer and panel descriptors: hal.h only
    hal/<backend>      hal and itself; never firmware/ (the board includes
                       the backend, not the other way round)
    firmware/app       the core and the HAL; never tools/ or host_sim/
    firmware/board/*   the app's board interface, the HAL, its backend
    firmware/examples  the core and the HAL
    tools/scene        the parser: the core
    tools/core_api     the per-mode table: the core and the parser
    tools/scenec       the parser, the core, tools/core_api, tools/common, tools/quality;
                       never host_sim/
    tools/quality      methods chosen for an accuracy target: the core, the parser, tools/core_api
    tools/common       the host tools' shared helpers: nothing of the project's
    tools/bench        the core and the firmware's scene table
    host_sim, tests    anything below them

Inside firmware/core every file belongs to one part (CORE_PARTS, by path),
and a part includes only from the parts below it (CORE_BELOW):

    render   render.h, render.c: the dispatcher, over both renderers
    rt       raytracer.h, rt/: the ray tracer
    raster   raster.h, raster/: the rasterizer
    strip    strip.h, work.h: what both renderers write and carve
    scene    scene.h, scene_options.def: the data model
    mipmap   mipmap.h, mipmap.c: texture levels (scene builders too)
    num      num.h, num/: the numeric layer

so nothing in the core includes the dispatcher, and the renderers do not
include each other. A core file in no part fails.

Outside firmware/core (and host_sim, tests), only the core's public headers
may be included from it: PUBLIC_CORE (render.h the interface, strip.h its
target, scene.h and num.h its data, raytracer.h and raster.h the renderers'
contracts, mipmap.h the texture levels scene builders make, the schema
table scene_options.def); the rest (rt/rt_int.h, raster/raster_int.h,
num/num_int.h, ...) are internal.

Usage: test_includes.py [ROOT]   (default: the tree this file is in)
       test_includes.py --self-test
Prints one PASS/FAIL line per layer.
"""
import os
import re
import sys
import tempfile

CORE = "firmware/core"
HAL_BACKENDS = ("hal/sim", "hal/linux", "hal/rp2040", "hal/stm32f4")

# directory prefix -> directories it may include from (besides itself);
# the longest matching prefix applies. "*" allows anything.
LAYERS = {
    CORE: (),
    "hal": (),
    "hal/sim": ("hal",),
    "hal/linux": ("hal",),
    "hal/rp2040": ("hal",),
    "hal/stm32f4": ("hal",),
    "firmware/app": (CORE, "hal"),
    "firmware/board": ("firmware/app", "hal") + HAL_BACKENDS,
    "firmware/examples": (CORE, "hal") + HAL_BACKENDS,
    "tools/scene": (CORE,),
    "tools/core_api": (CORE, "tools/scene"),
    "tools/scenec": (CORE, "tools/scene", "tools/core_api", "tools/bench", "tools/common", "tools/quality"),
    "tools/quality": (CORE, "tools/scene", "tools/core_api"),
    "tools/common": (),
    "tools/bench": (CORE, "firmware/app", "tools/scene"),
    "tools/flasher": (),
    "host_sim": ("*",),
    "tests": ("*",),
}

PUBLIC_CORE = {"render.h", "strip.h", "scene.h", "num.h", "raytracer.h", "raster.h", "mipmap.h",
               "scene_options.def", "scene_features.h", "scene_features.def"}

# The core's parts: (path or folder/ prefix, part); the first match applies.
CORE_PARTS = (
    ("render.h", "render"), ("render.c", "render"),
    ("raytracer.h", "rt"), ("rt/", "rt"),
    ("raster.h", "raster"), ("raster/", "raster"),
    ("strip.h", "strip"), ("work.h", "strip"),
    ("scene.h", "scene"), ("scene_options.def", "scene"), ("scene_features.h", "scene"), ("scene_features.def", "scene"),
    ("mipmap.h", "mipmap"), ("mipmap.c", "mipmap"),
    ("num.h", "num"), ("num/", "num"),
)
# part -> the parts it may include from (besides itself)
CORE_BELOW = {
    "render": ("rt", "raster", "strip", "scene", "mipmap", "num"),
    "rt": ("strip", "scene", "num"),
    "raster": ("strip", "scene", "mipmap", "num"),
    "strip": ("scene", "num"),
    "scene": ("num",),
    "mipmap": (),
    "num": (),
}


def core_part(path):
    """The part of a file of firmware/core, None for a file in no part."""
    rel = path[len(CORE) + 1:]
    for key, part in CORE_PARTS:
        if rel == key or (key.endswith("/") and rel.startswith(key)):
            return part
    return None

SKIP_DIRS = {".git", "node_modules", "out"}
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)


def sources(root):
    for d, subdirs, files in os.walk(root):
        rel = os.path.relpath(d, root).replace(os.sep, "/")
        subdirs[:] = [s for s in subdirs
                      if s not in SKIP_DIRS and not (rel == "." and s.startswith("build"))]
        for f in files:
            if f.endswith((".c", ".h")):
                yield ("" if rel == "." else rel + "/") + f


def layer_of(path):
    best = None
    for prefix in LAYERS:
        if path == prefix or path.startswith(prefix + "/"):
            if best is None or len(prefix) > len(best):
                best = prefix
    return best


def allowed(layer, own_dir, target_dir):
    if target_dir == own_dir or layer_of(target_dir + "/x") == layer:
        return True
    ok = LAYERS[layer]
    if "*" in ok:
        return True
    return any(target_dir == a or target_dir.startswith(a + "/") for a in ok)


def check(root):
    files = sorted(sources(root))
    by_name = {}
    for f in files:
        by_name.setdefault(os.path.basename(f), []).append(os.path.dirname(f))
    fileset = set(files)
    bad = {}
    for f in files:
        layer = layer_of(f)
        if layer is None:
            continue
        own = os.path.dirname(f)
        with open(os.path.join(root, f), encoding="utf-8", errors="replace") as fh:
            text = fh.read()
        for name in INCLUDE.findall(text):
            own_path = os.path.normpath(os.path.join(own, name)).replace(os.sep, "/")
            if own_path in fileset:
                dirs = [os.path.dirname(own_path)]
            elif name in fileset:
                dirs = [os.path.dirname(name)]
            else:
                dirs = by_name.get(os.path.basename(name), [])
            if layer == CORE and dirs:
                part = core_part(f)
                targets = [own_path] if own_path in fileset else (
                    [name] if name in fileset else [d + "/" + os.path.basename(name) for d in dirs])
                for t in targets:
                    tp = core_part(t) if t.startswith(CORE + "/") else None
                    if part is None:
                        bad.setdefault(layer, []).append("%s belongs to no part of the core" % f)
                    elif tp is not None and tp != part and tp not in CORE_BELOW[part]:
                        bad.setdefault(layer, []).append("%s (%s) includes \"%s\" (%s)" % (f, part, name, tp))
            if dirs and not any(allowed(layer, own, d) for d in dirs):
                bad.setdefault(layer, []).append("%s includes \"%s\" (%s)" % (f, name, ", ".join(dirs)))
            elif (layer != CORE and "*" not in LAYERS[layer]
                  and any(d == CORE or d.startswith(CORE + "/") for d in dirs)
                  and not (CORE in dirs and os.path.basename(name) in PUBLIC_CORE)):
                bad.setdefault(layer, []).append("%s includes the core's internal \"%s\"" % (f, name))
    return bad


def report(bad):
    failed = 0
    for layer in sorted(LAYERS):
        if layer in bad:
            failed += 1
            print("FAIL includes %s: %s" % (layer, "; ".join(bad[layer])))
        else:
            print("PASS includes %s" % layer)
    return failed


def self_test():
    """A planted violation of each kind is found."""
    cases = [
        (CORE, "firmware/core/a.c", '#include "panel.h"\n'),
        (CORE, "firmware/core/raster/b.c", '#include "render.h"\n'),
        (CORE, "firmware/core/rt/c.c", '#include "raster/raster_int.h"\n'),
        ("hal/rp2040", "hal/rp2040/b.c", '#include "board.h"\n'),
        ("firmware/app", "firmware/app/c.c", '#include "bench.h"\n'),
        ("tools/scenec", "tools/scenec/d.c", '#include "host_sim/imgio.h"\n'),
        ("tools/bench", "tools/bench/e.c", '#include "rt/rt_int.h"\n'),
    ]
    headers = ["hal/panel.h", "firmware/board/rp2040/board.h", "tools/bench/bench.h",
               "host_sim/imgio.h", "firmware/core/rt/rt_int.h", "firmware/core/render.h",
               "firmware/core/raster/raster_int.h"]
    failed = 0
    for layer, path, text in cases:
        with tempfile.TemporaryDirectory() as root:
            for h in headers + [path]:
                os.makedirs(os.path.join(root, os.path.dirname(h)), exist_ok=True)
                with open(os.path.join(root, h), "w") as fh:
                    fh.write(text if h == path else "")
            bad = check(root)
            if layer in bad and len(bad) == 1:
                print("PASS includes self-test %s" % path)
            else:
                failed += 1
                print("FAIL includes self-test %s: found %r" % (path, bad))
    return failed


def main():
    if sys.argv[1:] == ["--self-test"]:
        return 1 if self_test() else 0
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    failed = report(check(root)) + self_test()
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
