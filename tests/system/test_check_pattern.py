#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The bring-up pattern (firmware/app/check_pattern.h) as the glass shows it:
host_sim --pattern check on every panel of hal/panels.def in every rotation,
the glass read back (--out-raw) and checked against the layout the header
describes: the red, green and blue squares in the top-left, top-right and
bottom-left corners of the glass and nothing in the bottom-right one, the
1-pixel white border, the eight bars' colours, the gradients' ends, and the
settings drawn in the font (firmware/app/font5x7.c, read from the source):
the panel's name, its size and rotation, the clocks given with
--board-clocks, and the offsets' and colour order's lines present. Then what
each --miswire shows on the ST7789 (the squares moved, their colours
changed), and the option errors (exit 2, one line).
  test_check_pattern.py HOST_SIM
Prints one PASS/FAIL line per check."""
import os
import re
import subprocess
import sys
import tempfile

GROUND, WHITE, BLACK = 0x2104, 0xFFFF, 0x0000
RED, GREEN, BLUE = 0xF800, 0x07E0, 0x001F
BARS = [0xFFFF, 0xFFE0, 0x07FF, 0x07E0, 0xF81F, 0xF800, 0x001F, 0x0000]
CLOCKS = "62500000,133000000"


def font():
    """The glyphs of firmware/app/font5x7.c: char -> 7 row bitmaps."""
    src = open("firmware/app/font5x7.c").read()
    rows = lambda body: [[int(v, 16) if v.startswith("0x") else int(v) for v in re.findall(r"0x[0-9a-f]+|\d+", r)]
                         for r in re.findall(r"\{([^{}]*)\}", body)]
    g = {}
    for name, first in (("digits", "0"), ("upper", "A")):
        body = re.search(r"%s\[\d+\]\[7\] = \{(.*?)\n\};" % name, src, re.S).group(1)
        for i, r in enumerate(rows(body)):
            g[chr(ord(first) + i)] = r
    named = dict(re.findall(r"static const uint8_t (g_\w+)\[7\] = \{([^}]*)\}", src))
    for ch, name in re.findall(r"case '(.)': return (g_\w+);", src):
        vals = re.findall(r"0x[0-9a-f]+|\d+", named[name]) if named[name].strip() != "0" else ["0"] * 7
        g[ch] = ([int(v, 16) if v.startswith("0x") else int(v) for v in vals] + [0] * 7)[:7]
    return g


def layout(w, h, rnd):
    """check_setup's layout (check_pattern.c)."""
    inset = min(w, h) * 3 // 20 if rnd else 0
    cw, ch = w - 2 * inset, h - 2 * inset
    m = min(cw, ch)
    L = {"inset": inset, "mark": m // 8, "scale": 2 if m >= 200 else 1}
    L["bars_y"] = inset + L["mark"] + 4
    L["bars_h"] = ch // 10
    L["grad_y"] = L["bars_y"] + L["bars_h"] + 2
    L["grad_h"] = max(ch // 30, 2)
    L["text_y"] = L["grad_y"] + 4 * L["grad_h"] + 2
    box = 7 * L["scale"] + 4
    L["box"] = box
    L["text_x"] = inset + (L["mark"] + 6 if L["text_y"] + 6 * box + 2 > h - inset - L["mark"] - 2 else 4)
    return L


def text_ok(px, w, h, x, y, s, text, glyphs):
    """font5x7_draw's box of text at (x, y) scale s, as far as the glass has it."""
    bw, bh = len(text) * 6 * s + 3, 7 * s + 4
    want = {}
    for yy in range(y, y + bh):
        for xx in range(x, x + bw):
            want[(xx, yy)] = BLACK
    for i, c in enumerate(text):
        g = glyphs[c]
        for r in range(7):
            for col in range(5):
                if g[r] & (0x10 >> col):
                    for dy in range(s):
                        for dx in range(s):
                            want[(x + 2 + (i * 6 + col) * s + dx, y + 2 + r * s + dy)] = WHITE
    bad = [(k, v) for k, v in want.items() if k[0] < w - 1 and k[1] < h - 1 and px[k[1] * w + k[0]] != v]
    return not bad, bad[:1]


def run(host_sim, args, tmp):
    raw = os.path.join(tmp, "g.raw")
    if os.path.exists(raw):
        os.remove(raw)
    r = subprocess.run([host_sim, "--pattern", "check", "--out-raw", raw] + args, capture_output=True, text=True)
    if r.returncode != 0:
        return None, r
    d = open(raw, "rb").read()
    return [d[i] | d[i + 1] << 8 for i in range(0, len(d), 2)], r


def main():
    host_sim = sys.argv[1]
    glyphs = font()
    panels = re.findall(r"^PANEL\((\w+),\s*(\w+),", open("hal/panels.def").read(), re.M)
    ok = True

    def report(name, good, why=""):
        nonlocal ok
        print(("PASS %s" % name) if good else ("FAIL %s: %s" % (name, why)))
        ok = ok and good

    with tempfile.TemporaryDirectory() as tmp:
        for name, ctl in panels:
            nw, nh = map(int, re.search(r"_(\d+)x(\d+)$", name).groups())
            for rot in range(4):
                w, h = (nh, nw) if rot & 1 and nw != nh else (nw, nh)
                case = "check_pattern[%s,rotation %d]" % (name, rot)
                px, r = run(host_sim, ["--panel", name, "--rotation", str(rot), "--board-clocks", CLOCKS], tmp)
                if px is None or len(px) != w * h:
                    report(case, False, "exit %d: %s" % (r.returncode, r.stderr.strip()[:200]))
                    continue
                rnd = ctl == "gc9a01"
                L = layout(w, h, rnd)
                at = lambda x, y: px[y * w + x]
                i0, m = L["inset"], L["mark"]
                c0, c1 = i0 + 2 + m // 2, w - i0 - 3 - m // 2
                r0, r1 = i0 + 2 + m // 2, h - i0 - 3 - m // 2
                why = []
                for what, x, y, want in (("top-left red", c0, r0, RED), ("top-right green", c1, r0, GREEN),
                                         ("bottom-left blue", c0, r1, BLUE), ("bottom-right ground", c1, r1, GROUND)):
                    if at(x, y) != want:
                        why.append("%s at (%d,%d) is %04x" % (what, x, y, at(x, y)))
                for x, y in ((w // 2, 0), (w // 2, h - 1), (0, h // 2), (w - 1, h // 2)):
                    if at(x, y) != WHITE:
                        why.append("border at (%d,%d) is %04x" % (x, y, at(x, y)))
                x0, n = i0 + 2, w - 2 * i0 - 4
                yb = L["bars_y"] + L["bars_h"] // 2
                got = [at(x0 + (2 * k + 1) * n // 16, yb) for k in range(8)]
                if got != BARS:
                    why.append("bars %s" % " ".join("%04x" % v for v in got))
                ends = [(at(x0, L["grad_y"] + k * L["grad_h"]), at(x0 + n - 1, L["grad_y"] + k * L["grad_h"]))
                        for k in range(4)]
                if ends != [(0, WHITE), (0, RED), (0, GREEN), (0, BLUE)]:
                    why.append("gradient ends %s" % ends)
                s, tx, ty, bh = L["scale"], L["text_x"], L["text_y"], L["box"]
                # (the driver's rotation is the one asked for: a panel that is not square turned
                # an odd number of quarters is its descriptor's rotation 1 or 3)
                lines = {0: name.upper(), 1: "%dX%d ROT %d" % (w, h, rot), 4: "SPI 62.5 MHZ", 5: "CLK_SYS 133 MHZ"}
                for k, text in lines.items():
                    if ty + (k + 1) * bh > h - 1:
                        continue   # (a glass too short for the text: its bottom lines clipped)
                    good, bad = text_ok(px, w, h, tx, ty + k * bh, s, text, glyphs)
                    if not good:
                        why.append("line %d '%s' not drawn (first bad pixel %s)" % (k, text, bad))
                for k in (2, 3):
                    y = ty + k * bh + 2
                    if y + 7 * s < h and not any(at(x, y + r) == WHITE for r in range(7 * s)
                                                 for x in range(tx, min(w - 1, tx + 60))):
                        why.append("line %d empty" % k)
                report(case, not why, "; ".join(why))

        # --miswire on the ST7789 240x240: where the squares go, what colour they turn
        L = layout(240, 240, False)
        m = L["mark"]
        c0, c1 = 2 + m // 2, 240 - 3 - m // 2
        for wrong, checks in (
                ("bgr", [(c0, c0, BLUE), (c1, c0, GREEN), (c0, c1, RED)]),
                ("invert", [(c0, c0, 0x07FF), (c1, c0, 0xF81F), (c0, c1, 0xFFE0), (c1, c1, 0xDEFB)]),
                ("rotation", [(c1, c1, RED), (c0, c1, GREEN), (c1, c0, BLUE), (c0, c0, GROUND)]),
                ("byteswap", [(c0, c0, 0x00F8), (c1, c0, 0xE007), (c0, c1, 0x1F00), (120, 0, WHITE)]),
                ("offset", [(c0, c0 + 80, RED), (c1, c0 + 80, GREEN), (120, 80, WHITE)])):
            px, r = run(host_sim, ["--miswire", wrong], tmp)
            case = "check_miswire_%s" % wrong
            if px is None:
                report(case, False, "exit %d: %s" % (r.returncode, r.stderr.strip()[:200]))
                continue
            bad = ["(%d,%d) %04x, not %04x" % (x, y, px[y * 240 + x], v) for x, y, v in checks if px[y * 240 + x] != v]
            report(case, not bad, "; ".join(bad))

        for args, what in ((["--pattern", "checks"], "unknown pattern 'checks'"),
                           (["--scene", "tests/data/spheres.scene"], "one or the other"),
                           (["--size", "100x100"], "no other option"),
                           (["--panel", "none"], "needs a panel"),
                           (["--miswire", "colour"], "unknown --miswire 'colour'"),
                           (["--miswire", "offset", "--panel", "ili9341"], "no offsets to get wrong"),
                           (["--board-clocks", "62500000"], "bad --board-clocks"),
                           (["--out", os.path.join(tmp, "f%d.png")], "one picture")):
            r = subprocess.run([host_sim, "--pattern", "check"] + args, capture_output=True, text=True)
            lines = r.stderr.strip().splitlines()
            good = r.returncode == 2 and len(lines) == 1 and what in lines[0]
            report("check_usage[%s]" % " ".join(args[:2]), good, "exit %d: %s" % (r.returncode, r.stderr.strip()))
        r = subprocess.run([host_sim, "--scene", "tests/data/spheres.scene", "--board-clocks", "1,1"],
                           capture_output=True, text=True)
        report("check_usage[--board-clocks without --pattern]", r.returncode == 2 and "needs --pattern" in r.stderr,
               "exit %d: %s" % (r.returncode, r.stderr.strip()))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
