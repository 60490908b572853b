#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The measured tables of README.md and docs/*.md are generated from
results.jsonl (tools/bench/doc_tables.py, `make bench-tables`).

Checks the repository's own documents (every generated table has its end
comment and names a generator of tools/bench/ that exists), then, on copies
in a scratch directory with made-up rows: --check lists exactly the tables
whose figures differ and writes nothing; a rewrite puts each generator's
table in place (the N-th of several with #N) and a second --check is clean;
a generator that finds no rows, a table without its end comment or an
unknown generator leave every file as it was, exit 1, one line on stderr.
usage: test_doc_tables.py
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
TOOL = os.path.join(ROOT, "tools", "bench", "doc_tables.py")
failed = 0


def check(ok, name, why=""):
    global failed
    print("PASS %s" % name if ok else "FAIL %s: %s" % (name, why))
    failed += not ok


def run(*args):
    p = subprocess.run([sys.executable, TOOL] + list(args), capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def rows():
    """Made-up rows of the two mesh scenes and the ray tracer's bench image."""
    out = []
    for scene, tris, fixed in (("bench/knot-4k-flat", 4096, 5.0e6), ("bench/knot-16k-flat", 16384, 13.0e6)):
        for target, numeric, scale in (("m0plus-qemu", "fixed", 1), ("m0plus-qemu", "float", 2),
                                       ("m4f-qemu", "fixed", 0.5), ("m4f-qemu", "float", 0.4)):
            for per, div in (("frame", 1), ("triangle", tris)):
                r = {"target": target, "what": "scene:" + scene, "numeric": numeric, "variant": "default",
                     "instructions": fixed * scale / div, "per": per, "image": "scene-x.elf"}
                if target == "m0plus-qemu":
                    r["psnr"] = None if numeric == "fixed" else 51.25
                out.append(r)
    for what, variant, m in (("scene:book/raytracer-02", "strip16", 60e6),
                             ("scene:book/raytracer-05", "strip16", 170e6),
                             ("scene:book/raytracer-05", "adaptive_subsample=4", 85e6)):
        for target, numeric, scale in (("m0plus-qemu", "fixed", 1), ("m0plus-qemu", "float", 3),
                                       ("m4f-qemu", "fixed", 0.5), ("m4f-qemu", "float", 0.4)):
            out.append({"target": target, "what": what, "numeric": numeric, "variant": variant,
                        "instructions": m * scale, "per": "frame", "image": "raytracer.elf",
                        "psnr": 70.04 if numeric == "fixed" else 50.0})
    return out


DOC = """# Figures

Meshes (`tools/bench/mesh_table.py`):

<!-- begin bench-table mesh_table.py -->
| scene | old |
<!-- end bench-table -->

The ray tracer's board rows (`tools/bench/rt_table.py`):

<!-- begin bench-table rt_table.py #2 -->
| scene (RP2040, 133 MHz) | one core | two cores |
|---|---|---|
| raytracer-05 (exact) | — | — |
| raytracer-05, `adaptive_subsample = 4` | — | — |
| raytracer-02 | — | — |
<!-- end bench-table -->
"""
README = """# Project

<!-- begin bench-table rt_table.py --summary -->
<!-- end bench-table -->
"""


def scratch(tmp, doc=DOC, readme=README):
    root = os.path.join(tmp, "repo")
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(os.path.join(root, "docs"))
    with open(os.path.join(root, "README.md"), "w") as fh:
        fh.write(readme)
    with open(os.path.join(root, "docs", "figures.md"), "w") as fh:
        fh.write(doc)
    return root


def files(root):
    out = {}
    for name in ("README.md", os.path.join("docs", "figures.md")):
        with open(os.path.join(root, name)) as fh:
            out[name] = fh.read()
    return out


def main():
    # the repository's own documents: well-formed markers naming real generators
    begin = re.compile(r"^<!-- begin bench-table (\S+)((?: \S+)*) -->$")
    count = 0
    for name in ["README.md"] + sorted("docs/" + f for f in os.listdir(os.path.join(ROOT, "docs")) if f.endswith(".md")):
        lines = open(os.path.join(ROOT, name), encoding="utf-8").read().split("\n")
        for i, line in enumerate(lines):
            m = begin.match(line)
            if not m:
                if line.startswith("<!--") and "bench-table" in line:
                    check(line == "<!-- end bench-table -->", "%s:%d: a bench-table comment is well formed"
                          % (name, i + 1), line)
                continue
            count += 1
            script = os.path.join(ROOT, "tools", "bench", m.group(1))
            check(os.path.isfile(script), "%s:%d: generator %s exists" % (name, i + 1, m.group(1)))
            end = next((j for j in range(i + 1, len(lines)) if "bench-table" in lines[j]), None)
            check(end is not None and lines[end] == "<!-- end bench-table -->",
                  "%s:%d: the table ends before the next one begins" % (name, i + 1))
            check(end is not None and all(l.startswith("|") for l in lines[i + 1:end]) and end > i + 2,
                  "%s:%d: only a table between the comments" % (name, i + 1))
    check(count >= 8, "the documents carry their generated tables", "%d found" % count)

    with tempfile.TemporaryDirectory() as tmp:
        results = os.path.join(tmp, "results.jsonl")
        with open(results, "w") as fh:
            fh.write("".join(json.dumps(r) + "\n" for r in rows()))
        root = scratch(tmp)
        before = files(root)
        rc, out, err = run("--check", results, "--root", root)
        check(rc == 1 and "stale: README.md:3 (rt_table.py --summary)" in out and
              "stale: docs/figures.md:5 (mesh_table.py)" in out and "docs/figures.md:11" not in out,
              "--check lists the stale tables, not the current one", out + err)
        check(files(root) == before, "--check writes nothing")

        rc, out, err = run(results, "--root", root)
        after = files(root)
        check(rc == 0 and after != before, "a rewrite succeeds", out + err)
        doc = after[os.path.join("docs", "figures.md")]
        check("| bench/knot-4k-flat | 5.0 M / 1221 | 10.0 M / 2441 | 2.5 M / 610 | 2.0 M / 488 | exact / 51.2 dB |"
              in doc, "the mesh table is mesh_table.py's", doc)
        check("| bench/knot-16k-flat | 13.0 M / 793 |" in doc, "every mesh scene has its row", doc)
        check(doc.index("bench/knot-4k-flat") < doc.index("bench/knot-16k-flat"), "rows by triangle count")
        check("| raytracer-02 | — | — |" in doc and "| scene (RP2040, 133 MHz)" in doc,
              "#2 picks the generator's second table", doc)
        check("| raytracer-05 | 170 M, 70.0 dB | 510 M, 50.0 dB | 85 M, 70.0 dB | 68 M, 50.0 dB |" in after["README.md"],
              "an option reaches the generator", after["README.md"])
        check("Meshes (`tools/bench/mesh_table.py`):" in doc and doc.endswith("<!-- end bench-table -->\n"),
              "the text around the tables is kept", doc)
        rc, out, err = run("--check", results, "--root", root)
        check(rc == 0 and out == "", "a second --check finds nothing stale", out + err)

        # failures: nothing written anywhere, one line, exit 1
        bad_cases = [
            ("a generator without rows", DOC.replace("mesh_table.py -->", "methods_table.py -->"), README,
             "methods_table.py: no bench scene rows"),
            ("a table without its end", DOC, README.replace("<!-- end bench-table -->\n", ""),
             "README.md:3: bench-table without its end comment"),
            ("an unknown generator", DOC.replace("mesh_table.py -->", "nothing.py -->"), README,
             "no generator tools/bench/nothing.py"),
            ("a table the generator does not print", DOC.replace("#2", "#3"), README,
             "rt_table.py prints 2 table(s), not #3"),
        ]
        for name, doc_text, readme_text, message in bad_cases:
            root = scratch(tmp, doc_text, readme_text)
            before = files(root)
            rc, out, err = run(results, "--root", root)
            check(rc == 1 and message in err and len(err.strip().splitlines()) == 1 and files(root) == before,
                  "%s: exit 1, one line, nothing written" % name, "rc=%d out=%r err=%r" % (rc, out, err))
        rc, out, err = run(os.path.join(tmp, "missing.jsonl"), "--root", root)
        check(rc == 1 and "make bench" in err, "no results file: exit 1 with the command that makes it", err)

    print("%d failed" % failed)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
