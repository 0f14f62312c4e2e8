#!/usr/bin/env bash
# Grid volume headers that claim more than their payload (issue 21, items 4
# and 5): the payload's size is checked against the header's dims before
# anything is allocated, and every failure prints a message that names the
# file and is printable text (dims [4096,4096,4096] used to print
# uninitialised memory after "volume.file:").
set -u
. "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/volume_errors"
rm -rf "$D" && mkdir -p "$D"
"$SOAK" bake volume --material sand --format grid --dims 2,2,2 -o "$D/vg" >/dev/null 2>&1 || { bad "fixture grid"; finish; }

scene_with() { # scene_with GRID_JSON > file
  printf '{"camera": {"position": [0, -4, 0], "look_at": [0, 0, 0]}, "environment": {"type": "constant", "radiance": 1},
 "materials": {"w": {"type": "wet", "base": {"type": "medium", "sigma_s": 1, "sigma_a": 0.1, "volume": {"file": "%s"}}}},
 "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "w"}]}\n' "$1"
}
# grid NAME DIMS: a copy of the fixture's header with other dims and its own payload name
grid() {
  sed -e "s/\"dims\":[^]]*]/\"dims\": [$2]/" -e "s/\"vg.raw\"/\"$1.raw\"/" "$D/vg.json" >"$D/$1.json"
}
printable() { ! LC_ALL=C grep -q '[^[:print:][:space:]]' "$SOAK_TMP/last.err"; }

# 1. dims [4096,4096,4096] over the 320-byte payload: refused by the voxel
# limit from the header alone, before the payload is opened; dims within
# the limit over the same payload: refused by size, at once.
grid big "4096, 4096, 4096"
cp "$D/vg.raw" "$D/big.raw"
scene_with "$D/big.json" >"$D/big_scene.json"
expect_exit 1 "dims 4096^3 over a 320-byte payload" -- "$SOAK" render "$D/big_scene.json" --width 4 --height 4 --spp 1 -o "$D/o.exr"
expect_stderr "big\.json: dims: too many voxels" "the header's voxel count is refused first"
grid big "64, 64, 64"
expect_exit 1 "dims 64^3 over a 320-byte payload" -- "$SOAK" render "$D/big_scene.json" --width 4 --height 4 --spp 1 -o "$D/o.exr"
expect_stderr "big\.raw: size does not match the header: 320 bytes, but dims 64x64x64 with 10 channels of float32 need 10485760" \
  "the message names the payload and both sizes"
printable && ok "the message is printable" || bad "the message holds unprintable bytes"

# 2. A payload of exactly the claimed size (a sparse file) past the voxel
# limit: the allocation's refusal has its own message.
grid huge "2048, 2048, 2048"
if truncate -s $((2048 * 2048 * 2048 * 10 * 4)) "$D/huge.raw" 2>/dev/null; then
  scene_with "$D/huge.json" >"$D/huge_scene.json"
  expect_exit 1 "dims 2048^3 with a payload of that size" -- "$SOAK" render "$D/huge_scene.json" --width 4 --height 4 --spp 1 -o "$D/o.exr"
  expect_stderr "huge\.json: dims: too many voxels" "the voxel limit is named with the header file"
  printable && ok "the message is printable" || bad "the message holds unprintable bytes"
  rm -f "$D/huge.raw"
else
  skip "this file system cannot hold a sparse 320 GiB file" "volume voxel limit"
fi

# 3. The payload missing.
grid gone "2, 2, 2"
scene_with "$D/gone.json" >"$D/gone_scene.json"
expect_exit 1 "payload missing" -- "$SOAK" render "$D/gone_scene.json" --width 4 --height 4 --spp 1 -o "$D/o.exr"
expect_stderr "gone\.raw: cannot open" "a missing payload is named"
finish
