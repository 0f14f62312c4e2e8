#!/bin/bash
# The shipped blender_addon/soak/soak_data.json must be what
# `soak export --target blender` writes now (byte compare).
set -eu
soak=$1 root=$2 tmp=$3
mkdir -p "$tmp"
"$soak" export --target blender --materials "$root/c_core/data/materials.json" -o "$tmp/soak_data.json"
if ! cmp "$tmp/soak_data.json" "$root/blender_addon/soak/soak_data.json"; then
  echo "FAIL: blender_addon/soak/soak_data.json is stale: regenerate it with"
  echo "  soak export --target blender -o blender_addon/soak/soak_data.json"
  exit 1
fi
echo "PASS: shipped soak_data.json is current"
