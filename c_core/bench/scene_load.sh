#!/bin/bash
# Scene loading time against the number of objects (issue 13, item 7): N
# separate spheres on a grid and N spheres stacked at one point, loaded and
# rendered at 1x1 pixel, 1 sample (so the time is the parse, the geometry
# build and the commit). CPU time (user+sys) of one run each; not a test.
#   usage: c_core/bench/scene_load.sh BUILD_DIR [N...]
set -u
B=${1:-build}
shift || true
COUNTS=${*:-10000 20000 40000 80000}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
gen() { # gen N sep|stack > file
    awk -v n="$1" -v kind="$2" 'BEGIN {
        printf "{\"render\": {\"width\": 1, \"height\": 1, \"spp\": 1}, \"camera\": {\"position\": [0, -40, 5], \"look_at\": [0, 0, 0]},"
        printf " \"environment\": {\"type\": \"constant\", \"radiance\": 1}, \"materials\": {\"m\": {\"type\": \"lambert\", \"albedo\": 0.5}},"
        printf " \"objects\": ["
        for (i = 0; i < n; ++i) {
            x = kind == "stack" ? 0 : (i % 200) * 0.1; y = kind == "stack" ? 0 : int(i / 200) * 0.1
            printf "%s{\"type\": \"sphere\", \"center\": [%g, %g, 0], \"radius\": 0.04, \"material\": \"m\"}", i ? ", " : "", x, y
        }
        printf "]}\n" }'
}
echo "| spheres | layout | CPU s |"
echo "|---:|---|---:|"
for kind in sep stack; do
    for n in $COUNTS; do
        [ "$kind" = stack ] && [ "$n" -gt 20000 ] && continue # quadratic: see the note in the results
        gen "$n" "$kind" >"$T/s.json"
        /usr/bin/time -o "$T/time" -f "%U %S" "$B/bin/soak" render "$T/s.json" -q -o "$T/o.exr" >/dev/null 2>&1
        cpu=$(awk '{ print $1 + $2 }' "$T/time")
        echo "| $n | $kind | $cpu |"
    done
done
