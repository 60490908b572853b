#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Adds the image's number format to the JSON lines of a board run:
"num_frac": N from the NUM_FRAC a scene set's generated header defines
(build/firmware/scenes/fw_<set>_num_frac.h), so that accuracy.py measures
each row's accuracy at the format the board image renders in (a scene set
is built at the coarsest format among its scenes, not each scene's own).

usage: tag_frac.py RESULTS.jsonl HEADER   (rewrites RESULTS in place;
HEADER "-": nothing to add)
"""
import json
import os
import re
import sys


def main():
    path, header = sys.argv[1], sys.argv[2]
    if header == "-":
        return 0
    with open(header) as f:
        m = re.search(r"#define\s+NUM_FRAC\s+(\d+)", f.read())
    if not m:
        print("tag_frac.py: %s defines no NUM_FRAC" % header, file=sys.stderr)
        return 1
    frac = int(m.group(1))
    with open(path) as f:
        lines = [l for l in f if l.strip()]
    out = []
    for l in lines:
        try:
            r = json.loads(l)
        except ValueError:
            out.append(l.rstrip("\n"))   # not a result line: as it was
            continue
        if r.get("numeric") == "fixed":
            r["num_frac"] = frac
        out.append(json.dumps(r, separators=(",", ":")))
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(out) + "\n")
    os.replace(tmp, path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
