#!/usr/bin/env python3
"""Numeric stability where methods fail: the ray-sphere test under scene scale.

The same scene multiplied by k has the same exact image. The robust
formulation in fixed point (in the format each scaled scene's ranges call
for) must stay within the ray tracer's accuracy bound
(PSNR >= 45 dB against double) from k = 1 to k = 2048, while the book's
quadratic, evaluated in Q15.16, must be seen to fail by k = 64 (r^2 and
|CO|^2 leave the format) — if it stops failing, the sweep no longer reaches
the edge it is meant to test.
usage: test_stability.py HOST_SIM
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools", "charts"))
from stability import host_sim_compare, scaled_scene  # noqa: E402


def psnr_of(host_sim, tmp, k, form, numeric, num_frac=None):
    path = os.path.join(tmp, "k%d-%s.scene" % (k, form))
    with open(path, "w") as f:
        f.write(scaled_scene(k, form))
    s = host_sim_compare(host_sim, path, numeric, "80x80", num_frac)
    return float("inf") if s["psnr"] is None else s["psnr"]


def main():
    host_sim = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        for k in (1, 16, 256, 2048):
            p = psnr_of(host_sim, tmp, k, "robust", "fixed")
            ok = p >= 45
            print("%s robust_fixed_holds_at_scale_%d%s" % ("PASS" if ok else "FAIL", k,
                  "" if ok else ": PSNR %.2f dB < 45" % p))
        # the book's quadratic in Q15.16 (host_sim would refuse the scene in
        # its own format: r^2 fits none)
        p = psnr_of(host_sim, tmp, 64, "book", "fixed", 16)
        ok = p < 45
        print("%s book_quadratic_fixed_fails_at_scale_64%s" % ("PASS" if ok else "FAIL",
              "" if ok else ": PSNR %.2f dB, expected the Q15.16 overflow to show" % p))


if __name__ == "__main__":
    main()
