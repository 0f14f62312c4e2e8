#!/bin/bash
# POV-Ray: the user-pigment path and the existing-texture layer against the same
# scene dry (issue 45 / issue 50 item 3). One scene (a wall and a ground, both a
# procedural brick pigment, wetness a bozo pattern, a gradient sky to reflect),
# seven variants: dry (the pigment with diffuse 1), user (two
# Soak_Wet_User_Texture_Fn calls), existing (two Soak_Wet_Existing_Fn calls on
# the same texture), existing without the film (Soak_Film = 0: the darkening
# alone), user without the film (the darkening alone), and two fair dry rows
# that reflect as the wet film does: dry_reflect (the dry pigment with the
# film's reflection at wetness 1, one reflected ray per hit) and dry_reflect_map
# (the same texture in both entries of a texture_map over the wetness: the
# wet map's two reflected rays per hit, the same ray count as user). Parse and trace CPU seconds from POV-Ray's own statistics and the
# parser's token count; interleaved (dry, user, existing, nofilm, dry, ...),
# min and median of REPEAT. POVRAY_LIB points at another soak.inc to compare.
# usage: c_core/bench/bench_povray_user.sh [REPEAT] > c_core/bench/results/YYYY-MM-DD-povray-user.md
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
REPEAT=${1:-5}
LIB=${POVRAY_LIB:-$ROOT/povray}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cat > "$TMP/s.pov" <<'POV'
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "soak.inc"
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -2> rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 1>] [1 rgb <0.1, 0.2, 0.6>] } } }
#declare P = pigment { brick rgb 0.6 rgb <0.5, 0.3, 0.25> brick_size <0.5, 0.2, 0.3> mortar 0.02 }
#declare W = function { pattern { bozo scale 0.7 } }
#declare TT = texture { pigment { P } finish { diffuse 1 } }
#declare TR = texture { pigment { P } finish { diffuse 1 reflection { 0, 1 fresnel on } } }
#switch (Mode)
#case (0)
box { <-2, 0, 0>, <2, 2, 0.1> texture { TT } }
plane { y, 0 texture { TT } }
#break
#case (5)
box { <-2, 0, 0>, <2, 2, 0.1> texture { TR } interior { ior 1.333 } }
plane { y, 0 texture { TR } interior { ior 1.333 } }
#break
#case (6)
#declare TM = texture { function { W(x, y, z) } texture_map { [0 TR] [1 TR] } }
box { <-2, 0, 0>, <2, 2, 0.1> texture { TM } interior { ior 1.333 } }
plane { y, 0 texture { TM } interior { ior 1.333 } }
#break
#case (4)
#declare Soak_Film = 0;
#case (1)
box { <-2, 0, 0>, <2, 2, 0.1> material { Soak_Wet_User_Texture_Fn("brick", "water", W, P) Soak_Wet_Interior("water") } }
plane { y, 0 material { Soak_Wet_User_Texture_Fn("brick", "water", W, P) Soak_Wet_Interior("water") } }
#break
#else
#if (Mode = 3) #declare Soak_Film = 0; #end
box { <-2, 0, 0>, <2, 2, 0.1> Soak_Wet_Existing_Fn(TT, "brick", "water", W, <0.55, 0.4, 0.37>) }
plane { y, 0 Soak_Wet_Existing_Fn(TT, "brick", "water", W, <0.55, 0.4, 0.37>) }
#end
POV
NAMES=(dry user existing existing_nofilm user_nofilm dry_reflect dry_reflect_map)
run() { # mode: prints "parse trace tokens"
  povray "+I$TMP/s.pov" "+O$TMP/o.png" +W320 +H240 -D +WT1 "+L$LIB" Declare=Mode="$1" >"$TMP/log" 2>&1 \
    || { echo "mode $1 failed" >&2; tail -5 "$TMP/log" >&2; return 1; }
  local p t k
  p=$(grep -A1 "Parse Time" "$TMP/log" | grep -o "[0-9.]* CPU" | cut -d' ' -f1)
  t=$(grep -A1 "Trace Time" "$TMP/log" | grep -o "[0-9.]* CPU" | cut -d' ' -f1)
  k=$(grep -o "Parsing [0-9]*K tokens" "$TMP/log" | tail -1 | grep -o "[0-9]*" || echo 0)
  r=$(grep "Reflected Rays" "$TMP/log" | grep -o "[0-9]*" | head -1)
  echo "$p $t ${k:-0} ${r:-0}"
}
for m in 0 1 2 3 4 5 6; do : > "$TMP/r$m"; done
for _ in $(seq "$REPEAT"); do for m in 0 1 2 3 4 5 6; do run $m >> "$TMP/r$m"; done; done
stat() { sort -n | awk '{a[NR]=$1} END {printf "%.3f | %.3f", a[1], a[int((NR+1)/2)]}'; }
echo "# POV-Ray user pigment and existing-texture layer ($(date -u +%Y-%m-%d), $(povray --version 2>&1 | grep -o '3\.7[0-9.]*' | head -1), soak.inc from $LIB)"
echo
echo "320x240, +WT1, $REPEAT interleaved runs; CPU seconds from POV-Ray's statistics."
echo
echo "| variant | parse min | parse median | trace min | trace median | trace / dry (median) | parser progress (K tokens; 0: below its first report) | reflected rays |"
echo "|---|---|---|---|---|---|---|---|"
dry_med=$(cut -d' ' -f2 "$TMP/r0" | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
for m in 0 1 2 3 4 5 6; do
  pm=$(cut -d' ' -f1 "$TMP/r$m" | stat)
  tm=$(cut -d' ' -f2 "$TMP/r$m" | stat)
  med=$(cut -d' ' -f2 "$TMP/r$m" | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  echo "| ${NAMES[$m]} | $pm | $tm | $(awk -v a="$med" -v b="$dry_med" 'BEGIN {printf "%.2f", a / b}') | $(tail -1 "$TMP/r$m" | cut -d' ' -f3) | $(tail -1 "$TMP/r$m" | cut -d' ' -f4) |"
done
