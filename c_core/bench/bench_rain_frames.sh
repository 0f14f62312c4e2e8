#!/bin/bash
# Benchmark (not a test): `soak bake rain --frames` (the film in time, issue
# 37 item 3) on the gallery's bas-relief (scenes/povray/gallery/relief_mesh.py
# 240, 2.6 x 1.3 m, z up) in 10 minutes of 6 mm/h from the front: CPU time
# (user + sys) of RES x RES, FRAMES frames 50 s apart (rain, then drainage and
# drying), of the exposure alone (one frame at t = 0) and of the same frames
# in two chunks. With PLOT_DIR, also the frames of docs/images/
# rain_frames_relief.png (800 x 400 at t = 5, 15, 40, 600, 615, 660 s) and
# the plot (plot_rain_frames.py). Usage:
#   bench_rain_frames.sh BUILD [RES] [FRAMES] [THREADS] [PLOT_DIR]
set -eu
SOAK="$1/bin/soak"
RES="${2:-512}"
FRAMES="${3:-24}"
THREADS="${4:-2}"
PLOT="${5:-}"
HERE="$(cd "$(dirname "$0")" && pwd)"
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
python3 "$HERE/../../scenes/povray/gallery/relief_mesh.py" "$W" 240 >/dev/null
RAIN=(bake rain "$W/relief.obj" --up z --rain-dir 0,-0.55,1 --spread 15 --rays 32 --rainfall 6 --duration 600
      --threads "$THREADS")
cpu() { { /usr/bin/time -f "%U %S" "$@" >/dev/null; } 2>&1 | tail -1 | awk '{print $1 + $2}'; }
last=$((FRAMES - 1))
half=$((FRAMES / 2))
echo "| run | CPU s |"
echo "|---|---|"
echo "| exposure only (frame 0 at t = 0), ${RES}^2 | $(cpu "$SOAK" "${RAIN[@]}" --width "$RES" --height "$RES" --steps 60 \
    --frames 0-0 -o "$W/e.%04d.exr") |"
echo "| $FRAMES frames 50 s apart, ${RES}^2, --steps 60, with --film | $(cpu "$SOAK" "${RAIN[@]}" --width "$RES" \
    --height "$RES" --steps 60 --fps 0.02 --frames 0-$last --film "$W/f.%04d.exr" -o "$W/w.%04d.exr") |"
c1=$(cpu "$SOAK" "${RAIN[@]}" --width "$RES" --height "$RES" --steps 60 --fps 0.02 --frames 0-$((half - 1)) \
    --film "$W/c.f.%04d.exr" -o "$W/c.w.%04d.exr")
c2=$(cpu "$SOAK" "${RAIN[@]}" --width "$RES" --height "$RES" --steps 60 --fps 0.02 --frames $half-$last \
    --film "$W/c.f.%04d.exr" -o "$W/c.w.%04d.exr")
same=yes
for f in "$W"/w.*.exr; do cmp -s "$f" "$W/c.${f##*/}" || same=no; done
echo "| the same in two chunks ($c1 + $c2) | $(echo "$c1 + $c2" | bc -l) |"
echo "chunks equal one run: $same"
[ -n "$PLOT" ] || exit 0
mkdir -p "$PLOT"
for T in 5 15 40 600 615 660; do
    "$SOAK" "${RAIN[@]}" --width 800 --height 400 --steps 240 --time "$T" --frames 0-0 --float \
        --film "$PLOT/film_$T.%04d.exr" -o "$PLOT/wet_$T.%04d.exr" | tail -1
    for k in film wet; do oiiotool "$PLOT/${k}_$T.0000.exr" -d float -o "$PLOT/${k}_$T.tif"; done
done
/usr/bin/python3 "$HERE/plot_rain_frames.py" "$PLOT" 5 15 40 600 615 660
