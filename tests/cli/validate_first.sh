#!/usr/bin/env bash
# Validate before work (issue 51 items 5 and 6). Each row was an error after
# work, a wrong message or a value ignored without a word; each must now be
# refused (exit 2) before anything is written, by a message naming the
# option or variable (and the frame), never "frame -1".
set -u
. "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/validate_first"
rm -rf "$D" && mkdir -p "$D"
cd "$D" || exit 1

# refused WANT -- command...: exit 2, stderr holding WANT and not "frame -1",
# no file written.
refused() {
  local want=$1
  shift 2
  local before after
  before=$(ls -A | sort)
  expect_exit 2 "$*" -- "$@"
  after=$(ls -A | sort)
  grep -qF -- "$want" "$SOAK_TMP/last.err" && ok "message says '$want'" \
    || bad "message lacks '$want': $(head -c 300 "$SOAK_TMP/last.err")"
  grep -q 'frame -1' "$SOAK_TMP/last.err" && bad "message says 'frame -1'" || true
  [ "$before" = "$after" ] && ok "nothing written" || bad "files appeared: $(comm -13 <(echo "$before") <(echo "$after") | tr '\n' ' ')"
}

# -- item 5: every frame's time, names, derived quantities --
refused "frame 2 is at time 2e+06 s" -- "$SOAK" bake drops --width 16 --height 16 --fps 1e-6 --frames 0-2 -o 'f%d.exr'
refused "the map is at time -1 s" -- "$SOAK" bake drops --width 16 --height 16 --time -1 -o one.exr
refused "the map is at time -1 s" -- "$SOAK" bake drying --width 8 --height 8 --time -1 -o dry.exr
name=$(head -c 246 /dev/zero | tr '\0' n)
refused "temporary's 16-byte suffix" -- "$SOAK" bake turbulence --width 8 --height 8 -o "$name.exr"
refused "--water frame 0: the name" -- "$SOAK" bake rain nosuch.obj --width 8 --height 8 --frames 0-1 -o 'w%d.exr' \
  --water "$name%d.exr"
deep=$(printf 'd/%.0s' $(seq 2100))
refused "is longer than the 4079 a path may have" -- "$SOAK" bake turbulence --width 8 --height 8 --frames 0-1 \
  -o "${deep}x%d.exr"
refused "is longer than the 4079 a path may have" -- "$SOAK" bake turbulence --width 8 --height 8 -o "${deep}x.exr"
refused "--wavelength 1.9e-06 m: the ring width" -- "$SOAK" bake ripples --width 16 --wavelength 1.9e-6 -o r.exr
refused "--rain-dir" -- "$SOAK" bake rain nosuch.obj --width 8 --height 8 --rain-dir 1e-300,1e-300,1e-300 -o w.exr

# -- item 6: environment values parsed like options --
for v in SOAK_MAX_SCENE_MB=20MB SOAK_MAX_SCENE_MB=1e8 SOAK_MAX_SCENE_MB=inf SOAK_MAX_MEMORY_MB=63 \
  SOAK_MESH_TIMEOUT=0 SOAK_IMAGE_TIMEOUT=-3 SOAK_MAX_IMAGE_MB=nan SOAK_IMAGE_IN_PROCESS=yes SOAK_PROGRESS=2 SOAK_MESH_READER=native; do
  refused "${v%%=*}='${v#*=}'" -- env "$v" "$SOAK" bake turbulence --width 8 --height 8 -o env.exr
done
expect_exit 0 "SOAK_MAX_MEMORY_MB=64 (in range) is honoured" -- env SOAK_MAX_MEMORY_MB=64 "$SOAK" materials
expect_exit 0 "an empty value is unset" -- env SOAK_MAX_SCENE_MB= "$SOAK" materials
expect_exit 0 "SOAK_MESH_READER=assimp (one of its words) is honoured" -- env SOAK_MESH_READER=assimp "$SOAK" materials
"$SOAK" --help >help.txt 2>&1
for v in SOAK_DATA_DIR SOAK_MATERIALS SOAK_PLUGIN_DIR SOAK_PROGRESS SOAK_IMAGE_IN_PROCESS SOAK_MAX_SCENE_MB \
  SOAK_MAX_PRESETS_MB SOAK_MAX_IMAGE_MB SOAK_MAX_MESH_MB SOAK_MAX_VOLUME_MB SOAK_MAX_MEMORY_MB SOAK_MESH_MEMORY_MB \
  SOAK_MESH_TIMEOUT SOAK_IMAGE_TIMEOUT SOAK_MESH_READER; do
  grep -q "$v" help.txt && grep -q "$v" "$SOAK_ROOT/README.md" && ok "$v in --help and the README" \
    || bad "$v missing from --help or the README"
done
# Every variable the sources read is in that list.
for v in $(grep -rhoE 'getenv\("SOAK_[A-Z_]+"\)|"SOAK_[A-Z_]+(_MB|_TIMEOUT)"' "$SOAK_ROOT/c_core" | grep -oE 'SOAK_[A-Z_]+' | sort -u); do
  grep -q "$v" help.txt && ok "$v (read by the sources) in --help" || bad "$v is read but not in --help"
done
rm -f help.txt
finish
