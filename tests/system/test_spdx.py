#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""test_spdx.py — every source file of the repository carries its licence.

The project is MIT-licensed (LICENSE); each C, header, assembly, linker,
table, Python, shell, JavaScript, make and udev file says so in one of its
first two lines (after a #! line): "SPDX-License-Identifier: MIT". Data
(scene files, test vectors, images, JSON) and documents are not checked.

Usage: test_spdx.py [ROOT]   (default: the tree this file is in)
       test_spdx.py --self-test
Prints PASS or FAIL lines.
"""
import os
import subprocess
import sys
import tempfile

TAG = "SPDX-License-Identifier: MIT"
CODE = (".c", ".h", ".S", ".inc", ".ld", ".def", ".js", ".py", ".sh", ".mk", ".rules")
NAMED = ("Makefile", ".ci/run")


def tracked(root):
    out = subprocess.run(["git", "-C", root, "ls-files"], capture_output=True, text=True)
    if out.returncode != 0:
        return None
    return out.stdout.split()


def missing(root, files):
    bad = []
    for f in files:
        if not (f.endswith(CODE) or f in NAMED):
            continue
        with open(os.path.join(root, f), encoding="utf-8", errors="replace") as fh:
            head = [fh.readline() for _ in range(3)]
        if head[0].startswith("#!"):
            head = head[1:]
        if not any(TAG in line for line in head[:2]):
            bad.append(f)
    return bad


def self_test():
    with tempfile.TemporaryDirectory() as root:
        files = {"a.c": "/* " + TAG + " */\nint x;\n", "b.py": "#!/usr/bin/env python3\n# " + TAG + "\n",
                 "c.sh": "#!/bin/sh\necho\n", "d.scene": "x = 1\n"}
        for name, text in files.items():
            with open(os.path.join(root, name), "w") as fh:
                fh.write(text)
        bad = missing(root, list(files))
        ok = bad == ["c.sh"]
        print(("PASS" if ok else "FAIL") + " spdx self-test" + ("" if ok else ": found %r" % bad))
        return 0 if ok else 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    files = tracked(root)
    if files is None:
        print("SKIP spdx: not a git checkout")
        return self_test()
    bad = missing(root, files)
    if bad:
        print("FAIL spdx: %d source files without \"%s\": %s" % (len(bad), TAG, " ".join(bad[:20])))
    else:
        print("PASS spdx: %d source files" % sum(1 for f in files if f.endswith(CODE) or f in NAMED))
    return (1 if bad else 0) | self_test()


if __name__ == "__main__":
    sys.exit(main())
