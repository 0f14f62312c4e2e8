#!/bin/bash
# The asset library: built by scenes/blender/asset_library.py (as `make
# asset-library` does, 32 px previews to keep it short), then loaded and
# rendered by test_asset_library.py in a Blender without the add-on.
# Usage: test_asset_library.sh ZIP TMP (SOAK_BLENDER=4.3|5.2, BLENDER_USER_* set)
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
zip=$1; tmp=$2
rm -rf "$tmp/lib" "$BLENDER_USER_EXTENSIONS" "$BLENDER_USER_SCRIPTS"
mkdir -p "$tmp/lib"
bash "$here/run_blender.sh" "$root/scenes/blender/asset_library.py" --addon "$zip" \
  --out "$tmp/lib/soak_materials.blend" --preview 32 || { echo "FAIL: building the asset library"; exit 1; }
rm -rf "$BLENDER_USER_EXTENSIONS" "$BLENDER_USER_SCRIPTS"     # the check runs without the add-on
exec bash "$here/run_blender.sh" "$here/test_asset_library.py" --library "$tmp/lib/soak_materials.blend" \
  --data "$root/blender_addon/soak/soak_data.json" --tmp "$tmp"
