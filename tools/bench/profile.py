#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Instructions per function of an emulated-MCU image (qemu-system-arm).

Runs IMAGE.elf once in qemu with the translation-block trace
(-d in_asm,exec,nochain) streamed through a FIFO, so nothing large is
written to disk, and counts for every executed block its instructions
(from the block's disassembly) under the function the block starts in
(self cost: a function's callees are counted under their own names), and
its inclusive cost (callees included) by following BL/BLX calls and their
returns on a shadow stack (a recursive function is counted once per
outermost call).

  profile.py [--target m0plus-qemu|m4f-qemu] [--top N] [--json FILE]
             [--lines N] [--annotate FUNC ...] IMAGE.elf [ARG ...]

ARGs are passed to the image as its semihosting command line (argv[1] on),
e.g. the lab's bench_file.elf with a scene file, size, strip height and
frame count: profile.py bench_file.elf SCENE 240 240 16 1.

--lines N lists the N source lines whose instructions ran most (code
inlined from a header counted at the header's line); --annotate FUNC prints FUNC's disassembly (with source lines) and how many
times each instruction ran: where inside a function the time goes.

The target is taken from the image's path (build/bench/<target>/...) when
not given. Tracing slows qemu by about 50x: profile small images (a few
hundred million instructions at most). The image's own BENCH figures are
meaningless under tracing (no -icount) and are not printed.
"""
import argparse
import collections
import json
import os
import subprocess
import sys
import tempfile
import threading

MACHINES = {"m0plus-qemu": "mps2-an385", "m4f-qemu": "mps2-an386"}


def target_of(elf):
    for p in os.path.normpath(elf).split(os.sep):
        if p in MACHINES:
            return p
    return None


def profile(elf, target, args=()):
    tmp = tempfile.mkdtemp(prefix="qprof")
    fifo = os.path.join(tmp, "trace")
    os.mkfifo(fifo)
    cmd = ["qemu-system-arm", "-M", MACHINES[target], "-nographic", "-monitor", "none",
           "-serial", "null", "-semihosting-config",
           "enable=on,target=native" + "".join(",arg=" + x for x in ([elf] + list(args) if args else [])),
           "-d", "in_asm,exec,nochain", "-D", fifo, "-kernel", elf]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    size = {}                          # block start pc -> instructions
    insns = {}                         # block start pc -> addresses of its instructions
    calls = {}                         # block start pc -> return address if it ends in BL/BLX
    runs = collections.Counter()       # block start pc -> executions
    name = {}                          # block start pc -> function
    incl = collections.Counter()       # function -> inclusive instructions
    ncalls = collections.Counter()     # function -> calls (BL/BLX into it)
    active = collections.Counter()     # function -> activations on the stack
    stack = []                         # [return address, callee, total at the call]
    total = 0
    pending = None                     # a call whose callee is not known yet
    try:
        with open(fifo, "r", errors="replace") as f:
            block, count, last = None, 0, ""
            for line in f:
                c = line[:1]
                if c == "T":           # Trace 0: host [cs/pc/flags/..] symbol
                    lb = line.find("[")
                    if lb < 0:
                        continue
                    rb = line.find("]", lb)
                    pc = int(line[lb + 1:rb].split("/")[1], 16)
                    runs[pc] += 1
                    fn = name.get(pc)
                    if fn is None:
                        fn = name[pc] = line[rb + 1:].strip() or hex(pc)
                    while stack and stack[-1][0] == pc:      # returned
                        _, callee, t0 = stack.pop()
                        active[callee] -= 1
                        if active[callee] == 0:
                            incl[callee] += total - t0
                    if pending is not None:
                        pending[1] = fn
                        active[fn] += 1
                        ncalls[fn] += 1
                        pending = None
                    total += size.get(pc, 1)
                    ret = calls.get(pc)
                    if ret is not None:
                        pending = [ret, None, total]
                        stack.append(pending)
                elif c == "0":         # 0x0000349a:  3b01  subs ...
                    if block is not None:
                        a = int(line[:line.find(":")], 16)
                        if count == 0:
                            block = a
                            addrs = []
                        addrs.append(a)
                        count += 1
                        last = line
                elif c == "I":         # IN: symbol
                    block, count = -1, 0
                elif c == "\n" or c == "-":
                    if block is not None and block >= 0 and count:
                        size[block] = count
                        insns[block] = addrs
                        f2 = last.split()
                        # 0xADDR: hex [hex] mnemonic ...: BL is 4 bytes, BLX reg 2
                        if len(f2) >= 3:
                            addr = int(f2[0].rstrip(":"), 16)
                            nhex = 2 if len(f2) > 3 and all(ch in "0123456789abcdef" for ch in f2[2]) and len(f2[2]) == 4 else 1
                            mnem = f2[1 + nhex]
                            if mnem in ("bl", "blx"):
                                calls[block] = addr + 2 * nhex
                    block = None
    finally:
        proc.wait()
        os.unlink(fifo)
        os.rmdir(tmp)
    for _, callee, t0 in stack:
        if callee is not None and active[callee] > 0:
            incl[callee] += total - t0
            active[callee] = 0
    per = collections.Counter()
    at = collections.Counter()         # instruction address -> executions
    for pc, n in runs.items():
        per[name.get(pc, hex(pc))] += n * size.get(pc, 1)
        for a in insns.get(pc, ()):
            at[a] += n
    return per, incl, ncalls, at


def by_line(elf, at, top):
    """The top source lines (inlined code under its own line) by executions
    of their instructions."""
    addrs = sorted(at)
    res = subprocess.run(["arm-none-eabi-addr2line", "-e", elf, "-f", "-i", "-a"] +
                         [hex(a) for a in addrs], capture_output=True, text=True).stdout.splitlines()
    per = collections.Counter()
    a = None
    i = 0
    while i < len(res):
        line = res[i]
        if line.startswith("0x"):
            a = int(line, 16)
            i += 1
            # the innermost location comes first (function name, file:line)
            if i + 1 < len(res):
                fn, loc = res[i], res[i + 1].split(" (discriminator")[0]
                path, _, line_no = loc.rpartition(":")
                per[f"{os.path.relpath(path)}:{line_no} {fn}" if path else f"{loc} {fn}"] += at[a]
            while i < len(res) and not res[i].startswith("0x"):
                i += 1
        else:
            i += 1
    total = sum(at.values())
    print(f"{'source line (innermost, function)':60s} {'instructions':>14s} {'share':>7s}")
    for k, n in per.most_common(top):
        print(f"{k:60s} {n:14d} {100.0 * n / total:6.2f}%")


def annotate(elf, fn, at):
    """The disassembly of function fn with each instruction's executions."""
    out = subprocess.run(["arm-none-eabi-objdump", "-d", "-l", "--no-show-raw-insn",
                          f"--disassemble={fn}", elf], capture_output=True, text=True).stdout
    total = 0
    for line in out.splitlines():
        m = line.split(":", 1)
        try:
            a = int(m[0].strip(), 16) if len(m) == 2 and line.startswith(" ") else None
        except ValueError:
            a = None
        if a is None:
            print(f"{'':>10s}  {line}")
            continue
        n = at.get(a, 0)
        total += n
        print(f"{n:10d}  {line}")
    print(f"{total:10d}  instructions executed in {fn}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("image")
    ap.add_argument("args", nargs="*", help="the image's semihosting arguments")
    ap.add_argument("--target", choices=sorted(MACHINES))
    ap.add_argument("--top", type=int, default=25)
    ap.add_argument("--json")
    ap.add_argument("--lines", type=int, metavar="N",
                    help="also list the N most executed source lines (inlined code at its own line)")
    ap.add_argument("--annotate", metavar="FUNC", action="append", default=[],
                    help="print FUNC's disassembly with each instruction's executions")
    a = ap.parse_args()
    if not os.path.isfile(a.image):
        sys.exit(f"profile.py: {a.image}: no such image")
    target = a.target or target_of(a.image)
    if target is None:
        sys.exit(f"profile.py: {a.image}: path names no target; give --target")
    for x in a.args:
        if "," in x:
            sys.exit(f"profile.py: argument {x!r}: a semihosting argument cannot hold a comma")
    per, incl, ncalls, at = profile(a.image, target, a.args)
    total = sum(per.values())
    if total == 0:
        sys.exit("profile.py: no blocks traced (qemu-system-arm missing or the image did not run)")
    print(f"{'function (self)':40s} {'instructions':>14s} {'share':>7s}")
    for fn, n in per.most_common(a.top):
        print(f"{fn:40s} {n:14d} {100.0 * n / total:6.2f}%")
    print(f"{'total':40s} {total:14d}")
    print()
    print(f"{'function (inclusive)':40s} {'instructions':>14s} {'share':>7s} {'calls':>10s} {'per call':>9s}")
    for fn, n in incl.most_common(a.top):
        c = ncalls.get(fn, 0)
        print(f"{fn:40s} {n:14d} {100.0 * n / total:6.2f}% {c:10d} {n / c if c else 0:9.0f}")
    if a.lines:
        print()
        by_line(a.image, at, a.lines)
    for fn in a.annotate:
        print()
        annotate(a.image, fn, at)
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"image": a.image, "target": target, "total": total,
                       "self": dict(per.most_common()), "inclusive": dict(incl.most_common()),
                       "calls": dict(ncalls.most_common())},
                      f, indent=1)


if __name__ == "__main__":
    main()
