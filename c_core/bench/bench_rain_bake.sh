#!/bin/bash
# Benchmark (not a test): `soak bake rain` of the ~100k-triangle benchmark
# mesh (rain_mesh.py) at RES x RES with RAYS rays and the default rain (600 s
# in 32 steps, 16 flow sweeps each), for two builds side by side: OLD and NEW
# alternate REPS times (interleaved), min and median of wall and CPU
# (user + sys) seconds each; then the pixels of every output (wetness,
# exposure, water depth) of the two builds are compared (oiiotool --diff:
# max |difference|). Usage:
#   bench_rain_bake.sh OLD_BUILD NEW_BUILD [RES] [RAYS] [THREADS] [REPS]
set -eu
HERE="$(cd "$(dirname "$0")" && pwd)"
OLD="$1/bin/soak"
NEW="$2/bin/soak"
RES="${3:-1024}"
RAYS="${4:-64}"
THREADS="${5:-2}"
REPS="${6:-3}"
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
python3 "$HERE/rain_mesh.py" "$W/mesh.obj" 224
echo "mesh: $(grep -c '^f ' "$W/mesh.obj") triangles, ${RES}x${RES}, $RAYS rays, $THREADS threads, $REPS interleaved repeats"

run() { # build-label binary
    local t0 t1 cpu
    t0=$(date +%s.%N)
    cpu=$( { /usr/bin/time -f "%U %S" "$2" bake rain "$W/mesh.obj" --up y --rays "$RAYS" --threads "$THREADS" \
        --width "$RES" --height "$RES" --exposure "$W/$1_exposure.exr" --water "$W/$1_water.exr" \
        -o "$W/$1_wet.exr" >/dev/null; } 2>&1 | tail -1 | awk '{print $1 + $2}')
    t1=$(date +%s.%N)
    echo "$(echo "$t1 - $t0" | bc -l) $cpu" >>"$W/$1.times"
}
for ((r = 0; r < REPS; ++r)); do
    run old "$OLD"
    run new "$NEW"
done
stats() { # file column -> "min median"
    awk -v c="$2" '{print $c}' "$1" | sort -g | awk '{a[NR]=$1} END {m = (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2; printf "%.2f %.2f", a[1], m}'
}
printf "| build | wall min (s) | wall median (s) | CPU min (s) | CPU median (s) |\n|---|---:|---:|---:|---:|\n"
for b in old new; do
    read -r wmin wmed <<<"$(stats "$W/$b.times" 1)"
    read -r cmin cmed <<<"$(stats "$W/$b.times" 2)"
    printf "| %s | %s | %s | %s | %s |\n" "$b" "$wmin" "$wmed" "$cmin" "$cmed"
done
for m in wet exposure water; do
    d=$(oiiotool --fail 0 --warn 0 "$W/old_$m.exr" "$W/new_$m.exr" --diff 2>&1 | sed -n 's/.*Max error *= *\([^ ]*\).*/\1/p' | head -1)
    echo "pixels $m: max |old - new| = ${d:-0 (identical)}"
done
