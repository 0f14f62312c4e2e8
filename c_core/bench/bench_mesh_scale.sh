#!/bin/bash
# Benchmark (not a test; issue 47 item 6): `soak bake rain` of the rain
# benchmark surface (rain_mesh.py) at about 60 k and 1 M triangles, same map
# (RES x RES), same rays, exposure only (--duration 0: the rays and the mesh,
# not the water), as OBJ and as binary PLY, through soak's native reader
# (SOAK_MESH_READER=auto) and through Assimp alone (=assimp), every
# combination once per repeat, REPS repeats (interleaved). Prints min and
# median of CPU (user + sys of soak and its reader child, /usr/bin/time)
# and wall seconds, the peak resident memory, the 1 M / 60 k CPU ratio and
# the memory per million triangles from the difference.
#   bench_mesh_scale.sh BUILD [RES] [RAYS] [REPS] [READERS] [FORMATS]
set -eu
HERE="$(cd "$(dirname "$0")" && pwd)"
SOAK="$1/bin/soak"
RES="${2:-1024}"
RAYS="${3:-16}"
REPS="${4:-3}"
READERS="${5:-auto assimp}"
FORMATS="${6:-obj ply}"
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
for fmt in $FORMATS; do
  python3 "$HERE/rain_mesh.py" "$W/small.$fmt" 173 # 59,858 triangles
  python3 "$HERE/rain_mesh.py" "$W/large.$fmt" 708 # 1,002,528 triangles
done
for r in $(seq "$REPS"); do
  for rd in $READERS; do
    for fmt in $FORMATS; do
      for m in small large; do
        t0=$(date +%s.%N)
        SOAK_MESH_READER=$rd /usr/bin/time -f "%U %S %M" -o "$W/t" nice "$SOAK" bake rain "$W/$m.$fmt" --rays "$RAYS" \
          --duration 0 --width "$RES" --height "$RES" -o "$W/$m.exr" >/dev/null
        t1=$(date +%s.%N)
        read -r u s kb <"$W/t"
        echo "$(echo "$t1 - $t0" | bc -l) $(echo "$u + $s" | bc -l) $kb" >>"$W/$rd.$fmt.$m.times"
      done
    done
  done
done
echo "rain_mesh.py surfaces (59,858 and 1,002,528 triangles), ${RES}x${RES}, $RAYS rays, exposure only, $REPS interleaved repeats"
echo
echo "| reader | format | mesh | CPU min / median (s) | wall min / median (s) | peak RSS (MiB) |"
echo "|---|---|---|---|---|---|"
stat_of() { # file column -> "min median"
  sort -n -k"$2" "$1" | awk -v c="$2" '{v[NR] = $c} END {printf "%.2f %.2f", v[1], v[int((NR + 1) / 2)]}'
}
for rd in $READERS; do
  for fmt in $FORMATS; do
    for m in small large; do
      f="$W/$rd.$fmt.$m.times"
      read -r cmin cmed <<<"$(stat_of "$f" 2)"
      read -r wmin wmed <<<"$(stat_of "$f" 1)"
      echo "| $rd | $fmt | $m | $cmin / $cmed | $wmin / $wmed | $(sort -n -k3 "$f" | tail -1 | awk '{printf "%.0f", $3 / 1024}') |"
    done
  done
done
echo
echo "| reader | format | 1 M / 60 k CPU (min) | memory per million triangles (MiB, peak RSS difference) |"
echo "|---|---|---|---|"
for rd in $READERS; do
  for fmt in $FORMATS; do
    s="$W/$rd.$fmt.small.times" l="$W/$rd.$fmt.large.times"
    ratio=$(echo "$(stat_of "$l" 2 | cut -d' ' -f1) / $(stat_of "$s" 2 | cut -d' ' -f1)" | bc -l)
    ks=$(sort -n -k3 "$s" | tail -1 | awk '{print $3}'); kl=$(sort -n -k3 "$l" | tail -1 | awk '{print $3}')
    echo "| $rd | $fmt | $(printf '%.2f' "$ratio") | $(echo "($kl - $ks) / 1024 / (1002528 - 59858) * 1000000" | bc -l | xargs printf '%.0f') |"
  done
done
