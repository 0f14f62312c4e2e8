#!/bin/bash
# POV-Ray: the rain overlay's cost (issue 45 / issue 50 item 3). The README's
# "Rain over time" set-up, small: `soak bake drops` (4 frames) and `soak bake
# ripples` (a 4-frame loop) under a z-up concrete ground, a gradient sky and one
# box, 240x180, at t = 0.6 s. Variants: dry (wetness 0), wet (the drops' wet map
# alone), overlay (+ the README's clear reflecting plane carrying
# Soak_Ripple_Normal), bumped (the ripple normal in every knot,
# Soak_Wet_Material_Bumped), rippled (the ripple normal only on knots of wetness
# >= 0.5, Soak_Wet_Material_Rippled), drops_as_water (Soak_Wet_Drops_Material),
# the same + the overlay through Soak_Ripple_Normal_Far (the sharp and --far
# flipbooks by distance), and overlay_before_accuracy (the overlay's normal with
# POV-Ray's default finite-difference step, as Soak_Ripple_Normal was before
# 2026-12-08). Trace CPU seconds from POV-Ray's
# statistics, interleaved, min and median of REPEAT; ratios to the wet map alone.
# usage: c_core/bench/bench_povray_rain.sh SOAK [REPEAT] > c_core/bench/results/YYYY-MM-DD-povray-rain.md
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
SOAK=${1:?usage: bench_povray_rain.sh SOAK [REPEAT]}
REPEAT=${2:-5}
LIB=${POVRAY_LIB:-$ROOT/povray}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cd "$TMP"
"$SOAK" bake drops --rate 10 --map-size 1 --duration 2 --fps 4 --frames 0-3 -o drops.%04d.exr >/dev/null
"$SOAK" bake ripples --rate 10 --tile 0.5 --frames 0-3 --loop-frames 4 -o rip.%04d.exr --far far.%04d.exr >/dev/null
cat > s.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "soak.inc"
camera { location <0.5, -0.6, 0.35> look_at <0.5, 0.5, 0> sky z }
light_source { <3, -2, 5> rgb 1 }
sky_sphere { pigment { gradient z color_map { [0 rgb <0.6, 0.7, 1>] [1 rgb <0.1, 0.2, 0.6>] } } }
box { <0.2, 0.8, 0>, <0.4, 1.0, 0.3> pigment { rgb <0.8, 0.2, 0.1> } }
#declare Wet = Soak_Drops_Fn("drops.", ".exr", 4, 0.6, 0, 3, 1)
#declare Rip = Soak_Ripple_Normal("rip.", ".exr", 4, 1, 0.6, 4 * 0.0003 / 0.5)
#switch (Mode)
#case (0) plane { z, 0 Soak_Wet_Material("concrete", "water", 0) } #break
#case (1) plane { z, 0 Soak_Wet_Material_Fn("concrete", "water", Wet) } #break
#case (2)
plane { z, 0 Soak_Wet_Material_Fn("concrete", "water", Wet) }
plane { z, 0.001 texture { pigment { rgbf 1 } finish { reflection { 0.02, 1 fresnel on } } normal { Rip scale 0.5 } } interior { ior 1.33 } }
#break
#case (3) plane { z, 0 Soak_Wet_Material_Bumped("concrete", "water", Wet, normal { Rip scale 0.5 }) } #break
#case (4) plane { z, 0 Soak_Wet_Material_Rippled("concrete", "water", Wet, normal { Rip scale 0.5 }, 0.5) } #break
#case (5) plane { z, 0 Soak_Wet_Drops_Material("concrete", "water", Wet, 0.1) } #break
#case (6)
plane { z, 0 Soak_Wet_Drops_Material("concrete", "water", Wet, 0.1) }
#declare Far = Soak_Ripple_Normal_Far("rip.", "far.", ".exr", 4, 1, 0.6, 4 * 0.0003 / 0.5, 0.5, <0.5, -0.6, 0.35>, Soak_Ripple_Far_Distance(0.01713, 67.38, image_width))
plane { z, 0.001 texture { pigment { rgbf 1 } finish { reflection { 0.02, 1 fresnel on } } normal { Far } } interior { ior 1.33 } }
#break
#case (7)
plane { z, 0 Soak_Wet_Material_Fn("concrete", "water", Wet) }
#declare H = Soak_Ripple_Height_Fn("rip.", ".exr", 4, 1, 0.6)
plane { z, 0.001 texture { pigment { rgbf 1 } finish { reflection { 0.02, 1 fresnel on } } normal { function { H(x, y, z) } 4 * 0.0003 / 0.5 scale 0.5 } } interior { ior 1.33 } }
#break
#end
POV
NAMES=(dry wet overlay bumped rippled drops_as_water drops_as_water+far_overlay overlay_before_accuracy)
run() { # mode: prints the trace CPU seconds
  povray +Is.pov +Oo.png +W240 +H180 -D +WT1 "+L$LIB" Declare=Mode="$1" >log 2>&1 \
    || { echo "mode $1 failed" >&2; tail -5 log >&2; return 1; }
  grep -A1 "Trace Time" log | grep -o "[0-9.]* CPU" | cut -d' ' -f1
}
MODES=${MODES:-"0 1 2 3 4 5 6 7"}   # a subset: MODES="1 5" (ratios need 0 and 1)
for m in $MODES; do : > "r$m"; done
for _ in $(seq "$REPEAT"); do for m in $MODES; do run $m >> "r$m"; done; done
med() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
echo "# POV-Ray rain overlay ($(date -u +%Y-%m-%d), soak.inc from $LIB)"
echo
echo "240x180, +WT1, $REPEAT interleaved runs; trace CPU seconds from POV-Ray's statistics."
echo
echo "| variant | trace min | trace median | / wet map alone (median) | / dry scene (median) |"
echo "|---|---|---|---|---|"
wet=$(med < r1)
dry=$(med < r0)
for m in $MODES; do
  echo "| ${NAMES[$m]} | $(sort -n "r$m" | head -1) | $(med < "r$m") | $(awk -v a="$(med < "r$m")" -v b="$wet" 'BEGIN {printf "%.2f", a / b}') | $(awk -v a="$(med < "r$m")" -v b="$dry" 'BEGIN {printf "%.2f", a / b}') |"
done
