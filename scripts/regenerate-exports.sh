#!/usr/bin/env bash
# Regenerates every checked-in file that `soak export` writes (each has a
# test that fails when it is stale). usage: scripts/regenerate-exports.sh [SOAK]
set -euo pipefail
cd "$(dirname "$0")/.."
soak=${1:-build/bin/soak}
"$soak" export --target povray -o povray/soak_materials.inc
"$soak" export --target blender -o blender_addon/soak/soak_data.json
"$soak" export --target osl -o osl/soak_wet_surface.osl
"$soak" export --target osl-legacy -o osl/soak_wet_surface_legacy.osl
"$soak" export --target osl-sheet -o osl/soak_wet_sheet.osl
"$soak" export --target osl-wetmap -o osl/soak_wetmap.osl
"$soak" export --target osl-math -o osl/soak_wet_math.h
