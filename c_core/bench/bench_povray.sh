#!/bin/bash
# POV-Ray render time of each seed scene with the wet macros vs the same scene
# with plain dry textures (soak.inc's macros replaced by a grey pigment with
# diffuse 1; the scene's own bump normal kept), and, for scenes that take
# `Declare=Dry=1`, vs the same scene dry (every wetness 0: the dry preset's
# finish, metals' mirrors included). Same settings, interleaved; CPU time of the
# whole process (user + sys, /usr/bin/time: robust on the shared machine where
# wall time moves 25-50 %), min and median of REPEAT.
# usage: c_core/bench/bench_povray.sh [REPEAT] > c_core/bench/results/YYYY-MM-DD-povray.md
# env: SCENES (names without .pov; default all seed scenes), POVRAY_LIB (soak.inc's folder,
# default povray/: point it at an older copy to compare versions)
set -eu
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
REPEAT=${1:-1}
LIB=${POVRAY_LIB:-$ROOT/povray}
SCENES=${SCENES:-wet_paper beach_rock bricks_drying flowerpot_porosity film_copper gauze_media marble_subsurface}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# plain variant: every Soak material/texture macro call becomes a plain texture
cat > "$TMP/plain.inc" <<'INC'
#include "soak.inc"
#macro Plain() texture { pigment { rgb 0.4 } finish { diffuse 1 } } #end
#undef Soak_Wet_Material #macro Soak_Wet_Material(P, L, W) Plain() #end
#undef Soak_Wet_Material_Fn #macro Soak_Wet_Material_Fn(P, L, W) Plain() #end
#undef Soak_Wet_Material_Bumped #macro Soak_Wet_Material_Bumped(P, L, W, N) texture { pigment { rgb 0.4 } finish { diffuse 1 } normal { N } } #end
#undef Soak_Wet_User_Material #macro Soak_Wet_User_Material(P, L, W, U) Plain() #end
#undef Soak_Puddle_Material #macro Soak_Puddle_Material(P, L, W, Lv, N) texture { pigment { rgb 0.4 } finish { diffuse 1 } normal { N } } #end
#undef Soak_Sheet_Material #macro Soak_Sheet_Material(P, L, W) material { Plain() } #end
#undef Soak_Sheet_Material_Fn #macro Soak_Sheet_Material_Fn(P, L, W, Pw) material { Plain() } #end
#undef Soak_Wet_Subsurface_Material #macro Soak_Wet_Subsurface_Material(P, L, W) Plain() #end
#undef Soak_Wet_User_Subsurface_Material #macro Soak_Wet_User_Subsurface_Material(P, L, W, U) Plain() #end
#undef Soak_Subsurface_Settings #macro Soak_Subsurface_Settings() #end
INC
cp "$ROOT"/scenes/povray/*.pov "$TMP/"
for f in "$TMP"/*.pov; do sed 's|#include "soak.inc"|#include "plain.inc"|' "$f" > "${f%.pov}_plain.pov"; done
W=640 H=480
cpu() { # scene [declares...]: CPU seconds (user + sys) of one render
  local scene=$1; shift
  /usr/bin/time -o "$TMP/t" -f "%U %S" povray "+I$scene" "+O$TMP/o.png" +W$W +H$H -D -V +WT1 "+L$LIB" "+L$TMP" \
    +A0.3 Declare=Use_Map=0 "$@" >"$TMP/log" 2>&1 || { echo "povray $scene failed" >&2; tail -5 "$TMP/log" >&2; exit 1; }
  awk '{print $1 + $2}' "$TMP/t"
}
echo "# POV-Ray: wet macros vs plain textures and vs the same scene dry ($(date -u +%Y-%m-%d), ${W}x${H}, +A0.3, 1 thread, CPU s (user + sys of the process, start-up included), min and median of $REPEAT, interleaved)"
echo
echo "| scene | plain min (s) | dry min (s) | wet min (s) | wet/plain (min) | wet/dry (min) | wet/plain (median) | wet/dry (median) |"
echo "|---|---|---|---|---|---|---|---|"
stats() { sort -g | awk '{v[NR] = $1} END {m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; print v[1], m}'; }
for s in $SCENES; do
  : > "$TMP/plain.t"; : > "$TMP/wet.t"; : > "$TMP/dry.t"
  has_dry=0; grep -q "ifndef(Dry)" "$TMP/$s.pov" && has_dry=1
  for r in $(seq "$REPEAT"); do
    cpu "$TMP/${s}_plain.pov" >> "$TMP/plain.t"
    [ $has_dry = 1 ] && cpu "$TMP/$s.pov" Declare=Dry=1 >> "$TMP/dry.t"
    cpu "$TMP/$s.pov" >> "$TMP/wet.t"
  done
  read -r pmin pmed < <(stats < "$TMP/plain.t"); read -r wmin wmed < <(stats < "$TMP/wet.t")
  if [ $has_dry = 1 ]; then read -r dmin dmed < <(stats < "$TMP/dry.t"); else dmin=0 dmed=0; fi
  awk -v s="$s" -v a="$pmin" -v b="$wmin" -v c="$pmed" -v d="$wmed" -v e="$dmin" -v f="$dmed" \
    'BEGIN{ if (e > 0) printf "| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", s, a, e, b, b / a, b / e, d / c, d / f;
            else printf "| %s | %.2f | - | %.2f | %.2f | - | %.2f | - |\n", s, a, b, b / a, d / c }'
done
