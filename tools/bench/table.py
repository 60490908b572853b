#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Prints the markdown cost table of docs/numerics.md from results.jsonl:
instructions per operation (qemu instruction counts, not cycles) for each
target and numeric mode.  Usage: table.py [build/bench/results.jsonl]"""
import json
import sys

path = sys.argv[1] if len(sys.argv) > 1 else "build/bench/results.jsonl"
rows = {}
cols = []
with open(path) as fh:
    for line in fh:
        r = json.loads(line)
        if r.get("per") != "op" or r.get("target") not in ("m0plus-qemu", "m4f-qemu"):
            continue
        col = f'{r["target"]} {r["numeric"]}' if not r["variant"].startswith("toolchain") else f'{r["target"]} toolchain'
        if col not in cols:
            cols.append(col)
        rows.setdefault(r["what"][3:], {})[col] = r["instructions"]
cols.sort(key=lambda c: (c.split()[0] != "m0plus-qemu", ["fixed", "float", "double", "toolchain"].index(c.split()[1])))
print("| operation | " + " | ".join(cols) + " |")
print("|---" * (len(cols) + 1) + "|")
for op, v in rows.items():
    print(f"| `{op}` | " + " | ".join(f"{v[c]:.0f}" if c in v else "" for c in cols) + " |")
