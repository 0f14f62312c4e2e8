#!/usr/bin/env bash
# soak bake rain's falling film from the command line: --film writes the
# film on a 1 m vertical wall whose foot matches Nusselt's formula evaluated
# here (awk), the steady-rain line says all of the 10 L/h that falls on it
# drips off, --no-film leaves no film, and --film may not name another output.
. "$(dirname "$0")/lib.bash"

D="$SOAK_TMP/rain_film"
rm -rf "$D"
mkdir -p "$D"
command -v oiiotool >/dev/null || { skip "oiiotool not on PATH" "reading the film map"; finish; }

wall_obj "$D/wall.obj"
# Rain from (0,-1,1) in a cone of spread 0: exposure n.u / u.up = 1 exactly.
P=(bake rain "$D/wall.obj" --up z --rain-dir 0,-1,1 --spread 0 --rays 1 --rainfall 10 --evaporation 0
   --duration 60 --steps 1 --width 32 --height 32 --threads 2)
expect_exit 0 "wall with --film" -- "$SOAK" "${P[@]}" --film "$D/film.exr" -o "$D/wet.exr"
grep -qE "steady rain on the mesh 10 L/h: 100.0 % drips off" "$SOAK_TMP/last.out" &&
  ok "10 L/h falls on the 1 m^2 wall, all of it drips off" || bad "steady-rain line: $(cat "$SOAK_TMP/last.out")"
# The texel at the foot of the wall's middle (last image row) carries the rain of the whole 1 m above it.
got=$(oiiotool --dumpdata "$D/film.exr" | sed -n 's/^ *Pixel (16, 31): *//p')
want=$(awk 'BEGIN { q = 10 / 3.6e6 * 1.0; x = 3 * 1.002e-3 * q / (998.2 * 9.80665); printf "%.9g", exp(log(x) / 3) }')
close "$got" "$want" "$(awk -v w="$want" 'BEGIN { printf "%.3g", 0.01 * w }')" "film at the foot vs (3 mu q / (rho g))^(1/3) (1 %, half EXR)"

expect_exit 0 "wall with --no-film" -- "$SOAK" "${P[@]}" --no-film --film "$D/nofilm.exr" -o "$D/wet2.exr"
max=$(oiiotool "$D/nofilm.exr" --printstats | sed -n 's/.*Stats Max: *\([^ ]*\).*/\1/p')
close "$max" 0 0 "--no-film: the film map is 0"
grep -q "steady rain" "$SOAK_TMP/last.out" && bad "--no-film printed a steady-rain line" || ok "--no-film: no steady-rain line"

expect_exit 2 "--film same as -o" -- "$SOAK" "${P[@]}" --film "$D/same.exr" -o "$D/same.exr"
expect_stderr "\-\-film" "the refusal names --film"
[ -e "$D/same.exr" ] && bad "a refused run left output" || ok "the refused run left no output"
# --float: every map of the single bake as 32-bit EXR (half floats store a 10 um film to ~0.3 %).
expect_exit 0 "wall with --float" -- "$SOAK" "${P[@]}" --float --film "$D/ffilm.exr" --water "$D/fwater.exr" \
  --exposure "$D/fexp.exr" -o "$D/fwet.exr"
for f in fwet ffilm fwater fexp; do
  oiiotool --info -v "$D/$f.exr" | grep -q "float" && ok "--float: $f.exr is 32-bit float" ||
    bad "--float: $f.exr is not float: $(oiiotool --info "$D/$f.exr")"
done
got=$(oiiotool --dumpdata "$D/ffilm.exr" | sed -n 's/^ *Pixel (16, 31): *//p')
close "$got" "$want" "$(awk -v w="$want" 'BEGIN { printf "%.3g", 1e-4 * w }')" "--float film at the foot vs Nusselt (1e-4)"
# --preset: the preset's contact angle (materials.json gives brick 30 deg) = --contact-angle 30, byte for byte
expect_exit 0 "wall with --contact-angle 30" -- "$SOAK" "${P[@]}" --contact-angle 30 --film "$D/ca.exr" -o "$D/cawet.exr"
expect_exit 0 "wall with --preset brick" -- "$SOAK" "${P[@]}" --preset brick --film "$D/pb.exr" -o "$D/pbwet.exr"
grep -q "runnels:" "$SOAK_TMP/last.out" && ok "--preset brick: runnels reported" || bad "--preset brick: no runnels line"
oiiotool "$D/ca.exr" "$D/pb.exr" --diff >/dev/null 2>&1 && ok "--preset brick = --contact-angle 30 (film)" ||
  bad "--preset brick differs from --contact-angle 30"
expect_exit 2 "unknown preset" -- "$SOAK" "${P[@]}" --preset nosuch -o "$D/np.exr"
expect_stderr "no preset named 'nosuch'" "the refusal names the preset"
[ -e "$D/np.exr" ] && bad "a refused run left output" || ok "the refused --preset left no output"
expect_exit 0 "--help" -- "$SOAK" bake rain --help
grep -q -- "--no-film" "$SOAK_TMP/last.out" && ok "--help lists --no-film" || bad "--help lacks --no-film"
finish
