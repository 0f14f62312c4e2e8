#!/bin/bash
# Benchmark (not a test; issue 47 item 6): `soak bake rain` of the rain
# benchmark surface (rain_mesh.py) at about 60 k and 1 M triangles, same map
# (RES x RES), same rays, exposure only (--duration 0: the rays and the mesh,
# not the water), the two sizes alternating REPS times (interleaved). Prints
# min and median of wall and CPU (user + sys) seconds and the peak resident
# memory, and the memory per million triangles from the difference.
#   bench_mesh_scale.sh BUILD [RES] [RAYS] [REPS]
set -eu
HERE="$(cd "$(dirname "$0")" && pwd)"
SOAK="$1/bin/soak"
RES="${2:-1024}"
RAYS="${3:-16}"
REPS="${4:-3}"
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
python3 "$HERE/rain_mesh.py" "$W/small.obj" 173 # 59,858 triangles
python3 "$HERE/rain_mesh.py" "$W/large.obj" 708 # 1,002,528 triangles
for m in small large; do : >"$W/$m.times"; done
for r in $(seq "$REPS"); do
  for m in small large; do
    t0=$(date +%s.%N)
    /usr/bin/time -f "%U %S %M" -o "$W/t" "$SOAK" bake rain "$W/$m.obj" --rays "$RAYS" --duration 0 \
      --width "$RES" --height "$RES" -o "$W/$m.exr" >/dev/null
    t1=$(date +%s.%N)
    read -r u s kb <"$W/t"
    echo "$(echo "$t1 - $t0" | bc -l) $(echo "$u + $s" | bc -l) $kb" >>"$W/$m.times"
  done
done
echo "rain_mesh.py surfaces, ${RES}x${RES}, $RAYS rays, exposure only, $REPS interleaved repeats"
echo "| mesh | triangles | wall min / median (s) | CPU min / median (s) | peak RSS (MiB) |"
echo "|---|---|---|---|---|"
for m in small large; do
  tris=$(grep -c '^f ' "$W/$m.obj")
  sort -n -k1 "$W/$m.times" >"$W/a"; sort -n -k2 "$W/$m.times" >"$W/b"
  n=$(wc -l <"$W/a"); mid=$(((n + 1) / 2))
  echo "| $m | $tris | $(sed -n 1p "$W/a" | awk '{printf "%.2f", $1}') / $(sed -n ${mid}p "$W/a" | awk '{printf "%.2f", $1}') |" \
       "$(sed -n 1p "$W/b" | awk '{printf "%.2f", $2}') / $(sed -n ${mid}p "$W/b" | awk '{printf "%.2f", $2}') |" \
       "$(sort -n -k3 "$W/$m.times" | tail -1 | awk '{printf "%.0f", $3 / 1024}') |"
done
s=$(sort -n -k3 "$W/small.times" | tail -1 | awk '{print $3}'); l=$(sort -n -k3 "$W/large.times" | tail -1 | awk '{print $3}')
echo "memory per million triangles: $(echo "($l - $s) / 1024 / (1002528 - 59858) * 1000000" | bc -l | xargs printf '%.0f') MiB"
