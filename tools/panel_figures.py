#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""panel_figures.py - the README's panel table: each panel's cube image on the
emulated RP2040 (tools/rp2040sim, both cores), its frame rate and bus bytes.

usage: tools/panel_figures.py BUILD_DIR                  print the table
       tools/panel_figures.py BUILD_DIR --write README   rewrite it in README,
                                                         between the lines
                                                         <!-- panel-table --> and
                                                         <!-- /panel-table -->

For each panel below, its two-core cube image (build/firmware/pico/IMAGE.elf,
`make firmware`) runs FRAMES frames of each of the three cube scenes
(`rp2040sim.js --image ... --panel MODULE --frames 30 --json --average`):
the SPI clock the image runs its panel at (the boot line's spi_hz: the
controller's rated write clock, or FW_SPI_HZ's), the mean frame rate of
each scene (frames after the first send only the
columns that changed, as on the board), the frames a second the glass shows
whole at the panel's scan rate (rp2040sim's shown_fps: not torn, and not
overwritten before a scan pass shows them), and the mean SPI bytes a frame;
and
the bytes of one whole frame at the panel's pixel size. About 10 s of
emulation a panel. Exit status: 0; 1 an image is missing or a run failed;
2 usage.
"""
import json
import os
import subprocess
import sys

# module (a PANEL of hal/panels.def), controller, its cube image, bytes a pixel
PANELS = [
    ("st7789_240x240", "ST7789VW", "cgfs-cube", 2),
    ("ili9341_320x240", "ILI9341", "cgfs-cube-ili9341", 2),
    ("ili9341_320x240", "ILI9341, SPI beyond its rating (`FW_SPI_HZ`)", "cgfs-cube-ili9341-fastspi", 2),
    ("st7735_128x160", "ST7735S", "cgfs-cube-st7735", 2),
    ("ssd1351_128x128", "SSD1351 (OLED, not DCS)", "cgfs-cube-ssd1351", 2),
    ("gc9a01_240x240", "GC9A01 (round)", "cgfs-cube-gc9a01", 2),
    ("ili9488_320x480", "ILI9488 (18-bit)", "cgfs-cube-ili9488", 3),
]
SCENES = ["bench/cube-textured", "bench/cube-gouraud", "bench/cube-flat"]
FRAMES_PER_SCENE = 10
BEGIN, END = "<!-- panel-table -->", "<!-- /panel-table -->"


def die(msg, code=1):
    sys.stderr.write(f"panel_figures.py: {msg}\n")
    sys.exit(code)


def run(build, module, image):
    elf = os.path.join(build, "firmware", "pico", image + ".elf")
    if not os.path.isfile(elf):
        die(f"{elf}: no such image (make firmware)")
    cmd = ["node", "tools/rp2040sim/rp2040sim.js", "--image", elf, "--panel", module,
           "--frames", str(FRAMES_PER_SCENE * len(SCENES)), "--json", "--average"]
    r = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if r.returncode != 0:
        die(f"{image} on {module}: {(r.stderr.strip().splitlines() or ['rp2040sim failed'])[-1]}")
    rows = {}
    for line in r.stdout.splitlines():
        j = json.loads(line)
        rows[j["what"].removeprefix("scene:")] = j
    if any(s not in rows for s in SCENES):
        die(f"{image} on {module}: not every cube scene was shown")
    return rows


def table(build):
    head = ("| Panel (`--panel`) | Controller | Size | Bytes a pixel: a whole frame | Board image | SPI clock | "
            + " | ".join(f"{s.split('/')[1]}: fps sent / shown whole, bus KB a frame" for s in SCENES) + " |")
    lines = [head, "|" + "---|" * (6 + len(SCENES))]
    for module, ctl, image, bpp in PANELS:
        w, h = map(int, module.rsplit("_", 1)[1].split("x"))
        rows = run(build, module, image)
        cells = [f"{rows[s]['fps']:.0f} / {rows[s]['shown_fps']:.0f}, {rows[s]['spi_bytes'] / 1000:.1f}"
                 for s in SCENES]
        hz = rows[SCENES[0]].get("spi_hz", 0)
        lines.append(f"| `{module}` | {ctl} | {w}x{h} | {bpp}: {w * h * bpp / 1000:.1f} KB | `{image}.uf2` | "
                     + f"{hz / 1e6:.4g} MHz | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def main(argv):
    if len(argv) not in (2, 4) or (len(argv) == 4 and argv[2] != "--write"):
        die("usage: tools/panel_figures.py BUILD_DIR [--write README]", 2)
    t = table(argv[1])
    if len(argv) == 2:
        sys.stdout.write(t)
        return 0
    doc = argv[3]
    text = open(doc, encoding="utf-8").read()
    a, b = text.find(BEGIN), text.find(END)
    if a < 0 or b < a:
        die(f"{doc}: no {BEGIN} ... {END} lines")
    text = text[:a + len(BEGIN)] + "\n" + t + text[b:]
    with open(doc, "w", encoding="utf-8") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
