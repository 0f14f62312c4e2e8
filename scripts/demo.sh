#!/usr/bin/env bash
# demo.sh BUILD OUT JOBS: what `make demo` runs after the set-up, one line per
# step. Each step's own output (compiler, soak, POV-Ray, Blender) goes to a
# log file under OUT/logs that the step's line names; a failed step prints
# the end of its log and stops the demo. On a terminal the running step's
# line counts its progress (build percentage, pictures rendered, bakes done).
# It builds only what the demo runs: the soak tool and its I/O modules (not
# the tests, nor the clang fuzzing tree that `make test` adds).
set -uo pipefail
BUILD=${1:?usage: demo.sh BUILD OUT JOBS}
OUT=${2:?usage: demo.sh BUILD OUT JOBS}
JOBS=${3:-2}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
case "$BUILD" in /*) BUILD_ABS=$BUILD ;; *) BUILD_ABS=$ROOT/$BUILD ;; esac
LOGS=$OUT/logs
mkdir -p "$LOGS"
SOAK=$BUILD/bin/soak
N_STEPS=5
t_demo=$(date +%s.%N)
tty=0
[ -t 1 ] && tty=1

elapsed() { awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f s", b - a }'; }

# step K TITLE LOG PROGRESS_FN CMD...: runs CMD with its output in LOG; on a
# terminal redraws "[K/N] TITLE: <progress>" every second; prints the step's
# final line (time, log) or, on failure, the log's last lines and exits.
step() {
  local k=$1 title=$2 log=$3 progress=$4; shift 4
  local t0 pid rc
  t0=$(date +%s.%N)
  "$@" > "$log" 2>&1 &
  pid=$!
  while kill -0 "$pid" 2>/dev/null; do
    [ $tty = 1 ] && printf '\r\033[K[%d/%d] %s: %s' "$k" "$N_STEPS" "$title" "$($progress)"
    sleep 1
  done
  wait "$pid"; rc=$?
  [ $tty = 1 ] && printf '\r\033[K'
  if [ $rc -ne 0 ]; then
    echo "[$k/$N_STEPS] $title: FAILED (exit $rc) after $(elapsed "$t0"); the end of $log:"
    tail -20 "$log" | sed 's/^/    /'
    exit 1
  fi
  echo "[$k/$N_STEPS] $title: done in $(elapsed "$t0")$($progress | sed 's/^/, /;s/, $//') (log: $log)"
}

# progress readers: they print a short count, or nothing
build_progress() {   # (cmake's percentages count the whole project's targets, not soak's)
  local n; n=$(grep -cE '^\[ *[0-9]+%\] Building' "$LOGS/build.log" 2>/dev/null); echo "${n:-0} files compiled"; }
soak_progress() {   # soak demo echoes each command it runs as "$ soak ..."
  local n; n=$(grep -c '^\$ soak' "$LOGS/soak-demo.log" 2>/dev/null); echo "${n:-0} soak commands"; }
# POV-Ray: the pictures begun, by their logs (render_scenes.sh writes
# NAME.exr.log as it starts NAME.exr), out of the last run's count
pov_progress() {
  local n; n=$(find "$OUT/povray" -maxdepth 1 -name '*.exr.log' -newer "$LOGS/.povray-start" 2>/dev/null | wc -l)
  echo "$n${POV_TOTAL:+/$POV_TOTAL} pictures"; }
blender_progress() {   # render_all.py prints "wrote PATH" for each picture
  local n; n=$(grep -c '^wrote ' "$LOGS/blender.log" 2>/dev/null); echo "${n:-0} pictures"; }

configure_and_build() {
  # No -DSOAK_FUZZ_IN_TEST here: a build folder that `make test` configured keeps its setting.
  cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DSOAK_WERROR=ON &&
    cmake --build "$BUILD" -j "$JOBS" --target soak_cli
}
step 1 "build soak ($BUILD/bin/soak)" "$LOGS/build.log" build_progress configure_and_build

step 2 "soak demo: albedo table, swatches, wet maps, wet-vs-dry render" "$LOGS/soak-demo.log" soak_progress \
  "$SOAK" demo --out "$OUT"

POV_TOTAL=$(ls "$OUT"/povray/*.exr.log 2>/dev/null | wc -l)
touch "$LOGS/.povray-start"
[ "$POV_TOTAL" -gt 0 ] || POV_TOTAL=""
step 3 "POV-Ray seed scenes, 480 px" "$LOGS/povray.log" pov_progress \
  bash povray/render_scenes.sh "$SOAK" "$OUT/povray" full

zips() {
  /usr/bin/python3 blender_addon/build_zip.py "$BUILD/soak_blender.zip" &&
    /usr/bin/python3 scenes/blender/variant_addon.py "$SOAK" "$BUILD/soak_blender.zip" scenes/gallery/variants.txt \
      "$BUILD/soak_blender_gallery.zip"
}
step 4 "Blender add-on ($BUILD/soak_blender.zip, with the gallery's presets)" "$LOGS/addon.log" true zips

blender_render() {
  BLENDER_USER_SCRIPTS=$BUILD_ABS/blender_user blender -b --factory-startup --python-exit-code 1 \
    --python scenes/blender/render_all.py -- --addon "$BUILD/soak_blender_gallery.zip" --out "$OUT/blender" --soak "$SOAK"
}
step 5 "Blender seed scenes, Cycles 320x180" "$LOGS/blender.log" blender_progress blender_render

first=""
[ -f "$OUT/swatches.png" ] && first=$(awk -v a="$t_demo" -v b="$(stat -c %Y "$OUT/swatches.png")" \
  'BEGIN { printf "; the first picture, %s, %.0f s after the start", "swatches.png", b - a }')
echo "demo finished in $(elapsed "$t_demo")$first; results:"
echo "  $OUT/albedo_table.csv, $OUT/swatches.png, $OUT/wetmap_*.png, $OUT/render_wet_dry.png  (soak)"
echo "  $OUT/povray/*.png  ($(ls "$OUT"/povray/*.png 2>/dev/null | wc -l) pictures)"
echo "  $OUT/blender/*.png  ($(ls "$OUT"/blender/*.png 2>/dev/null | wc -l) pictures)"
echo "  logs: $LOGS/"
