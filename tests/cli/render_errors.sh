#!/usr/bin/env bash
# soak render: every bad scene fails with exit 1 and a message naming the
# file, the JSON path and the reason; bad usage exits 2; -o never overwrites
# an input; a missing output folder is reported.
set -u
: "${SOAK:?}" "${SOAK_TMP:?}"
dir="$SOAK_TMP/render_errors"
rm -rf "$dir" && mkdir -p "$dir"
fails=0

good_objects='"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]'
head='"camera": {"position": [0, -4, 0], "look_at": [0, 0, 0]}, "environment": {"type": "constant", "radiance": 1}, "materials": {"m": {"type": "lambert", "albedo": 0.5}}'

# expect NAME EXIT_CODE PATTERN... : runs soak render on $dir/NAME.json
expect() {
    local name=$1 code=$2
    shift 2
    "$SOAK" render "$dir/$name.json" -o "$dir/$name.exr" --spp 1 --width 4 --height 4 >"$dir/$name.out" 2>"$dir/$name.err"
    local rc=$?
    local ok=1
    [ "$rc" -eq "$code" ] || ok=0
    for pat in "$@"; do
        grep -qF -- "$pat" "$dir/$name.err" || ok=0
    done
    if [ $ok -eq 1 ]; then
        echo "ok   $name (exit $rc): $(cat "$dir/$name.err")"
    else
        echo "FAIL $name: exit $rc (want $code), stderr: $(cat "$dir/$name.err") (want: $*)"
        fails=$((fails + 1))
    fi
}

printf '{\n  %s,\n  "objects": [\n    {"type": "sphere", "radius": 1,, "material": "m"}\n  ]\n}\n' "$head" >"$dir/syntax.json"
expect syntax 1 "$dir/syntax.json" "line 4" "syntax"

printf '{ %s, "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1, "material": "m", "raduis": 2}] }\n' "$head" >"$dir/unknown_key.json"
expect unknown_key 1 "$dir/unknown_key.json" "objects[0].raduis" "unknown key (accepted: type, material"

printf '{ %s, "objects": [{"type": "mesh", "file": "no_such_mesh.obj", "material": "m"}] }\n' "$head" >"$dir/missing_mesh.json"
expect missing_mesh 1 "$dir/missing_mesh.json" "objects[0].file" "no_such_mesh.obj" "cannot open"

printf '{\n %s,\n "objects": [{"type": "sphere", "center": [0,0,0], "radius": NaN, "material": "m"}] }\n' "$head" >"$dir/nan.json"
expect nan 1 "$dir/nan.json" "line 3" "NaN"

printf '{ %s, "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1e999, "material": "m"}] }\n' "$head" >"$dir/inf.json"
expect inf 1 "$dir/inf.json" "objects[0].radius" "finite"

printf '{ %s, "objects": [{"type": "sphere", "center": [0,0,0], "radius": -1, "material": "m"}] }\n' "$head" >"$dir/negative_radius.json"
expect negative_radius 1 "$dir/negative_radius.json" "objects[0].radius" "must be > 0"

printf '{ %s, "objects": [{"type": "box", "min": [0,0,0], "max": [1,-1,1], "material": "m"}] }\n' "$head" >"$dir/negative_box.json"
expect negative_box 1 "$dir/negative_box.json" "objects[0].max" "negative or zero size"

printf '{ %s, "objects": [{"type": "plane", "size": [2, -3], "material": "m"}] }\n' "$head" >"$dir/negative_plane.json"
expect negative_plane 1 "$dir/negative_plane.json" "objects[0].size" "> 0"

printf '{ %s, "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1, "material": "nope"}] }\n' "$head" >"$dir/no_material.json"
expect no_material 1 "$dir/no_material.json" "objects[0].material" "nope"

printf '{ "render": {"robust": 1}, %s, %s }\n' "$head" "$good_objects" >"$dir/robust_number.json"
expect robust_number 1 "$dir/robust_number.json" "render.robust" "must be true or false"

printf '{ "camera": {"position": [0,-4,0], "look_at": [0,0,0]}, "environment": {"type": "constant", "radiance": 1}, "materials": {"m": {"type": "wet", "base": {"type": "medium", "sigma_s": -2}}}, %s }\n' "$good_objects" >"$dir/negative_sigma.json"
expect negative_sigma 1 "$dir/negative_sigma.json" "materials.m.base.sigma_s" "[0, 1e+09]"

# a preset's base_colour: each channel in [0, 1]; a metal has no base colour to replace
env='"camera": {"position": [0,-4,0], "look_at": [0,0,0]}, "environment": {"type": "constant", "radiance": 1}'
printf '{ %s, "materials": {"m": {"type": "preset", "name": "sand", "base_colour": [0.2, 1.5, 0.3]}}, %s }\n' "$env" "$good_objects" >"$dir/base_colour_range.json"
expect base_colour_range 1 "$dir/base_colour_range.json" "materials.m.base_colour[1]" "[0, 1]"
printf '{ %s, "materials": {"m": {"type": "preset", "name": "copper", "base_colour": [0.2, 0.5, 0.3]}}, %s }\n' "$env" "$good_objects" >"$dir/base_colour_metal.json"
expect base_colour_metal 1 "$dir/base_colour_metal.json" "materials.m.base_colour" "'copper' is a metal"
printf '{ %s, "materials": {"m": {"type": "preset", "name": "sand", "base_colour": [0.2, 0.5, 0.3]}}, %s }\n' "$env" "$good_objects" >"$dir/base_colour_ok.json"
expect base_colour_ok 0

printf '{ "camera": {"position": [0,-4,0], "look_at": [0,0,0]}, "materials": {"m": {"type": "lambert", "albedo": 0.5}}, %s }\n' "$good_objects" >"$dir/no_light.json"
expect no_light 1 "$dir/no_light.json" "lights" "neither lights nor an environment"

printf '{ "camera": {"position": [0,-4,0], "look_at": [0,0,0]}, "environment": {"type": "map", "file": "missing_sky.exr"}, "materials": {"m": {"type": "lambert", "albedo": 0.5}}, %s }\n' "$good_objects" >"$dir/missing_env.json"
expect missing_env 1 "$dir/missing_env.json" "environment.file" "missing_sky.exr"

printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$dir/tri_nouv.obj"
printf '{ %s, "objects": [{"type": "mesh", "file": "tri_nouv.obj", "material": "w", "wetness": {"type": "map", "file": "wet.png"}}] }\n' \
    "$(echo "$head" | sed 's/"materials": {/"materials": {"w": {"type": "wet", "base": {"type": "lambert", "albedo": 0.5}}, /')" >"$dir/mesh_no_uv.json"
expect mesh_no_uv 1 "$dir/mesh_no_uv.json" "objects[0].file" "mesh has no UVs"

# A good scene renders; -o equal to the scene or a missing folder is refused.
printf '{ %s, %s }\n' "$head" "$good_objects" >"$dir/good.json"
expect good 0
"$SOAK" render "$dir/good.json" -o "$dir/good.json" --spp 1 2>"$dir/same.err"
rc=$?
if [ $rc -eq 2 ] && grep -q "refusing to overwrite" "$dir/same.err"; then echo "ok   -o = scene refused (exit 2)"; else echo "FAIL -o = scene: exit $rc $(cat "$dir/same.err")"; fails=$((fails + 1)); fi
"$SOAK" render "$dir/good.json" -o "$dir/no_such_dir/out.exr" --spp 1 2>"$dir/nodir.err"
rc=$?
if [ $rc -eq 1 ] && grep -q "no_such_dir" "$dir/nodir.err"; then echo "ok   missing output folder (exit 1): $(cat "$dir/nodir.err")"; else echo "FAIL missing folder: exit $rc $(cat "$dir/nodir.err")"; fails=$((fails + 1)); fi
"$SOAK" render "$dir/good.json" -o "$dir/out.exr" --spp 0 2>"$dir/spp.err"
rc=$?
if [ $rc -eq 2 ] && grep -q -- "--spp" "$dir/spp.err"; then echo "ok   --spp 0 (exit 2)"; else echo "FAIL --spp 0: exit $rc"; fails=$((fails + 1)); fi
"$SOAK" render "$dir/missing.json" -o "$dir/out.exr" 2>"$dir/missing.err"
rc=$?
if [ $rc -eq 1 ] && grep -q "missing.json" "$dir/missing.err"; then echo "ok   missing scene file (exit 1)"; else echo "FAIL missing scene: exit $rc"; fails=$((fails + 1)); fi
"$SOAK" render --help | grep -q "example" || { echo "FAIL --help has no example"; fails=$((fails + 1)); }

echo "$fails failure(s)"
[ $fails -eq 0 ]
