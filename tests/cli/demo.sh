#!/usr/bin/env bash
# soak demo (the README's main job): every promised file exists and opens,
# the table's dry albedos equal the preset file's values (read here with
# python's json module, independently of libsoak), wet porous materials are
# darker than dry, and the wet maps are linear 16-bit PNGs with gAMA 1.0.
. "$(dirname "$0")/lib.bash"
out="$SOAK_TMP/demo"
rm -rf "$out"
expect_exit 0 "demo --help" -- "$SOAK" demo --help
expect_exit 0 "demo runs" -- "$SOAK" demo --out "$out" --quick
for f in albedo_table.csv swatches.png wetmap_turbulence.exr wetmap_turbulence.png wetmap_drying_t0.3.png wetmap_waves.png render_wet_dry.exr render_wet_dry.png; do
  [ -s "$out/$f" ] && ok "wrote $f" || bad "missing $f"
done
if command -v iinfo >/dev/null; then
  dims=$(iinfo "$out/swatches.png" | grep -oE '[0-9]+ x [0-9]+')
  n=$(/usr/bin/python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['materials']))" "$SOAK_ROOT/c_core/data/materials.json")
  [ "$dims" = "480 x $((96 * n))" ] && ok "swatch sheet is 5 x $n swatches ($dims)" || bad "swatch sheet is $dims, want 480 x $((96 * n))"
  iinfo -v "$out/wetmap_waves.png" | grep -q 'uint16' && ok "wet map PNG is 16-bit" || bad "wet map PNG is not 16-bit"
else
  bad "iinfo (openimageio-tools) missing"
fi
grep -qa 'gAMA' "$out/wetmap_waves.png" && ok "wet map PNG carries gAMA" || bad "wet map PNG has no gAMA chunk"

/usr/bin/python3 - "$SOAK_ROOT/c_core/data/materials.json" "$out/albedo_table.csv" > "$SOAK_TMP/demo_check.txt" <<'PY'
import csv, json, sys
presets = {m["name"]: m for m in json.load(open(sys.argv[1]))["materials"]}
rows = list(csv.DictReader(open(sys.argv[2])))
print("rows", len(rows), len(presets))
for r in rows:
    p = presets[r["material"]]
    if p["kind"] == "conductor":
        continue
    want = p["albedo"]["rgb"]
    got = [float(r["dry_r"]), float(r["dry_g"]), float(r["dry_b"])]
    print("dry", r["material"], max(abs(a - b) for a, b in zip(got, want)))
    if p["kind"] in ("porous_dielectric", "thin_sheet"):
        print("ratio", r["material"], float(r["wet_over_dry"]))
PY
read -r _ nrows npresets < <(grep '^rows' "$SOAK_TMP/demo_check.txt")
# (a failed python leaves both empty: that is no match)
[ -n "$nrows" ] && [ "$nrows" -gt 0 ] && [ "$nrows" = "$npresets" ] && ok "table has one row per preset ($nrows)" \
  || bad "table has '$nrows' rows for '$npresets' presets"
ndry=$(grep -c '^dry' "$SOAK_TMP/demo_check.txt")
[ "$ndry" -gt 0 ] && ok "$ndry dielectric presets compared" || bad "no dry albedo compared"
while read -r _ name diff; do close "$diff" 0 1e-6 "dry albedo of $name equals the preset file"; done < <(grep '^dry' "$SOAK_TMP/demo_check.txt")
while read -r _ name ratio; do
  awk -v r="$ratio" 'BEGIN { exit !(r < 1) }' && ok "wet $name darker than dry ($ratio)" || bad "wet $name not darker ($ratio)"
done < <(grep '^ratio' "$SOAK_TMP/demo_check.txt")

# Nothing lost: an uncreatable output folder is an error, not a crash.
expect_exit 1 "uncreatable --out" -- "$SOAK" demo --out /proc/no/such/dir
expect_stderr "--out" "message names --out"
finish
