# SPDX-License-Identifier: MIT
"""host_sim renders and image comparisons for the lab, the sweeps and their tests.

render() runs host_sim on scene text (written to a temporary file) with
--panel none and returns the RGB565 pixels (--out-raw), the renderer's 8-bit
colours (--out-rgb888) and the --stats object of the last frame. The
comparisons are plain Python (no numpy: the tests use them too):
psnr() over 8-bit RGB as host_sim --compare computes it, within1() the share
of pixels whose three RGB565 channels are each within one level.
"""
import hashlib
import json
import math
import os
import subprocess
import tempfile


class RenderError(RuntimeError):
    """host_sim refused or failed; the message is its one line."""


def _read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    # P6 <w> <h> 255 then one whitespace byte
    parts, pos = [], 0
    while len(parts) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        parts.append(data[start:pos])
    if parts[0] != b"P6" or parts[3] != b"255":
        raise RenderError("%s: not an 8-bit binary PPM" % path)
    w, h = int(parts[1]), int(parts[2])
    return data[pos + 1:pos + 1 + w * h * 3]


def render(host_sim, text, numeric="fixed", size="240x240", frac=None, strip=16, frames=1,
           extra=(), timeout=600):
    """Renders scene text; returns (raw565 bytes, rgb888 bytes, stats dict)."""
    with tempfile.TemporaryDirectory(prefix="cgfs-charts-") as tmp:
        scene = os.path.join(tmp, "s.scene")
        with open(scene, "w") as f:
            f.write(text)
        raw, rgb = os.path.join(tmp, "o.raw"), os.path.join(tmp, "o.ppm")
        cmd = [host_sim, "--scene", scene, "--panel", "none", "--size", size, "--numeric", numeric,
               "--strip-rows", str(strip), "--out-raw", raw, "--out-rgb888", rgb, "--stats"]
        if frames != 1:
            cmd += ["--frames", str(frames)]
        if frac is not None and numeric == "fixed":
            cmd += ["--num-frac", str(frac)]
        cmd += list(extra)
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        if r.returncode != 0:
            msg = (r.stderr.strip().splitlines() or ["host_sim exit status %d" % r.returncode])[-1]
            raise RenderError(msg.replace(scene, "<scene>"))
        stats = json.loads(r.stdout.strip().splitlines()[-1])
        with open(raw, "rb") as f:
            raw_px = f.read()
        return raw_px, _read_ppm(rgb), stats


def coarse_blocks(raw, rgb, w, h, b=8):
    """The ray tracer's progressive preview (RENDER_PASS_COARSE) from a full
    render without subsampling: each b x b block takes the colour of the
    pixel at its centre, ((c0 + c1 - 1) / 2, (r0 + r1 - 1) / 2), whose ray
    the preview traces. Returns (raw565, rgb888)."""
    out565, out888 = bytearray(len(raw)), bytearray(len(rgb))
    for r0 in range(0, h, b):
        r1 = min(r0 + b, h)
        for c0 in range(0, w, b):
            c1 = min(c0 + b, w)
            src = ((r0 + r1 - 1) // 2) * w + (c0 + c1 - 1) // 2
            p565, p888 = raw[2 * src:2 * src + 2], rgb[3 * src:3 * src + 3]
            for y in range(r0, r1):
                for x in range(c0, c1):
                    i = y * w + x
                    out565[2 * i:2 * i + 2] = p565
                    out888[3 * i:3 * i + 3] = p888
    return bytes(out565), bytes(out888)


def psnr(a, b):
    """PSNR in dB of two 8-bit images of the same size; inf when identical."""
    if len(a) != len(b):
        raise ValueError("images of different sizes")
    se = sum((x - y) * (x - y) for x, y in zip(a, b) if x != y)
    if se == 0:
        return math.inf
    return 10 * math.log10(255.0 * 255.0 * len(a) / se)


def within1(a, b):
    """Share (0..1) of RGB565 pixels (little-endian raw) with every channel
    within one level of the other image's."""
    if len(a) != len(b):
        raise ValueError("images of different sizes")
    n = len(a) // 2
    ok = 0
    for i in range(0, 2 * n, 2):
        p = a[i] | a[i + 1] << 8
        q = b[i] | b[i + 1] << 8
        if p == q or (abs((p >> 11) - (q >> 11)) <= 1 and abs(((p >> 5) & 63) - ((q >> 5) & 63)) <= 1
                      and abs((p & 31) - (q & 31)) <= 1):
            ok += 1
    return ok / n if n else 1.0


def differ(a, b):
    """Pixels (RGB565 raw) that differ at all."""
    return sum(1 for i in range(0, len(a), 2) if a[i] != b[i] or a[i + 1] != b[i + 1])


def fnv1a(data):
    """32-bit FNV-1a, as tools/bench/bench_file.c sums frame 0."""
    h = 2166136261
    for c in data:
        h = ((h ^ c) * 16777619) & 0xFFFFFFFF
    return h


def file_hash(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def psnr_text(p):
    """PSNR for tables: 'inf' when identical."""
    return "inf" if math.isinf(p) else "%.2f" % p
