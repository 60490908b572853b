#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""fw_sizes.py - the memory figures of the board images, from their ELF files.

usage: tools/fw_sizes.py BUILD_DIR                 every image in BUILD_DIR/firmware: a table
       tools/fw_sizes.py BUILD_DIR --before OLD    the same, each figure OLD's -> BUILD_DIR's
                                                   (OLD: another build directory)
       tools/fw_sizes.py BUILD_DIR --write DOC     rewrite the figures in DOC
       tools/fw_sizes.py BUILD_DIR --check DOC     compare DOC with them: a
                                                   PASS or FAIL line each

Figures (KB = 1000 bytes, one decimal), as docs/firmware.md gives them:
  flash   every loadable segment stored in flash (boot2, vectors, .text, the
          .data load image);
  SRAM    split four ways:
    code    code and constant tables copied to SRAM (RP2040_RAM_TEXT:
            __ram_code_start .. __ram_code_end of firmware/board/rp2040/rp2040.ld;
            an image linked before those symbols: the .text, .rodata and
            .ram_text input sections of .data in its .map);
    work    the renderer's work memory (the scene table's buffers: fw_work0,
            fw_work1; the placeholder table's work0, work1);
    stacks  core 1's stack (core1_stack) and core 0's: the RP2040's SCRATCH
            banks (.stack0, 8 KB), the STM32F411's .stack;
    data    the rest of .data and .bss (strips, the UART ring, contexts, ...);
  left    the SRAM none of them takes: the RP2040's 264 KB (270,336 bytes:
          256 KB and the two 4 KB SCRATCH banks, which core 0's stack fills),
          the STM32F411's 128 KB (131,072 bytes).
Where DOC holds them (docs/firmware.md):
  the table rows  | `IMAGE` ... | F KB | C + D + W + S = T KB | L KB |
  (`IMAGE` of build/firmware/pico, `stm32f411/IMAGE` of build/firmware/stm32f411)
  "The two-core cube image leaves N KB of SRAM"
Exit status: 0, 1 a figure differs (--check) or an image is missing, 2 usage.
"""
import glob
import os
import re
import struct
import sys

# the images whose rows docs/firmware.md has (test_fw_docs: mk/firmware.mk's TEST_NEEDS_test_fw_docs)
RP_IMAGES = ["cgfs-book", "cgfs-book-1core", "cgfs-cube", "cgfs-cube-1core", "cgfs-cube-ili9341", "cgfs-rt",
             "cgfs-mesh", "cgfs", "cgfs-check"]
ST_IMAGES = ["cgfs", "cgfs-fixed"]
BOARDS = {  # directory under firmware/: flash range, SRAM range, SRAM bytes
    "pico": ((0x10000000, 0x11000000), (0x20000000, 0x20042000), 270336),
    "stm32f411": ((0x08000000, 0x08080000), (0x20000000, 0x20020000), 131072),
}
WORK_SYMBOLS = {"fw_work0", "fw_work1", "work0", "work1"}
STACK_SYMBOLS = {"core1_stack"}
STACK_SECTIONS = {".stack0", ".stack"}
SHF_ALLOC, SHT_NOBITS, SHT_SYMTAB, PT_LOAD = 2, 8, 2, 1


def cstr(b, off):
    return b[off:b.index(b"\0", off)].decode()


def map_code(path, data_addr):
    """SRAM code bytes from the .map next to an image linked without
    __ram_code_start/__ram_code_end: the end of .data's last .text,
    .rodata or .ram_text input section (they come first) less its start"""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            lines = f.read().split("\n")
    except OSError:
        return 0
    end, inside, name = data_addr, False, None
    for ln in lines:
        if re.match(r"^\.data\s", ln):
            inside = True
            continue
        if inside and re.match(r"^\.\S", ln):
            break
        if not inside:
            continue
        m = re.match(r"^ (\.\S+)(?:\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+\S.*)?$", ln)
        if m:
            name = m.group(1)
            if not m.group(2):
                continue
            addr, size = int(m.group(2), 16), int(m.group(3), 16)
        else:
            m = re.match(r"^\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+\S", ln)
            if not m or not name:
                continue
            addr, size = int(m.group(1), 16), int(m.group(2), 16)
        if re.match(r"\.(text|rodata|ram_text)(\.|$)", name) and size:
            end = max(end, addr + size)
        name = None
    return end - data_addr


def elf_figures(path, board):
    """{flash, code, data, work, stacks, sram, left} of one image, in bytes"""
    flash, sram, total = BOARDS[board]
    with open(path, "rb") as f:
        b = f.read()
    if b[:4] != b"\x7fELF" or b[4] != 1 or b[5] != 1:
        raise ValueError(f"{path}: not a 32-bit little-endian ELF")
    phoff, shoff = struct.unpack_from("<II", b, 28)
    phentsize, phnum, shentsize, shnum, shstrndx = struct.unpack_from("<HHHHH", b, 42)
    fl = 0
    for i in range(phnum):
        typ, _off, _va, pa, filesz = struct.unpack_from("<IIIII", b, phoff + i * phentsize)
        if typ == PT_LOAD and filesz and flash[0] <= pa < flash[1]:
            fl += filesz
    secs = [struct.unpack_from("<IIIIIIIIII", b, shoff + i * shentsize) for i in range(shnum)]
    names_off = secs[shstrndx][4]
    alloc = stacks = data_addr = 0
    for name, typ, flags, addr, _off, size, *_ in secs:
        if not flags & SHF_ALLOC or not size or not sram[0] <= addr < sram[1]:
            continue
        n = cstr(b, names_off + name)
        alloc += size
        if n in STACK_SECTIONS:
            stacks += size
        if n == ".data":
            data_addr = addr
    syms, work = {}, 0
    for _name, typ, _flags, _addr, off, size, link, _info, _align, entsize in secs:
        if typ != SHT_SYMTAB:
            continue
        stroff = secs[link][4]
        for k in range(size // entsize):
            st_name, value, st_size, _i, _o, _shndx = struct.unpack_from("<IIIBBH", b, off + k * entsize)
            n = cstr(b, stroff + st_name)
            syms[n] = value
            if n in WORK_SYMBOLS and sram[0] <= value < sram[1]:
                work += st_size
            elif n in STACK_SYMBOLS and sram[0] <= value < sram[1]:
                stacks += st_size
    if "__ram_code_start" in syms and "__ram_code_end" in syms:
        code = syms["__ram_code_end"] - syms["__ram_code_start"]
    elif board == "pico" and data_addr:
        code = map_code(path[:-4] + ".map", data_addr)
    else:
        code = 0
    return {"flash": fl, "code": code, "data": alloc - code - work - stacks, "work": work, "stacks": stacks,
            "sram": alloc, "left": total - alloc}


def kb(n):
    return f"{n / 1000:.1f}"


def images(build):
    """[(board, name, path)] of every image in BUILD/firmware"""
    out = []
    for board in BOARDS:
        for p in sorted(glob.glob(os.path.join(build, "firmware", board, "*.elf"))):
            name = os.path.basename(p)[:-4]
            if board == "pico" and name == "boot2":
                continue
            out.append((board, name, p))
    return out


def doc_key(board, name):
    return name if board == "pico" else f"stm32f411/{name}"


def figures(build):
    """{doc key: figures} of the images docs/firmware.md names"""
    fig = {}
    for board, names in (("pico", RP_IMAGES), ("stm32f411", ST_IMAGES)):
        for im in names:
            fig[doc_key(board, im)] = elf_figures(os.path.join(build, "firmware", board, im + ".elf"), board)
    return fig


def row_text(f):
    return (f"{kb(f['flash'])} KB | {kb(f['code'])} + {kb(f['data'])} + {kb(f['work'])} + {kb(f['stacks'])} = "
            f"{kb(f['sram'])} KB | {kb(f['left'])} KB")


def rewrite(text, fig, report):
    """text with every figure replaced by fig's; report(name, doc, build) for each"""
    def row(m):
        f = fig.get(m.group(2))
        if not f:
            return m.group(0)
        want = row_text(f)
        report(f"table_{m.group(2)}", m.group(3), want)
        return m.group(1) + want
    text = re.sub(r"^(\| `([\w/-]+)`[^|\n]*\| )([\d.]+ KB \| [\d.]+ \+ [\d.]+ \+ [\d.]+ \+ [\d.]+ = [\d.]+ KB "
                  r"\| [\d.]+ KB)", row, text, flags=re.M)

    def one(name, pattern, value):
        nonlocal text
        m = re.search(pattern, text)
        if not m:
            report(name, None, value)
            return
        report(name, m.group(2), value)
        text = text[:m.start(2)] + value + text[m.end(2):]
    one("cube_sram_left", r"(The two-core cube image leaves )([\d.]+)(?= KB of SRAM)", kb(fig["cgfs-cube"]["left"]))
    return text


COLS = ("flash", "code", "data", "work", "stacks", "sram", "left")


def table(build, before):
    """every image of build (with before's figures first, where it has the image)"""
    rows = [("image",) + COLS]
    for board, name, path in images(build):
        f = elf_figures(path, board)
        old = None
        if before:
            op = os.path.join(before, "firmware", board, name + ".elf")
            old = elf_figures(op, board) if os.path.exists(op) else None
        cells = [doc_key(board, name)]
        for c in COLS:
            cells.append(f"{f[c]:,}" if not old else f"{old[c]:,} -> {f[c]:,}")
        rows.append(tuple(cells))
    w = [max(len(r[i]) for r in rows) for i in range(len(COLS) + 1)]
    for r in rows:
        print("  ".join(c.ljust(w[0]) if i == 0 else c.rjust(w[i]) for i, c in enumerate(r)))
    print("bytes; SRAM = code + data + work + stacks; left: of the board's SRAM (tools/fw_sizes.py's docstring)")


def main(argv):
    if len(argv) not in (1, 3) or (len(argv) == 3 and argv[1] not in ("--write", "--check", "--before")):
        sys.stderr.write("usage: fw_sizes.py BUILD_DIR [--write DOC | --check DOC | --before OLD_BUILD_DIR]\n")
        return 2
    if len(argv) == 1 or argv[1] == "--before":
        try:
            if not images(argv[0]):
                raise OSError(f"no images in {argv[0]}/firmware")
            table(argv[0], argv[2] if len(argv) == 3 else None)
        except (OSError, ValueError) as e:
            sys.stderr.write(f"fw_sizes.py: {e} (make firmware builds the images)\n")
            return 1
        return 0
    try:
        fig = figures(argv[0])
    except (OSError, ValueError) as e:
        sys.stderr.write(f"fw_sizes.py: {e} (make firmware builds the images)\n")
        if argv[1] == "--check":
            print(f"FAIL fw_sizes_images: {e}")
        return 1
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
