"""The scaled scene of the stability sweep, and host_sim's accuracy figures.

Used by tools/charts/charts.py (the chart) and tests/test_stability.py (the
bounds that must hold).
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scene"))
import gen_sweep  # noqa: E402


def host_sim_compare(host_sim, scene, numeric, size, num_frac=None):
    """Accuracy of one scene in one mode against double, from host_sim --stats.
    Fixed point is in the scene's own format unless num_frac is given."""
    cmd = [host_sim, "--scene", scene, "--panel", "none", "--size", size,
           "--numeric", numeric, "--compare", "double", "--stats"]
    if num_frac is not None and numeric == "fixed":
        cmd += ["--num-frac", str(num_frac)]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        raise RuntimeError(r.stderr.strip() or "host_sim exit status %d" % r.returncode)
    return json.loads(r.stdout.strip().splitlines()[-1])


def scaled_scene(k, formulation):
    """Three spheres and the lights of the book, every position and radius times k
    (the ground sphere is radius 10k, as far as Q15.16 positions allow)."""
    return gen_sweep.rt_scale(k, formulation)
