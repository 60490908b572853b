"""The scaled scene of the stability sweep, and host_sim's accuracy figures.

Used by tools/charts/charts.py (the chart) and tests/test_stability.py (the
bounds that must hold).
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


SCALED_SCENE = """name = "stability-k{k}"
renderer = raytracer
canvas {{ width = 600 height = 600 }}
viewport {{ width = 1 height = 1 d = 1 }}
background = (0, 0, 0)
camera {{ position = (0, 0, 0) }}
raytracer {{ recursion_depth = 1 t_min = 1 epsilon = 0.001 formulation = {form} }}
sphere {{ center = (0, {a}, {b}) radius = {r1} color = (255, 0, 0) specular = 500 reflective = 0.2 }}
sphere {{ center = ({c}, 0, {d}) radius = {r1} color = (0, 255, 0) specular = 10 reflective = 0.4 }}
sphere {{ center = (0, {g}, 0) radius = {rg} color = (255, 255, 0) specular = 1000 reflective = 0.5 }}
light {{ type = ambient intensity = 0.2 }}
light {{ type = point intensity = 0.6 position = ({lx}, {ly}, 0) }}
light {{ type = directional intensity = 0.2 direction = (1, 4, 4) }}
"""


def scaled_scene(k, formulation):
    """Three spheres and the lights of the book, every position and radius times k
    (the ground sphere is radius 10k, as far as Q15.16 positions allow)."""
    return SCALED_SCENE.format(k=k, form=formulation, a=-1 * k, b=3 * k, c=-2 * k, d=4 * k,
                               r1=k, g=-11 * k, rg=10 * k, lx=2 * k, ly=1 * k)
