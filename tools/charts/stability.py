# SPDX-License-Identifier: MIT
"""host_sim's accuracy figures of one scene against the double build
(`host_sim --compare double --stats`), for tools/bench/accuracy.py.
"""
import json
import subprocess


def host_sim_compare(host_sim, scene, numeric, size, num_frac=None, frames=None, strip_rows=None):
    """Accuracy of one scene in one mode against double, from host_sim --stats:
    the last frame's object (its `checksum` that of the frame compared).
    Fixed point is in the scene's own format unless num_frac is given;
    frames 0 .. frames-1 are rendered (default 1), in strips of strip_rows
    (default host_sim's)."""
    cmd = [host_sim, "--scene", scene, "--panel", "none", "--size", size,
           "--numeric", numeric, "--compare", "double", "--stats"]
    if num_frac is not None and numeric == "fixed":
        cmd += ["--num-frac", str(num_frac)]
    if frames:
        cmd += ["--frames", str(frames)]
    if strip_rows:
        cmd += ["--strip-rows", str(strip_rows)]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        raise RuntimeError(r.stderr.strip() or "host_sim exit status %d" % r.returncode)
    return json.loads(r.stdout.strip().splitlines()[-1])
