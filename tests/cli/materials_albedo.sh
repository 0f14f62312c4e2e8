#!/usr/bin/env bash
# soak materials / soak albedo: help, output shape, the film albedo against
# Lekner & Dorf's closed form evaluated here with awk (midpoint quadrature of
# the Fresnel equations), and argument errors (exit 2, argument named).
. "$(dirname "$0")/lib.bash"

expect_exit 0 "materials --help" -- "$SOAK" materials --help
grep -q "example" "$SOAK_TMP/last.out" && ok "materials help has an example" || bad "materials help has no example"
expect_exit 0 "albedo --help" -- "$SOAK" albedo --help
grep -q "example" "$SOAK_TMP/last.out" && ok "albedo help has an example" || bad "albedo help has no example"

# ---- soak materials ----------------------------------------------------------
expect_exit 0 "materials table" -- "$SOAK" materials
# (soak materials prints the model under uniform diffuse light, 0.668; the
# measurement's light, a sun at 35 deg, gives 0.632: tests/c/materials/test_calibration.c)
grep -Eq "^sand .* 0\.607 \+- 0\.030 \| 0\.6[0-9][0-9] \(dry 0\.395\)" "$SOAK_TMP/last.out" && ok "materials: sand's measured wet/dry beside the model's" || bad "materials: sand's measured vs model wet/dry missing or off"
for name in sand clay brick concrete asphalt limestone paper cotton oak marble copper aluminium; do
  grep -qE "^$name " "$SOAK_TMP/last.out" && ok "table lists $name" || bad "table lacks $name"
done

expect_exit 0 "materials --json --table 5" -- "$SOAK" materials --json --table 5
if command -v python3 > /dev/null; then
  if python3 - "$SOAK_TMP/last.out" << 'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
m = d["materials"]
assert len(m) >= 12, len(m)
for p in m:
    t = p["wetness_table"]
    assert len(t) == 5, (p["name"], len(t))
    assert t[0]["wetness"] == 0 and t[-1]["wetness"] == 1
    assert t[0]["albedo"] == p["albedo"], p["name"]
    assert all(0 <= v <= 1 for r in t for v in r["albedo"]), p["name"]
assert any(l["name"] == "water" for l in d["liquids"])
EOF
  then ok "JSON parses: >= 12 presets, 5 rows each, row 0 = dry albedo"; else bad "JSON export malformed"; fi
else
  skip "python3 not on PATH" "JSON structure check"
fi
expect_exit 0 "materials --table 3 (text)" -- "$SOAK" materials --table 3
grep -q "wetness" "$SOAK_TMP/last.out" && ok "text table has a header" || bad "text table has no header"

expect_exit 2 "materials --table 1" -- "$SOAK" materials --json --table 1
expect_stderr "--table" "message names --table"
expect_exit 2 "materials --liquid lava" -- "$SOAK" materials --liquid lava
expect_stderr "--liquid" "message names --liquid"
expect_stderr "water" "message lists the known liquids"
expect_exit 2 "materials unknown option" -- "$SOAK" materials --bogus
expect_stderr "--bogus" "message names the option"
expect_exit 1 "materials --materials missing file" -- "$SOAK" materials --materials "$SOAK_TMP/none.json"
expect_stderr "none.json" "message names the file"

bad_file="$SOAK_TMP/bad_materials.json"
sed 's/"alpha": 0.395/"alpha": -0.25/' "$SOAK_ROOT/c_core/data/materials.json" > "$bad_file"
expect_exit 1 "SOAK_MATERIALS with a negative porosity" -- env SOAK_MATERIALS="$bad_file" "$SOAK" materials
expect_stderr "materials\[0\]\.porosity\.alpha" "message names the JSON path"

# ---- soak albedo, preset mode --------------------------------------------------
expect_exit 0 "albedo sand wet" -- "$SOAK" albedo --material sand --wetness 1
# albedo_line LABEL: the three numbers of the last output's "<LABEL> albedo" row,
# or nothing (a missing row or a non-number fails the checks below).
albedo_line() {
  awk -v l="$1" '$1 == l && $2 == "albedo" && NF == 5 && $3 $4 $5 ~ /^[0-9.eE+-]+$/ { print $3, $4, $5 }' "$SOAK_TMP/last.out"
}
dry=$(albedo_line dry)
wet=$(albedo_line wet)
# The dry albedo is the data file's, whatever the calibration sets it to.
want=$(/usr/bin/python3 -c 'import json, sys
m = [p for p in json.load(open(sys.argv[1]))["materials"] if p["name"] == "sand"][0]
print(" ".join("%.6f" % v for v in m["albedo"]["rgb"]))' "$SOAK_ROOT/c_core/data/materials.json")
[ -n "$dry" ] && [ "$dry" = "$want" ] && ok "dry sand albedo printed = materials.json ($want)" || bad "dry line '$dry', materials.json '$want'"
if [ -n "$wet" ] && awk -v d="$dry" -v w="$wet" 'BEGIN { split(d, a, " "); split(w, b, " ");
     exit !(b[1] < a[1] && b[2] < a[2] && b[3] < a[3] && b[3] > 0) }'; then
  ok "wet sand darker in every channel"; else bad "wet sand not darker: '$wet' vs '$dry'"; fi
# --sun-zenith: the directional-hemispherical albedo beside the diffuse-light one.
# Wet asphalt: the water's mirror adds F(30 deg) = 0.0205 under the sun (Fresnel,
# n = 1.333) against 0.066 under uniform diffuse light, so its sun total is below
# its diffuse-light total and its sun mirror share is F(30 deg).
expect_exit 0 "albedo asphalt wet under a sun at 30 deg" -- "$SOAK" albedo --material asphalt --wetness 1 --sun-zenith 30
if awk '$1 == "wet" && $2 == "albedo" && $3 == "total" { t = $5 } $1 == "sun" && $2 == "wet" { d = $4 }
        $1 == "sun" && $2 == "albedo" && $3 == "total" { s = $5 }
        END { m = s - d; exit !(t > 0 && s < 0.7 * t && m > 0.0200 && m < 0.0210) }' "$SOAK_TMP/last.out"; then
  ok "sun at 30 deg: total below the diffuse-light total, mirror share = F(30 deg)"
else bad "sun albedo lines missing or off"; fi
expect_exit 2 "albedo --sun-zenith 95" -- "$SOAK" albedo --material sand --wetness 1 --sun-zenith 95
expect_stderr "--sun-zenith" "message names --sun-zenith"
expect_exit 0 "albedo sand dry" -- "$SOAK" albedo --material sand --wetness 0
dry=$(albedo_line dry); wet=$(albedo_line wet)
[ -n "$dry" ] && [ "$wet" = "$dry" ] && ok "wetness 0 = dry ($dry)" || bad "wetness 0: wet '$wet', dry '$dry'"
expect_exit 0 "albedo before the liquid arrives" -- "$SOAK" albedo --material paper --wetness 1 --time 0.1 --t0 0.5 --fill-time 0
dry=$(albedo_line dry); wet=$(albedo_line wet)
[ -n "$dry" ] && [ "$wet" = "$dry" ] && ok "t < t0: still dry ($dry)" || bad "t < t0: wet '$wet', dry '$dry'"

expect_exit 2 "unknown material" -- "$SOAK" albedo --material unobtainium --wetness 1
expect_stderr "unobtainium" "message names the material"
expect_stderr "sand" "message lists the known materials"
expect_exit 2 "NaN wetness" -- "$SOAK" albedo --material sand --wetness nan
expect_stderr "--wetness" "message names --wetness"
expect_exit 2 "wetness > 1" -- "$SOAK" albedo --material sand --wetness 1.5
expect_stderr "--wetness" "message names --wetness"
expect_exit 2 "missing --wetness" -- "$SOAK" albedo --material sand
expect_stderr "--wetness" "message names --wetness"
expect_exit 2 "missing --material" -- "$SOAK" albedo --wetness 1
expect_stderr "--material" "message names --material"
expect_exit 2 "negative fill time" -- "$SOAK" albedo --material sand --wetness 1 --fill-time -1
expect_stderr "--fill-time" "message names --fill-time"
expect_exit 2 "film thickness inf" -- "$SOAK" albedo --material sand --wetness 1 --film-thickness inf
expect_stderr "--film-thickness" "message names --film-thickness"
expect_exit 2 "missing value" -- "$SOAK" albedo --material sand --wetness
expect_stderr "needs a value" "message says the value is missing"

# ---- soak albedo, film mode ----------------------------------------------------
v=$("$SOAK" albedo --model film --base-albedo 0.5 --ior 1.33 --incidence normal | tail -n 1)
if awk -v v="$v" 'BEGIN { exit !(v ~ /^[0-9.eE+-]+$/ && v + 0 > 0 && v + 0 < 0.5) }'; then
  ok "film albedo $v is a number in (0, 0.5)"; else bad "film albedo last line '$v'"; fi
# Lekner & Dorf: R = F0 + (1 - F0) A (1 - ri) / (1 - A ri), ri = 1 - (1 - re) / n^2,
# re = 2 int_0^1 F(mu) mu dmu (exact unpolarised Fresnel, midpoint rule).
want=$(awk -v n=1.33 -v A=0.5 'BEGIN {
  N = 200000; re = 0
  for (i = 0; i < N; i++) {
    mu = (i + 0.5) / N; ct = sqrt(1 - (1 - mu * mu) / (n * n))
    rs = (mu - n * ct) / (mu + n * ct); rp = (n * mu - ct) / (n * mu + ct)
    re += (rs * rs + rp * rp) * mu / N
  }
  ri = 1 - (1 - re) / (n * n); F0 = ((n - 1) / (n + 1)) ^ 2
  printf "%.12f", F0 + (1 - F0) * A * (1 - ri) / (1 - A * ri) }')
close "$v" "$want" 1e-8 "film albedo = Lekner-Dorf closed form (awk)"
v=$("$SOAK" albedo --model film --base-albedo 0.5 --ior 1 --incidence 30 | tail -n 1)
close "$v" 0.5 1e-15 "index 1 is no interface: albedo = base"
expect_exit 0 "film diffuse incidence" -- "$SOAK" albedo --model film --base-albedo 0.5 --ior 1.33 --incidence diffuse --thickness 1e-3 --absorption 350

expect_exit 2 "film: bad incidence" -- "$SOAK" albedo --model film --base-albedo 0.5 --ior 1.33 --incidence sideways
expect_stderr "--incidence" "message names --incidence"
expect_exit 2 "film: incidence 95 deg" -- "$SOAK" albedo --model film --base-albedo 0.5 --ior 1.33 --incidence 95
expect_stderr "--incidence" "message names --incidence"
expect_exit 2 "film: ior < 1" -- "$SOAK" albedo --model film --base-albedo 0.5 --ior 0.5 --incidence normal
expect_stderr "--ior" "message names --ior"
expect_exit 2 "film: missing --base-albedo" -- "$SOAK" albedo --model film --ior 1.33 --incidence normal
expect_stderr "--base-albedo" "message names --base-albedo"
expect_exit 2 "film: base albedo NaN" -- "$SOAK" albedo --model film --base-albedo nan --ior 1.33 --incidence normal
expect_stderr "--base-albedo" "message names --base-albedo"
expect_exit 2 "film: negative absorption" -- "$SOAK" albedo --model film --base-albedo 0.5 --ior 1.33 --incidence normal --absorption -1
expect_stderr "--absorption" "message names --absorption"
expect_exit 2 "unknown model" -- "$SOAK" albedo --model nosuch --base-albedo 0.5
expect_stderr "--model" "message names --model"
expect_exit 2 "film with a preset option" -- "$SOAK" albedo --model film --material sand --base-albedo 0.5 --ior 1.33 --incidence normal
finish
