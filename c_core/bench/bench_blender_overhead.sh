#!/bin/bash
# The Soak Wet group's Cycles CPU cost on a close-up textured plane, in
# Blender 3.4 and 4.3, default and exact lookups (bench_blender_overhead.py:
# dry / dry+coat / wet interleaved, min and median of REPEAT).
# usage: c_core/bench/bench_blender_overhead.sh [BUILD_DIR] [REPEAT]
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
REPEAT=${2:-3}
TMP="$BUILD/bench_tmp/blender_overhead"
mkdir -p "$TMP"
/usr/bin/python3 "$ROOT/blender_addon/build_zip.py" "$TMP/soak.zip" > /dev/null
for ver in 3.4 4.3; do
  for exact in 0 1; do
    echo "### Blender $ver, exact lookups $exact"
    SOAK_BLENDER=$ver SOAK_BLENDER43_ROOT="$BUILD/trixie-root" BLENDER_USER_SCRIPTS="$TMP/user_$ver" \
      bash "$ROOT/tests/blender/run_blender.sh" "$ROOT/c_core/bench/bench_blender_overhead.py" \
      --addon "$TMP/soak.zip" --repeat "$REPEAT" --exact "$exact" 2>&1 |
      grep -E '^(run |Blender [0-9]|dry:|coat:|wet:|ratio)'
  done
done
