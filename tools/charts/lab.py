#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The speed/accuracy lab: every method choice of the renderers as a variant,
its cost on the emulated MCUs against its accuracy, the Pareto frontier per
scene and target.

A variant is a numeric mode (fixed point in the scene's own format or at
NUM_FRAC F, float, double), scene options written into the scene text
(tools/charts/scenetext.py: KEY=VALUE in the renderer block, BLOCK.KEY=VALUE
in every BLOCK block) and a strip height. To add a method, add a line to
the scene's list below (rt_variants() for the ray tracer's options).

Cost: tools/bench/bench_file.c parses the variant's scene file on the
emulated target (qemu-system-arm -icount shift=0: instructions, not cycles;
m0plus-qemu = mps2-an385 with Cortex-M0+ code, m4f-qemu = mps2-an386 with the
FPU) and measures render_init and every frame; cost per frame =
(init + all frames) / frames. RP2040 cycles (rp2040js, 133 MHz, one core,
SPI included) come from the firmware's own benchmark images for the variants
they are built with. Each run is cached under BUILD/charts/cache by the
SHA-256 of the image, the scene text and the arguments, so a rerun measures
only what changed.

Accuracy: the variant rendered by host_sim at 240x240 (frame 0) against the
scene's reference, the double build with the scene's exact methods
(`reference` of each scene): PSNR over 8-bit RGB and the share of pixels
with every RGB565 channel within one level; psnr_numeric against the
double build of the same variant (the numeric error alone). Frame 0 of the
image measured on the target must equal host_sim's (same_image = 1; fixed
point only, where both builds are bit-exact).
"""
import concurrent.futures
import hashlib
import json
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hostsim  # noqa: E402
import scenetext  # noqa: E402

SIZE = (240, 240)
FRACS = range(12, 21)
MACHINES = {"m0plus-qemu": "mps2-an385", "m4f-qemu": "mps2-an386"}
TARGETS = ("m0plus-qemu", "m4f-qemu", "rp2040-sim")


def qfmt(frac):
    return "Q%d.%d" % (31 - frac, frac)


class Variant:
    """label: the method in words (the scene's options beyond the reference's
    ones); numeric: fixed, float or double; frac: NUM_FRAC (None: the
    scene's own format); options: scene options; strip: rows per strip;
    coarse: the ray tracer's progressive preview pass alone (one ray per
    8x8 block)."""

    def __init__(self, label, numeric="fixed", frac=None, options=(), strip=16, coarse=False):
        self.label, self.numeric, self.frac = label, numeric, frac
        self.options, self.strip, self.coarse = list(options), strip, coarse

    def name(self, own_frac=None):
        mode = self.numeric
        if self.numeric == "fixed" and self.frac is not None and self.frac != own_frac:
            mode = "fixed %s" % qfmt(self.frac)
        parts = [mode] + ([self.label] if self.label else []) + (["strip=%d" % self.strip] if self.strip != 16 else [])
        return " ".join(parts)


class LabScene:
    """A scene of the lab: its reference options (the exact method, rendered
    in double), its variants, and the firmware images that run some of them
    on the emulated RP2040: (image, scene set, the firmware's scene, variant
    label, options); the firmware's frame 0 must equal host_sim's render of
    the variant (same_image)."""

    def __init__(self, name, reference, variants, rp2040=(), quality=None):
        self.name, self.reference, self.variants, self.rp2040 = name, reference, variants, list(rp2040)
        self.quality = quality


class LabQuality:
    """What the scene compiler's choice for an accuracy target (tools/quality)
    is checked on: the scene text it chooses for is the lab's scene with
    `apply` set (the frame of reference every variant of the lab shares, as
    written keys that stay) and `remove` taken out (keys the lab varies that
    the scene writes, so that the compiler may choose them); cls is the
    scene's class in tools/quality/cost_model.def; base the options of its
    base method there (the lab variant whose cost per unit of work the class's
    costs scale from); targets the accuracy targets (dB) marked on the charts
    and pinned by tests/system/test_quality.py; fit: whether the cost model is
    fitted on the scene (False: a held-out scene, measured only to check the
    model's predictions and the compiler's choices on a scene it was not
    fitted on; tools/quality/cost_model.py validate)."""

    def __init__(self, cls, targets, apply=(), remove=(), base=(), fit=True):
        self.cls, self.targets, self.apply, self.remove = cls, list(targets), list(apply), list(remove)
        self.base, self.fit = list(base), fit

    def text(self, text):
        for k in self.remove:
            text = scenetext.remove(text, k)
        return scenetext.apply(text, self.apply)


# rows the cost model leaves out: other formats than the scene's own, other
# strip heights (the board's RAM decides them), the preview pass, options
# that compute another image (supersampling) or the same one with more work
QUALITY_SKIP = ("pass=coarse", "supersample=", "adaptive_supersample=", "shortcuts=", "bvh=")


def method_key(row, lab_scene, text, keys, board=False):
    """The method of a pareto row as tools/quality names it: its options less
    the scene's `apply` ones, with every key of `keys` (the keys the scene's
    variants set) the scene writes and the row does not set added at the
    written value, sorted; None for a row the compiler does not consider (a
    book-path row of a book scene, another format or strip height, QUALITY_SKIP;
    board: any format and strip height, as the RP2040 images run them)."""
    q = lab_scene.quality
    opts = [o for o in (row["options"] or "").split() if o]
    if any(a not in opts for a in q.apply):
        return None
    if (not board and (int(row["strip"]) != 16 or " Q" in row["variant"])) or any(o.startswith(QUALITY_SKIP) for o in opts):
        return None
    opts = [o for o in opts if o not in q.apply]
    have = {o.split("=")[0] for o in opts} | {a.split("=")[0] for a in q.apply}
    for k in keys:
        v = scenetext.written(text, k)
        if k not in have and v is not None:
            opts.append("%s=%s" % (k, v))
    return " ".join(sorted(opts))


def quality_variant(v, lab_scene):
    """Whether the cost model or the compiler's checks use variant v of the
    scene (the lab with quality_only measures no other): any numeric mode at
    the scene's own format, 16-row strips, an option the compiler considers,
    with the scene's `apply` options (or the options of one of its RP2040
    variants, whose M0+ instructions give rho)."""
    q = lab_scene.quality
    if not q or v.frac is not None or v.strip != 16 or v.coarse or any(o.startswith(QUALITY_SKIP) for o in v.options):
        return False
    return all(a in v.options for a in q.apply) or any(sorted(v.options) == sorted(r[4]) for r in lab_scene.rp2040)


def quality_row(row, lab_scene):
    """Whether the cost model's fixture keeps a pareto row (quality_variant's
    rows, and every RP2040 row)."""
    if not lab_scene or not lab_scene.quality:
        return False
    if row["target"] == "rp2040-sim":
        return True
    opts = [o for o in (row["options"] or "").split() if o]
    v = Variant("", row["numeric"], 0 if " Q" in row["variant"] else None,
                [o for o in opts if o != "pass=coarse"], int(row["strip"]), "pass=coarse" in opts)
    return quality_variant(v, lab_scene)


def variant_keys(rows, scene):
    """The keys the variants of a scene set (KEY or BLOCK.KEY)."""
    return sorted({o.split("=")[0] for r in rows if r["scene"] == scene for o in (r["options"] or "").split() if o})


RT_EXACT = ["adaptive_subsample=0", "subsample=1", "supersample=1", "adaptive_supersample=off"]
RAS_DEFAULT = ["book_exact=off", "truncate=off", "clip=split"]
RAS_EXACT = ["perspective_step=1", "lighting=exact"]


def formats():
    """Fixed point at every format 12 … 20 other than the scene's own (those
    the parser cannot load the scene in are left out)."""
    return [Variant("", "fixed", f) for f in FRACS]


def rt_variants(reflective):
    """The ray tracer's methods (docs/raytracer.md); new options: add here."""
    v = [Variant(""), *formats(), Variant("", "float"), Variant("", "double")]
    for b in (2, 4, 8):
        v.append(Variant("adaptive_subsample=%d" % b, options=["adaptive_subsample=%d" % b]))
    for t in (4, 7, 10):
        o = ["adaptive_subsample=4", "adaptive_threshold=%d" % t]
        v.append(Variant(" ".join(o), options=o))
    v += [Variant("adaptive_subsample=4", "float", options=["adaptive_subsample=4"]),
          Variant("adaptive_subsample=4 adaptive_threshold=7", "float",
                  options=["adaptive_subsample=4", "adaptive_threshold=7"]),
          Variant("subsample=2", options=["subsample=2"]),
          Variant("supersample=2", options=["supersample=2"]),
          Variant("adaptive_supersample=on", options=["adaptive_supersample=on"]),
          Variant("shortcuts=off", options=["shortcuts=off"]),
          Variant("bvh=on", options=["bvh=on"]),
          Variant("", strip=8),
          Variant("preview (8x8 blocks)", coarse=True),
          Variant("preview (8x8 blocks)", "float", coarse=True)]
    if reflective:
        v += [Variant("recursion_depth=%d" % d, options=["recursion_depth=%d" % d]) for d in (0, 1, 2)]
    return v


def ras_default(label, *opts, numeric="fixed", frac=None, strip=16):
    """A method of the default (real-time) path of a book-path scene."""
    return Variant(label, numeric, frac, RAS_DEFAULT + list(opts), strip)


def raster_book_variants(textured):
    """A book scene (book_exact = on) on the book path as written and on the
    default path with each of its methods."""
    fast = "fast nearest N=16" if textured else "fast Phong N=16"
    tex = ["texture.filter=nearest"] if textured else []
    v = [Variant("book path"), Variant("book path", "float"), Variant("book path", "double"),
         ras_default(fast, *tex)]
    v += [ras_default(fast, *tex, numeric="fixed", frac=f) for f in FRACS]
    v += [ras_default(fast, *tex, numeric="float"), ras_default(fast, *tex, numeric="double"),
          ras_default(fast.replace("16", "8"), *tex, "perspective_step=8"),
          ras_default(fast.replace("16", "32"), *tex, "perspective_step=32"),
          ras_default("exact N=1" + (" nearest" if textured else ""), *tex, *RAS_EXACT),
          ras_default("exact N=1" + (" nearest" if textured else ""), *tex, *RAS_EXACT, numeric="float"),
          ras_default("exact N=1" + (" nearest" if textured else ""), *tex, *RAS_EXACT, numeric="double"),
          ras_default("exact Phong N=16" + (" nearest" if textured else ""), *tex, "lighting=exact"),
          ras_default("vertex lighting" + (" nearest" if textured else ""), *tex, "lighting=vertex")]
    if textured:
        v += [ras_default("uv=linear nearest", *tex, "uv=linear"),
              ras_default("bilinear", "texture.filter=bilinear"),
              ras_default("trilinear", "texture.filter=trilinear"),
              ras_default("trilinear", "texture.filter=trilinear", numeric="float"),
              ras_default("trilinear", "texture.filter=trilinear", numeric="double"),
              ras_default("trilinear exact N=1", "texture.filter=trilinear", *RAS_EXACT)]
    else:
        v += [ras_default("Gouraud", "shading=gouraud"), ras_default("flat", "shading=flat"),
              ras_default(fast + " depth_bits=16", "depth_bits=16"),
              ras_default(fast + " depth_bits=32", "depth_bits=32"),
              ras_default(fast + " subpixel_bits=2", "subpixel_bits=2"),
              ras_default(fast + " subpixel_bits=8", "subpixel_bits=8"),
              ras_default(fast, strip=8), ras_default(fast, strip=240)]
    return v


def lit_variants():
    """A lit scene's methods on the default path, every one with its shading
    written (the cost model's predictions are checked on each; the compiler
    keeps the shading the scene writes)."""
    p = "shading=phong"
    return [ras_default("fast Phong N=16", p), ras_default("fast Phong N=8", p, "perspective_step=8"),
            ras_default("fast Phong N=32", p, "perspective_step=32"),
            ras_default("exact N=1", p, *RAS_EXACT), ras_default("exact Phong N=16", p, "lighting=exact"),
            ras_default("vertex lighting", p, "lighting=vertex"), ras_default("Gouraud", "shading=gouraud"),
            ras_default("flat", "shading=flat"), ras_default("fast Phong N=16 depth_bits=16", p, "depth_bits=16"),
            ras_default("fast Phong N=16 depth_bits=32", p, "depth_bits=32"),
            ras_default("fast Phong N=16 subpixel_bits=2", p, "subpixel_bits=2"),
            ras_default("fast Phong N=16 subpixel_bits=8", p, "subpixel_bits=8")]


def textured_variants():
    """A textured scene's methods (cube_variants'), the filter written in each
    (a held-out scene whose own filters are taken out)."""
    v = []
    for c in cube_variants():
        if c.numeric != "fixed" or c.frac is not None or c.strip != 16:
            continue
        o = c.options if any(x.startswith("texture.filter=") for x in c.options) else \
            ["texture.filter=nearest"] + c.options
        v.append(Variant(c.label, options=o))
    return v


def cube_variants():
    v = [Variant("N=16"), *[Variant("N=16", "fixed", f) for f in FRACS], Variant("N=16", "float"),
         Variant("N=16", "double")]
    for n in (4, 8, 32):
        v.append(Variant("N=%d" % n, options=["perspective_step=%d" % n]))
    v += [Variant("exact N=1", options=["perspective_step=1"]),
          Variant("exact N=1", "float", options=["perspective_step=1"]),
          Variant("exact N=1", "double", options=["perspective_step=1"]),
          Variant("uv=linear", options=["uv=linear"]),
          Variant("N=16 depth_bits=16", options=["depth_bits=16"]),
          Variant("N=16 depth_bits=32", options=["depth_bits=32"]),
          Variant("N=16 subpixel_bits=2", options=["subpixel_bits=2"]),
          Variant("N=16 subpixel_bits=8", options=["subpixel_bits=8"]),
          Variant("bilinear", options=["texture.filter=bilinear"]),
          *[Variant("bilinear N=%d" % n, options=["texture.filter=bilinear", "perspective_step=%d" % n])
            for n in (4, 8)],
          Variant("bilinear exact N=1", options=["texture.filter=bilinear", "perspective_step=1"]),
          *[Variant("bilinear coarse" + ("" if n == 16 else " N=%d" % n),
                    options=["texture.filter=bilinear", "bilinear_weights=coarse"] +
                    ([] if n == 16 else ["perspective_step=%d" % n])) for n in (16, 8)],
          Variant("N=16", strip=8), Variant("N=16", strip=240)]
    return v


def shadow_map_variants():
    v = [Variant("map 192 pcf 3"), *[Variant("map 192 pcf 3", "fixed", f) for f in FRACS],
         Variant("map 192 pcf 3", "float"), Variant("map 192 pcf 3", "double")]
    for n in (64, 128, 256, 512):
        v.append(Variant("map %d pcf 3" % n, options=["shadow_map_size=%d" % n]))
    for k in (1, 2):
        v.append(Variant("map 192 pcf %d" % k, options=["pcf=%d" % k]))
    vol = ["shadows=off", "shadow_volumes=on"]
    v += [Variant("volumes", options=vol), Variant("volumes", "float", options=vol),
          Variant("volumes", "double", options=vol),
          Variant("volumes", options=vol, strip=8), Variant("volumes", options=vol, strip=48),
          Variant("no shadows", options=["shadows=off"])]
    return v


LAB = [
    LabScene("book/raytracer-02", RT_EXACT, rt_variants(False),
             rp2040=[("cgfs-book-1core", "book", "book/raytracer-02", "", [])],
             quality=LabQuality("rt", (40, 60, 80))),
    LabScene("book/raytracer-05", RT_EXACT, rt_variants(True),
             rp2040=[("cgfs-rt-1core", "rt", "book/raytracer-05", "", []),
                     ("cgfs-rt-1core", "rt", "bench/raytracer-05-adaptive", "adaptive_subsample=4",
                      ["adaptive_subsample=4"])],
             quality=LabQuality("rt-reflective", (45, 57, 65))),
    LabScene("book/raster-11", RAS_DEFAULT + RAS_EXACT, raster_book_variants(False),
             rp2040=[("cgfs-book-1core", "book", "book/raster-11", "book path", [])],
             quality=LabQuality("lit", (30, 45, 90), apply=RAS_DEFAULT)),
    LabScene("book/raster-13", RAS_DEFAULT + RAS_EXACT + ["texture.filter=trilinear"], raster_book_variants(True),
             quality=LabQuality("textured-npot", (20, 25, 60), apply=RAS_DEFAULT, remove=["texture.filter"],
                                base=["texture.filter=nearest"])),
    LabScene("bench/cube-textured", ["perspective_step=1"], cube_variants(),
             rp2040=[("cgfs-cube-1core", "cube", "bench/cube-textured", "N=16", [])],
             quality=LabQuality("textured", (30, 35, 45))),
    LabScene("demo/ch15-shadow-map", ["shadows=off", "shadow_volumes=on"] + RAS_EXACT, shadow_map_variants(),
             quality=LabQuality("shadows", (25, 28, 60), remove=["shadow_map_size", "pcf"])),
    # held out: not fitted on, the model's predictions and the compiler's choices checked on them
    # (tools/quality/cost_model.py validate, tests/system/test_quality.py); fixed point only
    LabScene("book/raytracer-04", RT_EXACT, [v for v in rt_variants(False) if v.numeric == "fixed"],
             quality=LabQuality("rt", (40, 64, 66), fit=False)),
    LabScene("book/raytracer-06", RT_EXACT, [v for v in rt_variants(True) if v.numeric == "fixed"],
             quality=LabQuality("rt-reflective", (45, 55, 57), fit=False)),
    LabScene("book/raster-rt-scene", RAS_DEFAULT + RAS_EXACT, lit_variants(),
             quality=LabQuality("lit", (25, 45, 90), apply=RAS_DEFAULT, base=["shading=phong"],
                                fit=False)),
    LabScene("bench/cube-gouraud", RAS_DEFAULT + RAS_EXACT, lit_variants(),
             quality=LabQuality("lit", (30, 35, 40), apply=RAS_DEFAULT, base=["shading=phong"],
                                fit=False)),
    LabScene("demo/spinning-crate", ["perspective_step=1", "lighting=exact", "texture.filter=trilinear"],
             textured_variants(),
             quality=LabQuality("textured", (20, 40, 43), remove=["texture.filter"], base=["texture.filter=nearest"],
                                fit=False)),
]

# The RP2040 images: which scene set each links (mk/firmware.mk), rp2040sim
# arguments and the strip height they render with (FW_STRIP_ROWS).
RP2040_IMAGES = {"cgfs-book-1core": ["--frames", "2"], "cgfs-rt-1core": ["--frames", "2"],
                 "cgfs-cube-1core": ["--frames", "30", "--average"]}
RP2040_STRIP = 8
# make run from here: its own -j, not the jobserver of a make that runs us
MAKE_ENV = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}


def sha(*parts):
    h = hashlib.sha256()
    for p in parts:
        h.update(p.encode() if isinstance(p, str) else p)
        h.update(b"\0")
    return h.hexdigest()


class Cache:
    """JSON results under DIR, one file per key."""

    def __init__(self, d):
        self.d = d
        os.makedirs(d, exist_ok=True)

    def get(self, key):
        p = os.path.join(self.d, key + ".json")
        if os.path.exists(p):
            with open(p) as f:
                return json.load(f)
        return None

    def put(self, key, value):
        p = os.path.join(self.d, key + ".json")
        with open(p + ".tmp", "w") as f:
            json.dump(value, f)
        os.replace(p + ".tmp", p)
        return value


class ImageMissing(RuntimeError):
    """A benchmark image is not built (and this Lab may not build it)."""


class Lab:
    """build_images: run make for the benchmark images it needs (else they
    must exist: ImageMissing)."""

    def __init__(self, host_sim, build, jobs=2, log=print, rp2040=True, make="make", build_images=True):
        self.host_sim, self.build, self.jobs, self.log = host_sim, build, jobs, log
        self.make, self.want_rp2040, self.build_images = make, rp2040, build_images
        self.cache = Cache(os.path.join(build, "charts", "cache"))
        self.scene_dir = os.path.join(build, "charts", "scenes")
        os.makedirs(self.scene_dir, exist_ok=True)
        self.hs_hash = hostsim.file_hash(host_sim)
        self.hits = self.runs = 0

    # ---- accuracy (host_sim) --------------------------------------------------
    def accuracy(self, text, ref_text, numeric, frac, strip, coarse=False):
        """Accuracy of one variant; None when host_sim refuses it (a format
        the scene does not load in). coarse: of the progressive preview, made
        from the full render (hostsim.coarse_blocks)."""
        key = sha("acc2", self.hs_hash, text, ref_text, numeric, str(frac), str(strip), "%dx%d" % SIZE,
                  "coarse" if coarse else "")
        got = self.cache.get(key)
        if got is not None:
            return got.get("result")
        size = "%dx%d" % SIZE
        try:
            ref_raw, ref_rgb, _ = self.reference(ref_text)
            raw, rgb, st = hostsim.render(self.host_sim, text, numeric, size, frac, strip)
        except hostsim.RenderError as e:
            return self.cache.put(key, {"result": None, "error": str(e)})["result"]
        if coarse:
            raw, rgb = hostsim.coarse_blocks(raw, rgb, *SIZE)
        if numeric == "double":
            num_psnr = math.inf
        else:
            draw, drgb, _ = hostsim.render(self.host_sim, text, "double", size, None, strip)
            if coarse:
                draw, drgb = hostsim.coarse_blocks(draw, drgb, *SIZE)
            num_psnr = hostsim.psnr(rgb, drgb)
        r = {"psnr": _fin(hostsim.psnr(rgb, ref_rgb)), "within1": hostsim.within1(raw, ref_raw),
             "psnr_numeric": _fin(num_psnr), "num_frac": st.get("num_frac"), "checksum": hostsim.fnv1a(raw),
             "saturations": st.get("saturations"), "rays": st.get("rays"), "pixels": st.get("pixels_written")}
        return self.cache.put(key, {"result": r})["result"]

    def reference(self, ref_text):
        if not hasattr(self, "_refs"):
            self._refs = {}
        if ref_text not in self._refs:
            self._refs[ref_text] = hostsim.render(self.host_sim, ref_text, "double", "%dx%d" % SIZE)
        return self._refs[ref_text]

    # ---- cost (qemu) ------------------------------------------------------------
    def elf(self, target, mode):
        return os.path.join(self.build, "charts", "bench", target, mode, "bench_file.elf")

    def build_elves(self, pairs, quiet=False):
        """Builds (make) the benchmark images of (target, mode) pairs not built
        by this run yet and hashes them."""
        if not hasattr(self, "elf_hash"):
            self.elf_hash = {}
        paths = sorted({self.elf(t, m) for t, m in pairs} - set(self.elf_hash))
        if not paths:
            return
        if not self.build_images:
            missing = [p for p in paths if not os.path.exists(p)]
            if missing:
                raise ImageMissing("%s is not built (make %s)" % (missing[0], missing[0]))
            self.elf_hash.update({p: hostsim.file_hash(p) for p in paths})
            return
        if not quiet:
            self.log("lab: %d benchmark images (built by make when out of date)" % len(paths))
        r = subprocess.run([self.make, "-s", "--no-print-directory", "-j%d" % self.jobs, "BUILD=%s" % self.build] + paths,
                           env=MAKE_ENV, stdout=subprocess.DEVNULL if quiet else None)
        if r.returncode != 0:
            raise SystemExit("lab: building the benchmark images failed")
        self.elf_hash.update({p: hostsim.file_hash(p) for p in paths})

    def cost(self, target, mode, text, strip, size=SIZE, coarse=False):
        elf = self.elf(target, mode)
        w, h = size
        key = sha("cost1", self.elf_hash[elf], text, str(w), str(h), str(strip)) if not coarse else \
            sha("cost1", self.elf_hash[elf], text, str(w), str(h), str(strip), "coarse")
        got = self.cache.get(key)
        if got is not None:
            self.hits += 1
            return got
        path = os.path.join(self.scene_dir, sha(text)[:32] + ".scene")
        if not os.path.exists(path):
            with open(path, "w") as f:
                f.write(text)
        cmd = ["qemu-system-arm", "-M", MACHINES[target], "-nographic", "-monitor", "none", "-serial", "null",
               "-icount", "shift=0,align=off", "-semihosting-config",
               "enable=on,target=native,arg=bench,arg=%s,arg=%d,arg=%d,arg=%d,arg=0%s"
               % (path, w, h, strip, ",arg=coarse" if coarse else ""),
               "-kernel", elf]
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=1800)
        except subprocess.TimeoutExpired:
            return {"error": "timed out"}
        out = (p.stdout or "") + (p.stderr or "")
        m = re.search(r"^RESULT (.*)$", out, re.M)
        if p.returncode != 0 or not m:
            err = re.search(r"^ERROR (.*)$", out, re.M)
            return {"error": err.group(1) if err else "qemu exit status %d" % p.returncode}
        r = {k: int(v) for k, v in (kv.split("=") for kv in m.group(1).split())}
        self.runs += 1
        return self.cache.put(key, r)

    # ---- RP2040 (rp2040js) --------------------------------------------------------
    def rp2040(self, images):
        """rp2040sim's frames of each image: {image: [(record, fnv of its frame 0), ...]}."""
        fw = os.path.join(self.build, "firmware")
        elves = [os.path.join(fw, "pico", i + ".elf") for i in images]
        r = subprocess.run([self.make, "--no-print-directory", "-j%d" % self.jobs, "BUILD=%s" % self.build,
                            "tools/rp2040sim/node_modules/.package-lock.json"] + elves,
                           capture_output=True, text=True, env=MAKE_ENV)
        if r.returncode != 0:
            self.log("lab: RP2040 images not built, no rp2040-sim points: %s" %
                     ((r.stderr.strip().splitlines() or ["make failed"])[-1]))
            return {}
        out = {}
        for img, elf in zip(images, elves):
            args = RP2040_IMAGES[img]
            key = sha("rp1", hostsim.file_hash(elf), *args)
            got = self.cache.get(key)
            if got is None:
                tmp = os.path.join(self.build, "charts", "rp2040-" + img)
                os.makedirs(tmp, exist_ok=True)
                self.log("lab: rp2040sim %s (%s)" % (img, " ".join(args)))
                p = subprocess.run(["node", "tools/rp2040sim/rp2040sim.js", "--image", elf, "--json",
                                    "--out-dir", tmp] + args, capture_output=True, text=True)
                if p.returncode != 0:
                    self.log("lab: rp2040sim %s failed: %s" % (img, (p.stderr.strip().splitlines() or ["?"])[-1]))
                    continue
                recs, first = [], 0
                for line in p.stdout.splitlines():
                    rec = json.loads(line)
                    with open(os.path.join(tmp, "frame-%d.raw" % first), "rb") as f:
                        rec["checksum"] = hostsim.fnv1a(f.read())
                    first += rec.get("frames", 1)
                    recs.append(rec)
                got = self.cache.put(key, {"records": recs})
                self.runs += 1
            else:
                self.hits += 1
            out[img] = got["records"]
        return out

    def set_frac(self, set_name):
        """NUM_FRAC of a firmware scene set (its generated header)."""
        p = os.path.join(self.build, "firmware", "scenes", "fw_%s_num_frac.h" % set_name)
        with open(p) as f:
            m = re.search(r"#define NUM_FRAC (\d+)", f.read())
        return int(m.group(1))

    # ---- the whole lab --------------------------------------------------------------
    def run(self, scenes_dir, only=None, quality_only=False, numerics=None):
        """quality_only: only the variants the cost model and the compiler's
        checks use (quality_variant), of the scenes with a LabQuality;
        numerics: only variants in these numeric modes (None: all)."""
        rows = []
        scenes = [s for s in LAB if (not only or s.name in only) and (s.quality or not quality_only)]
        rp = {}
        if self.want_rp2040:
            imgs = sorted({r[0] for s in scenes for r in s.rp2040})
            if imgs:
                rp = self.rp2040(imgs)
        plan = []   # (scene, variant, text, accuracy)
        for s in scenes:
            with open(os.path.join(scenes_dir, s.name + ".scene")) as f:
                text = f.read()
            ref_text = scenetext.apply(text, s.reference)
            own = self.accuracy(text, ref_text, "fixed", None, 16)["num_frac"]
            variants = [v for v in s.variants if (not quality_only or quality_variant(v, s)) and
                        (not numerics or v.numeric in numerics)]
            own_of = {}

            def own_frac(vt):
                """The format host_sim (and scenec) choose for this scene text."""
                if vt not in own_of:
                    a = self.accuracy(vt, ref_text, "fixed", None, 16)
                    own_of[vt] = a["num_frac"] if a else None
                return own_of[vt]
            rp_of = {}   # variant name -> (the RP2040 image that runs it, its scene there)
            for img, set_name, fw_scene, label, opts in s.rp2040:
                if img in rp:
                    v = Variant(label, "fixed", self.set_frac(set_name), opts, RP2040_STRIP)
                    variants.append(v)
                    rp_of[v.name(own_frac(scenetext.apply(text, opts)))] = (img, fw_scene)
            seen = set()
            for v in variants:
                vt = scenetext.apply(text, v.options)
                name = v.name(own_frac(vt))   # fixed at the text's own format is plain "fixed"
                if name in seen:
                    continue
                seen.add(name)
                acc = self.accuracy(vt, ref_text, v.numeric, v.frac, v.strip, v.coarse)
                if acc is None:
                    continue
                plan.append((s, v, name, vt, acc, rp_of.get(name)))
            self.log("lab: %s: %d variants, own format %s" % (s.name, sum(1 for p in plan if p[0] is s), qfmt(own)))
        modes = lambda v, acc: "fixed%d" % acc["num_frac"] if v.numeric == "fixed" else v.numeric  # noqa: E731
        self.build_elves([(t, modes(v, acc)) for (_, v, _, _, acc, _) in plan for t in MACHINES])
        jobs = [(p, t) for p in plan for t in MACHINES]
        # fixed point first (the boards' mode), the slow float and double runs last; rows in plan order
        order = sorted(range(len(jobs)), key=lambda i: ("fixed", "float", "double").index(jobs[i][0][1].numeric))
        with concurrent.futures.ThreadPoolExecutor(max_workers=self.jobs) as ex:
            done = list(ex.map(lambda i: self.cost(jobs[i][1], modes(jobs[i][0][1], jobs[i][0][4]), jobs[i][0][3],
                                                   jobs[i][0][1].strip, coarse=jobs[i][0][1].coarse), order))
        costs = [None] * len(jobs)
        for i, c in zip(order, done):
            costs[i] = c
        for ((s, v, name, vt, acc, img), target), c in zip(jobs, costs):
            if "error" in c:
                self.log("lab: %s %s on %s: %s" % (s.name, name, target, c["error"]))
                continue
            frames = c["frames"]
            rows.append(self.row(s, v, name, acc, target, (c["init"] + c["total"]) / frames, "instructions",
                                 c["checksum"] == acc["checksum"], c["init"], c["total"] / frames, frames))
        for (s, v, name, vt, acc, on_rp) in plan:
            if not on_rp:
                continue
            img, fw_scene = on_rp
            recs = [r for r in rp[img] if r.get("what") == "scene:" + fw_scene]
            if not recs:
                self.log("lab: %s: no frame of %s" % (img, fw_scene))
                continue
            r = recs[0]
            rows.append(self.row(s, v, name, acc, "rp2040-sim", r["cycles"], "cycles",
                                 r["checksum"] == acc["checksum"], 0, r["cycles"], r.get("frames", 1)))
        for r in rows:
            if not r["same_image"]:
                self.log("lab: %s %s on %s: frame 0 differs from host_sim's render of the variant" %
                         (r["scene"], r["variant"], r["target"]))
        self.log("lab: %d emulator runs, %d cached results reused" % (self.runs, self.hits))
        return frontier(rows)

    @staticmethod
    def row(s, v, name, acc, target, cost, unit, same, init, frame, frames):
        return {"scene": s.name, "variant": name, "target": target, "cost": round(cost), "unit": unit,
                "psnr": acc["psnr"], "within1": round(100 * acc["within1"], 3), "psnr_numeric": acc["psnr_numeric"],
                "numeric": v.numeric, "format": qfmt(acc["num_frac"]) if acc["num_frac"] else "",
                "options": " ".join(v.options + (["pass=coarse"] if v.coarse else [])), "strip": v.strip,
                "frames": frames,
                "init": round(init), "frame": round(frame), "same_image": int(bool(same)),
                "saturations": acc["saturations"]}


def _fin(p):
    return None if math.isinf(p) else round(p, 3)


def psnr_value(p):
    """PSNR for ordering: identical (None) above every finite value."""
    return math.inf if p is None else p


def frontier(rows):
    """frontier = 1 when no other variant of the same scene and target is both
    cheaper and at least as accurate (PSNR)."""
    for r in rows:
        r["frontier"] = int(not any(o is not r and o["scene"] == r["scene"] and o["target"] == r["target"]
                                    and o["cost"] < r["cost"] and psnr_value(o["psnr"]) >= psnr_value(r["psnr"])
                                    for o in rows))
    return rows


COLUMNS = ["scene", "variant", "target", "cost", "psnr", "frontier", "unit", "within1", "psnr_numeric", "numeric",
           "format", "options", "strip", "frames", "init", "frame", "same_image", "saturations"]
