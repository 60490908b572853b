#!/bin/sh
# The scene compiler's promise on valid extreme scenes (tools/scene/gen_extreme.py):
# for every generated scene that the double build renders, host_sim in fixed
# point either refuses it on one line with the format analysis's reason
# (nothing fits, or ill-conditioned for fixed point) or renders it at the
# format the analysis chose — never "accepted, then refused" (exit 2 for any
# other reason), never a crash or a sanitizer report, and, where float is
# within 30 dB of double or exact, fixed is at least 20 dB.
# usage: test_scene_extremes.sh HOST_SIM SEED COUNT
set -u
hs=$1
seed=${2:-1}
count=${3:-100}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
python3 tools/scene/gen_extreme.py "$seed" "$count" "$t" || { echo "FAIL extremes_generator: exit $?"; exit 1; }
ran=0 refused=0 bad=0 low=0 crash=0
psnr() { sed -n 's/.*"psnr":\([0-9.]*\|null\).*/\1/p' "$1" | tail -n 1; }
for f in "$t"/x-*.scene; do
  timeout 120 "$hs" --scene "$f" --numeric double --size 32x32 --panel none --out-raw "$t/d.raw" >/dev/null 2>"$t/derr" || continue
  timeout 120 "$hs" --scene "$f" --numeric fixed --size 32x32 --panel none --compare double --stats >"$t/fo" 2>"$t/ferr"
  rc=$?
  if [ $rc -eq 2 ]; then
    if grep -q "exceeds the widest number format\|ill-conditioned for fixed point" "$t/ferr" &&
       [ "$(grep -vc 'warning:' "$t/ferr")" -eq 1 ]; then
      refused=$((refused + 1))
    else
      bad=$((bad + 1))
      echo "# accepted, then refused: $(basename "$f"): $(grep -v 'warning:' "$t/ferr" | head -c 200)"
      cp "$f" "$t/../extreme-$(basename "$f")" 2>/dev/null
    fi
    continue
  fi
  if [ $rc -ne 0 ] || grep -q "ERROR: \|runtime error" "$t/ferr"; then
    crash=$((crash + 1))
    echo "# exit $rc: $(basename "$f"): $(head -c 200 "$t/ferr")"
    continue
  fi
  ran=$((ran + 1))
  timeout 120 "$hs" --scene "$f" --numeric float --size 32x32 --panel none --compare double --stats >"$t/flo" 2>/dev/null || continue
  pf=$(psnr "$t/fo"); pl=$(psnr "$t/flo")
  [ "$pf" = null ] && continue
  if [ "$pl" = null ] || awk -v a="$pl" 'BEGIN { exit !(a >= 30) }'; then
    if awk -v a="$pf" 'BEGIN { exit !(a < 20) }'; then
      low=$((low + 1))
      echo "# fixed $pf dB, float ${pl} dB: $(basename "$f")"
    fi
  fi
done
echo "# seed $seed: $count scenes; $ran rendered in fixed point, $refused refused by the format analysis"
[ $bad -eq 0 ] && echo "PASS extremes_never_accepted_then_refused" || echo "FAIL extremes_never_accepted_then_refused: $bad scenes"
[ $crash -eq 0 ] && echo "PASS extremes_no_crash_or_sanitizer_report" || echo "FAIL extremes_no_crash_or_sanitizer_report: $crash scenes"
[ $low -eq 0 ] && echo "PASS extremes_fixed_20db_where_float_is_fine" || echo "FAIL extremes_fixed_20db_where_float_is_fine: $low scenes"
