#!/bin/bash
# The Soak Wet group's Cycles CPU cost on a close-up textured plane, in
# Blender 3.4, 4.3 and 5.2, each Quality (bench_blender_overhead.py:
# dry / dry+coat / wet Draft / Balanced / Exact interleaved, min and median
# of REPEAT). VERSIONS (default "3.4 4.3 5.2"), VARYING=1 (a Noise texture
# into the wetness: the tables read at every point), FOLD=1 (also Draft with the
# coat folded into the base's specular: an experiment) and RUN_BLENDER (default
# tests/blender/run_blender.sh) from the environment.
# usage: c_core/bench/bench_blender_overhead.sh [BUILD_DIR] [REPEAT] [BEFORE_REF]
# BEFORE_REF (a git commit): also the add-on as it was there (blender_addon/
# and osl/ from `git archive`), run after the current one for each version
# and lookup mode: a before/after pair under the same load.
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
REPEAT=${2:-3}
BEFORE=${3:-}
TMP="$BUILD/bench_tmp/blender_overhead"
mkdir -p "$TMP"
/usr/bin/python3 "$ROOT/blender_addon/build_zip.py" "$TMP/soak.zip" > /dev/null
zips=(soak)
if [ -n "$BEFORE" ]; then
  rm -rf "$TMP/before" && mkdir -p "$TMP/before"
  git -C "$ROOT" archive "$BEFORE" blender_addon osl | tar -x -C "$TMP/before"
  /usr/bin/python3 "$TMP/before/blender_addon/build_zip.py" "$TMP/soak_before.zip" > /dev/null
  zips+=(soak_before)
fi
RUN=${RUN_BLENDER:-$ROOT/tests/blender/run_blender.sh}
for ver in ${VERSIONS:-3.4 4.3 5.2}; do
  for z in "${zips[@]}"; do
    echo "### Blender $ver, add-on $z"
    qualities=DRAFT,BALANCED,EXACT
    [ "$z" = soak ] || qualities=BALANCED     # an add-on from before the Quality setting
    SOAK_BLENDER=$ver SOAK_BLENDER43_ROOT="${SOAK_BLENDER43_ROOT:-$BUILD/trixie-root}" BLENDER_USER_SCRIPTS="$TMP/user_${ver}_$z" \
      bash "$RUN" "$ROOT/c_core/bench/bench_blender_overhead.py" \
      --addon "$TMP/$z.zip" --repeat "$REPEAT" --qualities "$qualities" --fold "${FOLD:-0}" --varying "${VARYING:-0}" 2>&1 |
      grep -E '^(run |Blender [0-9]|dry:|coat:|coat noise:|wet|ratio)'
  done
done
