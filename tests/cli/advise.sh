#!/bin/bash
# soak advise and soak render --auto-model, verified rather than promised:
# for every shipped scene (scenes/*.json, small size and spp) the auto-model
# render is within T of the full render. Measured: d_auto = RMS(auto - full)
# with independent seeds, d_noise = RMS(full' - full) between two seeds of
# the full render; the auto model's bias is b = sqrt(max(0, d_auto^2 -
# k d_noise^2)) with k = 1 + 4 sqrt(2/n) (n pixel channels: the spread of a
# mean of n squared differences) covering the noise of the noise estimate;
# the check is b / mean(full) <= T. The ratio of render times is printed,
# never asserted. Also: --help, argument errors (exit 2, option named).
# ctest-label: slow
set -u
source "$(dirname "$0")/lib.bash"
root=${SOAK_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
T=0.25

expect_exit 0 "--help" -- "$SOAK" advise --help
grep -q "soak advise SCENE.json --tol" "$SOAK_TMP/last.out" && ok "--help prints usage" || bad "--help prints no usage"
expect_exit 2 "missing --tol" -- "$SOAK" advise "$root/scenes/sand.json"
expect_stderr "--tol" "error names --tol"
expect_exit 2 "--tol out of range" -- "$SOAK" advise "$root/scenes/sand.json" --tol -1
expect_stderr "--tol" "error names --tol"
expect_exit 2 "--tol NaN" -- "$SOAK" advise "$root/scenes/sand.json" --tol nan
expect_exit 2 "bad --grid" -- "$SOAK" advise "$root/scenes/sand.json" --tol 0.1 --grid 3y4
expect_stderr "--grid" "error names --grid"
expect_exit 2 "missing scene" -- "$SOAK" advise --tol 0.1
expect_stderr "SCENE" "error names the scene argument"
expect_exit 1 "unreadable scene" -- "$SOAK" advise "$SOAK_TMP/nosuch.json" --tol 0.1
expect_stderr "nosuch.json" "error names the scene file"
expect_exit 2 "render --auto-model out of range" -- "$SOAK" render "$root/scenes/sand.json" -o "$SOAK_TMP/x.exr" --auto-model 0
expect_stderr "--auto-model" "error names --auto-model"

if ! command -v oiiotool > /dev/null; then skip "oiiotool not on PATH" "image comparisons"; finish; fi
rms() { oiiotool "$1" "$2" --diff 2>&1 | awk '/RMS error/ { for (i = 1; i <= NF; ++i) if ($i == "=") { print $(i + 1); exit } }'; }
avg() { oiiotool --stats "$1" 2>&1 | awk '/Stats Avg/ { print ($3 + $4 + $5) / 3; exit }'; }
# The render's own time (its statistics, one thread; the advice before it is
# not counted): printed only, a loaded machine makes it noisy.
secs() { awk '/^time:/ { print $2 }' "$1"; }
for scene in "$root"/scenes/*.json; do
  name=$(basename "$scene" .json)
  T_DIR="$SOAK_TMP/$name"; mkdir -p "$T_DIR"
  args=(--width 48 --height 36 --spp 16 --threads 1)
  if ! "$SOAK" render "$scene" -o "$T_DIR/full_a.exr" "${args[@]}" --seed 11 > "$T_DIR/full_a.log" 2>&1 ||
     ! "$SOAK" render "$scene" -o "$T_DIR/full_b.exr" "${args[@]}" --seed 12 > "$T_DIR/full_b.log" 2>&1 ||
     ! "$SOAK" render "$scene" -o "$T_DIR/auto.exr" "${args[@]}" --seed 13 --auto-model $T > "$T_DIR/auto.log" 2> "$T_DIR/auto.err"; then
    bad "$name: a render failed: $(tail -c 300 "$T_DIR"/*.log "$T_DIR/auto.err")"; continue
  fi
  d_auto=$(rms "$T_DIR/auto.exr" "$T_DIR/full_a.exr"); d_noise=$(rms "$T_DIR/full_b.exr" "$T_DIR/full_a.exr")
  mean=$(avg "$T_DIR/full_a.exr")
  if ! number "$d_auto" || ! number "$d_noise" || ! number "$mean"; then bad "$name: no image statistics ($d_auto, $d_noise, $mean)"; continue; fi
  chosen=$(awk 'NR > 2 { printf "%s%s=%s", (n++ ? " " : ""), $1, $2 }' "$T_DIR/auto.err")
  verdict=$(awk -v a="$d_auto" -v n0="$d_noise" -v m="$mean" -v t=$T -v n=$((48 * 36 * 3)) -v fa="$(secs "$T_DIR/full_a.log")" -v fu="$(secs "$T_DIR/auto.log")" 'BEGIN {
    k = 1 + 4 * sqrt(2 / n); b2 = a * a - k * n0 * n0; b = b2 > 0 ? sqrt(b2) : 0
    printf "%s relative RMSE %.4f (raw %.4f, noise %.4f) <= %.2f; speed ratio full/auto %.2fx", (b / m <= t ? "ok" : "FAIL"), b / m, a / m, n0 / m, t, (fu > 0 ? fa / fu : 0) }')
  case "$verdict" in
    ok*) ok "$name [$chosen]: ${verdict#ok }" ;;
    *) bad "$name [$chosen]: ${verdict#FAIL }" ;;
  esac
done
finish
