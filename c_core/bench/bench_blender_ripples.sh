#!/bin/bash
# The ripples' Cycles CPU cost in Blender 3.4, 4.3 and 5.2 (bench_blender_ripples.py:
# the wet plane without the Rain wiring's ripple normal, with the sharp flipbook alone,
# with the sharp and far ones blended by distance, and Bake Rain's near-only wiring, interleaved, min
# and median of REPEAT). VERSIONS (default "3.4 4.3 5.2") and RUN_BLENDER (default
# tests/blender/run_blender.sh) from the environment.
# usage: c_core/bench/bench_blender_ripples.sh [BUILD_DIR] [REPEAT]
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
REPEAT=${2:-5}
TMP="$BUILD/bench_tmp/blender_ripples"
mkdir -p "$TMP/frames"
/usr/bin/python3 "$ROOT/blender_addon/build_zip.py" "$TMP/soak.zip" > /dev/null
# the flipbooks the add-on's Bake Rain makes (256 px, 0.5 m tile) and a wet map that floods the plane
"$BUILD/bin/soak" bake ripples --rate 10 --width 256 --frames 0-0 --threads 2 -o "$TMP/frames/ripples.%04d.exr" \
  --far "$TMP/frames/ripples_far.%04d.exr" > /dev/null
oiiotool --pattern constant:color=0.8,0.8,0.8 64x64 3 -d half -o "$TMP/frames/wet.0001.exr"
echo "commit $(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet HEAD -- blender_addon || echo ' (with uncommitted add-on changes)')"
RUN=${RUN_BLENDER:-$ROOT/tests/blender/run_blender.sh}
for ver in ${VERSIONS:-3.4 4.3 5.2}; do
  echo "### Blender $ver"
  SOAK_BLENDER=$ver SOAK_BLENDER43_ROOT="${SOAK_BLENDER43_ROOT:-$BUILD/trixie-root}" \
    SOAK_BLENDER52_ROOT="${SOAK_BLENDER52_ROOT:-$BUILD/sid-root}" BLENDER_USER_SCRIPTS="$TMP/user_$ver" \
    nice -n 5 bash "$RUN" "$ROOT/c_core/bench/bench_blender_ripples.py" --addon "$TMP/soak.zip" \
    --frames "$TMP/frames" --repeat "$REPEAT" 2>&1 | grep -E '^(run |Blender [0-9]|wet:|sharp:|ripples:|near:|ratio|Traceback|  File|[A-Za-z]*Error)'
done
