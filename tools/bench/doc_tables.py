#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Rewrites the measured tables of README.md and docs/*.md from
build/bench/results.jsonl (`make bench-tables`, after `make bench`).

A generated table sits between two comments that name its generator:

    <!-- begin bench-table rt_table.py --summary #1 -->
    | ... |
    <!-- end bench-table -->

The first word is a script of tools/bench/ that prints markdown tables from a
results file; further words are its options, and `#N` picks the N-th of the
tables it prints (separated by blank lines; the first by default).

Usage: doc_tables.py [--check] [RESULTS] [--root DIR]
  (default) rewrite every generated table whose figures changed
  --check   rewrite nothing; list the stale tables and exit 1 if any
Every generator runs before anything is written: one that fails (rows
missing from the results) leaves every file as it was, exit 1.
"""
import os
import re
import subprocess
import sys

BEGIN = re.compile(r"^<!-- begin bench-table (\S+)((?: \S+)*) -->$")
END = "<!-- end bench-table -->"
HERE = os.path.dirname(os.path.abspath(__file__))


class TableError(Exception):
    pass


def documents(root):
    out = [os.path.join(root, "README.md")]
    docs = os.path.join(root, "docs")
    if os.path.isdir(docs):
        out += sorted(os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
    return [p for p in out if os.path.isfile(p)]


def generate(script, args, results, cache):
    """The lines of the table `script args` prints (cached per command)."""
    pick = [a for a in args if a.startswith("#")]
    opts = [a for a in args if not a.startswith("#")]
    if len(pick) > 1 or not re.fullmatch(r"[a-z0-9_]+\.py", script):
        raise TableError("bad generator %s" % " ".join([script] + args))
    key = (script, tuple(opts))
    if key not in cache:
        path = os.path.join(HERE, script)
        if not os.path.isfile(path):
            raise TableError("no generator tools/bench/%s" % script)
        p = subprocess.run([sys.executable, path] + opts + [results], capture_output=True, text=True)
        if p.returncode != 0:
            msg = (p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[-1]
            raise TableError("%s: %s" % (script, msg))
        tables = [t.strip("\n").splitlines() for t in re.split(r"\n\s*\n", p.stdout) if t.strip()]
        cache[key] = tables
    tables = cache[key]
    n = int(pick[0][1:]) if pick else 1
    if not 1 <= n <= len(tables):
        raise TableError("%s prints %d table(s), not #%d" % (script, len(tables), n))
    return tables[n - 1]


def rewrite(text, name, results, cache):
    """text with its generated tables renewed; (new text, [stale table names])."""
    lines = text.split("\n")
    out, stale, i = [], [], 0
    while i < len(lines):
        m = BEGIN.match(lines[i])
        out.append(lines[i])
        i += 1
        if not m:
            continue
        j = i
        while j < len(lines) and lines[j] != END and not BEGIN.match(lines[j]):
            j += 1
        if j == len(lines) or lines[j] != END:
            raise TableError("%s:%d: bench-table without its end comment" % (name, i))
        new = generate(m.group(1), m.group(2).split(), results, cache)
        if lines[i:j] != new:
            stale.append("%s:%d (%s)" % (name, i, (m.group(1) + m.group(2))))
        out += new
        i = j
    return "\n".join(out), stale


def main(argv):
    check = "--check" in argv
    argv = [a for a in argv if a != "--check"]
    root = "."
    if "--root" in argv:
        k = argv.index("--root")
        if k + 1 >= len(argv):
            sys.exit("usage: doc_tables.py [--check] [RESULTS] [--root DIR]")
        root = argv[k + 1]
        del argv[k:k + 2]
    if len(argv) > 1 or any(a.startswith("-") for a in argv):
        sys.exit("usage: doc_tables.py [--check] [RESULTS] [--root DIR]")
    results = argv[0] if argv else os.path.join(root, "build/bench/results.jsonl")
    if not os.path.isfile(results):
        sys.stderr.write("doc_tables.py: error: no %s (make bench writes it)\n" % results)
        return 1
    cache, new, stale = {}, {}, []
    try:
        for path in documents(root):
            with open(path, encoding="utf-8") as fh:
                text = fh.read()
            name = os.path.relpath(path, root)
            renewed, s = rewrite(text, name, results, cache)
            stale += s
            if renewed != text:
                new[path] = renewed
    except TableError as e:
        sys.stderr.write("doc_tables.py: error: %s (nothing written)\n" % e)
        return 1
    for s in stale:
        print(("stale: " if check else "rewrote: ") + s)
    if check:
        return 1 if stale else 0
    for path, text in new.items():
        tmp = path + ".tmp"
        with open(tmp, "w", encoding="utf-8") as fh:
            fh.write(text)
        os.replace(tmp, path)
    if not stale:
        print("doc_tables.py: every generated table is up to date")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
