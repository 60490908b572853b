#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""tools/bench/profile.py's accounting (Calls) on a made-up block trace,
without qemu: a call (BL), a tail call (B into another function's entry)
returning straight to the first caller, recursion whose inner activation
branches to its own call's return address before returning, exceptions
(one between a call and its callee's first block), and a BL that is a long
jump inside a function. Checks self and inclusive
instructions and calls of every function (inclusive never below self, the
entry function's inclusive the total, recursion counted once), and the
classification of a block's last instruction (end_of).
usage: test_profile.py
"""
import importlib.util
import os
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
spec = importlib.util.spec_from_file_location("profile_tool", os.path.join(ROOT, "tools", "bench", "profile.py"))
prof = importlib.util.module_from_spec(spec)
spec.loader.exec_module(prof)
failed = 0


def check(ok, name, why=""):
    global failed
    print("PASS %s" % name if ok else "FAIL %s: %s" % (name, why))
    failed += not ok


# (pc, function, instructions, kind of its last instruction, return address)
TRACE = [
    (0x100, "main", 2, "call", 0x104),  # BL f, interrupted before f's first block
    "enter",
    (0x500, "isr", 2, "ret", None),
    "return",
    (0x200, "f", 2, None, None),        # f: a conditional branch to 0x20c or on
    (0x204, "f", 1, "call", 0x208),     # BL g
    (0x300, "g", 4, None, None),        # B h: a tail call
    (0x400, "h", 5, "ret", None),       # returns to f (g's caller)
    (0x208, "f", 1, "call", 0x20c),     # BL f: recursion
    (0x200, "f", 2, None, None),        # the inner f branches to 0x20c,
    (0x20c, "f", 1, "ret", None),       # its own call's return address: no return
    (0x20c, "f", 1, "ret", None),       # the outer f, back from the inner one
    (0x104, "main", 1, None, None),
    "enter",
    (0x500, "isr", 2, "ret", None),     # an exception's handler
    "return",
    (0x106, "main", 1, "call", 0x10a),  # BL to a label of main: a long jump
    (0x180, "main", 1, None, None),
]
acc = prof.Calls({0x100, 0x200, 0x300, 0x400, 0x500})
for b in TRACE:
    if isinstance(b, str):
        acc.exception(b)
    else:
        acc.block(*b)
acc.finish()
want_self = {"main": 5, "f": 8, "g": 4, "h": 5, "isr": 4}
want_incl = {"main": 26, "f": 17, "g": 9, "h": 5, "isr": 4}
want_calls = {"main": 1, "f": 2, "g": 1, "h": 1, "isr": 2}
check(acc.total == 26, "total", acc.total)
check(dict(acc.self) == want_self, "self", dict(acc.self))
check(dict(acc.incl) == want_incl, "inclusive", dict(acc.incl))
check(dict(acc.ncalls) == want_calls, "calls", dict(acc.ncalls))
check(all(acc.incl[f] >= n for f, n in acc.self.items()), "inclusive >= self")
check(not acc.stack and not +acc.active, "every activation ended", acc.stack)

# Without the functions' start addresses, a change of function name or a BL
# starts one (the long jump is then a call of main).
acc = prof.Calls()
for b in TRACE[:-2]:
    if isinstance(b, str):
        acc.exception(b)
    else:
        acc.block(*b)
acc.finish()
want_incl["main"] -= 2
check(dict(acc.incl) == want_incl and dict(acc.ncalls) == want_calls, "no entries",
      (dict(acc.incl), dict(acc.ncalls)))

ENDS = [
    ("0x00040d86:  f000 fa1f  bl       #0x411c8", ("call", 0x40d8a)),
    ("0x00000102:  4798       blx      r3", ("call", 0x104)),
    ("0x00041262:  bdf0       pop      {r4, r5, r6, r7, pc}", ("ret", None)),
    ("0x00041264:  4770       bx       lr", ("ret", None)),
    ("0x0002e86e:  bc80       pop      {r7}", (None, None)),
    ("0x0002e870:  e7f0       b        #0x2e854", (None, None)),
    ("0x0002e872:  d1f0       bne      #0x2e856", (None, None)),
]
for line, want in ENDS:
    got = prof.end_of(line)
    check(got == want, "end_of " + " ".join(line.split()[-2:]), got)

sys.exit(1 if failed else 0)
