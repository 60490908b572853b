#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The README's and the docs' pictures are current: tools/pictures.sh renders them again
with HOST_SIM into a temporary directory, and each must hold the same
pixels as its committed file in docs/images/ (pixels, not bytes: another
libpng may compress them otherwise); README.md or a page of docs/ shows every
one of them, and docs/images/ holds no other PNG; the README's example scene (the
first fenced block after "A scene is a short text file") renders without a
word on stderr.
  test_pictures.py HOST_SIM
Prints one PASS/FAIL line per check; `make pictures` rewrites the files."""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from xwd_compare import read_png  # noqa: E402

IMAGES = "docs/images"


def main():
    host_sim = sys.argv[1]
    ok = True
    with tempfile.TemporaryDirectory() as tmp:
        r = subprocess.run(["tools/pictures.sh", host_sim, tmp], capture_output=True, text=True)
        made = sorted(f for f in os.listdir(tmp) if f.endswith(".png"))
        if r.returncode != 0 or not made:
            print("FAIL pictures_render: exit %d: %s" % (r.returncode, r.stderr.strip()[:300]))
            return 1
        print("PASS pictures_render (%d pictures)" % len(made))
        for f in made:
            mine = os.path.join(IMAGES, f)
            if not os.path.exists(mine):
                print("FAIL picture_current[%s]: %s is missing (make pictures)" % (f, mine))
                ok = False
                continue
            new, old = read_png(os.path.join(tmp, f)), read_png(mine)
            if new != old:
                print("FAIL picture_current[%s]: %s differs from what the renderers draw now (make pictures)"
                      % (f, mine))
                ok = False
            else:
                print("PASS picture_current[%s] (%dx%d)" % (f, new[0], new[1]))
        extra = sorted(set(f for f in os.listdir(IMAGES) if f.endswith(".png")) - set(made))
        if extra:
            print("FAIL pictures_no_stale: %s not made by tools/pictures.sh" % ", ".join(extra))
            ok = False
        else:
            print("PASS pictures_no_stale")
        readme = open("README.md").read()
        shown = set(re.findall(r"\(docs/images/([^)]+\.png)\)", readme))
        for page in sorted(os.listdir("docs")):
            if page.endswith(".md"):
                shown |= set(re.findall(r"\(images/([^)]+\.png)\)", open(os.path.join("docs", page)).read()))
        missing = [f for f in made if f not in shown]
        if missing:
            print("FAIL pictures_in_readme: neither README.md nor docs/*.md shows %s" % ", ".join(missing))
            ok = False
        else:
            print("PASS pictures_in_readme")
        m = re.search(r"A scene is a short text file.*?\n```\n(.*?)```", readme, re.S)
        if not m:
            print("FAIL readme_scene_example: no example scene in README.md")
            return 1
        scene = os.path.join(tmp, "example.scene")
        with open(scene, "w") as f:
            f.write(m.group(1))
        r = subprocess.run([host_sim, "--scene", scene, "--out", os.path.join(tmp, "example.png")],
                           capture_output=True, text=True)
        lines = m.group(1).count("\n")
        if r.returncode != 0 or r.stderr or lines > 5:
            print("FAIL readme_scene_example: %d lines, exit %d: %s" % (lines, r.returncode, r.stderr.strip()[:300]))
            ok = False
        else:
            print("PASS readme_scene_example (%d lines)" % lines)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
