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
# The header's source paths exist (they went stale once when c_core/ was split into layers).
paths=$(grep -o 'c_core/[A-Za-z0-9_./-]*[A-Za-z0-9_]' "$TMP/soak_materials.inc" | sort -u)
[ -n "$paths" ] || { echo "FAIL: the header names no source file"; exit 1; }
for p in $paths; do
  [ -e "$ROOT/$p" ] || { echo "FAIL: soak_materials.inc's header names $p, which does not exist"; exit 1; }
done
echo PASS
