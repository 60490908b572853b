#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Instructions per function of an emulated-MCU image (qemu-system-arm).

Runs IMAGE.elf once in qemu with the translation-block trace
(-d in_asm,exec,nochain,int) streamed through a FIFO, so nothing large is
written to disk, and counts for every executed block its instructions
(from the block's disassembly) under the function the block starts in
(self cost: a function's callees are counted under their own names), and
its inclusive cost (callees included) and calls by following BL/BLX calls,
tail calls (a branch to a function's entry: the function that branched
includes the one it branched to), returns and exceptions (qemu's interrupt
log) on a shadow stack (class Calls; a recursive function is counted once
per outermost call). The entry function's inclusive cost is the total.

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


EXC = -1                               # the return address of an exception's frame


class Calls:
    """Self and inclusive instructions and calls per function from the
    executed blocks, in order (block()), on a shadow stack of frames.

    A frame is what one call opens: BL/BLX into another function (a BL
    whose target lies in the calling function is a long jump, not a call),
    an exception's entry, or the first block (the entry function's frame,
    which never returns). A block reached by a return (BX, POP/LDM/LDR/MOV
    into pc) at the return address of a frame on the stack closes that
    frame and every frame above it (functions that returned past their
    caller); an exception's return closes the innermost exception frame and
    those above it, and the block after it follows the interrupted one (a
    call interrupted before its callee's first block is still a call).

    Tail calls: a function's entry reached otherwise (a B or BX to it, or by
    falling through) is a call of that function in the current frame, so
    both the function that branched and the one it branched to are active
    until the frame returns: the first's inclusive cost includes the
    second's, as if it had called it. Each call, and the entry function's
    start, counts once; a function's inclusive cost counts from its
    outermost activation's start to its end (recursion is not counted
    twice), so it is never below its self cost and the entry function's is
    the total.

    entries: the functions' start addresses (None: a block whose function's
    name differs from the previous block's, or that a BL/BLX reached, starts
    a function).
    """

    def __init__(self, entries=None):
        self.entries = entries
        self.self = collections.Counter()     # function -> self instructions
        self.incl = collections.Counter()     # function -> inclusive instructions
        self.ncalls = collections.Counter()   # function -> calls
        self.active = collections.Counter()   # function -> activations on the stack
        self.since = {}                       # function -> total at its outermost activation
        self.stack = []                       # [return address or EXC, [functions active]
                                              #  (, the interrupted block's self.prev)]
        self.total = 0
        self.prev = None                      # (function, kind, return address) of the last block
        self.exc = []                         # exceptions entered / returned from before the next block

    def _enter(self, fn, frame):
        frame[1].append(fn)
        self.ncalls[fn] += 1
        self.active[fn] += 1
        if self.active[fn] == 1:
            self.since[fn] = self.total

    def _pop(self, depth):
        while len(self.stack) > depth:
            for fn in self.stack.pop()[1]:
                self.active[fn] -= 1
                if self.active[fn] == 0:
                    self.incl[fn] += self.total - self.since.pop(fn)

    def exception(self, what):
        """The next block enters ("enter") or returns from ("return") an exception."""
        self.exc.append(what)

    def block(self, pc, fn, size, kind=None, ret=None):
        """One executed block at pc in function fn of size instructions, ending
        in a call ("call", returning to ret), a return ("ret") or neither."""
        exc, self.exc = self.exc, []
        for what in exc:
            if what == "return":
                for i in range(len(self.stack) - 1, 0, -1):
                    if self.stack[i][0] == EXC:
                        self.prev = self.stack[i][2]          # the interrupted block
                        self._pop(i)
                        break
        pfn, pkind, pret = self.prev or (None, None, None)
        entry = pc in self.entries if self.entries is not None else fn != pfn or pkind == "call"
        if not self.stack:
            self.stack.append([None, []])
            self._enter(fn, self.stack[-1])
        elif exc and exc[-1] == "enter":
            self.stack.append([EXC, [], self.prev])
            self._enter(fn, self.stack[-1])
        elif pkind == "call" and (entry or fn != pfn):
            self.stack.append([pret, []])
            self._enter(fn, self.stack[-1])
        else:
            back = False
            if pkind == "ret":
                for i in range(len(self.stack) - 1, 0, -1):
                    if self.stack[i][0] == pc:
                        self._pop(i)
                        back = True
                        break
                    if self.stack[i][0] == EXC:
                        break
            if not back and entry and fn != pfn:
                self._enter(fn, self.stack[-1])
        self.self[fn] += size
        self.total += size
        self.prev = (fn, kind, ret)

    def finish(self):
        """Ends every activation still on the stack (the image exited)."""
        self._pop(0)
        return self


def entries_of(elf):
    """The start addresses of the image's functions (None without nm)."""
    try:
        out = subprocess.run(["arm-none-eabi-nm", "--defined-only", elf],
                             capture_output=True, text=True).stdout
    except OSError:
        return None
    res = set()
    for line in out.splitlines():
        f = line.split()
        if len(f) == 3 and f[1] in "tTwW":
            res.add(int(f[0], 16) & ~1)
    return res or None


def end_of(line):
    """The kind of a block's last instruction ("call", "ret" or None) and the
    return address of a call, from its disassembly line
    (0xADDR: hex [hex] mnemonic operands)."""
    f = line.split()
    if len(f) < 3:
        return None, None
    addr = int(f[0].rstrip(":"), 16)
    nhex = 2 if len(f) > 3 and len(f[2]) == 4 and all(ch in "0123456789abcdef" for ch in f[2]) else 1
    mnem = f[1 + nhex]
    ops = " ".join(f[2 + nhex:])
    if mnem in ("bl", "blx"):
        return "call", addr + 2 * nhex            # BL is 4 bytes, BLX reg 2
    if mnem.startswith("bx") or (mnem.split(".")[0] in ("pop", "ldm", "ldmia") and "pc" in ops) \
            or (mnem.split(".")[0] in ("ldr", "mov") and ops.startswith("pc")):
        return "ret", None
    return None, None


def profile(elf, target, args=()):
    tmp = tempfile.mkdtemp(prefix="qprof")
    fifo = os.path.join(tmp, "trace")
    os.mkfifo(fifo)
    cmd = ["qemu-system-arm", "-M", MACHINES[target], "-nographic", "-monitor", "none",
           "-serial", "null", "-semihosting-config",
           "enable=on,target=native" + "".join(",arg=" + x for x in ([elf] + list(args) if args else [])),
           "-d", "in_asm,exec,nochain,int", "-D", fifo, "-kernel", elf]
    acc = Calls(entries_of(elf))
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    size = {}                          # block start pc -> instructions
    insns = {}                         # block start pc -> addresses of its instructions
    ends = {}                          # block start pc -> (kind, return address) of its end
    runs = collections.Counter()       # block start pc -> executions
    name = {}                          # block start pc -> function
    held = None                        # the last block traced: qemu may yet cancel it
    try:
        with open(fifo, "r", errors="replace") as f:
            block, count, last = None, 0, ""
            for line in f:
                c = line[:1]
                if line.startswith("Trace"):      # Trace 0: host [cs/pc/flags/..] symbol
                    lb = line.find("[")
                    if lb < 0:
                        continue
                    rb = line.find("]", lb)
                    pc = int(line[lb + 1:rb].split("/")[1], 16)
                    fn = name.get(pc)
                    if fn is None:
                        fn = name[pc] = line[rb + 1:].strip() or hex(pc)
                    if held is not None:
                        runs[held[0]] += 1
                        acc.block(*held)
                    held = (pc, fn, size.get(pc, 1)) + ends.get(pc, (None, None))
                elif line.startswith("Stopped execution"):   # ... before host [pc] symbol
                    lb = line.find("[")
                    if held is not None and lb >= 0 and int(line[lb + 1:line.find("]", lb)], 16) == held[0]:
                        held = None    # the block did not run (an interrupt came first)
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
                        ends[block] = end_of(last)
                    block = None
                elif line.startswith(("...loaded new PC", "Exception return")):
                    if held is not None:
                        runs[held[0]] += 1
                        acc.block(*held)
                        held = None
                    acc.exception("enter" if line[0] == "." else "return")
    finally:
        proc.wait()
        os.unlink(fifo)
        os.rmdir(tmp)
    if held is not None:
        runs[held[0]] += 1
        acc.block(*held)
    acc.finish()
    at = collections.Counter()         # instruction address -> executions
    for pc, n in runs.items():
        for a in insns.get(pc, ()):
            at[a] += n
    return acc.self, acc.incl, acc.ncalls, at


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
