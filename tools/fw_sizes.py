#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""fw_sizes.py - the memory figures of the board images, from their ELF files.

usage: tools/fw_sizes.py BUILD_DIR                 print the figures
       tools/fw_sizes.py BUILD_DIR --write DOC     rewrite them in DOC
       tools/fw_sizes.py BUILD_DIR --check DOC     compare DOC with them: a
                                                   PASS or FAIL line each

Figures (KB = 1000 bytes, one decimal), as docs/firmware.md gives them:
  RP2040 images (build/firmware/pico/*.elf): flash = every loadable segment
  stored in flash (boot2, vectors, .text, the .data load image); RAM = .data
  (code and data in SRAM) + .bss in the 256 KB of SRAM (0x20000000 -
  0x20040000; the core-0 stack is in SCRATCH); left = 262,144 bytes - RAM.
  STM32F411 images (build/firmware/stm32f411/*.elf): flash likewise; RAM =
  every allocated section in SRAM (.data, .bss and the stack).
Where DOC holds them (docs/firmware.md):
  the table rows  | `IMAGE` ... | F KB | D + B = R KB ...
  "N KB more `.bss` than `cgfs-cube`" (cgfs-cube-ili9341)
  "The two-core cube image leaves N KB of SRAM"
  "float image F KB flash, R KB RAM", "fixed F KB flash"
Exit status: 0, 1 a figure differs (--check) or an image is missing, 2 usage.
"""
import os
import re
import struct
import sys

RP_IMAGES = ["cgfs-book", "cgfs-book-1core", "cgfs-cube", "cgfs-cube-1core", "cgfs-cube-ili9341", "cgfs-rt",
             "cgfs", "cgfs-check"]
ST_IMAGES = ["cgfs", "cgfs-fixed"]
RP_FLASH, RP_SRAM = (0x10000000, 0x11000000), (0x20000000, 0x20040000)
ST_FLASH, ST_SRAM = (0x08000000, 0x08080000), (0x20000000, 0x20020000)
SHF_ALLOC, SHT_NOBITS, PT_LOAD = 2, 8, 1


def elf_sizes(path, flash, sram):
    """(flash bytes, .data-like bytes in sram, .bss-like bytes in sram)"""
    with open(path, "rb") as f:
        b = f.read()
    if b[:4] != b"\x7fELF" or b[4] != 1 or b[5] != 1:
        raise ValueError(f"{path}: not a 32-bit little-endian ELF")
    phoff, shoff = struct.unpack_from("<II", b, 28)
    phentsize, phnum, shentsize, shnum = struct.unpack_from("<HHHH", b, 42)
    fl = 0
    for i in range(phnum):
        typ, _off, _va, pa, filesz = struct.unpack_from("<IIIII", b, phoff + i * phentsize)
        if typ == PT_LOAD and filesz and flash[0] <= pa < flash[1]:
            fl += filesz
    data = bss = 0
    for i in range(shnum):
        _name, typ, flags, addr, _off, size = struct.unpack_from("<IIIIII", b, shoff + i * shentsize)
        if not flags & SHF_ALLOC or not size or not sram[0] <= addr < sram[1]:
            continue
        if typ == SHT_NOBITS:
            bss += size
        else:
            data += size
    return fl, data, bss


def kb(n):
    return f"{n / 1000:.1f}"


def figures(build):
    """{key: text}: every figure the docs give"""
    fig = {}
    pico = os.path.join(build, "firmware", "pico")
    sizes = {}
    for im in RP_IMAGES:
        sizes[im] = elf_sizes(os.path.join(pico, im + ".elf"), RP_FLASH, RP_SRAM)
        fl, d, s = sizes[im]
        fig[f"rp:{im}"] = (kb(fl), kb(d), kb(s), kb(d + s))
    fig["rp:ili9341_more_bss"] = kb(sizes["cgfs-cube-ili9341"][2] - sizes["cgfs-cube"][2])
    _, d, s = sizes["cgfs-cube"]
    fig["rp:cube_left"] = kb(262144 - d - s)
    st = os.path.join(build, "firmware", "stm32f411")
    for im in ST_IMAGES:
        fl, d, s = elf_sizes(os.path.join(st, im + ".elf"), ST_FLASH, ST_SRAM)
        fig[f"st:{im}"] = (kb(fl), kb(d + s))
    return fig


def rewrite(text, fig, report):
    """text with every figure replaced by fig's; report(name, doc, build) for each"""
    def row(m):
        im = m.group(2)
        want = fig.get(f"rp:{im}")
        if not want:
            return m.group(0)
        fl = m.group(3)
        got = (fl, m.group(5), m.group(6), m.group(7))
        report(f"table_{im}", got if fl else got[1:], want if fl else want[1:])
        out = m.group(1) + (f"{want[0]} KB" if fl else "") + m.group(4)
        return out + f"{want[1]} + {want[2]} = {want[3]} KB"
    text = re.sub(r"^(\| `([\w-]+)`[^|\n]*\| )(?:([\d.]+) KB)?( \| )([\d.]+) \+ ([\d.]+) = ([\d.]+) KB", row, text,
                  flags=re.M)

    def one(name, pattern, value):
        nonlocal text
        m = re.search(pattern, text)
        if not m:
            report(name, None, value)
            return
        report(name, m.group(2), value)
        text = text[:m.start(2)] + value + text[m.end(2):]
    one("ili9341_more_bss", r"(\| `cgfs-cube-ili9341`[^\n]*?)([\d.]+)(?= KB more `\.bss` than `cgfs-cube`)",
        fig["rp:ili9341_more_bss"])
    one("cube_sram_left", r"(The two-core cube image leaves )([\d.]+)(?= KB of SRAM)", fig["rp:cube_left"])
    one("stm32_float_flash", r"(float image )([\d.]+)(?= KB flash)", fig["st:cgfs"][0])
    one("stm32_float_ram", r"(float image [\d.]+ KB flash, )([\d.]+)(?= KB RAM)", fig["st:cgfs"][1])
    one("stm32_fixed_flash", r"(fixed )([\d.]+)(?= KB flash)", fig["st:cgfs-fixed"][0])
    return text


def main(argv):
    if len(argv) not in (1, 3) or (len(argv) == 3 and argv[1] not in ("--write", "--check")):
        sys.stderr.write("usage: fw_sizes.py BUILD_DIR [--write DOC | --check DOC]\n")
        return 2
    try:
        fig = figures(argv[0])
    except (OSError, ValueError) as e:
        sys.stderr.write(f"fw_sizes.py: {e} (make firmware builds the images)\n")
        if len(argv) == 3 and argv[1] == "--check":
            print(f"FAIL fw_sizes_images: {e}")
        return 1
    if len(argv) == 1:
        for k, v in fig.items():
            print(k, " ".join(v) if isinstance(v, tuple) else v)
        return 0
    doc = argv[2]
    with open(doc, encoding="utf-8") as f:
        text = f.read()
    bad = []

    def report(name, got, want):
        if argv[1] == "--check":
            if got == want:
                print(f"PASS fw_sizes_{name}")
            else:
                print(f"FAIL fw_sizes_{name}: {doc} says {got}, the build {want} "
                      f"(tools/fw_sizes.py {argv[0]} --write {doc})")
        if got != want:
            bad.append(name)
    new = rewrite(text, fig, report)
    if argv[1] == "--write":
        with open(doc, "w", encoding="utf-8") as f:
            f.write(new)
        return 0
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
