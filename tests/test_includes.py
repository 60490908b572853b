#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""test_includes.py — the include graph follows the layers.

Every quoted #include of every C source and header is resolved to the
directory that holds it (the including file's own directory first, then the
path from the top of the tree, then any directory with a file of that name;
names found nowhere are generated files and are skipped) and checked against
LAYERS: a directory may include only from the directories listed for it.

    firmware/core      the renderer: nothing above it
    hal                the DCS layer and panel descriptors: hal.h only
    hal/<backend>      hal and itself; never firmware/ (the board includes
                       the backend, not the other way round)
    firmware/app       the core and the HAL; never tools/ or host_sim/
    firmware/board/*   the app's board interface, the HAL, its backend
    firmware/examples  the core and the HAL
    tools/scene        the parser: the core
    tools/core_api     the per-mode table: the core and the parser
    tools/scenec       the parser, the core, tools/core_api; never host_sim/
    tools/bench        the core and the firmware's scene table
    host_sim, tests    anything below them

Outside firmware/core (and host_sim, tests), only the core's public headers
may be included from it: PUBLIC_CORE (render.h the interface, scene.h and
num.h its data, raytracer.h and raster.h the renderers' contracts,
mipmap.h the texture levels scene builders make); the rest (rt_int.h,
raster_int.h, num_rt.h, ...) are internal.

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
    "tools/scenec": (CORE, "tools/scene", "tools/core_api", "tools/bench"),
    "tools/bench": (CORE, "firmware/app", "tools/scene"),
    "tools/flasher": (),
    "host_sim": ("*",),
    "tests": ("*",),
}

PUBLIC_CORE = {"render.h", "scene.h", "num.h", "raytracer.h", "raster.h", "mipmap.h"}

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
            if dirs and not any(allowed(layer, own, d) for d in dirs):
                bad.setdefault(layer, []).append("%s includes \"%s\" (%s)" % (f, name, ", ".join(dirs)))
            elif (dirs == [CORE] and layer != CORE and "*" not in LAYERS[layer]
                  and os.path.basename(name) not in PUBLIC_CORE):
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
    cases = {
        CORE: ("firmware/core/a.c", '#include "panel.h"\n'),
        "hal/rp2040": ("hal/rp2040/b.c", '#include "board.h"\n'),
        "firmware/app": ("firmware/app/c.c", '#include "bench.h"\n'),
        "tools/scenec": ("tools/scenec/d.c", '#include "host_sim/imgio.h"\n'),
        "tools/bench": ("tools/bench/e.c", '#include "rt_int.h"\n'),
    }
    headers = ["hal/panel.h", "firmware/board/rp2040/board.h", "tools/bench/bench.h",
               "host_sim/imgio.h", "firmware/core/rt_int.h"]
    failed = 0
    for layer, (path, text) in cases.items():
        with tempfile.TemporaryDirectory() as root:
            for h in headers + [path]:
                os.makedirs(os.path.join(root, os.path.dirname(h)), exist_ok=True)
                with open(os.path.join(root, h), "w") as fh:
                    fh.write(text if h == path else "")
            bad = check(root)
            if layer in bad and len(bad) == 1:
                print("PASS includes self-test %s" % layer)
            else:
                failed += 1
                print("FAIL includes self-test %s: found %r" % (layer, bad))
    return failed


def main():
    if sys.argv[1:] == ["--self-test"]:
        return 1 if self_test() else 0
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    failed = report(check(root)) + self_test()
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
