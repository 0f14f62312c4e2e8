#!/usr/bin/env bash
# soak bake beads from the command line (issue 48 item 4): the preset's
# contact angle from materials.json (copper 75 deg beads, sand 20 deg is a
# film: a flat map and the message saying so), the refusals (PNG names EXR
# and TIFF, an unknown preset, a bake too large to hold, --materials without
# --preset), and nothing lost: a refused run leaves an earlier output's
# bytes, a finished run leaves no temporary beside its output. The map's
# content is checked against the cap formulas in tests/c/bake/test_bake_beads.c.
. "$(dirname "$0")/lib.bash"

D="$SOAK_TMP/bake_beads"
rm -rf "$D"
mkdir -p "$D"
base=(bake beads --width 64 --height 64 --duration 60 --rate 25)

expect_exit 0 "copper (75 deg in materials.json) beads" -- "$SOAK" "${base[@]}" --preset copper -o "$D/cu.exr"
expect_stderr "drops -> [0-9]+ beads at 75 deg" "copper: the preset's 75 deg, the beads counted"
expect_exit 0 "sand (20 deg): a film" -- "$SOAK" "${base[@]}" --preset sand -o "$D/sand.exr"
expect_stderr "20 deg is below --bead-above 60 deg: .*the map is flat" "sand: the flat map is said"
expect_exit 0 "--contact-angle overrides the preset" -- "$SOAK" "${base[@]}" --preset sand --contact-angle 160 -o "$D/lotus.exr"
expect_stderr "beads at 160 deg" "the override is the angle baked"
if cmp -s "$D/cu.exr" "$D/sand.exr"; then bad "beads and film maps are the same bytes"; else ok "beads and film maps differ"; fi

cp "$D/cu.exr" "$D/keep.exr"
expect_exit 2 "PNG refused" -- "$SOAK" "${base[@]}" --preset copper -o "$D/b.png"
expect_stderr "write \.exr or \.tif" "the PNG refusal names EXR and TIFF"
[ ! -e "$D/b.png" ] && ok "no PNG written" || bad "a refused PNG was written"
expect_exit 2 "unknown preset" -- "$SOAK" "${base[@]}" --preset unobtainium -o "$D/keep.exr"
expect_stderr "no preset named 'unobtainium'" "the unknown preset is named"
expect_exit 2 "a bake too large to hold" -- "$SOAK" bake beads --rate 500 --duration 1e6 --width 16384 --height 16384 -o "$D/keep.exr"
expect_stderr "drops expected .* shorten --duration" "the size refusal says what to change"
expect_exit 2 "--materials without --preset" -- "$SOAK" "${base[@]}" --materials x.json -o "$D/keep.exr"
expect_exit 2 "a NaN contact angle" -- "$SOAK" "${base[@]}" --contact-angle nan -o "$D/keep.exr"
cmp -s "$D/cu.exr" "$D/keep.exr" && ok "refused runs left the earlier output's bytes" || bad "a refused run changed keep.exr"
left=$(find "$D" -name '.*' -type f | wc -l)
[ "$left" -eq 0 ] && ok "no temporaries left beside the outputs" || bad "$left temporaries left in $D"
finish
