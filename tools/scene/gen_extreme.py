#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""gen_extreme.py — valid but extreme scenes, for checking the scene
compiler's format promise (tests/system/test_scene_extremes.sh).

usage: gen_extreme.py [--family=1|2] SEED COUNT DIR

Writes DIR/x-SEED-I.scene for I in 0 .. COUNT-1: ray-traced and rasterized
scenes with values near the limits the scene format allows (docs/scene-
format.md) and near a number format's limits: huge and tiny radii and
coordinates, the camera inside objects, large specular exponents and t_min,
supersampling of bright colours, long animations that turn, tiny and huge
light directions, narrow and wide viewports, big model vertices and
scales. Every scene is valid notation; whether a fixed-point format holds it
is what the test checks. Deterministic for a given SEED.

--family=2 (round two) writes the book quadratic, viewports whose width and
height differ by up to 10^5, d from 0.001 to 1000, mirrored and turned
cameras, the camera inside large spheres and scaled instances with culling
off, planes that every ray grazes, 3D lines and the book raster path, each
with a render size on a "# size WxH" line (flat and tall ones among them).
"""
import random
import sys


def num(r, lo, hi, logscale=False):
    if logscale:
        v = 10 ** r.uniform(lo, hi)
    else:
        v = r.uniform(lo, hi)
    return float('%.6g' % v)


def vec(r, scale):
    return '(%s, %s, %s)' % tuple('%.6g' % r.uniform(-scale, scale) for _ in range(3))


def colour(r):
    return '(%d, %d, %d)' % tuple(r.choice([0, 64, 255]) for _ in range(3))


def lights(r, scale):
    out = ['light { type = ambient intensity = %s }' % num(r, 0, 0.5)]
    n = r.randint(0, 3)
    for _ in range(n):
        kind = r.choice(['point', 'directional'])
        inten = num(r, 0.05, r.choice([1, 4, 16]))
        if kind == 'point':
            out.append('light { type = point intensity = %s position = %s }' % (inten, vec(r, scale * 2)))
        else:
            mag = r.choice([1e-3, 1e-2, 1, 100, 1000])
            out.append('light { type = directional intensity = %s direction = %s }' % (inten, vec(r, mag)))
    return out


def raytracer(r):
    scale = r.choice([0.01, 1, 10, 100, 1000, 5000])
    lines = ['renderer = raytracer', 'canvas { width = 600 height = 600 }']
    vw = num(r, -2.5, 1.5, True)
    lines.append('viewport { width = %s height = %s d = %s }' % (vw, vw, num(r, -2, 2, True)))
    lines.append('background = %s' % colour(r))
    frames = r.choice([1, 1, 2, 50, 300, 3000])
    if frames > 1:
        lines.append('frames = %d' % frames)
    cam = 'camera { position = %s' % vec(r, scale)
    if r.random() < 0.5:
        cam += ' rotation { y = %s }' % num(r, -180, 180)
    if frames > 1 and r.random() < 0.7:
        cam += ' animate { rotate_y = %s move = %s }' % (num(r, -20, 20), vec(r, scale / 100))
    lines.append(cam + ' }')
    opts = []
    if r.random() < 0.4:
        opts.append('supersample = %d' % r.randint(2, 4))
    if r.random() < 0.3:
        opts.append('t_min = %s' % r.choice([0, 0.001, 1, 100, 3000]))
    if r.random() < 0.3:
        opts.append('recursion_depth = %d' % r.randint(0, 5))
    if r.random() < 0.2:
        opts.append('adaptive_subsample = %d' % r.choice([2, 4, 8]))
    if opts:
        lines.append('raytracer { %s }' % ' '.join(opts))
    lines += lights(r, scale)
    for _ in range(r.randint(1, 5)):
        kind = r.choice(['sphere', 'sphere', 'sphere', 'plane', 'triangle'])
        mat = 'color = %s specular = %s reflective = %s' % (
            colour(r), r.choice([-1, 10, 500, 1000, 5000, 10000]), r.choice([0, 0.3, 1]))
        if kind == 'sphere':
            rad = num(r, -3, 4, True) * (scale if r.random() < 0.5 else 1)
            rad = min(rad, 1e5)
            lines.append('sphere { center = %s radius = %.6g %s }' % (vec(r, scale), max(rad, 1e-3), mat))
        elif kind == 'plane':
            lines.append('plane { normal = %s dist = %s %s }' % (vec(r, 1), num(r, -scale, scale), mat))
        else:
            lines.append('triangle { points = (%s, %s, %s) %s }' % (vec(r, scale), vec(r, scale), vec(r, scale), mat))
    return lines


def rasterizer(r):
    scale = r.choice([0.01, 1, 10, 100, 1000])
    lines = ['renderer = rasterizer', 'canvas { width = 600 height = 600 }']
    vw = num(r, -1.5, 1, True)
    lines.append('viewport { width = %s height = %s d = %s }' % (vw, vw, num(r, -2, 1, True)))
    frames = r.choice([1, 1, 50, 500, 3000])
    if frames > 1:
        lines.append('frames = %d' % frames)
    lines.append('camera { position = %s }' % vec(r, scale / 10))
    shading = r.choice(['flat', 'gouraud', 'phong', 'none'])
    lines.append('rasterizer { clip = %s depth = on cull = on shading = %s }' % (r.choice(['book', 'split']), shading))
    lines += lights(r, scale)
    vs = r.choice([0.001, 1, 100, 1000, 10000])
    lines.append('model { name = m generate = sphere divs = %d color = %s }' % (r.choice([4, 8]), colour(r)))
    lines.append('model { name = c vertices { (%g, %g, %g) (%g, %g, %g) (%g, %g, %g) (%g, %g, %g) } '
                 'triangles { (0, 1, 2, color = %s) (0, 2, 3, color = %s) } }'
                 % (vs, vs, 0, -vs, vs, 0, -vs, -vs, 0, vs, -vs, 0, colour(r), colour(r)))
    for _ in range(r.randint(1, 4)):
        mdl = r.choice(['m', 'c'])
        sc = num(r, -3, 3, True)
        anim = ''
        if frames > 1 and r.random() < 0.6:
            anim = ' animate { rotate_y = %s }' % num(r, -30, 30)
        z = abs(r.uniform(1, 5)) * scale
        lines.append('instance { model = %s transform { scale = %.6g translation = (%.6g, %.6g, %.6g) }%s specular = %s }'
                     % (mdl, sc, r.uniform(-1, 1) * scale, r.uniform(-1, 1) * scale, z, anim,
                        r.choice([-1, 10, 500, 5000])))
    return lines


def camera_rotation(r):
    """A turn about x or y, literal rows (mirrored or not), or none."""
    k = r.random()
    if k < 0.3:
        return ''
    if k < 0.55:
        return ' rotation { %s = %s }' % (r.choice(['x', 'y']), num(r, -180, 180))
    sx, sy = r.choice([-1, 1]), r.choice([-1, 1])
    return ' rotation { rows = ((%d, 0, 0), (0, %d, 0), (0, 0, 1)) }' % (sx, sy)


def viewport2(r):
    """Width and height apart (flat and tall views), d from 0.001 to 1000."""
    vw = num(r, -3, 2, True)
    vh = vw if r.random() < 0.4 else num(r, -3, 2, True)
    return 'viewport { width = %s height = %s d = %s }' % (vw, vh, num(r, -3, 3, True))


def raytracer2(r):
    """Round two: the book quadratic, flat and tall viewports, mirrored
    cameras, the camera inside large spheres, planes every ray grazes."""
    scale = r.choice([0.01, 1, 10, 100, 1000])
    lines = ['renderer = raytracer', 'canvas { width = 600 height = 600 }', viewport2(r),
             'background = %s' % colour(r)]
    inside = r.random() < 0.3
    cam = (0, 0, 0) if inside else tuple(r.uniform(-scale, scale) for _ in range(3))
    lines.append('camera { position = (%.6g, %.6g, %.6g)%s }' % (cam + (camera_rotation(r),)))
    opts = ['formulation = %s' % r.choice(['book', 'robust', 'default'])]
    if r.random() < 0.3:
        opts.append('epsilon = %s' % r.choice([0.0001, 0.01, 0.1]))
    if r.random() < 0.4:
        opts.append('recursion_depth = %d' % r.randint(0, 3))
    if r.random() < 0.3:
        opts.append('shadows = off')
    lines.append('raytracer { %s }' % ' '.join(opts))
    lines += lights(r, scale)
    if inside:
        lines.append('sphere { center = %s radius = %.6g color = %s }'
                     % (vec(r, scale / 10), r.choice([10, 100, 1000]) * max(scale, 1), colour(r)))
    for _ in range(r.randint(1, 4)):
        mat = 'color = %s specular = %s reflective = %s' % (colour(r), r.choice([-1, 10, 500]), r.choice([0, 0.3]))
        if r.random() < 0.3:
            # a plane nearly along the view: every ray grazes it
            n = (r.uniform(-0.01, 0.01), 1, r.uniform(-0.01, 0.01))
            lines.append('plane { normal = (%.6g, %.6g, %.6g) dist = %s %s }' % (n + (num(r, -scale, scale), mat)))
        else:
            lines.append('sphere { center = %s radius = %.6g %s }'
                         % (vec(r, scale), max(num(r, -2, 1, True) * scale, 1e-3), mat))
    return lines


def rasterizer2(r):
    """Round two: wide and flat viewports, the camera inside scaled
    instances (culling off), mirrored cameras, 3D lines, the book path."""
    scale = r.choice([0.01, 1, 10, 100])
    lines = ['renderer = rasterizer', 'canvas { width = 600 height = 600 }', viewport2(r)]
    lines.append('camera { position = %s%s }' % (vec(r, scale / 10), camera_rotation(r)))
    shading = r.choice(['flat', 'gouraud', 'phong', 'none'])
    book = r.random() < 0.2
    lines.append('rasterizer { clip = %s depth = on cull = %s shading = %s%s }'
                 % (r.choice(['book', 'split']), r.choice(['on', 'off']), shading,
                    ' book_exact = on' if book else ''))
    lines += lights(r, scale)
    lines.append('model { name = m generate = sphere divs = %d color = %s }' % (r.choice([4, 8, 15]), colour(r)))
    lines.append('model { name = c vertices { (1, 1, 1) (-1, 1, 1) (-1, -1, 1) (1, -1, 1) (1, 1, -1) (-1, 1, -1) '
                 '(-1, -1, -1) (1, -1, -1) } triangles { (0, 1, 2, color = %s) (0, 2, 3, color = %s) '
                 '(4, 0, 3, color = %s) (4, 3, 7, color = %s) (5, 4, 7, color = %s) (5, 7, 6, color = %s) '
                 '(1, 5, 6, color = %s) (1, 6, 2, color = %s) (4, 5, 1, color = %s) (4, 1, 0, color = %s) '
                 '(2, 6, 7, color = %s) (2, 7, 3, color = %s) } }' % tuple(colour(r) for _ in range(12)))
    for _ in range(r.randint(1, 3)):
        sc = num(r, -1, 2, True) * max(scale, 1)
        if r.random() < 0.4:
            pos = (0, 0, 0)   # around the camera
        else:
            pos = (r.uniform(-1, 1) * scale, r.uniform(-1, 1) * scale, abs(r.uniform(1, 5)) * scale)
        lines.append('instance { model = %s transform { scale = %.6g translation = (%.6g, %.6g, %.6g) } }'
                     % ((r.choice(['m', 'c']), sc) + pos))
    for _ in range(r.choice([0, 0, 3])):
        lines.append('line3d { p0 = %s p1 = %s color = %s }' % (vec(r, scale), vec(r, scale), colour(r)))
    return lines


def main(argv):
    family = 1
    if len(argv) == 5 and argv[1].startswith('--family='):
        family = int(argv[1].split('=', 1)[1])
        argv = argv[:1] + argv[2:]
    if len(argv) != 4 or family not in (1, 2):
        sys.stderr.write('usage: gen_extreme.py [--family=1|2] SEED COUNT DIR\n')
        return 2
    seed, count, out = int(argv[1]), int(argv[2]), argv[3]
    for i in range(count):
        r = random.Random(seed * 1000003 + i)
        if family == 1:
            lines = raytracer(r) if r.random() < 0.6 else rasterizer(r)
        else:
            lines = raytracer2(r) if r.random() < 0.5 else rasterizer2(r)
        with open('%s/x-%d-%d.scene' % (out, seed, i), 'w') as f:
            f.write('# generated by tools/scene/gen_extreme.py --family=%d %d (scene %d)\n' % (family, seed, i))
            if family == 2:
                f.write('# size %s\n' % r.choice(['32x32', '32x32', '64x8', '8x64', '200x2', '48x24']))
            f.write('\n'.join(lines) + '\n')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
