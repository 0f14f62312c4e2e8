#!/usr/bin/env bash
# Every shipped scene (scenes/*.json) renders, small and with few samples,
# without a NaN path or a failed geometry query: the counters `soak render`
# prints must be 0 (a NaN radiance would otherwise turn silently into black,
# and a geometry error silently end a path).
. "$(dirname "$0")/lib.bash"

n=0
for scene in "$SOAK_ROOT"/scenes/*.json; do
  name=$(basename "$scene" .json)
  n=$((n + 1))
  expect_exit 0 "render $name" -- "$SOAK" render "$scene" -o "$SOAK_TMP/$name.exr" --width 48 --height 32 --spp 8 --threads 2
  line=$(grep -E '^capped paths: ' "$SOAK_TMP/last.out")
  nan=$(sed -nE 's/.*NaN paths: ([0-9]+).*/\1/p' <<< "$line")
  geo=$(sed -nE 's/.*geometry errors: ([0-9]+).*/\1/p' <<< "$line")
  close "$nan" 0 0 "$name: NaN paths"
  close "$geo" 0 0 "$name: geometry errors"
done
[ "$n" -ge 5 ] && ok "$n shipped scenes" || bad "only $n scenes found in $SOAK_ROOT/scenes"
finish
