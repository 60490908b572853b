#!/bin/sh
# SPDX-License-Identifier: MIT
# host_sim's command line: exit codes and messages for bad input, output
# sizes and formats, atomic output, --stats, --frames, and protocol
# violations injected into the panel driver (exit 3).
#   tests/system/test_host_sim.sh HOST_SIM
set -u
hs=${1:?usage: test_host_sim.sh HOST_SIM}
tmp=$(mktemp -d)
trap 'chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT

# A scene to render: the book's raytracer-02.
scene=firmware/scenes/book/raytracer-02.scene

pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; }
skip() { echo "SKIP $1: $2"; }

# run NAME ARGS...: runs host_sim, leaving status in $rc, stdout in $tmp/o,
# stderr in $tmp/e.
run() {
  "$hs" "$@" >"$tmp/o" 2>"$tmp/e"
  rc=$?
}

# expect_err NAME STATUS PATTERN ARGS...: exit status STATUS and exactly one
# line on stderr matching the grep pattern PATTERN.
expect_err() {
  name=$1 want=$2 pat=$3
  shift 3
  run "$@"
  lines=$(wc -l <"$tmp/e" | tr -d ' ')
  if [ "$rc" -ne "$want" ]; then
    fail "$name" "exit $rc, want $want; stderr: $(head -c 300 "$tmp/e")"
  elif [ "$lines" -ne 1 ]; then
    fail "$name" "$lines lines on stderr, want 1: $(head -c 300 "$tmp/e")"
  elif ! grep -q -- "$pat" "$tmp/e"; then
    fail "$name" "stderr does not match '$pat': $(cat "$tmp/e")"
  else
    pass "$name"
  fi
}

# png_size FILE: "WxH" from the PNG signature and IHDR, or "bad".
png_size() {
  sig=$(od -An -tx1 -N8 "$1" 2>/dev/null | tr -d ' \n')
  [ "$sig" = 89504e470d0a1a0a ] || { echo bad; return; }
  set -- $(od -An -tu1 -j16 -N8 "$1")
  echo "$(( ($1 << 24) | ($2 << 16) | ($3 << 8) | $4 ))x$(( ($5 << 24) | ($6 << 16) | ($7 << 8) | $8 ))"
}

fsize() { wc -c <"$1" | tr -d ' '; }

# ---- usage errors -----------------------------------------------------------
expect_err no_args 2 "scene" 
expect_err unknown_option 2 "unknown option '--frobnicate'" --scene "$scene" --frobnicate
expect_err unknown_short_option 2 "unknown option" -x --scene "$scene"
expect_err missing_argument 2 "option --size needs an argument" --scene "$scene" --size
expect_err missing_argument_empty 2 "option --out needs an argument" --scene "$scene" --out=
expect_err unknown_panel 2 "unknown panel 'st9999'" --scene "$scene" --panel st9999
expect_err unknown_numeric 2 "unknown numeric mode 'posit'" --scene "$scene" --numeric posit
expect_err unknown_backend 2 "unknown backend 'usb'" --scene "$scene" --backend usb
expect_err bad_frames 2 "bad frame count" --scene "$scene" --frames 0
for s in 0x10 10x0 -5x10 10x-5 abc 10x x10 10x10x10 12345678901234567890x10 9000x10 10X10 " 10x10" 10.5x10; do
  expect_err "bad_size[$s]" 2 "bad size" --scene "$scene" --panel none --size "$s"
done
expect_err missing_scene 2 "$tmp/nope.scene" --scene "$tmp/nope.scene"
expect_err scene_is_directory 2 "is a directory" --scene "$tmp"
expect_err no_scene_option 2 "--scene FILE is required" --panel none
expect_err out_extension 2 "must end in .png or .ppm" --scene "$scene" --out "$tmp/x.bmp"
expect_err rgb888_extension 2 "must end in .ppm" --scene "$scene" --out-rgb888 "$tmp/x.png"
expect_err size_larger_than_st7789 2 "larger than" --scene "$scene" --panel st7789 --size 241x321
expect_err size_larger_than_st7789_wide 2 "larger than" --scene "$scene" --panel st7789 --size 400x200
expect_err size_larger_than_ili9341 2 "larger than" --scene "$scene" --panel ili9341 --size 321x240

# Every panel hal/panels.def lists is a --panel name, at its own size; on a
# panel that is not square, --rotation 1 and 3 show its size turned
# (landscape for a portrait module), the image upright on the glass.
bad=""
for p in $(sed -n 's/^PANEL(\([a-z0-9_]*\),.*/\1/p' hal/panels.def); do
  size=${p##*_}
  run --scene "$scene" --panel "$p" --out "$tmp/p.png"
  [ "$rc" -eq 0 ] && [ "$(png_size "$tmp/p.png")" = "$size" ] || bad="$bad [$p: exit $rc, $(png_size "$tmp/p.png"): $(head -c 200 "$tmp/e")]"
  w=${size%x*} h=${size#*x}
  [ "$w" = "$h" ] && continue
  "$hs" --scene "$scene" --panel none --size "${h}x$w" --out-raw "$tmp/none.raw" 2>/dev/null
  for rot in 1 3; do
    run --scene "$scene" --panel "$p" --rotation $rot --out-raw "$tmp/p.raw"
    [ "$rc" -eq 0 ] && cmp -s "$tmp/p.raw" "$tmp/none.raw" || bad="$bad [$p --rotation $rot: exit $rc: $(head -c 200 "$tmp/e")]"
  done
done
[ -n "$(sed -n 's/^PANEL(\([a-z0-9_]*\),.*/\1/p' hal/panels.def)" ] || bad="no PANEL lines read"
if [ -z "$bad" ]; then pass every_listed_panel_name; else fail every_listed_panel_name "$bad"; fi
expect_err unknown_panel_lists_modules 2 "st7789_240x320" --scene "$scene" --panel st7789_240x999
expect_err rotation_with_size_not_square 2 "odd turns need a square size" --scene "$scene" --panel st7789 \
  --size 240x320 --rotation 1

# --help
run --help
if [ "$rc" -eq 0 ] && grep -q -- "--scene FILE" "$tmp/o"; then pass help; else fail help "exit $rc"; fi

# Scene errors are printed as the parser returns them: FILE:LINE:COLUMN: error: MESSAGE.
run --scene tests/data/bad.scene --panel none --size 4x4
if [ "$rc" -eq 2 ] && [ "$(wc -l <"$tmp/e")" -eq 1 ] &&
     grep -q '^tests/data/bad.scene:[0-9][0-9]*:[0-9][0-9]*: error: ' "$tmp/e"; then
  pass scene_error_format
else
  fail scene_error_format "exit $rc: $(cat "$tmp/e")"
fi

# --backend linux without an SPI device: a one-line error, exit 2, no file
# written (tests/system/test_linux_backend.sh runs it against an emulated device).
if [ ! -e /dev/spidev0.0 ]; then
  expect_err backend_linux_no_device 2 "backend linux" --scene "$scene" --backend linux --out "$tmp/l.png"
  [ ! -e "$tmp/l.png" ] && pass backend_linux_no_file || fail backend_linux_no_file "l.png was written"
else
  skip backend_linux_no_device "this machine has /dev/spidev0.0"
fi

# ---- outputs ----------------------------------------------------------------
run --scene "$scene" --panel none --size 64x48 --out "$tmp/n.png" --out-raw "$tmp/n.raw" \
    --out-rgb888 "$tmp/n888.ppm"
if [ "$rc" -eq 0 ]; then pass none_renders; else fail none_renders "exit $rc: $(cat "$tmp/e")"; fi
[ "$(png_size "$tmp/n.png")" = 64x48 ] && pass none_png_size || fail none_png_size "$(png_size "$tmp/n.png")"
[ "$(fsize "$tmp/n.raw")" = $((64 * 48 * 2)) ] && pass out_raw_size || fail out_raw_size "$(fsize "$tmp/n.raw") bytes"
hdr=$(head -c 13 "$tmp/n888.ppm" | tr '\n' ' ')
if [ "$hdr" = "P6 64 48 255 " ] && [ "$(fsize "$tmp/n888.ppm")" = $((13 + 64 * 48 * 3)) ]; then
  pass out_rgb888_ppm
else
  fail out_rgb888_ppm "header '$hdr', $(fsize "$tmp/n888.ppm") bytes"
fi
run --scene "$scene" --panel none --size 64x48 --out "$tmp/n.ppm"
hdr=$(head -c 13 "$tmp/n.ppm" | tr '\n' ' ')
[ "$rc" -eq 0 ] && [ "$hdr" = "P6 64 48 255 " ] && [ "$(fsize "$tmp/n.ppm")" = $((13 + 64 * 48 * 3)) ] &&
  pass out_ppm || fail out_ppm "exit $rc, header '$hdr'"
# The PNG and the PPM hold the same pixels.
if python3 - "$tmp/n.png" "$tmp/n.ppm" "$tmp/n.raw" <<'PY'
import struct, sys, zlib
png = open(sys.argv[1], 'rb').read()
pos, idat, w, h = 8, b'', 0, 0
while pos < len(png):
    n, t = struct.unpack('>I4s', png[pos:pos + 8])
    d = png[pos + 8:pos + 8 + n]
    if t == b'IHDR': w, h = struct.unpack('>II', d[:8])
    if t == b'IDAT': idat += d
    pos += 12 + n
raw, out, prev, i = zlib.decompress(idat), bytearray(), bytearray(3 * w), 0
for y in range(h):
    f, line = raw[i], bytearray(raw[i + 1:i + 1 + 3 * w]); i += 1 + 3 * w
    for x in range(3 * w):
        a = line[x - 3] if x >= 3 else 0; b = prev[x]; c = prev[x - 3] if x >= 3 else 0
        if f == 1: line[x] = (line[x] + a) & 255
        elif f == 2: line[x] = (line[x] + b) & 255
        elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    out += line; prev = line
ppm = open(sys.argv[2], 'rb').read()[13:]
rw = open(sys.argv[3], 'rb').read()
exp = bytearray()
for k in range(0, len(rw), 2):
    p = rw[k] | rw[k + 1] << 8
    r, g, b = p >> 11, (p >> 5) & 63, p & 31
    exp += bytes((r << 3 | r >> 2, g << 2 | g >> 4, b << 3 | b >> 2))
sys.exit(0 if bytes(out) == ppm == bytes(exp) else 1)
PY
then pass png_ppm_raw_same_pixels; else fail png_ppm_raw_same_pixels "PNG, PPM and raw differ"; fi

# Default size with --panel none: the scene's canvas.
run --scene "$scene" --panel none --out "$tmp/c.png"
[ "$rc" -eq 0 ] && [ "$(png_size "$tmp/c.png")" = 600x600 ] && pass none_default_canvas_size ||
  fail none_default_canvas_size "exit $rc, $(png_size "$tmp/c.png")"

# ---- atomic output ----------------------------------------------------------
expect_err out_missing_dir 2 "does not exist" --scene "$scene" --panel none --size 8x8 --out "$tmp/no/such/x.png"
[ ! -e "$tmp/no" ] && pass out_missing_dir_no_file || fail out_missing_dir_no_file "something was created"
: >"$tmp/afile"
expect_err out_dir_is_file 2 "" --scene "$scene" --panel none --size 8x8 --out "$tmp/afile/x.png"
# A directory the program cannot create files in: /proc even for root.
run --scene "$scene" --panel none --size 8x8 --out /proc/host_sim_test.png
[ "$rc" -ne 0 ] && [ ! -e /proc/host_sim_test.png ] && pass out_unwritable_dir ||
  fail out_unwritable_dir "exit $rc"
if [ "$(id -u)" != 0 ]; then
  mkdir "$tmp/ro" && chmod 555 "$tmp/ro"
  run --scene "$scene" --panel none --size 8x8 --out "$tmp/ro/x.png"
  [ "$rc" -eq 2 ] && [ -z "$(ls -A "$tmp/ro")" ] && pass out_readonly_dir || fail out_readonly_dir "exit $rc"
fi
# A write that fails half-way (file size limit): the old file stays as it
# was and no temporary file is left.
mkdir "$tmp/lim" && echo old >"$tmp/lim/x.ppm"
(trap '' XFSZ; ulimit -f 1; exec "$hs" --scene "$scene" --panel none --size 200x200 \
   --out "$tmp/lim/x.ppm") >/dev/null 2>"$tmp/e"
rc=$?
left=$(ls -A "$tmp/lim" | tr '\n' ' ')
if [ "$rc" -eq 1 ] && [ "$left" = "x.ppm " ] && [ "$(cat "$tmp/lim/x.ppm")" = old ]; then
  pass out_failed_write_atomic
else
  fail out_failed_write_atomic "exit $rc, directory holds '$left': $(head -n 1 "$tmp/e")"
fi
# Overwriting succeeds and replaces the file whole.
run --scene "$scene" --panel none --size 16x8 --out "$tmp/lim/x.ppm"
[ "$rc" -eq 0 ] && [ "$(fsize "$tmp/lim/x.ppm")" = $((12 + 16 * 8 * 3)) ] && pass out_replaces ||
  fail out_replaces "exit $rc"
[ "$(ls -A "$tmp/lim" | tr '\n' ' ')" = "x.ppm " ] && pass out_no_temp_left || fail out_no_temp_left "$(ls -A "$tmp/lim")"

# ---- --stats and --frames ---------------------------------------------------
stats_check() {
  python3 - "$1" "$2" <<'PY'
import json, sys
want = ["scene", "numeric", "width", "height", "frame", "render_us", "pixels_written",
        "spi_bytes", "triangles_in", "triangles_drawn", "rays", "shadow_rays", "saturations", "checksum"]
lines = open(sys.argv[1]).read().splitlines()
n = int(sys.argv[2])
if len(lines) != n:
    sys.exit("%d lines, want %d" % (len(lines), n))
for i, l in enumerate(lines):
    o = json.loads(l)
    miss = [k for k in want if k not in o]
    if miss: sys.exit("missing " + ",".join(miss))
    if o["frame"] != i: sys.exit("frame %r, want %d" % (o["frame"], i))
    for k in want[2:]:
        if not isinstance(o[k], int) or o[k] < 0: sys.exit("%s not a count: %r" % (k, o[k]))
PY
}
run --scene "$scene" --panel none --size 32x24 --stats
if [ "$rc" -eq 0 ] && msg=$(stats_check "$tmp/o" 1 2>&1); then pass stats_json; else fail stats_json "exit $rc: $msg"; fi
run --scene "$scene" --panel none --size 32x24 --stats --frames 3
if [ "$rc" -eq 0 ] && msg=$(stats_check "$tmp/o" 3 2>&1); then pass stats_frames; else fail stats_frames "exit $rc: $msg"; fi
# "checksum": FNV-1a of the frame's RGB565 pixels, low byte first: the sum
# the benchmark images print, of the same bytes --out-raw writes
run --scene "$scene" --panel none --size 32x24 --stats --frames 2 --out-raw "$tmp/sum.raw"
if [ "$rc" -eq 0 ] && msg=$(python3 - "$tmp/o" "$tmp/sum.raw" 2>&1 <<'PY'
import json, sys
last = json.loads(open(sys.argv[1]).read().splitlines()[-1])
h = 2166136261
for c in open(sys.argv[2], "rb").read():
    h = ((h ^ c) * 16777619) & 0xFFFFFFFF
if last.get("checksum") != h:
    sys.exit("checksum %r, FNV-1a of --out-raw %d" % (last.get("checksum"), h))
PY
); then pass stats_checksum; else fail stats_checksum "exit $rc: $msg"; fi
run --scene "$scene" --panel none --size 32x24 --stats --numeric double --compare fixed
if [ "$rc" -eq 0 ] && msg=$(stats_check "$tmp/o" 1 2>&1) &&
   python3 -c 'import json,sys; o=json.loads(open(sys.argv[1]).read()); assert "psnr" in o and "max_err" in o' "$tmp/o"
then pass stats_compare; else fail stats_compare "exit $rc: $msg"; fi
run --scene "$scene" --panel none --size 32x24 --frames 4
[ "$rc" -eq 0 ] && [ ! -s "$tmp/o" ] && pass frames_quiet_without_stats || fail frames_quiet_without_stats "exit $rc"

# ---- the number format of fixed point ---------------------------------------
# --numeric fixed renders in the format the scene's ranges call for
# (tools/scene/scene_format.c, as scenec chooses it for the firmware), shown
# as "num_frac" in --stats; --num-frac F overrides it.
num_frac_of() { sed -n 's/.*"num_frac":\([0-9a-z]*\).*/\1/p' "$tmp/o" | head -n 1; }
for want in book/raster-06=20 book/raytracer-02=17 book/raytracer-05=16 demo/planet-horizon=13 book/raster-rt-scene=20 demo/ch15-shadow-volume=20; do
  n=${want%=*} f=${want#*=} id=$(basename "${want%=*}")
  run --scene "firmware/scenes/$n.scene" --panel none --size 240x240 --stats
  got=$(num_frac_of)
  [ "$rc" -eq 0 ] && [ "$got" = "$f" ] && pass "num_frac_$id ($f)" ||
    fail "num_frac_$id" "exit $rc, num_frac '$got', want $f: $(head -n 1 "$tmp/e")"
done
r6=firmware/scenes/book/raster-06.scene
run --scene "$r6" --panel none --size 240x240 --stats --num-frac 16
[ "$rc" -eq 0 ] && [ "$(num_frac_of)" = 16 ] && pass num_frac_override ||
  fail num_frac_override "exit $rc, num_frac '$(num_frac_of)'"
# the override at the scene's own format is the same render, bit for bit
run --scene "$r6" --panel none --size 240x240 --stats --out-raw "$tmp/own.raw"
own=$(num_frac_of)
run --scene "$r6" --panel none --size 240x240 --num-frac "$own" --out-raw "$tmp/forced.raw"
[ "$rc" -eq 0 ] && cmp -s "$tmp/own.raw" "$tmp/forced.raw" && pass num_frac_override_same_format ||
  fail num_frac_override_same_format "exit $rc, format $own"
run --scene "$r6" --panel none --size 240x240 --stats --numeric float
[ "$rc" -eq 0 ] && [ "$(num_frac_of)" = null ] && pass num_frac_null_in_float ||
  fail num_frac_null_in_float "exit $rc, num_frac '$(num_frac_of)'"
# --compare fixed takes the scene's format too: the same figures both ways round
run --scene "$r6" --panel none --size 240x240 --stats --compare double
a=$(sed -n 's/.*"psnr":\([0-9.a-z]*\).*/\1/p' "$tmp/o")
run --scene "$r6" --panel none --size 240x240 --stats --numeric double --compare fixed
b=$(sed -n 's/.*"psnr":\([0-9.a-z]*\).*/\1/p' "$tmp/o")
[ "$rc" -eq 0 ] && [ -n "$a" ] && [ "$a" = "$b" ] && pass num_frac_compare_fixed ||
  fail num_frac_compare_fixed "psnr '$a' vs '$b'"
# bilinear textures on the fast path (bench/cube-bilinear): close to the
# double build's exact bilinear sampling at perspective_step 8 (52.6 dB on
# frame 0 when written), and the exact path (step 1) closer still
cb=firmware/scenes/bench/cube-bilinear.scene
sed 's/uv = perspective/uv = perspective perspective_step = 8/' "$cb" >"$tmp/cb8.scene"
run --scene "$tmp/cb8.scene" --panel none --size 240x240 --stats --compare double
a=$(sed -n 's/.*"psnr":\([0-9.a-z]*\).*/\1/p' "$tmp/o")
[ "$rc" -eq 0 ] && awk -v p="$a" 'BEGIN { exit !(p + 0 >= 52) }' && pass bilinear_fast_psnr ||
  fail bilinear_fast_psnr "exit $rc, psnr '$a' (want >= 52 dB)"
sed 's/filter = bilinear/filter = nearest/' "$tmp/cb8.scene" >"$tmp/cn8.scene"
run --scene "$tmp/cn8.scene" --panel none --size 240x240 --stats --compare double
b=$(sed -n 's/.*"psnr":\([0-9.a-z]*\).*/\1/p' "$tmp/o")
[ "$rc" -eq 0 ] && awk -v a="$a" -v b="$b" 'BEGIN { exit !(a + 0 > b + 10) }' && pass bilinear_fast_beats_nearest ||
  fail bilinear_fast_beats_nearest "bilinear '$a' dB, nearest '$b' dB"
# --compare double on a ray-traced scene counts the primary decisions (item
# hit, lights shadowed) that differ from double's, and how many double takes
# too with its camera moved by the format's resolution: raytracer-02 at
# 240x240 has none in fixed point (exact directions), four in float, none of
# them below 2^-21; raytracer-06 two, one below Q15.16's
# step; a rasterized scene has no count
dec_of() { sed -n "s/.*\"decisions_$1\":\([0-9]*\).*/\1/p" "$tmp/o"; }
r2=firmware/scenes/book/raytracer-02.scene
run --scene "$r2" --panel none --size 240x240 --stats --compare double
dfx="$(dec_of off)/$(dec_of below_resolution)"
run --scene "$r2" --panel none --size 240x240 --stats --compare double --numeric float
dfl="$(dec_of off)/$(dec_of below_resolution)"
run --scene firmware/scenes/book/raytracer-06.scene --panel none --size 240x240 --summary --compare double
[ "$dfx" = 0/0 ] && [ "$dfl" = 4/0 ] && grep -q "2 primary decisions off, 1 below resolution" "$tmp/o" &&
  pass compare_decisions || fail compare_decisions "raytracer-02 fixed $dfx, float $dfl (off/below): $(cat "$tmp/o")"
run --scene "$r6" --panel none --size 240x240 --stats --compare double
grep -q decisions_off "$tmp/o" && fail compare_decisions_raster "counted on a rasterized scene" ||
  pass compare_decisions_raster
expect_err num_frac_bad 2 "bad --num-frac '11' (12..20)" --scene "$scene" --num-frac 11
expect_err num_frac_not_fixed 2 "--num-frac applies to fixed point" --scene "$scene" --numeric float --num-frac 16
# A scene no format holds (the book's discriminant of a 5000-radius sphere
# kept in num): exit 2 with the analysis's line; --num-frac still forces one.
cat >"$tmp/ground.scene" <<'SCENE'
raytracer { formulation = book }
sphere { center = (0, -1, 3) radius = 1 color = (255, 0, 0) }
sphere { center = (0, -5001, 0) radius = 5000 color = (255, 255, 0) }
SCENE
expect_err num_frac_refused 2 \
  "ground.scene:1:1: error: sphere 1: the book's discriminant k2^2 - 4 k1 k3 (|CO| <= .*) = .* exceeds the widest number format (|x| < 524288 at NUM_FRAC 12); use a plane, or formulation = robust" \
  --scene "$tmp/ground.scene" --panel none --size 32x24
run --scene "$tmp/ground.scene" --panel none --size 32x24 --num-frac 12
[ "$rc" -eq 0 ] && pass num_frac_refused_forced || fail num_frac_refused_forced "exit $rc: $(head -n 1 "$tmp/e")"
# A scene past every format's positions: the fix named is host_sim's own
# (floating point), not a scene compiler option; float renders it.
cat >"$tmp/far.scene" <<'SCENE'
sphere { center = (0, 0, 3000000) radius = 100000 color = (255, 0, 0) }
SCENE
expect_err num_frac_refused_hint 2 \
  "far.scene:1:1: error: sphere 0: hit points (their reach) = .* exceeds the widest number format .*; scale the scene down, or render it in floating point (--numeric float)" \
  --scene "$tmp/far.scene" --panel none --size 32x24
grep -q -- "--allow-wide" "$tmp/e" && fail num_frac_refused_hint_tool "names scenec's option: $(cat "$tmp/e")" ||
  pass num_frac_refused_hint_tool
run --scene "$tmp/far.scene" --panel none --size 32x24 --numeric float
[ "$rc" -eq 0 ] && pass num_frac_refused_float || fail num_frac_refused_float "exit $rc: $(head -n 1 "$tmp/e")"
run --scene "$tmp/ground.scene" --panel none --size 32x24 --numeric double
[ "$rc" -eq 0 ] && pass num_frac_refused_double_renders || fail num_frac_refused_double_renders "exit $rc"

# ---- the panel path ---------------------------------------------------------
run --scene "$scene" --panel st7789 --out "$tmp/s.png"
[ "$rc" -eq 0 ] && [ "$(png_size "$tmp/s.png")" = 240x240 ] && pass st7789_png_240x240 ||
  fail st7789_png_240x240 "exit $rc, $(png_size "$tmp/s.png"): $(head -n 1 "$tmp/e")"
run --scene "$scene" --out "$tmp/d.png"
[ "$rc" -eq 0 ] && [ "$(png_size "$tmp/d.png")" = 240x240 ] && pass default_panel_st7789 ||
  fail default_panel_st7789 "exit $rc, $(png_size "$tmp/d.png")"
run --scene "$scene" --panel ili9341 --out "$tmp/i.png"
[ "$rc" -eq 0 ] && [ "$(png_size "$tmp/i.png")" = 320x240 ] && pass ili9341_png_320x240 ||
  fail ili9341_png_320x240 "exit $rc, $(png_size "$tmp/i.png"): $(head -n 1 "$tmp/e")"

# The panel path is lossless: the glass shows exactly the renderer's RGB565.
for p in st7789:240x240 st7789:240x320 st7789:320x240 st7789:300x200 st7789:100x37 ili9341:320x240 ili9341:240x320 ili9341:17x5; do
  panel=${p%%:*} size=${p#*:}
  run --scene "$scene" --panel "$panel" --size "$size" --out-raw "$tmp/p.raw" --strip-rows 7
  rc1=$rc
  run --scene "$scene" --panel none --size "$size" --out-raw "$tmp/m.raw"
  if [ "$rc1" -eq 0 ] && [ "$rc" -eq 0 ] && cmp -s "$tmp/p.raw" "$tmp/m.raw"; then
    pass "glass_equals_framebuffer[$p]"
  else
    fail "glass_equals_framebuffer[$p]" "exit $rc1/$rc: $(head -n 1 "$tmp/e")"
  fi
done

# spi_bytes counts the pixel bytes of a frame (2 a pixel) plus the commands.
run --scene "$scene" --panel st7789 --stats
spi=$(sed -n 's/.*"spi_bytes":\([0-9]*\).*/\1/p' "$tmp/o")
[ "$rc" -eq 0 ] && [ -n "$spi" ] && [ "$spi" -ge $((240 * 240 * 2)) ] && [ "$spi" -lt $((240 * 240 * 2 + 4096)) ] &&
  pass stats_spi_bytes || fail stats_spi_bytes "exit $rc, spi_bytes '$spi'"

# ---- protocol violations (exit 3, one line naming the command) --------------
expect_err fault_ramwr_no_window 3 "RAMWR (0x2C) at byte [0-9]" --scene "$scene" --inject-fault ramwr-no-window
expect_err fault_early_after_slpout 3 "(0x[0-9A-F][0-9A-F]) at byte [0-9][0-9]*: .*SLPOUT" --scene "$scene" --inject-fault early-after-slpout
expect_err fault_unknown 2 "unknown fault" --scene "$scene" --inject-fault frob
exit 0
