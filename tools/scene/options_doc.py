#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""options_doc.py — the key tables of docs/scene-format.md from the scene
options table, firmware/core/scene_options.def.

    options_doc.py                 print the raytracer and rasterizer option tables
    options_doc.py --write DOC     replace the tables between DOC's markers
    options_doc.py --check DOC     PASS/FAIL: the table is consistent, DOC's
                                   option tables are what --write would write,
                                   and DOC's top-level table lists the table's
                                   top-level keys in its order, *repeatable*
                                   where the table says so
    options_doc.py --self-test     the check finds planted differences

The option tables stand between the lines
    <!-- begin options BLOCK (tools/scene/options_doc.py) -->
    <!-- end options BLOCK -->
for BLOCK raytracer and rasterizer: one row per key, in the table's `order`,
with its values (kind, range, allowed values), default and doc line.
"""
import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
DEF = os.path.join(ROOT, "firmware", "core", "scene_options.def")
BLOCKS = (("raytracer", "RT_OPTION"), ("rasterizer", "RAS_OPTION"))
COLUMNS = ("key", "field", "type", "kind", "min", "max", "values", "values_error", "def", "def_doc", "emit_line",
           "order", "doc")
KINDS = ("BOOL", "NOT", "INT", "NUM", "CHOICE", "INDEX")
TOKEN = re.compile(r'"(?:[^"\\\n]|\\.)*"|/\*.*?\*/|//[^\n]*|[(),]|[^\s(),"/]+|/', re.S)


def begin_marker(block):
    return "<!-- begin options %s (tools/scene/options_doc.py) -->" % block


def end_marker(block):
    return "<!-- end options %s -->" % block


def c_string(tok):
    body = tok[1:-1]
    return re.sub(r'\\(.)', lambda m: {"n": "\n", "t": "\t"}.get(m.group(1), m.group(1)), body)


def value(toks):
    """A macro argument: adjacent string literals joined, NULL as None, else its text."""
    if toks and all(t.startswith('"') for t in toks):
        return "".join(c_string(t) for t in toks)
    text = " ".join(toks)
    return None if text == "NULL" else text


def rows(text):
    """[(macro, {column: value})] for every row of the .def text, in file order."""
    out = []
    lines = [l for l in text.split("\n") if not l.lstrip().startswith("#")]
    toks = [t for t in TOKEN.findall("\n".join(lines)) if not t.startswith(("/*", "//"))]
    i = 0
    while i < len(toks):
        name = toks[i]
        if name in ("SCENE_KEY", "RT_OPTION", "RAS_OPTION") and i + 1 < len(toks) and toks[i + 1] == "(":
            args, cur, depth, i = [], [], 0, i + 2
            while True:
                t = toks[i]
                i += 1
                if t == "(":
                    depth += 1
                elif t == ")":
                    if depth == 0:
                        break
                    depth -= 1
                elif t == "," and depth == 0:
                    args.append(value(cur))
                    cur = []
                    continue
                cur.append(t)
            args.append(value(cur))
            if name == "SCENE_KEY":
                out.append((name, {"key": args[0], "repeatable": args[1] == "1"}))
            else:
                if len(args) != len(COLUMNS):
                    raise ValueError("%s(%s ...): %d columns, not %d" % (name, args[0], len(args), len(COLUMNS)))
                out.append((name, dict(zip(COLUMNS, args))))
        else:
            i += 1
    return out


def load(path=DEF):
    with open(path, encoding="utf-8") as fh:
        return rows(fh.read())


def options(table, macro):
    return sorted((r for m, r in table if m == macro), key=lambda r: int(r["order"]))


def problems(table):
    """What is inconsistent in the table itself."""
    bad = []
    for block, macro in BLOCKS:
        rs = [r for m, r in table if m == macro]
        orders = sorted(int(r["order"]) for r in rs)
        if orders != list(range(1, len(rs) + 1)):
            bad.append("%s: the order column is not 1 .. %d" % (block, len(rs)))
        for what in ("key", "field"):
            names = [r[what] for r in rs]
            if len(set(names)) != len(names):
                bad.append("%s: a %s appears twice" % (block, what))
        for r in rs:
            k, name = r["kind"], "%s %s" % (block, r["key"])
            lo, hi, d = float(r["min"]), float(r["max"]), float(r["def"])
            if k not in KINDS:
                bad.append("%s: unknown kind %s" % (name, k))
            elif k == "CHOICE":
                if not r["values"] or lo != 0 or hi != len(r["values"].split("|")) - 1 or not 0 <= d <= hi:
                    bad.append("%s: a choice needs values, min 0, max their count - 1, a default among them" % name)
            elif k in ("BOOL", "NOT"):
                if r["values"] or lo != 0 or hi != 1 or d not in (0, 1):
                    bad.append("%s: a switch has no values, range 0 .. 1, default 0 or 1" % name)
            elif not (lo <= d <= hi or r["def_doc"]):
                bad.append("%s: default %s outside %s .. %s without a def_doc" % (name, r["def"], r["min"], r["max"]))
            if (r["values"] is None) != (r["values_error"] is None) and k == "INT":
                bad.append("%s: values and values_error go together" % name)
            if (k == "NUM") != (r["type"] == "num"):
                bad.append("%s: NUM and type num go together" % name)
    keys = [r["key"] for m, r in table if m == "SCENE_KEY"]
    if len(set(keys)) != len(keys):
        bad.append("top level: a key appears twice")
    return bad


def cell(text):
    return text.replace("|", "\\|")


def values_text(r):
    k = r["kind"]
    if k in ("BOOL", "NOT"):
        return "bool"
    if k == "CHOICE":
        return " \\| ".join("`%s`" % v for v in r["values"].split("|"))
    if k == "INT" and r["values"]:
        return " \\| ".join(v.replace("..", " … ") for v in r["values"].split("|"))
    return "%s … %s" % (r["min"], r["max"])


def default_text(r):
    if r["def_doc"]:
        return r["def_doc"]
    k, d = r["kind"], float(r["def"])
    if k == "BOOL":
        return "on" if d else "off"
    if k == "NOT":
        return "off" if d else "on"
    if k == "CHOICE":
        return r["values"].split("|")[int(d)]
    return r["def"]


def block_table(table, block, macro):
    out = [begin_marker(block), "| key | value | default | meaning |", "|---|---|---|---|"]
    for r in options(table, macro):
        out.append("| `%s` | %s | %s | %s |" % (r["key"], values_text(r), cell(default_text(r)), cell(r["doc"])))
    out.append(end_marker(block))
    return "\n".join(out) + "\n"


def section(doc, block):
    """DOC's text from the begin marker of BLOCK to the end of its end marker's line, or None."""
    a = doc.find(begin_marker(block))
    b = doc.find(end_marker(block), a)
    if a < 0 or b < 0:
        return None
    return doc[a:b + len(end_marker(block))] + "\n"


def write(doc, table):
    for block, macro in BLOCKS:
        old = section(doc, block)
        if old is None:
            raise ValueError("no '%s' ... '%s' in the doc" % (begin_marker(block), end_marker(block)))
        doc = doc.replace(old, block_table(table, block, macro))
    return doc


def top_level(doc):
    """[(key, repeatable)] of the doc's '## Top level' table."""
    m = re.search(r"^## Top level\n(.*?)(?=^## )", doc, re.M | re.S)
    out = []
    for line in (m.group(1) if m else "").split("\n"):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if not line.startswith("| `") or len(cells) < 2:
            continue
        rep = "*repeatable*" in cells[1]
        out += [(k, rep) for k in re.findall(r"`([A-Za-z0-9_]+)`", cells[0])]
    return out


def check(doc, table):
    """[(name, problem or None)]"""
    res = [("options_doc_table", "; ".join(problems(table)) or None)]
    for block, macro in BLOCKS:
        have, want = section(doc, block), block_table(table, block, macro)
        if have is None:
            why = "no '%s' ... '%s'" % (begin_marker(block), end_marker(block))
        elif have != want:
            hl, wl = have.split("\n"), want.split("\n")
            k = next((i for i in range(max(len(hl), len(wl))) if i >= len(hl) or i >= len(wl) or hl[i] != wl[i]))
            why = "the doc's table differs from the table's at its line %d: doc %r, table %r (regenerate: " \
                  "tools/scene/options_doc.py --write docs/scene-format.md)" % (
                      k + 1, hl[k] if k < len(hl) else "", wl[k] if k < len(wl) else "")
        else:
            why = None
        res.append(("options_doc_" + block, why))
    want = [(r["key"], r["repeatable"]) for m, r in table if m == "SCENE_KEY"]
    have = top_level(doc)
    why = None
    if have != want:
        diff = [(h, w) for h, w in zip(have + [None] * len(want), want + [None] * len(have)) if h != w]
        why = "the doc's top-level keys differ from the table's SCENE_KEY rows: first doc %r, table %r " \
              "(key, repeatable)" % diff[0]
    res.append(("options_doc_top_level", why))
    return res


def report(res):
    failed = 0
    for name, why in res:
        if why:
            failed += 1
            print("FAIL %s: %s" % (name, why))
        else:
            print("PASS %s" % name)
    return 1 if failed else 0


def self_test(doc, table):
    """Planted differences are found; the doc rewritten from the table passes."""
    def fails(d, t, name):
        return dict(check(d, t))[name] is not None
    good = write(doc, table)
    cases = [
        ("rewritten", not any(why for _, why in check(good, table))),
        ("default", fails(good.replace("| `pcf` | 1 … 3 | 3 |", "| `pcf` | 1 … 3 | 2 |"), table,
                          "options_doc_rasterizer")),
        ("range", fails(good.replace("| `supersample` | 1 … 4 |", "| `supersample` | 1 … 5 |"), table,
                        "options_doc_raytracer")),
        ("values", fails(good.replace("`flat` \\| `gouraud`", "`gouraud` \\| `flat`"), table,
                         "options_doc_rasterizer")),
        ("key", fails(good, table + [("RT_OPTION", dict(options(table, "RT_OPTION")[0], key="new_key",
                                                          field="new_field", order="99"))],
                      "options_doc_raytracer")),
        ("order", fails(good, table + [("RT_OPTION", dict(options(table, "RT_OPTION")[0], key="new_key",
                                                            field="new_field", order="99"))],
                        "options_doc_table")),
        ("top level", fails(good.replace("| `frames` |", "| `frame` |"), table, "options_doc_top_level")),
        ("repeatable", fails(good, [(m, dict(r, repeatable=True) if m == "SCENE_KEY" and r["key"] == "camera"
                                     else r) for m, r in table], "options_doc_top_level")),
    ]
    return [("options_doc_self_test_" + name.replace(" ", "_"), None if ok else "not detected")
            for name, ok in cases]


def main(argv):
    table = load()
    if len(argv) == 1:
        for block, macro in BLOCKS:
            sys.stdout.write(block_table(table, block, macro))
        return 0
    if len(argv) == 2 and argv[1] == "--self-test":
        with open(os.path.join(ROOT, "docs", "scene-format.md"), encoding="utf-8") as fh:
            return report(self_test(fh.read(), table))
    if len(argv) != 3 or argv[1] not in ("--write", "--check"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    with open(argv[2], encoding="utf-8") as fh:
        doc = fh.read()
    if argv[1] == "--check":
        return report(check(doc, table))
    new = write(doc, table)
    if new != doc:
        with open(argv[2], "w", encoding="utf-8") as fh:
            fh.write(new)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
