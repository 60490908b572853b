#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""gen_sweep.py — the scenes of the stability sweeps (tools/charts/sweeps.py,
tests/system/test_stability.py): one scene per point of a sweep, each built
so that its exact image is known in advance or changes smoothly with the
parameter, and the method under test is the only thing that can break it.

usage: gen_sweep.py SWEEP VALUE [KEY=VALUE ...]   (the scene on stdout)
       gen_sweep.py --list
SWEEP is one of the names of SWEEPS below; VALUE its parameter; KEY=VALUE
the sweep's other knobs (e.g. depth_bits=16). Exit 2 with one line on bad
input.
"""
import inspect
import math
import sys

HEADER = 'renderer = rasterizer\ncanvas {{ width = 240 height = 240 }}\n' \
         'viewport {{ width = {vw} height = {vw} d = {d} }}\nbackground = (0, 0, 0)\n'


def _quad(name, half, z, colour):
    """A square facing the camera at depth z, two triangles, wound to face it."""
    a, b, z = "%.9g" % -half, "%.9g" % half, "%.9g" % z
    return ("model {{ name = {n} color = {c} vertices {{ ({a}, {a}, {z}) ({b}, {a}, {z}) ({b}, {b}, {z}) ({a}, {b}, {z}) }}\n"
            "  triangles {{ (0, 2, 1, normal = (0, 0, -1)) (0, 3, 2, normal = (0, 0, -1)) }} }}\n"
            ).format(n=name, c=colour, a=a, b=b, z=z)


def _fan(scale, opts):
    """48 slivers (7.5 degrees each) around the centre of the view at z = 2,
    their outer corners 0.95 * scale from it, in four colours on black."""
    n = 48
    verts = ["(0, 0, 2)"] + ["(%.9g, %.9g, 2)" % (0.95 * scale * math.cos(2 * math.pi * k / n),
                                                   0.95 * scale * math.sin(2 * math.pi * k / n)) for k in range(n + 1)]
    cols = ["(255, 64, 64)", "(64, 255, 64)", "(64, 64, 255)", "(255, 255, 64)"]
    tris = ["(0, %d, %d, color = %s, normal = (0, 0, -1))" % (k + 2, k + 1, cols[k % 4]) for k in range(n)]
    return (HEADER.format(vw=1, d=1)
            + "rasterizer { book_exact = off clip = split shading = none %s}\n" % opts
            + "model { name = fan vertices { %s }\n  triangles { %s } }\n" % (" ".join(verts), " ".join(tris))
            + "instance { model = fan }\n")


def depth(z, depth_bits="auto", gap="0.01", near="1"):
    """Depth precision against depth range: a red square at distance z in
    front of a blue one `gap` behind it (along their normal), drawn first,
    both tilted 30 degrees about the horizontal so that depth varies over the
    image; the blue one shows through at the pixels where the depth format no
    longer tells them apart. The near plane is the viewport's d (near/z is
    what the depth buffer stores)."""
    z, gap, near = float(z), float(gap), float(near)
    half = 0.9 * z / near   # beyond the view's edges (viewport 1 at d)
    opts = "book_exact = off clip = split cull = off shading = none depth = on"
    if depth_bits != "auto":
        opts += " depth_bits = %s" % depth_bits
    tilt = "rotation { x = 30 } translation = (0, 0, %.9g)" % z
    return (HEADER.format(vw=1, d=near) + "rasterizer { %s }\n" % opts
            + _quad("far", half, gap, "(0, 0, 255)")
            + _quad("near", half, 0, "(255, 0, 0)")
            + "instance {{ model = far transform {{ {t} }} }}\ninstance {{ model = near transform {{ {t} }} }}\n"
            .format(t=tilt))


def slope(angle, perspective_step="16", texture="64", uv="perspective"):
    """Perspective step N against triangle slope: a long textured wall (a
    checkerboard of power-of-two side, nearest), its near edge at the left
    of the view, turned by `angle` degrees about the vertical from facing the
    camera (0: no change of depth along a row; toward 90: a wall receding to
    several times the near edge's distance). The more it slopes, the more
    1/z varies along a span and the further the linear steps between
    perspective-correct points stray."""
    a = float(angle)
    return (HEADER.format(vw=1, d=1)
            + "rasterizer { book_exact = off clip = split shading = none perspective_step = %s uv = %s }\n"
            % (perspective_step, uv)
            + "texture {{ name = t generate = checkerboard width = {s} height = {s} square = {q} filter = nearest }}\n"
              .format(s=texture, q=max(1, int(texture) // 16))
            + "model { name = q vertices { (0, -1, 0) (8, -1, 0) (8, 1, 0) (0, 1, 0) }\n"
              "  triangles { (0, 2, 1, color = (255, 255, 255), normal = (0, 0, -1), uv = ((0, 1), (1, 0), (1, 1)))\n"
              "              (0, 3, 2, color = (255, 255, 255), normal = (0, 0, -1), uv = ((0, 1), (0, 0), (1, 0))) } }\n"
            + "instance { model = q texture = t transform { rotation { y = %.6g } "
              "translation = (-0.5537, 0.0123, 1.2031) } }\n" % a)


def subpixel(size, subpixel_bits="4"):
    """Sub-pixel bits against screen size: a fan of slivers around the centre
    of the view, whose edges cross pixel rows at every slope; `size` is the
    render size (given to host_sim), the scene is the same at every size."""
    return _fan(1.0, "subpixel_bits = %s " % subpixel_bits)


def subpixel_range(size, subpixel_bits="4"):
    """The fast span loops' range against screen size: one flat triangle
    over the lower left half of the view (its box 0.9 of the screen wide),
    at `subpixel_bits`; the loops take boxes up to 2^14 sub-pixel units and
    leave wider ones to the exact per-pixel filler."""
    return (HEADER.format(vw=1, d=1)
            + "rasterizer { book_exact = off clip = split shading = none subpixel_bits = %s }\n" % subpixel_bits
            + "model { name = t vertices { (-0.45, -0.45, 1) (0.45, -0.45, 1) (-0.45, 0.45, 1) }\n"
              "  triangles { (0, 2, 1, color = (200, 120, 40), normal = (0, 0, -1)) } }\n"
            + "instance { model = t }\n")


def raster_scale(k):
    """Fixed format against scene scale for the rasterizer: raster-11's lit
    cubes and sphere with the camera, the lights, the viewport (and with it
    the near plane) and every position and size multiplied by k: the exact
    image does not change with k."""
    k = float(k)
    s = lambda v: "%.9g" % (v * k)  # noqa: E731
    head = HEADER.format(vw="%.9g" % k, d="%.9g" % k).replace("width = 240 height = 240", "width = 600 height = 600")
    return (head + "camera { position = (%s, %s, %s) rotation { y = -30 } }\n" % (s(-3), s(1), s(2))
            + "rasterizer { book_exact = off clip = split shading = phong lighting = exact normals = model }\n"
            + "light { type = ambient intensity = 0.2 }\n"
            + "light { type = directional intensity = 0.2 direction = (-1, 0, 1) }\n"
            + "light { type = point intensity = 0.6 position = (%s, %s, %s) }\n" % (s(-3), s(2), s(-10))
            + CUBE
            + "model { name = sphere generate = sphere divs = 15 variant = s450 color = (0, 255, 0) }\n"
            + "instance { model = cube transform { scale = %s translation = (%s, 0, %s) } specular = 50 }\n"
            % (s(0.75), s(-1.5), s(7))
            + "instance { model = cube transform { scale = %s rotation { y = 195 } translation = (%s, %s, %s) } "
              "specular = 50 }\n" % (s(1), s(1.25), s(2.5), s(7.5))
            + "instance { model = sphere transform { scale = %s translation = (%s, %s, %s) } specular = 50 }\n"
            % (s(1.5), s(1.75), s(-0.5), s(7)))


# the book's cube (raster-11): eight corners, twelve triangles with normals
CUBE = """model {
  name = cube
  vertices { (1, 1, 1) (-1, 1, 1) (-1, -1, 1) (1, -1, 1) (1, 1, -1) (-1, 1, -1) (-1, -1, -1) (1, -1, -1) }
  triangles {
    (0, 1, 2, color = (255, 0, 0), normal = (0, 0, 1)) (0, 2, 3, color = (255, 0, 0), normal = (0, 0, 1))
    (4, 0, 3, color = (0, 255, 0), normal = (1, 0, 0)) (4, 3, 7, color = (0, 255, 0), normal = (1, 0, 0))
    (5, 4, 7, color = (0, 0, 255), normal = (0, 0, -1)) (5, 7, 6, color = (0, 0, 255), normal = (0, 0, -1))
    (1, 5, 6, color = (255, 255, 0), normal = (-1, 0, 0)) (1, 6, 2, color = (255, 255, 0), normal = (-1, 0, 0))
    (1, 0, 5, color = (255, 0, 255), normal = (0, 1, 0)) (5, 0, 4, color = (255, 0, 255), normal = (0, 1, 0))
    (2, 6, 7, color = (0, 255, 255), normal = (0, -1, 0)) (2, 7, 3, color = (0, 255, 255), normal = (0, -1, 0))
  }
}
"""


def rotation(frames, rate="7.3"):
    """Accumulated rotation over many animation frames: the lit cube turning
    `rate` degrees a frame; the frame rendered is the last of `frames`."""
    return (HEADER.format(vw=1, d=1)
            + "frames = %d\n" % int(frames)
            + "rasterizer { book_exact = off clip = split shading = gouraud normals = model }\n"
            + "light { type = ambient intensity = 0.3 }\n"
            + "light { type = directional intensity = 0.7 direction = (-1, 2, -3) }\n"
            + CUBE
            + "instance { model = cube transform { rotation { x = 35 } translation = (0, 0, 4) } animate { rotate_y = %s } }\n"
            % rate)


def _highlight():
    """Where the highlight of a unit sphere at (0, 0, 3) lit from (-2, 2, 0)
    lies, seen from the origin: the point whose normal halves the angle
    between the light and the view (fixed-point iteration)."""
    c, light = (0.0, 0.0, 3.0), (-2.0, 2.0, 0.0)
    unit = lambda v: tuple(x / math.sqrt(sum(y * y for y in v)) for x in v)  # noqa: E731
    n = unit((-0.3, 0.3, -1.0))
    for _ in range(200):
        p = tuple(ci + ni for ci, ni in zip(c, n))
        lv = unit(tuple(a - b for a, b in zip(light, p)))
        vv = unit(tuple(-x for x in p))
        n = unit(tuple(a + b for a, b in zip(lv, vv)))
    return tuple(ci + ni for ci, ni in zip(c, n))


def specular(exponent, lighting="fast", renderer="rasterizer"):
    """Specular exponent against the power's error: a Phong-lit unit sphere
    under one point light, looked at on its highlight from a camera on the
    line from the origin to it (so the view direction there, and with it the
    highlight, stays put) moved closer as 1/sqrt(exponent): the highlight
    (where cos^e falls to a half) covers the same part of the image at every
    exponent. The field of view stays 53 degrees (viewport = d), so the
    projection's scale stays the render size."""
    e = int(exponent)
    p = _highlight()
    dist = math.sqrt(sum(x * x for x in p))
    yaw = math.degrees(math.atan2(p[0], p[2]))
    pitch = -math.degrees(math.atan2(p[1], math.hypot(p[0], p[2])))
    k = min(1.0, 9.0 / (math.sqrt(e) * dist))   # the camera's distance to the highlight / dist
    pos = tuple(x * (1 - k) for x in p)
    d = min(1.0, 0.5 * k * dist)
    head = ("canvas { width = 240 height = 240 }\nviewport { width = %.9g height = %.9g d = %.9g }\n"
            "background = (0, 0, 0)\ncamera { position = (%.9g, %.9g, %.9g) rotation { x = %.9g y = %.9g } }\n"
            % ((d, d, d) + pos + (pitch, yaw)))
    if renderer == "raytracer":
        return ("renderer = raytracer\n" + head +
                "raytracer { recursion_depth = 0 shadows = off t_min = 0 }\n"
                "sphere { center = (0, 0, 3) radius = 1 color = (40, 90, 200) specular = %d }\n"
                "light { type = ambient intensity = 0.1 }\n"
                "light { type = point intensity = 0.9 position = (-2, 2, 0) }\n" % e)
    return ("renderer = rasterizer\n" + head
            + "rasterizer { book_exact = off clip = split shading = phong lighting = %s normals = model }\n" % lighting
            + "light { type = ambient intensity = 0.1 }\n"
            + "light { type = point intensity = 0.9 position = (-2, 2, 0) }\n"
            + "model { name = ball generate = sphere divs = 48 color = (40, 90, 200) }\n"
            + "instance { model = ball specular = %d transform { translation = (0, 0, 3) } }\n" % e)


def near(d, depth_bits="auto"):
    """Near-plane distance: the same view (viewport d x d at distance d, a
    90-degree field) of two lit cubes 0.3 apart in depth at z = 4 … 5.5 while
    the near plane d moves from far below them toward them."""
    d = float(d)
    opts = "book_exact = off clip = split shading = flat normals = model"
    if depth_bits != "auto":
        opts += " depth_bits = %s" % depth_bits
    return ("renderer = rasterizer\ncanvas { width = 240 height = 240 }\n"
            "viewport { width = %.9g height = %.9g d = %.9g }\nbackground = (0, 0, 0)\n" % (d, d, d)
            + "rasterizer { %s }\n" % opts
            + "light { type = ambient intensity = 0.3 }\n"
            + "light { type = directional intensity = 0.7 direction = (-1, 2, -3) }\n"
            + CUBE
            + "instance { model = cube transform { rotation { y = 30 } translation = (-0.4, 0, 4.5) } }\n"
            + "instance { model = cube transform { scale = 0.9 rotation { y = 10 x = 20 } translation = (0.5, 0.3, 4.8) } }\n")


def triangle_size(scale):
    """Tiny and huge triangles: the fan of the sub-pixel sweep scaled by
    `scale` about the centre of the view, so its slivers shrink below a pixel
    or reach far beyond the screen (the clipper cuts them at the guard band)."""
    return _fan(float(scale), "")


RT_SCALE = """name = "stability-k{k}"
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


def rt_scale(k, formulation="robust"):
    """The ray tracer's sphere test against scene scale: three spheres and a
    ground sphere ten times their radius, every position and radius times k
    about the camera (the exact image does not change with k), with the
    book's quadratic (formulation = book) or the robust one."""
    k = int(float(k))
    return RT_SCALE.format(k=k, form=formulation, a=-1 * k, b=3 * k, c=-2 * k, d=4 * k, r1=k, g=-11 * k,
                           rg=10 * k, lx=2 * k, ly=1 * k)


SWEEPS = {"depth": depth, "slope": slope, "subpixel": subpixel, "subpixel_range": subpixel_range,
          "raster_scale": raster_scale,
          "rotation": rotation, "rt_scale": rt_scale, "specular": specular, "near": near, "triangle_size": triangle_size}


def main(argv):
    if argv[1:] == ["--list"]:
        print("\n".join(sorted(SWEEPS)))
        return 0
    if len(argv) < 3 or argv[1] not in SWEEPS:
        print("usage: gen_sweep.py SWEEP VALUE [KEY=VALUE ...] (SWEEP: %s)" % ", ".join(sorted(SWEEPS)),
              file=sys.stderr)
        return 2
    knobs = list(inspect.signature(SWEEPS[argv[1]]).parameters)[1:]
    kw = {}
    for a in argv[3:]:
        k, eq, v = a.partition("=")
        if not eq or k not in knobs:
            print("gen_sweep.py: %s: expected KEY=VALUE with KEY one of %s" % (a, ", ".join(knobs) or "none"),
                  file=sys.stderr)
            return 2
        kw[k] = v
    try:
        sys.stdout.write(SWEEPS[argv[1]](argv[2], **kw))
    except (TypeError, ValueError) as e:
        print("gen_sweep.py: %s %s: %s" % (argv[1], argv[2], e), file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
