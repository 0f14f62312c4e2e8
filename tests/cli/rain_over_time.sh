#!/usr/bin/env bash
# soak bake drops / ripples from the command line: help with an example,
# refusals with a message naming the culprit (negative or NaN rate, a frame
# range backwards, a mesh without UVs, an exposure map of the wrong size,
# non-square ripples), the same pixels at 1 and 2 threads and for a frame
# range baked in two chunks, a mesh's exposure computed as `bake rain` does,
# and no output left by a failed run.
. "$(dirname "$0")/lib.bash"

D="$SOAK_TMP/rain_over_time"
rm -rf "$D"
mkdir -p "$D"

same_pixels() { # A B WHAT
  if cmp -s "$1" "$2" || idiff -fail 0 -warn 0 "$1" "$2" >/dev/null 2>&1; then ok "$3"; else bad "$3"; fi
}

for kind in drops ripples; do
  expect_exit 0 "bake $kind --help" -- "$SOAK" bake "$kind" --help
  grep -q "example" "$SOAK_TMP/last.out" && ok "$kind help has an example" || bad "$kind help has no example"
done

P=(bake drops --width 48 --height 40 --map-size 0.05 --rate 40 --duration 1 --dry-time 1 --fps 4)
expect_exit 2 "negative rate" -- "$SOAK" "${P[@]}" --rate -1 --frames 0-1 -o "$D/n.%04d.exr"
expect_stderr "\-\-rate" "negative rate names --rate"
expect_exit 2 "NaN rate" -- "$SOAK" "${P[@]}" --rate nan --frames 0-1 -o "$D/n.%04d.exr"
expect_stderr "\-\-rate" "NaN rate names --rate"
expect_exit 2 "frames backwards" -- "$SOAK" "${P[@]}" --frames 5-2 -o "$D/n.%04d.exr"
expect_stderr "\-\-frames" "backwards range names --frames"
expect_exit 2 "--texel and --map-size" -- "$SOAK" "${P[@]}" --texel 0.001 --frames 0-1 -o "$D/n.%04d.exr"
expect_exit 2 "pattern without --frames" -- "$SOAK" "${P[@]}" -o "$D/n.%04d.exr"
ls "$D"/n.* >/dev/null 2>&1 && bad "a refused run left output" || ok "refused runs leave no output"

expect_exit 0 "drops, 1 thread" -- "$SOAK" "${P[@]}" --threads 1 --frames 0-7 -o "$D/a.%04d.exr"
expect_exit 0 "drops, 2 threads, chunk 0-3" -- "$SOAK" "${P[@]}" --threads 2 --frames 0-3 -o "$D/b.%04d.exr"
expect_exit 0 "drops, 2 threads, chunk 4-7" -- "$SOAK" "${P[@]}" --threads 2 --frames 4-7 -o "$D/b.%04d.exr"
for f in 0002 0004 0007; do
  same_pixels "$D/a.$f.exr" "$D/b.$f.exr" "frame $f: 1 thread one run = 2 threads in chunks"
done
expect_exit 0 "single map at the rain's end" -- "$SOAK" "${P[@]}" -o "$D/end.exr"
same_pixels "$D/end.exr" "$D/a.0004.exr" "no --frames: the map at --duration (= frame 4 at 4 fps)"

uv_plane_obj "$D/plane.obj" "$D/nouv.obj"
M=(bake drops --width 16 --height 16 --map-size 1 --rate 50 --duration 1 --fps 1 --rays 4)
expect_exit 1 "mesh without UVs" -- "$SOAK" "${M[@]}" "$D/nouv.obj" --frames 0-1 -o "$D/m.%04d.exr"
expect_stderr "UV" "the message says UVs"
expect_exit 0 "open mesh plane" -- "$SOAK" "${M[@]}" "$D/plane.obj" --frames 0-1 -o "$D/m.%04d.exr"
max=$(oiiotool "$D/m.0001.exr" --printstats 2>/dev/null | awk '/Stats Max/ {print $3}')
number "$max" && awk -v m="$max" 'BEGIN { exit !(m > 0) }' && ok "rain reaches the open plane (max $max)" \
  || bad "no water on the open plane (max '$max')"
oiiotool --create 8x8 1 -o "$D/small.exr" >/dev/null 2>&1
expect_exit 2 "exposure of another size" -- "$SOAK" bake drops --width 16 --height 16 --exposure "$D/small.exr" \
  --frames 0-1 -o "$D/e.%04d.exr"
expect_stderr "exposure" "the message names --exposure"

R=(bake ripples --width 32 --tile 0.2 --loop-frames 4 --period 0.4 --rate 40)
expect_exit 2 "ripples: non-square" -- "$SOAK" "${R[@]}" --height 16 --frames 0-3 -o "$D/r.%04d.exr"
expect_exit 2 "ripples: zero rate" -- "$SOAK" "${R[@]}" --rate 0 --frames 0-3 -o "$D/r.%04d.exr"
expect_exit 2 "ripples: --frame-time" -- "$SOAK" "${R[@]}" --frame-time 0.1 --frames 0-3 -o "$D/r.%04d.exr"
expect_exit 0 "ripples, 1 thread" -- "$SOAK" "${R[@]}" --threads 1 --frames 0-3 -o "$D/r.%04d.exr" --far "$D/f.%04d.exr"
expect_exit 0 "ripples, 2 threads, frames 2-4" -- "$SOAK" "${R[@]}" --threads 2 --frames 2-4 -o "$D/s.%04d.exr"
same_pixels "$D/r.0002.exr" "$D/s.0002.exr" "ripples: 1 thread = 2 threads, any range"
same_pixels "$D/r.0000.exr" "$D/s.0004.exr" "ripples: frame 4 of a 4-frame loop = frame 0"
[ -f "$D/f.0003.exr" ] && ok "--far writes the distance frames" || bad "no --far frames"
finish
