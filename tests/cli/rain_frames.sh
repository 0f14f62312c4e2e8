#!/usr/bin/env bash
# soak bake rain --frames from the command line, on a 1 m vertical wall in
# rain at 10 mm/h for 60 s: the film at the foot while it rises (r t) and at
# steady state (Nusselt, both evaluated here with awk), wetness 1 under the
# running film, the printed balance against 10 mm/h x 1 m^2 x 60 s, chunks
# and thread counts giving the same bytes as one run, and clear refusals
# (a backwards range, NaN --fps, --fps without --frames, no rain, a --film
# that is not a frame pattern) that leave no output.
. "$(dirname "$0")/lib.bash"

D="$SOAK_TMP/rain_frames"
rm -rf "$D"
mkdir -p "$D/one" "$D/chunks"
command -v oiiotool >/dev/null || { skip "oiiotool not on PATH" "reading the frames"; finish; }

wall_obj "$D/wall.obj"
# Exposure n.u / u.up = 1 exactly; frame f at t = 20 f s.
P=(bake rain "$D/wall.obj" --up z --rain-dir 0,-1,1 --spread 0 --rays 1 --rainfall 10 --evaporation 0
   --duration 60 --steps 60 --width 32 --height 32 --fps 0.05)
expect_exit 0 "frames 0-5 in one run" -- "$SOAK" "${P[@]}" --threads 2 --frames 0-5 \
  --film "$D/one/film.%04d.exr" -o "$D/one/wet.%04d.exr"
line=$(grep "fell on the mesh" "$SOAK_TMP/last.out")
in=$(sed -n 's/.* s) \([0-9.e+-]*\) L fell.*/\1/p' <<<"$line")
close "$in" 0.16667 0.0002 "rain by frame 5 (t = 100 s) vs 10 mm/h x 1 m^2 x 60 s = 0.1667 L"
sum=$(awk '{ for (i = 1; i <= NF; ++i) if ($(i + 1) == "%") s += $i } END { print s }' <<<"$line")
close "$sum" 100 0.15 "dripped + on the mesh + evaporated = 100 % ($line)"

pixel() { oiiotool --dumpdata "$1" | sed -n "s/^ *Pixel ($2): *//p"; }
r=$(awk 'BEGIN { printf "%.9g", 10 / 3.6e6 }')
close "$(pixel "$D/one/film.0001.exr" "16, 31")" "$(awk -v r="$r" 'BEGIN { printf "%.9g", r * 20 }')" 6e-7 \
  "frame 1 (20 s): the foot's film is still r t (the front is 0.2 m down)"
want=$(awk -v r="$r" 'BEGIN { x = 3 * 1.002e-3 * r * 1.0 / (998.2 * 9.80665); printf "%.9g", exp(log(x) / 3) }')
close "$(pixel "$D/one/film.0003.exr" "16, 31")" "$want" 1e-6 "frame 3 (60 s): the foot's film vs Nusselt (1 %)"
close "$(pixel "$D/one/wet.0003.exr" "16, 31")" 1 0 "wetness 1 under the running film"
close "$(pixel "$D/one/film.0000.exr" "16, 31")" 0 0 "frame 0 (t = 0): dry"

expect_exit 0 "frames 0-2 (1 thread)" -- "$SOAK" "${P[@]}" --threads 1 --frames 0-2 \
  --film "$D/chunks/film.%04d.exr" -o "$D/chunks/wet.%04d.exr"
expect_exit 0 "frames 3-5 (2 threads)" -- "$SOAK" "${P[@]}" --threads 2 --frames 3-5 \
  --film "$D/chunks/film.%04d.exr" -o "$D/chunks/wet.%04d.exr"
same=1
for f in 0 1 2 3 4 5; do
  for k in wet film; do cmp -s "$D/one/$k.000$f.exr" "$D/chunks/$k.000$f.exr" || same=0; done
done
[ $same = 1 ] && ok "chunks 0-2 (1 thread) + 3-5 (2 threads) = one run, byte for byte" || bad "chunks differ from one run"

E="$D/err"
mkdir -p "$E"
expect_exit 2 "--frames 5-2" -- "$SOAK" "${P[@]}" --frames 5-2 -o "$E/w.%04d.exr"
expect_stderr "\-\-frames" "the refusal names --frames"
expect_exit 2 "--fps nan" -- "$SOAK" "${P[@]}" --fps nan --frames 0-2 -o "$E/w.%04d.exr"
expect_stderr "\-\-fps" "the refusal names --fps"
expect_exit 2 "--fps without --frames" -- "$SOAK" "${P[@]}" -o "$E/w.exr"
expect_stderr "\-\-frames" "the refusal asks for --frames"
expect_exit 2 "--frames with --duration 0" -- "$SOAK" "${P[@]}" --duration 0 --frames 0-2 -o "$E/w.%04d.exr"
expect_stderr "\-\-duration" "the refusal names --duration"
expect_exit 2 "--film without a pattern" -- "$SOAK" "${P[@]}" --frames 0-2 --film "$E/film.exr" -o "$E/w.%04d.exr"
expect_stderr "\-\-film" "the refusal names --film"
[ -z "$(ls -A "$E")" ] && ok "the refused runs left no output" || bad "left behind: $(ls -A "$E")"
expect_exit 0 "--help" -- "$SOAK" bake rain --help
grep -q -- "--fps" "$SOAK_TMP/last.out" && grep -q "frames A-B" "$SOAK_TMP/last.out" && ok "--help explains --frames and --fps" ||
  bad "--help lacks --frames/--fps"
finish
