#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The boundaries of the stability sweeps, pinned (tools/charts/sweeps.py).

Each sweep of `make charts` finds where a method fails along one parameter
(depth bits against depth range, perspective step against slope, sub-pixel
bits against screen size and the span loops' range, the rasterizer's and the
ray tracer's formats against scene scale, accumulated rotation, specular
exponent, near plane, triangle size). Its PINS are the swept points on
either side of each boundary as measured: this test renders exactly those
points, with the sweep's own scenes, sizes and measures, and fails when one
of them is on the other side of the threshold, i.e. when a boundary moved.
A method that got better or worse is then a documented change: update the
pin and docs/charts.md. The subpixel-range pins measure cost on the emulated
Cortex-M0+ with the lab's benchmark images (built by make test).
usage: test_stability.py HOST_SIM BUILD
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "charts"))
import lab  # noqa: E402
import sweeps  # noqa: E402


def main():
    if len(sys.argv) != 3:
        print("usage: test_stability.py HOST_SIM BUILD", file=sys.stderr)
        return 2
    host_sim, build = sys.argv[1], sys.argv[2]
    L = lab.Lab(host_sim, build, jobs=1, log=lambda m: None, rp2040=False, build_images=False)
    for sw in sweeps.SWEEPS:
        for label, pins in sw.pins.items():
            s = sweeps.series_of(sw, label)
            for x, want in pins:
                name = "stability_%s_%s_%s_at_%g" % (sw.name, "".join(c if c.isalnum() else "_" for c in label)
                                                     .strip("_"), "holds" if want else "fails", x)
                try:
                    v, r = sweeps.measure(host_sim, sw, s, x, L)
                except lab.ImageMissing as e:
                    print("FAIL %s: %s" % (name, e))
                    continue
                if v is None:
                    print("FAIL %s: %s" % (name, r.get("error", "no measure")))
                elif bool(sw.holds(v)) != want:
                    print("FAIL %s: %s = %s, the boundary moved (threshold %g; update the pin in "
                          "tools/charts/sweeps.py and docs/charts.md)" % (name, sw.metric, v, sw.threshold))
                else:
                    print("PASS %s" % name)
    return 0


if __name__ == "__main__":
    sys.exit(main())
