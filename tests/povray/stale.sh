#!/bin/bash
# povray/soak_materials.inc is generated: regenerate it and byte-compare with
# the checked-in copy (fails when materials.json or the writer changed).
set -u
SOAK=$1 ROOT=$2 TMP=$3
mkdir -p "$TMP"
"$SOAK" export --target povray -o "$TMP/soak_materials.inc" || { echo "FAIL: soak export --target povray"; exit 1; }
if ! cmp "$TMP/soak_materials.inc" "$ROOT/povray/soak_materials.inc"; then
  echo "FAIL: povray/soak_materials.inc is stale; regenerate it:"
  echo "  soak export --target povray -o povray/soak_materials.inc"
  diff "$TMP/soak_materials.inc" "$ROOT/povray/soak_materials.inc" | head -20
  exit 1
fi
# Deterministic bytes: a second run gives the same file.
"$SOAK" export --target povray -o "$TMP/again.inc" && cmp "$TMP/soak_materials.inc" "$TMP/again.inc" || { echo "FAIL: two exports differ"; exit 1; }
grep -q "Soak_Data_Materials_Hash" "$TMP/soak_materials.inc" || { echo "FAIL: no materials hash in the header"; exit 1; }
echo PASS
