#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""rp2040_ram_text.py - which functions and constant tables the RP2040 images
run from SRAM (RP2040_RAM_TEXT=1), from execution profiles of the images on
the emulator: of the renderer core, the application, the panel drivers and
the board's code (the objects CORE matches).

usage: tools/rp2040_ram_text.py collect --out TSV PROFILE.json:IMAGE.map ...
       tools/rp2040_ram_text.py ld TSV --out LD      write the linker-script fragment
       tools/rp2040_ram_text.py ld TSV --check LD    compare LD with it (exit 1 if not)
       tools/rp2040_ram_text.py check-map TSV IMAGE.map ...
                                                     a PASS or FAIL line an image: its
                                                     placement is the TSV's
       tools/rp2040_ram_text.py report TSV           the sections by heat

collect: each PROFILE.json is `rp2040sim --profile`'s (tools/rp2040sim/profile.js:
reads and cycles per symbol over a run, and the run's frame cycles),
IMAGE.map the image's linker map. Each profiled symbol of those
objects is attributed to the input section that holds it
(-ffunction-sections, -fdata-sections: one function or table a section;
RAS_HOT's span loops too, firmware/core/raster/raster_int.h), and TSV gets a
line per section and image: object, section (GCC's clone suffixes .isra.N,
.constprop.N, .part.N folded into the function's name), bytes, image, reads
a million frame cycles (instruction fetches, literal and data loads, over
the run, by the cycles of its frames: rp2040sim --json's "cycles").

ld: a section's heat in an image is its reads a million frame cycles per
halfword of it; a section is hot when its heat is HEAT_MIN or more in some
profiled image: the code a frame runs once a pixel, span, triangle or
vertex, the tables it reads, and the set-up of a frame short enough that
missing the XIP cache on it would show (the cube scenes' 1.4 M cycles: what
a frame reads about once, 0.7 a million cycles). The code that runs once a
scene (render_init) or once a long frame (the book and ray-traced scenes'
set-up), and what no profiled scene runs, stays in flash. The fragment
names the hot sections per object file (ram_text_hot.ld, included by
ram_text/on/ram_text.ld inside .data: the reset handler copies them to
SRAM); the rest of the core stays in .text and .rodata, in flash, read
through the XIP cache. `make ram-text-profile` builds the profiled images,
runs them with --profile and rewrites the TSV and the fragment; `make check
T=test_ram_text` compares the fragment with the TSV's and checks the
images' placement.
"""
import bisect
import json
import re
import sys
from collections import defaultdict

HEAT_MIN = 0.1         # reads a million frame cycles per halfword: hot at or above
CODE = re.compile(r"\.(text|rodata)(\.|$)")     # code and constant tables (not .data, .bss)
CLONE = re.compile(r"(\.(?:isra|constprop|part|lto_priv)\.\d+)+$")
# the objects placed by the profile: the renderer core, the application and
# the panel drivers, the board's code (not crt0.o: the reset handler runs
# before .data is copied; not scenes_builtin.o, the placeholder table of the
# images without scenes: an image's scenes keep their const data in flash,
# and `make image` sizes its SRAM from the placeholder image, so the two
# must place the same)
CORE = re.compile(r"(?:^|/)((?:firmware/core|firmware/app|hal)/(?!scenes_builtin\.o$)\S+\.o"
                  r"|firmware/board/rp2040/(?:board|fw_board_rp2040)\.o)$")
SECTION = re.compile(r"^ (\.[^\s]+)(?:\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+(\S+))?\s*$")
CONT = re.compile(r"^\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+(\S+)\s*$")


def map_sections(path):
    """(addr, size, section, object) of the input sections of the image's
    memory map that lie in flash or SRAM"""
    out, name, started = [], None, False
    with open(path) as f:
        for line in f:
            if not started:
                started = line.startswith("Linker script and memory map")
                continue
            m = SECTION.match(line)
            if m:
                name = m.group(1)
                if m.group(2) is None:
                    continue
                addr, size, obj = int(m.group(2), 16), int(m.group(3), 16), m.group(4)
            else:
                c = CONT.match(line)
                if not c or name is None:
                    name = None
                    continue
                addr, size, obj = int(c.group(1), 16), int(c.group(2), 16), c.group(3)
            if size and (0x10000000 <= addr < 0x11000000 or 0x20000000 <= addr < 0x20042000):
                out.append((addr, size, name, obj))
            name = None
    out.sort()
    return out


def section_key(name):
    return CLONE.sub("", name)


def collect(pairs, out):
    rows = {}
    for pair in pairs:
        prof_path, map_path = pair.rsplit(":", 1)
        with open(prof_path) as f:
            prof = json.load(f)
        image = prof["image"].removesuffix(".elf")
        mcycles = prof["frame_cycles"] / 1e6
        secs = map_sections(map_path)
        starts = [s[0] for s in secs]
        # the map must be the profiled link's: its functions' sections named after them
        funcs = [sym for sym in prof["symbols"] if sym["type"] == "func" and sym["reads"]]
        named = 0
        for sym in funcs:
            i = bisect.bisect_right(starts, sym["addr"]) - 1
            named += i >= 0 and section_key(secs[i][2]).endswith("." + section_key(sym["name"]))
        if funcs and named < len(funcs) // 2:
            sys.exit(f"rp2040_ram_text.py: {map_path} is not the link {prof_path} profiled "
                     f"({named} of {len(funcs)} functions in sections of their names)")
        heat = defaultdict(float)
        sizes = {}
        for s in secs:
            m = CORE.search(s[3])
            if m:
                key = (m.group(1), section_key(s[2]))
                sizes[key] = sizes.get(key, 0) + s[1]
        for sym in prof["symbols"]:
            i = bisect.bisect_right(starts, sym["addr"]) - 1
            if i < 0:
                continue
            addr, size, name, obj = secs[i]
            if not addr <= sym["addr"] < addr + size or not CODE.match(name):
                continue
            m = CORE.search(obj)
            if not m:
                continue
            heat[(m.group(1), section_key(name))] += sym["reads"] / mcycles
        for key, reads in heat.items():
            if reads > 0:
                rows[(key[0], key[1], image)] = (sizes[key], reads)
    with open(out, "w") as f:
        f.write("# object\tsection\tbytes\timage\treads a million frame cycles (tools/rp2040_ram_text.py collect)\n")
        for (obj, sec, image), (size, reads) in sorted(rows.items()):
            f.write(f"{obj}\t{sec}\t{size}\t{image}\t{reads:.4g}\n")


def read_tsv(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            obj, sec, size, image, reads = line.rstrip("\n").split("\t")
            rows.append((obj, sec, int(size), image, float(reads)))
    return rows


def heat_of(rows):
    """per (object, section): (heat, bytes, image): the largest reads a frame
    per halfword among the images"""
    best = {}
    for obj, sec, size, image, reads in rows:
        h = reads / max(1, size / 2)
        if (obj, sec) not in best or h > best[(obj, sec)][0]:
            best[(obj, sec)] = (h, size, image)
    return best


def ld_text(rows):
    best = heat_of(rows)
    hot = defaultdict(list)
    for (obj, sec), (h, size, image) in best.items():
        # .ram_text: explicit SRAM code (RP2040_RAM_TEXT=raster's RAS_HOT), SRAM anyway
        if h >= HEAT_MIN and sec != ".ram_text":
            hot[obj].append(sec)
    lines = ["/* SPDX-License-Identifier: MIT */",
             "/* ram_text_hot.ld - generated by tools/rp2040_ram_text.py from",
             " * profile.tsv (make ram-text-profile): the input sections of the core, the",
             " * application, the panel drivers and the board's code",
             f" * read {HEAT_MIN:g} times or more a million frame cycles per halfword in",
             " * some profiled image. Included by ram_text.ld; do not edit. */"]
    for obj in sorted(hot):
        lines.append(f"*{obj}(")
        lines += [f"    {sec} {sec}.*" if sec.startswith(".text.") else f"    {sec}" for sec in sorted(hot[obj])]
        lines.append(")")
    return "\n".join(lines) + "\n"


def check_map(rows, maps):
    """PASS/FAIL lines: in each image, the hot sections of the objects the
    profile places lie in SRAM and their others in flash (.ram_text: SRAM)"""
    best = heat_of(rows)
    bad = 0
    for path in maps:
        wrong, n = [], 0
        for addr, size, name, obj in map_sections(path):
            m = CORE.search(obj)
            if not m or not (CODE.match(name) or name == ".ram_text"):
                continue
            key = (m.group(1), section_key(name))
            want = name == ".ram_text" or (key in best and best[key][0] >= HEAT_MIN)
            n += 1
            if want != (addr >= 0x20000000):
                wrong.append(f"{key[0]}({name}) in {'SRAM' if addr >= 0x20000000 else 'flash'}")
        if wrong:
            bad += 1
            print(f"FAIL ram_text_placement {path}: " + "; ".join(wrong[:8]) +
                  (f" and {len(wrong) - 8} more" if len(wrong) > 8 else ""))
        else:
            print(f"PASS ram_text_placement {path} ({n} sections placed by the profile)")
    return bad


def report(rows):
    best = heat_of(rows)
    total = 0
    for (obj, sec), (h, size, image) in sorted(best.items(), key=lambda kv: -kv[1][0]):
        mark = "hot" if h >= HEAT_MIN else "   "
        if h >= HEAT_MIN:
            total += size
        print(f"{mark} {h:12.1f} {size:6d} {image:16s} {obj} {sec}")
    print(f"hot: {total} bytes")


def main(argv):
    if len(argv) >= 3 and argv[1] == "collect" and argv[2] == "--out":
        collect(argv[4:], argv[3])
        return 0
    if len(argv) == 5 and argv[1] == "ld" and argv[3] in ("--out", "--check"):
        text = ld_text(read_tsv(argv[2]))
        if argv[3] == "--out":
            with open(argv[4], "w") as f:
                f.write(text)
            return 0
        with open(argv[4]) as f:
            same = f.read() == text
        print("PASS ram_text_hot_ld" if same else
              f"FAIL ram_text_hot_ld: {argv[4]} is not what tools/rp2040_ram_text.py ld {argv[2]} writes")
        return 0 if same else 1
    if len(argv) >= 4 and argv[1] == "check-map":
        check_map(read_tsv(argv[2]), argv[3:])
        return 0
    if len(argv) == 3 and argv[1] == "report":
        report(read_tsv(argv[2]))
        return 0
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
