# SPDX-License-Identifier: MIT
"""Method choices written into scene text (the speed/accuracy lab's variants).

An option is KEY=VALUE: set in the scene's renderer block (`raytracer { }`
or `rasterizer { }`, added when the scene has none), replacing the key where
the block has it; or BLOCK.KEY=VALUE: set in every top-level BLOCK block of
the scene (texture.filter=trilinear, instance.specular=100). Values are single
words or numbers. Comments and strings are skipped, so a key inside them is
never touched. Errors raise ValueError with one line.
"""
import re

_TOKEN = re.compile(r'\s+|#[^\n]*|//[^\n]*|"[^"\n]*"|[{}()=,;]|[^\s{}()=,;#"]+')
_WORD = re.compile(r"^[A-Za-z0-9_.+-]+$")


def _tokens(text):
    """(start, end, token) of every significant token (no blanks or comments)."""
    pos, out = 0, []
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m:
            raise ValueError("scene text: cannot read at offset %d" % pos)
        t = m.group(0)
        if not (t.isspace() or t.startswith("#") or t.startswith("//")):
            out.append((m.start(), m.end(), t))
        pos = m.end()
    return out


def _blocks(toks, name):
    """Token index ranges (open brace, close brace) of every top-level NAME block."""
    found, depth, i = [], 0, 0
    while i < len(toks):
        t = toks[i][2]
        if t in "{(":
            depth += 1
        elif t in "})":
            depth -= 1
        elif depth == 0 and t == name:
            j = i + 1
            if j < len(toks) and toks[j][2] == "=":
                j += 1
            if j < len(toks) and toks[j][2] == "{":
                d, k = 0, j
                while k < len(toks):
                    if toks[k][2] in "{(":
                        d += 1
                    elif toks[k][2] in "})":
                        d -= 1
                        if d == 0:
                            break
                    k += 1
                if k == len(toks):
                    raise ValueError("scene text: unclosed %s block" % name)
                found.append((j, k))
                i = k
        i += 1
    return found


def _set_in_block(text, toks, block, key, value):
    """text with key = value inside the block (open, close) of toks."""
    j, k = block
    depth = 0
    for i in range(j + 1, k):
        t = toks[i][2]
        if t in "{(":
            depth += 1
        elif t in "})":
            depth -= 1
        elif depth == 0 and t == key and i + 2 < k and toks[i + 1][2] == "=":
            v = toks[i + 2]
            if v[2] in "{(":
                raise ValueError("scene text: %s is not a single value" % key)
            return text[:v[0]] + value + text[v[1]:]
    at = toks[j][1]
    return text[:at] + " %s = %s" % (key, value) + text[at:]


def renderer_block(text):
    """'raytracer' or 'rasterizer': the block a plain KEY=VALUE goes to."""
    toks = _tokens(text)
    for i, (_, _, t) in enumerate(toks):
        if t == "renderer" and i + 2 < len(toks) and toks[i + 1][2] == "=":
            return toks[i + 2][2]
    for kw in ("sphere", "plane", "triangle", "csg", "raytracer"):
        if _blocks(toks, kw):
            return "raytracer"
    return "rasterizer"


def set_option(text, opt):
    """The scene text with one option KEY=VALUE or BLOCK.KEY=VALUE set."""
    key, eq, value = opt.partition("=")
    key, value = key.strip(), value.strip()
    if not eq or not key or not _WORD.match(value):
        raise ValueError("option %r: expected KEY=VALUE or BLOCK.KEY=VALUE" % opt)
    block, dot, k = key.rpartition(".")
    if not dot:
        block, k = renderer_block(text), key
    if not re.match(r"^[A-Za-z_][A-Za-z0-9_]*$", k) or (dot and not re.match(r"^[A-Za-z_]+$", block)):
        raise ValueError("option %r: bad key" % opt)
    toks = _tokens(text)
    found = _blocks(toks, block)
    if not found:
        if dot:
            raise ValueError("option %r: the scene has no %s block" % (opt, block))
        return text.rstrip("\n") + "\n%s { %s = %s }\n" % (block, k, value)
    # from the last block back, so earlier offsets stay valid
    for b in reversed(found):
        text = _set_in_block(text, toks, b, k, value)
    return text


def _top_keys(toks, block, k):
    """Token indices of `k = value` at the top level of every BLOCK block,
    in order."""
    for j, e in _blocks(toks, block):
        depth = 0
        for i in range(j + 1, e):
            t = toks[i][2]
            if t in "{(":
                depth += 1
            elif t in "})":
                depth -= 1
            elif depth == 0 and t == k and i + 2 < e and toks[i + 1][2] == "=":
                yield i


def remove(text, opt):
    """The scene text without KEY (in the renderer block) or BLOCK.KEY (in
    every BLOCK block): `key = value` taken out where it is given."""
    block, dot, k = opt.rpartition(".")
    if not dot:
        block, k = renderer_block(text), opt
    toks = _tokens(text)
    cuts = [(toks[i][0], toks[i + 2][1]) for i in _top_keys(toks, block, k) if toks[i + 2][2] not in "{("]
    for a, b in reversed(cuts):
        text = text[:a] + text[b:]
    return text


def written(text, opt):
    """The value the scene gives KEY (renderer block) or BLOCK.KEY (the first
    BLOCK block that gives it), or None."""
    block, dot, k = opt.rpartition(".")
    if not dot:
        block, k = renderer_block(text), opt
    toks = _tokens(text)
    for i in _top_keys(toks, block, k):
        return toks[i + 2][2]
    return None


def apply(text, options):
    """The scene text with every option of the list (or comma-joined string) set."""
    if isinstance(options, str):
        options = [o for o in options.split(",") if o]
    for o in options:
        text = set_option(text, o)
    return text
