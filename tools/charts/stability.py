# SPDX-License-Identifier: MIT
"""host_sim's accuracy figures of one scene against the double build
(`host_sim --compare double --stats`), for tools/bench/accuracy.py.
"""
import json
import subprocess


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
