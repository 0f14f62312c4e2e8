#!/bin/bash
# EEVEE's first render (shader compilation) of the wet material against the
# dry one, per Quality, in Blender 4.3 and 5.2 (bench_eevee_compile.py, one
# Blender process per run, REPEAT runs interleaved over the qualities).
# usage: c_core/bench/bench_eevee_compile.sh [BUILD_DIR] [REPEAT]
# VERSIONS (default "4.3 5.2") and RUN_BLENDER (default
# tests/blender/run_blender.sh) from the environment.
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-$ROOT/build}" && pwd)
REPEAT=${2:-2}
TMP="$BUILD/bench_tmp/eevee_compile"
mkdir -p "$TMP"
/usr/bin/python3 "$ROOT/blender_addon/build_zip.py" "$TMP/soak.zip" > /dev/null
RUN=${RUN_BLENDER:-$ROOT/tests/blender/run_blender.sh}
for ver in ${VERSIONS:-4.3 5.2}; do
  for r in $(seq "$REPEAT"); do
    for q in DRAFT BALANCED EXACT; do
      SOAK_BLENDER=$ver SOAK_BLENDER43_ROOT="${SOAK_BLENDER43_ROOT:-$BUILD/trixie-root}" \
        BLENDER_USER_SCRIPTS="$TMP/user_$ver" \
        bash "$RUN" "$ROOT/c_core/bench/bench_eevee_compile.py" --addon "$TMP/soak.zip" --quality "$q" 2>&1 |
        grep -E '^Blender [0-9].*first render' || echo "run $r $q in $ver: no result"
    done
  done
done
