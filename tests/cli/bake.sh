#!/usr/bin/env bash
# soak bake (2D kinds): help, determinism across thread counts, sequences,
# and every refusal: bad sizes, unknown kinds, unreadable or truncated
# inputs, output = input, missing output folder -- each with a non-zero
# exit, a message naming the culprit, and no output (or temp file) left.
. "$(dirname "$0")/lib.bash"

T="$SOAK_TMP/bake"
rm -rf "$T"
mkdir -p "$T"

# no_output FILE... : none of the files exists, and no temp file is left in their folders
no_output() {
  local f
  for f in "$@"; do
    if [ -e "$f" ]; then bad "output $f left behind"; return; fi
    if [ -d "$(dirname "$f")" ] && ls -a "$(dirname "$f")" | grep -q "\.tmp"; then bad "temp file left in $(dirname "$f")"; return; fi
  done
  ok "no output left behind"
}

# same_pixels A B: identical pixel data (idiff with zero tolerance)
same_pixels() {
  if cmp -s "$1" "$2" || idiff -fail 0 -warn 0 "$1" "$2" > /dev/null 2>&1; then ok "$3"; else bad "$3"; fi
}

for kind in turbulence waves drying combine; do
  expect_exit 0 "bake $kind --help" -- "$SOAK" bake "$kind" --help
  grep -q "example" "$SOAK_TMP/last.out" && ok "$kind help has an example" || bad "$kind help has no example"
done
expect_exit 0 "bake --help" -- "$SOAK" bake --help
expect_exit 2 "unknown kind" -- "$SOAK" bake sparkle -o "$T/x.exr"
expect_stderr "unknown kind 'sparkle'" "message names the kind"
no_output "$T/x.exr"
expect_exit 2 "no kind" -- "$SOAK" bake

# Sizes: zero, negative, huge, not a number.
for size in 0 -5 16385 100000000000 12x; do
  expect_exit 2 "--width $size" -- "$SOAK" bake turbulence --width "$size" --height 16 -o "$T/s.exr"
  expect_stderr "--width" "message names --width ($size)"
  expect_exit 2 "--height $size" -- "$SOAK" bake waves --width 16 --height "$size" -o "$T/s.exr"
  expect_stderr "--height" "message names --height ($size)"
done
no_output "$T/s.exr"
expect_exit 2 "unknown option" -- "$SOAK" bake turbulence --octavez 3 -o "$T/s.exr"
expect_stderr "--octavez" "message names the option"
expect_exit 2 "octaves 0" -- "$SOAK" bake turbulence --octaves 0 -o "$T/s.exr"
expect_stderr "--octaves" "message names --octaves"
expect_exit 2 "missing -o" -- "$SOAK" bake turbulence --width 8 --height 8
expect_stderr "output" "message names -o/--output"

# Determinism: --threads 1 and --threads 2 give the same pixels.
for kind in turbulence waves; do
  expect_exit 0 "$kind, 1 thread" -- "$SOAK" bake "$kind" --width 96 --height 80 --seed 9 --threads 1 --float -o "$T/${kind}1.exr"
  expect_exit 0 "$kind, 2 threads" -- "$SOAK" bake "$kind" --width 96 --height 80 --seed 9 --threads 2 --float -o "$T/${kind}2.exr"
  same_pixels "$T/${kind}1.exr" "$T/${kind}2.exr" "$kind: identical pixel data for --threads 1 and 2"
done
expect_exit 0 "turbulence seed 10" -- "$SOAK" bake turbulence --width 96 --height 80 --seed 10 --float -o "$T/turbulence3.exr"
if idiff -fail 0 -warn 0 "$T/turbulence1.exr" "$T/turbulence3.exr" > /dev/null 2>&1; then bad "another seed changes the map"; else ok "another seed changes the map"; fi
expect_exit 0 "threshold png" -- "$SOAK" bake turbulence --width 64 --height 64 --threshold 0.1 --softness 0 -o "$T/mask.png"
info=$(iinfo -v "$T/mask.png")
echo "$info" | grep -q "uint16" && ok "png is 16-bit" || bad "png is not 16-bit: $info"
expect_exit 0 "tileable tx" -- "$SOAK" bake turbulence --width 64 --height 64 --tileable -o "$T/tile.tx"
iinfo "$T/tile.tx" > /dev/null 2>&1 && ok ".tx readable" || bad ".tx unreadable"

# Sequences.
expect_exit 0 "sequence of 3 frames" -- "$SOAK" bake waves --width 32 --height 32 --frames 4-6 --frame-time 2 -o "$T/wave.%04d.exr"
[ -f "$T/wave.0004.exr" ] && [ -f "$T/wave.0005.exr" ] && [ -f "$T/wave.0006.exr" ] && [ ! -e "$T/wave.0007.exr" ] \
  && ok "frames 4..6 written" || bad "frames 4..6 not written: $(ls "$T")"
expect_exit 0 "single image at the time of frame 5" -- "$SOAK" bake waves --width 32 --height 32 --time 2 -o "$T/wave_t2.exr"
same_pixels "$T/wave.0005.exr" "$T/wave_t2.exr" "frame 5 is time 0 + (5-4)*2"
expect_exit 2 "pattern without --frames" -- "$SOAK" bake turbulence --width 8 --height 8 -o "$T/p.%04d.exr"
expect_stderr "frames" "message asks for --frames"
expect_exit 2 "--frames without pattern" -- "$SOAK" bake turbulence --width 8 --height 8 --frames 1-3 -o "$T/p.exr"
expect_exit 2 "--frames 5-2" -- "$SOAK" bake turbulence --width 8 --height 8 --frames 5-2 -o "$T/p.%d.exr"
expect_stderr "--frames" "message names --frames"
no_output "$T/p.exr" "$T/p.0001.exr" "$T/p.2.exr"

# --frame-origin F: frame f at T + (f - F) DT whatever the --frames range, so
# chunks equal one run bit for bit. The mask's texel k (1..10) is k texels from
# the dry one and starts drying at time k/10; --t-fill 1e-20, far below one ulp
# of the time, makes it a step: dry iff t > k/10 (whether the schedule counts
# t = t0 as wet or dry). At T = 0, DT = 0.03 frame 11 is at 10 * 0.03 = 0.3,
# texel 3's time (wet); a chunk 10-12 started at its own time 0.27 (no origin)
# puts frame 11 at 0.27 + 0.03, one ulp above 0.3: texel 3 dry.
printf 'P2\n11 1\n1\n0 1 1 1 1 1 1 1 1 1 1\n' > "$T/step.pgm"
step=(bake drying "$T/step.pgm" --t-fill 1e-20 --time 0 --frame-time 0.03)
expect_exit 0 "frames 1-12 in one run" -- "$SOAK" "${step[@]}" --frames 1-12 -o "$T/one.%04d.exr"
for r in 1-5 6-9 10-12; do
  expect_exit 0 "frames $r with --frame-origin 1" -- "$SOAK" "${step[@]}" --frame-origin 1 --frames "$r" -o "$T/chunk.%04d.exr"
done
for f in $(seq -f %04g 1 12); do same_pixels "$T/one.$f.exr" "$T/chunk.$f.exr" "frame $f of the chunks = the single run's"; done
expect_exit 0 "chunk 10-12 at its own time, no origin" -- "$SOAK" bake drying "$T/step.pgm" --t-fill 1e-20 --time 0.27 \
  --frame-time 0.03 --frames 10-12 -o "$T/own.%04d.exr"
if idiff -fail 0 -warn 0 "$T/one.0011.exr" "$T/own.0011.exr" > /dev/null 2>&1; then
  bad "the chunk's own start time should miss frame 11's time by the last bit (the case proves nothing)"
else ok "without --frame-origin the chunk's frame 11 differs (the comparison sees one ulp)"; fi
expect_exit 0 "origin before the range" -- "$SOAK" bake waves --width 32 --height 32 --frames 4-4 --frame-time 2 \
  --frame-origin 2 -o "$T/wo.%04d.exr"
same_pixels "$T/wo.0004.exr" "$T/wave.0006.exr" "frame 4 from origin 2 is at (4-2)*2 = frame 6 of the run from 4"
for v in nan -1 10000000 1.5 x; do
  expect_exit 2 "--frame-origin $v" -- "$SOAK" bake turbulence --width 8 --height 8 --frames 1-2 --frame-origin "$v" -o "$T/fo.%d.exr"
  expect_stderr "--frame-origin" "message names --frame-origin ($v)"
done
expect_exit 2 "--frame-origin without --frames" -- "$SOAK" bake waves --width 8 --height 8 --frame-origin 1 -o "$T/fo.exr"
expect_stderr "--frames" "message asks for --frames"
expect_exit 2 "drying frame before time 0" -- "$SOAK" bake drying --width 4 --height 4 --time 0 --frames 3-4 \
  --frame-origin 9 -o "$T/fo.%d.exr"
expect_stderr "frame 3" "message names the frame"
no_output "$T/fo.exr" "$T/fo.1.exr" "$T/fo.3.exr"

# Drying from a mask.
expect_exit 0 "drying" -- "$SOAK" bake drying "$T/mask.png" --time 0.4 --t-fill 0 -o "$T/dry.exr"
expect_exit 0 "drying diffusion" -- "$SOAK" bake drying "$T/mask.png" --mode diffusion --time 0.3 --steps 4 -o "$T/dryd.exr"
expect_exit 0 "drying without mask, noise" -- "$SOAK" bake drying --width 32 --height 16 --noise 1 -o "$T/dryn.png"
expect_exit 2 "drying --mode bogus" -- "$SOAK" bake drying "$T/mask.png" --mode bogus -o "$T/d2.exr"
expect_stderr "--mode" "message names --mode"
expect_exit 2 "drying --width differs from the mask" -- "$SOAK" bake drying "$T/mask.png" --width 65 -o "$T/d2.exr"
expect_stderr "mask" "message names the mask"
expect_exit 2 "drying --t-fill 2" -- "$SOAK" bake drying "$T/mask.png" --t-fill 2 -o "$T/d2.exr"
expect_stderr "--t-fill" "message names --t-fill"
no_output "$T/d2.exr"

# Unreadable and truncated inputs.
echo "not an image" > "$T/text.png"
head -c 300 "$T/mask.png" > "$T/truncated.png"
for input in "$T/text.png" "$T/truncated.png" "$T/does_not_exist.exr"; do
  expect_exit 1 "drying from $(basename "$input")" -- "$SOAK" bake drying "$input" -o "$T/bad.exr"
  expect_stderr "$(basename "$input")" "message names $(basename "$input")"
  expect_exit 1 "combine with $(basename "$input")" -- "$SOAK" bake combine max "$T/mask.png" "$input" -o "$T/bad.exr"
  expect_stderr "$(basename "$input")" "message names $(basename "$input")"
done
no_output "$T/bad.exr"

# Output equal to an input: refused, input untouched.
sum_before=$(md5sum < "$T/mask.png")
expect_exit 2 "drying -o = mask" -- "$SOAK" bake drying "$T/mask.png" -o "$T/mask.png"
expect_stderr "mask.png" "message names the file"
expect_exit 2 "combine -o = an input by another path" -- "$SOAK" bake combine add "$T/dry.exr" "$T/mask.png" -o "$T/../bake/mask.png"
expect_exit 2 "blur -o = its input" -- "$SOAK" bake combine blur "$T/mask.png" --sigma 2 -o "$T/mask.png"
[ "$(md5sum < "$T/mask.png")" = "$sum_before" ] && ok "input unchanged" || bad "input was modified"
ls -a "$T" | grep -q '\.tmp' && bad "temp file left" || ok "no temp file left"

# Missing output folder.
expect_exit 1 "missing output folder" -- "$SOAK" bake turbulence --width 8 --height 8 -o "$T/no/such/dir/out.exr"
expect_stderr "no/such/dir" "message names the folder"
no_output "$T/no/such/dir/out.exr"
expect_exit 1 "missing output folder of a sequence" -- "$SOAK" bake waves --width 8 --height 8 --frames 1-2 -o "$T/no/seq/w.%04d.exr"
expect_stderr "'$T/no/seq'" "message names the folder"
expect_exit 1 "missing output folder of a rain map" -- "$SOAK" bake rain "$T/no_mesh.obj" --width 8 --height 8 -o "$T/no/rain/r.exr"
expect_stderr "'$T/no/rain'" "message names the folder"
expect_exit 2 "unsupported output type" -- "$SOAK" bake turbulence --width 8 --height 8 -o "$T/out.jpg"
expect_stderr "out.jpg" "message names the output"
no_output "$T/out.jpg"

# Combine: sizes must match; values against the inputs.
expect_exit 0 "small map" -- "$SOAK" bake turbulence --width 32 --height 32 -o "$T/small.exr"
expect_exit 2 "combine of different sizes" -- "$SOAK" bake combine max "$T/mask.png" "$T/small.exr" -o "$T/c.exr"
expect_stderr "small.exr" "message names the mismatching input"
no_output "$T/c.exr"
expect_exit 2 "combine unknown op" -- "$SOAK" bake combine xor "$T/mask.png" "$T/mask.png" -o "$T/c.exr"
expect_stderr "xor" "message names the op"
expect_exit 2 "combine max with one input" -- "$SOAK" bake combine max "$T/mask.png" -o "$T/c.exr"
expect_exit 0 "combine max" -- "$SOAK" bake combine max "$T/dry.exr" "$T/mask.png" --float -o "$T/c.exr"
ref=$(oiiotool "$T/dry.exr" "$T/mask.png" --max -o "$T/ref.exr" 2>&1) || true
if [ -f "$T/ref.exr" ]; then
  if idiff -fail 1e-6 -warn 1e-6 "$T/c.exr" "$T/ref.exr" > /dev/null 2>&1; then ok "combine max = oiiotool --max"; else bad "combine max differs from oiiotool --max"; fi
else
  skip "oiiotool failed: $ref" "combine max vs oiiotool"
fi
expect_exit 0 "combine remap" -- "$SOAK" bake combine remap "$T/mask.png" --in-lo 0 --in-hi 1 --out-lo 1 --out-hi 0 --float -o "$T/inv.exr"
expect_exit 0 "combine add back" -- "$SOAK" bake combine add "$T/inv.exr" "$T/mask.png" --float -o "$T/one.exr"
stats=$(oiiotool --stats "$T/one.exr" 2>&1 | grep -E "Stats (Min|Max)" | awk '{print $3}' | tr '\n' ' ')
set -- $stats
close "${1:-0}" 1 1e-6 "remap(1 - m) + m: min = 1"
close "${2:-0}" 1 1e-6 "remap(1 - m) + m: max = 1"

finish
