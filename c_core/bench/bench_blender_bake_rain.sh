#!/bin/bash
# Benchmark (not a test): Bake Rain in Blender for a 250-frame shot at the
# default resolution, OLD_ZIP against NEW_ZIP (add-on zips, e.g. `git stash;
# make addon` for the old one), interleaved REPS times; each side with its
# own defaults, then both with the old inputs (rain frames 1-120 in real
# time), then NEW again with the ripple flipbook cached from the run before.
# Min and median of wall and CPU (the soak processes) seconds.
#   bench_blender_bake_rain.sh SOAK OLD_ZIP NEW_ZIP [REPS] [BLENDER_VERSION]
set -eu
HERE="$(cd "$(dirname "$0")" && pwd)"
SOAK=$(readlink -f "$1"); OLD=$(readlink -f "$2"); NEW=$(readlink -f "$3"); REPS=${4:-2}
export SOAK_BLENDER=${5:-3.4}
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
export TMPDIR=$W/tmp     # the bakes of an unsaved file (and the ripple cache) in a folder of this run only
mkdir -p "$TMPDIR"
run() { # label zip extra-args...
  local label=$1 zip=$2; shift 2
  rm -rf "$W/user"
  BLENDER_USER_SCRIPTS=$W/user BLENDER_USER_EXTENSIONS=$W/user/ext BLENDER_USER_CONFIG=$W/user/cfg \
    bash "$HERE/../../tests/blender/run_blender.sh" "$HERE/bench_blender_bake_rain.py" --addon "$zip" \
    --soak "$SOAK" --label "$label" "$@" 2>&1 | grep '^BENCH' | tee -a "$W/all"
}
for r in $(seq "$REPS"); do
  run old_defaults "$OLD"
  run new_defaults "$NEW"
  run old_same_inputs "$OLD" --same-inputs 1
  run new_same_inputs "$NEW" --same-inputs 1
  run new_defaults_cached "$NEW" --cold 0
done
echo "label min_wall median_wall min_cpu median_cpu (s), $REPS runs each, Blender $SOAK_BLENDER, load $(cut -d' ' -f1-3 /proc/loadavg)"
for l in old_defaults new_defaults old_same_inputs new_same_inputs new_defaults_cached; do
  grep " $l " "$W/all" | /usr/bin/python3 -c "
import sys, statistics as st
rows = [l.split() for l in sys.stdin]
w = [float(r[3]) for r in rows]; c = [float(r[5]) for r in rows]
print('$l', f'{min(w):.2f} {st.median(w):.2f} {min(c):.2f} {st.median(c):.2f}')"
done
