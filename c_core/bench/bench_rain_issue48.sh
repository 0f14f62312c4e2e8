#!/bin/bash
# Benchmark (not a test) of issue 48's rain models, CPU seconds (user + sys)
# per baked frame at RES x RES, interleaved REPS times, min and median:
#   rain:      `soak bake rain` of the gallery's bas-relief (relief_mesh.py
#              240), one single map, RAYS rays, --film; OLD build vs NEW
#              (the streams' boxes) vs NEW --contact-angle 30 (runnels);
#   drops:     `soak bake drops` one frame at t = 10 s of 20 mm/h on a 0.2 m
#              map, OLD vs NEW vs NEW --splash;
#   frames:    `soak bake rain --frames 0-3` (4 frames, 240 steps of 600 s)
#              of the same relief, OLD vs NEW (the boxes in the film's wave)
#              vs NEW --contact-angle 30 (each frame's film into runnels).
# OLD may equal NEW (then only the options' cost shows). Usage:
#   bench_rain_issue48.sh OLD_BUILD NEW_BUILD [RES] [RAYS] [THREADS] [REPS]
set -eu
HERE="$(cd "$(dirname "$0")" && pwd)"
OLD="$1/bin/soak"
NEW="$2/bin/soak"
RES="${3:-1024}"
RAYS="${4:-16}"
THREADS="${5:-1}"
REPS="${6:-3}"
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
python3 "$HERE/../../scenes/povray/gallery/relief_mesh.py" "$W" 240 >/dev/null
echo "relief: $(grep -c '^f ' "$W/relief.obj") triangles; ${RES}x${RES}, $RAYS rays, $THREADS threads, $REPS interleaved repeats"

cpu() { # label command... : appends the CPU seconds of the command to $W/label.times
    local label="$1"
    shift
    /usr/bin/time -o "$W/time" -f "%U %S" "$@" >/dev/null 2>"$W/err" || { cat "$W/err" >&2; exit 1; }
    tail -1 "$W/time" | awk '{print $1 + $2}' >>"$W/$label.times"
}
rain() { # label binary extra...
    local label="$1" bin="$2"
    shift 2
    cpu "$label" "$bin" bake rain "$W/relief.obj" --up z --rain-dir 0,-0.55,1 --spread 15 --rainfall 6 --rays "$RAYS" \
        --threads "$THREADS" --width "$RES" --height "$RES" --film "$W/$label.film.exr" --float -o "$W/$label.exr" "$@"
}
drops() { # label binary extra...
    local label="$1" bin="$2"
    shift 2
    cpu "$label" "$bin" bake drops --rate 20 --map-size 0.2 --width "$RES" --height "$RES" --duration 10 --time 10 \
        --threads "$THREADS" -o "$W/$label.exr" "$@"
}
frames() { # label binary extra...
    local label="$1" bin="$2"
    shift 2
    cpu "$label" "$bin" bake rain "$W/relief.obj" --up z --rain-dir 0,-0.55,1 --spread 15 --rainfall 6 --rays "$RAYS" \
        --threads "$THREADS" --width "$RES" --height "$RES" --steps 240 --frames 0-3 --fps 0.01 \
        -o "$W/$label.%04d.exr" "$@"
}
for ((r = 0; r < REPS; ++r)); do
    rain rain_old "$OLD"
    rain rain_new "$NEW"
    rain rain_runnels "$NEW" --contact-angle 30
    drops drops_old "$OLD"
    drops drops_new "$NEW"
    drops drops_splash "$NEW" --splash
    frames frames_old "$OLD"
    frames frames_new "$NEW"
    frames frames_runnels "$NEW" --contact-angle 30
done
stats() { # file -> "min median"
    sort -g "$1" | awk '{a[NR]=$1} END {m = (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2; printf "%.2f %.2f", a[1], m}'
}
printf "| run | CPU min (s) | CPU median (s) |\n|---|---:|---:|\n"
for b in rain_old rain_new rain_runnels drops_old drops_new drops_splash frames_old frames_new frames_runnels; do
    read -r cmin cmed <<<"$(stats "$W/$b.times")"
    printf "| %s | %s | %s |\n" "$b" "$cmin" "$cmed"
done
