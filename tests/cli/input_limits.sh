#!/usr/bin/env bash
# Bounded before work, in the words of the option or the file (issue 21,
# items 4 and 5). Each case failed before:
#  - a 566-byte EXR whose string attribute claims 1.7 GB made OpenEXR
#    allocate 1.7 GB inside ImageInput::open (44 s); its header is now parsed
#    on the bytes first (soak/image_check.h) and refused with the numbers;
#    likewise a dataWindow of 200 million lines from the same 566 bytes;
#  - a UV of 1e30 was called "not finite": it is out of range, with the limit;
#  - sizes: every --width/--height/--dims of every command goes through one
#    parser with one limit and one message naming the option and the value
#    (before: "expected a whole number in [1, 16384]", "expected three
#    comma-separated values", "expected whole numbers", and a --dims over the
#    voxel cap refused only after the map was read);
#  - a grid header or payload that is a FIFO blocked in fopen.
set -u
. "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/input_limits"
rm -rf "$D" && mkdir -p "$D"
R="$SOAK_ROOT/tests/fuzz/reproducers/image"

tail -c +2 "$R/exr_attribute_claims_1700MB" >"$D/attr.exr"
expect_exit 1 "566-byte EXR claiming a 1.7 GB attribute" -- "$SOAK" bake drying "$D/attr.exr" --time 0.5 -o "$D/o.png"
expect_stderr "attr\.exr: OpenEXR attribute 'Exif:ImageHistory' \(string\) claims 1700000000 bytes, but only 529 bytes of the 566-byte file follow" \
  "the attribute bomb is refused from the header with the numbers"
tail -c +2 "$R/exr_datawindow_200M_lines" >"$D/tall.exr"
expect_exit 1 "566-byte EXR claiming 200 million lines" -- "$SOAK" bake drying "$D/tall.exr" --time 0.5 -o "$D/o.png"
expect_stderr "tall\.exr: OpenEXR dataWindow 2x200000001 needs 12500001 scanline blocks of at least 16 bytes each, but only 32 bytes follow" \
  "the tall window is refused by its chunk table"
[ ! -e "$D/o.png" ] && ok "no output after a refused mask" || bad "an output was written"

# UV 1e30 (bake rain reads UVs).
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1e30 0\nvt 0 1\nf 1/1 2/2 3/3\n' >"$D/uv.obj"
expect_exit 1 "UV of 1e30" -- "$SOAK" bake rain "$D/uv.obj" --width 8 --height 8 -o "$D/r.exr"
expect_stderr "mesh UV 1 \(1e\+30, 0\) is out of range: UVs must be finite and within \[-1e\+06, 1e\+06\]" \
  "UV 1e30: out of range with the limit"

# One size parser: option, value, range.
size_msg() { expect_stderr "$1: expected a size from 1 to $2, got '$3'" "$4: names $1 and '$3'"; }
expect_exit 2 "render --width 0" -- "$SOAK" render "$SOAK_ROOT/scenes/sand.json" --width 0 -o "$D/o.exr"
size_msg --width 16384 0 "render"
expect_exit 2 "render --height 16385" -- "$SOAK" render "$SOAK_ROOT/scenes/sand.json" --height 16385 -o "$D/o.exr"
size_msg --height 16384 16385 "render"
expect_exit 2 "bake turbulence --width 2.5" -- "$SOAK" bake turbulence --width 2.5 -o "$D/t.png"
size_msg --width 16384 2.5 "bake turbulence"
expect_exit 2 "bake waves --height -3" -- "$SOAK" bake waves --height -3 -o "$D/w.png"
size_msg --height 16384 -3 "bake waves"
expect_exit 2 "bake drying --width 99999" -- "$SOAK" bake drying --width 99999 --time 0.5 -o "$D/d.png"
size_msg --width 16384 99999 "bake drying"
expect_exit 2 "bake volume --dims 4,x,4" -- "$SOAK" bake volume --material sand --dims 4,x,4 -o "$D/v"
expect_stderr "\-\-dims: expected a size from 1 to 4096, got 'x' in '4,x,4'" "bake volume --dims: names the part and the value"
expect_exit 2 "bake volume --dims 2048,2048,64" -- "$SOAK" bake volume --material sand --dims 2048,2048,64 -o "$D/v"
expect_stderr "\-\-dims: '2048,2048,64' is 268435456 voxels; the limit is 214748364" "bake volume --dims: total voxels and the cap, before any work"

# Grid files that are not regular files are refused, not opened.
"$SOAK" bake volume --material sand --format grid --dims 2,2,2 -o "$D/g" >/dev/null 2>&1 || bad "grid fixture"
mv "$D/g.raw" "$D/g.raw.real" && mkfifo "$D/g.raw"
printf '{"camera": {"position": [0, -4, 0], "look_at": [0, 0, 0]}, "environment": {"type": "constant", "radiance": 1},
 "materials": {"w": {"type": "wet", "base": {"type": "medium", "sigma_s": 1, "sigma_a": 0.1, "volume": {"file": "%s"}}}},
 "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "w"}]}\n' "$D/g.json" >"$D/fifo_scene.json"
expect_exit 1 "grid payload that is a FIFO" -- timeout 60 "$SOAK" render "$D/fifo_scene.json" --width 4 --height 4 --spp 1 -o "$D/o.exr"
expect_stderr "g\.raw: cannot read this grid payload named by .*g\.json: it is a FIFO \(pipe\), not a regular file" "FIFO payload: refused by what it is"
finish
