#!/bin/bash
# Benchmark (not a test): the rain-over-time bakes of issue 37 with one
# build. `soak bake drops` on a RES x RES plane (1 m) for FRAMES frames at
# 24 fps (rain for the first 3/4, then drying) and `soak bake ripples`
# RRES x RRES x RFRAMES with its distance version; CPU time (user + sys,
# what the machine's load does not inflate) and wall time of each, and the
# CPU time of a second drops run split in two chunks (the farm's way: the
# second chunk replays the rain up to its first frame). Usage:
#   bench_rain_over_time.sh BUILD [RES] [FRAMES] [RRES] [RFRAMES] [THREADS]
set -eu
SOAK="$1/bin/soak"
RES="${2:-1024}"
FRAMES="${3:-240}"
RRES="${4:-512}"
RFRAMES="${5:-64}"
THREADS="${6:-2}"
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
DUR=$(echo "$FRAMES * 3 / 4 / 24" | bc -l)

timed() { # label command... -> "label wall cpu"
    local label=$1 t0 t1 cpu
    shift
    t0=$(date +%s.%N)
    cpu=$( { /usr/bin/time -f "%U %S" "$@" >/dev/null; } 2>&1 | tail -1 | awk '{print $1 + $2}')
    t1=$(date +%s.%N)
    printf "| %s | %.2f | %.2f |\n" "$label" "$(echo "$t1 - $t0" | bc -l)" "$cpu"
}
last=$((FRAMES - 1))
half=$((FRAMES / 2))
echo "| bake | wall (s) | CPU (s) |"
echo "|---|---:|---:|"
drops=(bake drops --rate 10 --map-size 1 --width "$RES" --height "$RES" --duration "$DUR" --dry-time 5 --fps 24
       --threads "$THREADS")
timed "drops ${RES}^2 x $FRAMES frames" "$SOAK" "${drops[@]}" --frames "0-$last" -o "$W/drops.%04d.exr"
timed "drops, chunk 0-$((half - 1))" "$SOAK" "${drops[@]}" --frames "0-$((half - 1))" -o "$W/chunk.%04d.exr"
timed "drops, chunk $half-$last" "$SOAK" "${drops[@]}" --frames "$half-$last" -o "$W/chunk.%04d.exr"
same=1
for f in 0 $((half - 1)) $half $last; do
    n=$(printf %04d "$f")
    idiff -fail 0 -warn 0 "$W/drops.$n.exr" "$W/chunk.$n.exr" >/dev/null 2>&1 || same=0
done
echo
echo "chunked frames equal to one run (pixels, frames 0, $((half - 1)), $half, $last): $([ $same = 1 ] && echo yes || echo NO)"
echo
echo "| bake | wall (s) | CPU (s) |"
echo "|---|---:|---:|"
timed "ripples ${RRES}^2 x $RFRAMES frames (+ distance version)" "$SOAK" bake ripples --rate 10 --width "$RRES" \
    --loop-frames "$RFRAMES" --frames "0-$((RFRAMES - 1))" --threads "$THREADS" -o "$W/rip.%04d.exr" --far "$W/far.%04d.exr"
