#!/bin/bash
# Benchmark (not a test): soak's rain sky-exposure bake vs Blender Cycles' AO
# bake of the same ~100k-triangle mesh, UVs, resolution and sample count, on
# the CPU, timed in the same run. soak runs with --sky hemisphere (cosine
# hemisphere about the normal: the same estimator as AO) and --duration 0
# (exposure only). Prints both times, the ratio and the mean |difference|
# of the two maps over the covered texels (a sanity check, not a criterion).
# usage: bench_rain_vs_cycles.sh [BUILD_DIR] [RES] [RAYS] [THREADS]   (soak = BUILD_DIR/bin/soak)
set -eu
HERE="$(cd "$(dirname "$0")" && pwd)"
SOAK="${1:-build}/bin/soak"
RES="${2:-1024}"
RAYS="${3:-64}"
THREADS="${4:-$(nproc)}"
command -v blender >/dev/null || { echo "blender not on PATH"; exit 1; }
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT

python3 "$HERE/rain_mesh.py" "$W/mesh.obj" 224
echo "mesh: $(grep -c '^f ' "$W/mesh.obj") triangles, ${RES}x${RES}, $RAYS rays/samples, $THREADS threads"

t0=$(date +%s.%N)
"$SOAK" bake rain "$W/mesh.obj" --up y --sky hemisphere --duration 0 --rays "$RAYS" --threads "$THREADS" \
    --width "$RES" --height "$RES" --gutter 4 --exposure "$W/soak_exposure.exr" -o "$W/soak_wet.exr" >/dev/null
t1=$(date +%s.%N)
soak_s=$(echo "$t1 - $t0" | bc -l)

blender -b --factory-startup --python-exit-code 1 --python "$HERE/cycles_ao_bake.py" -- \
    "$W/mesh.obj" "$W/cycles_ao.exr" "$RES" "$RAYS" "$THREADS" >"$W/blender.log" 2>&1 ||
    { cat "$W/blender.log"; exit 1; }
cycles_s=$(sed -n 's/^CYCLES_AO_BAKE_SECONDS //p' "$W/blender.log")

diff=$(oiiotool "$W/soak_exposure.exr" --ch 0 "$W/cycles_ao.exr" --ch 0 --absdiff --printstats 2>/dev/null |
    sed -n 's/.*Stats Avg: *\([0-9.eE+-]*\).*/\1/p' | head -1)
printf "soak rain exposure bake (whole command): %.2f s\n" "$soak_s"
printf "Cycles AO bake (bpy.ops.object.bake):    %.2f s\n" "$cycles_s"
printf "ratio soak / Cycles:                      %.2f\n" "$(echo "$soak_s / $cycles_s" | bc -l)"
mean_of() { oiiotool "$1" --ch 0 --printstats 2>/dev/null | sed -n 's/.*Stats Avg: *\([0-9.eE+-]*\).*/\1/p' | head -1; }
echo "mean |soak exposure - Cycles AO| (all texels): ${diff:-n/a}"
echo "map means: soak $(mean_of "$W/soak_exposure.exr"), Cycles $(mean_of "$W/cycles_ao.exr")"
