#!/usr/bin/env bash
# No command writes over one of its inputs (issue 21, item 1). Table-driven:
# each row is a command, one of its outputs and one of its inputs; the
# output is made the same file as the input three ways -- the same name, a
# symbolic link to the input, a hard link to the input -- and the command
# must exit 2 naming both files, with the input's bytes unchanged and no
# output written. Outputs of multi-file formats (grid header and payload,
# df3 set, --exposure/--water) each get their own row.
# Commands without file inputs (bake turbulence, bake waves) and stdout-only
# commands (materials, albedo, eval, measure) have nothing to protect.
# Rows run four at a time, each in its own folder with its own stderr file;
# their reports are printed in table order.
set -u
. "$(dirname "$0")/lib.bash"
d="$SOAK_TMP/no_overwrite"
rm -rf "$d" && mkdir -p "$d/fix"
fix="$d/fix"
cp "$SOAK_ROOT/c_core/data/materials.json" "$fix/presets.json"
"$SOAK" bake turbulence --width 8 --height 8 -o "$fix/map.png" >/dev/null 2>&1 || { bad "fixture map"; finish; }
cp "$fix/map.png" "$fix/map2.png"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' >"$fix/quad.obj"
scene_json() { # scene with a mesh and a wetness map, relative to the scene's folder
  printf '{"camera": {"position": [0.5, 0.5, 3], "look_at": [0.5, 0.5, 0], "up": [0, 1, 0]},
 "environment": {"type": "constant", "radiance": 1},
 "materials": {"w": {"type": "wet", "base": {"type": "lambert", "albedo": 0.5}}},
 "objects": [{"type": "mesh", "file": "quad.obj", "material": "w", "wetness": {"type": "map", "file": "map.png"}}]}\n'
}
scene_json >"$fix/scene.json"

# row NAME INPUT OUTPUT -- command... : INPUT and OUTPUT are file names in
# the row's folder ($r); the command runs there. INPUT exists (copied from
# the fixtures); OUTPUT is made INPUT itself (when the names can agree), a
# symbolic link to it, or a hard link to it.
row() {
  local name=$1 input=$2 output=$3
  shift 4
  local how
  for how in same symlink hardlink; do
    # the same name, or else two kinds of link
    { [ "$how" = same ] && [ "$input" != "$output" ]; } && continue
    { [ "$how" != same ] && [ "$input" = "$output" ]; } && continue
    local r="$d/$name.$how"
    cp -r "$fix" "$r"
    [[ $output == */* ]] && mkdir -p "$r/${output%/*}"
    case $how in
      symlink) ln -sf "$r/$input" "$r/$output" ;;
      hardlink) ln -f "$r/$input" "$r/$output" ;;
    esac
    # Every file's inode, size and modification time (ns): a write to the
    # input, a new file or a replaced one all show. Few processes per case:
    # the checks below are shell built-ins.
    local before after err=""
    before=$(find "$r" -printf '%p %i %s %T@\n')
    (cd "$r" && "$@") >"$r.out" 2>"$r.err"
    local rc=$?
    after=$(find "$r" -printf '%p %i %s %T@\n')
    IFS= read -r -d '' err <"$r.err"
    err=${err:0:400}
    if [ $rc -ne 2 ]; then
      bad "$name ($how): exit $rc, want 2; stderr: $err"
    elif [[ $err != *"refusing to overwrite"* || $err != *"$output"* || $err != *"$input"* ]]; then
      bad "$name ($how): message does not name both $output and $input: $err"
    elif [ "$before" != "$after" ]; then
      local line changed="files in the folder changed"
      while IFS= read -r line; do
        [[ $line == "$r/$input "* && $after != *"$line"* ]] && changed="input $input changed"
      done <<<"$before"
      bad "$name ($how): $changed"
    else
      ok "$name ($how): refused, named both, input intact"
    fi
  done
}

# spawn ROW_ARGS...: row in the background (at most 4 at once), its report
# kept in $d/report.NNN; reports are counted after the last row.
n_rows=0
spawn() {
  n_rows=$((n_rows + 1))
  row "$@" >"$d/report.$(printf %03d $n_rows)" 2>&1 &
  while [ "$(jobs -rp | wc -l)" -ge 4 ]; do wait -n; done
}

S=$SOAK
spawn export_json presets.json out.json -- "$S" export --target json --materials presets.json -o out.json
spawn export_json_same presets.json presets.json -- "$S" export --target json --materials presets.json -o presets.json
spawn export_env presets.json presets.json -- env SOAK_MATERIALS=presets.json "$S" export --target json -o presets.json
spawn export_povray presets.json out.inc -- "$S" export --target povray --materials presets.json -o out.inc
spawn export_povray_env presets.json out.inc -- env SOAK_MATERIALS=presets.json "$S" export --target povray -o out.inc
spawn volume_grid_header presets.json presets.json -- "$S" bake volume --material sand --materials presets.json --format grid --dims 4,4,4 -o presets
spawn volume_grid_header_env presets.json presets.json -- env SOAK_MATERIALS=presets.json "$S" bake volume --material sand --format grid --dims 4,4,4 -o presets
spawn volume_grid_raw map.png v.raw -- "$S" bake volume --material sand --materials presets.json --map map.png --format grid --dims 4,4,4 -o v
row volume_df3_json presets.json presets_df3.json -- "$S" bake volume --material sand --materials presets.json --format df3 --dims 4,4,4 -o presets
row volume_df3_inc map.png v.inc -- "$S" bake volume --material sand --map map.png --format df3 --dims 4,4,4 -o v
row volume_df3_channel map.png v_wetness.df3 -- "$S" bake volume --material sand --map map.png --format df3 --dims 4,4,4 -o v
if "$S" bake volume --help | grep -q vdb && "$S" bake volume --material sand --format vdb --dims 2,2,2 -o "$d/probe" >/dev/null 2>&1; then
  spawn volume_vdb map.png v.vdb -- "$S" bake volume --material sand --map map.png --format vdb --dims 4,4,4 -o v
else
  skip "this build writes no .vdb" "volume_vdb"
fi
spawn drying_mask map.png map.png -- "$S" bake drying map.png --time 0.5 -o map.png
spawn drying_mask_link map.png out.png -- "$S" bake drying map.png --time 0.5 -o out.png
spawn combine_input map2.png out.png -- "$S" bake combine max map.png map2.png -o out.png
spawn combine_same map.png map.png -- "$S" bake combine clamp map.png -o map.png
spawn rain_output quad.obj out.png -- "$S" bake rain quad.obj --width 8 --height 8 -o out.png
spawn rain_exposure quad.obj exp.png -- "$S" bake rain quad.obj --width 8 --height 8 --exposure exp.png -o out.png
spawn rain_water quad.obj water.exr -- "$S" bake rain quad.obj --width 8 --height 8 --water water.exr -o out.png
spawn render_scene scene.json out.exr -- "$S" render scene.json -o out.exr --spp 1 --width 4 --height 4
spawn render_map map.png map.png -- "$S" render scene.json -o map.png --spp 1 --width 4 --height 4
spawn render_mesh quad.obj out.png -- "$S" render scene.json -o out.png --spp 1 --width 4 --height 4
spawn demo_materials presets.json out/albedo_table.csv -- "$S" demo --quick --out out --materials presets.json
spawn demo_scene scene.json out/render_wet_dry.exr -- "$S" demo --quick --out out --scene scene.json
spawn demo_scene_map map.png out/wetmap_waves.png -- "$S" demo --quick --out out --scene scene.json

wait
for f in "$d"/report.*; do
  cat "$f"
  pass=$((pass + $(grep -c '^ok ' "$f")))
  fail=$((fail + $(grep -c '^FAIL' "$f")))
done

# The demo checks its scene and --out before it writes anything (issue 21,
# item 5): a bad scene leaves no output, a file as --out is called a file.
r="$d/demo_checks" && mkdir -p "$r" && echo '{"objects": []}' >"$r/bad.json" && touch "$r/file"
expect_exit 1 "demo --scene BAD" -- "$S" demo --quick --out "$r/out" --scene "$r/bad.json"
expect_stderr "bad\.json" "demo --scene BAD names the scene"
[ ! -e "$r/out" ] && ok "demo --scene BAD wrote nothing" || bad "demo --scene BAD wrote $(ls "$r/out" | head -3)"
expect_exit 2 "demo --out FILE" -- "$S" demo --quick --out "$r/file"
expect_stderr "file': is a file, not a folder" "demo --out FILE says it is a file"

# A different file of the same content is not an input: the command runs.
r="$d/distinct" && mkdir -p "$r" && cp "$fix"/* "$r/"
expect_exit 0 "export over a copy of its input" -- "$S" export --target json --materials "$r/presets.json" -o "$r/map2.png.json"
finish
