#!/usr/bin/env bash
# soak export: schema validity, reproducible bytes, no absolute paths, values
# equal to `soak albedo` at the knots, atomic output and argument errors.
. "$(dirname "$0")/lib.bash"
PY=/usr/bin/python3
ROOT=${SOAK_ROOT:?}

expect_exit 0 "export --help" -- "$SOAK" export --help
grep -q "example" "$SOAK_TMP/last.out" && ok "help has an example" || bad "help has no example"
grep -q "povray" "$SOAK_TMP/last.out" && ok "help lists the targets" || bad "help does not list the targets"

expect_exit 0 "export json" -- "$SOAK" export --target json -o "$SOAK_TMP/a.json"
expect_exit 0 "export json to stdout" -- "$SOAK" export --target json
cp "$SOAK_TMP/last.out" "$SOAK_TMP/b.json"
cmp -s "$SOAK_TMP/a.json" "$SOAK_TMP/b.json" && ok "same input, same bytes (file vs stdout)" \
  || bad "two exports differ"
[ -s "$SOAK_TMP/a.json" ] || bad "export is empty"
if grep -q "$ROOT" "$SOAK_TMP/a.json"; then bad "export contains the absolute path $ROOT"; else ok "no absolute path in the export"; fi

if $PY -c "import jsonschema" 2>/dev/null; then
  if $PY - "$ROOT/c_core/data/export.schema.json" "$SOAK_TMP/a.json" <<'PYEOF'
import json, sys, jsonschema
schema = json.load(open(sys.argv[1])); doc = json.load(open(sys.argv[2]))
jsonschema.Draft202012Validator.check_schema(schema)
jsonschema.Draft202012Validator(schema).validate(doc)
# A broken document must be rejected: the schema is not vacuous.
bad = json.loads(json.dumps(doc)); bad["materials"][0]["liquids"]["water"]["knots"]["albedo"][0] = [0.5, 2.0, 0.5]
try:
    jsonschema.Draft202012Validator(schema).validate(bad); sys.exit("schema accepted an albedo of 2")
except jsonschema.ValidationError:
    pass
bad = json.loads(json.dumps(doc)); bad["materials_file"] = "/home/build/materials.json"
try:
    jsonschema.Draft202012Validator(schema).validate(bad); sys.exit("schema accepted an absolute path")
except jsonschema.ValidationError:
    pass
PYEOF
  then ok "export validates against export.schema.json (and the schema rejects broken ones)"
  else bad "schema validation failed"; fi
else
  bad "python3-jsonschema missing: the README's set-up installs it"
fi

# Every porous preset's saturation wetness is a knot, and the knot albedos
# equal `soak albedo` at those wetness values (the command's own path).
$PY - "$SOAK_TMP/a.json" > "$SOAK_TMP/knots.txt" <<'PYEOF'
import json, sys
d = json.load(open(sys.argv[1]))
for m in d["materials"]:
    k = m["liquids"]["water"]["knots"]
    if m["saturation_wetness"] > 0:
        print("sat", m["name"], int(m["saturation_wetness"] in k["wetness"]))
    i = len(k["wetness"]) // 2
    print("alb", m["name"], repr(k["wetness"][i]), *k["albedo"][i])
PYEOF
while read -r kind name a b c d; do
  if [ "$kind" = sat ]; then
    [ "$a" = 1 ] && ok "$name: saturation wetness is a knot" || bad "$name: saturation wetness missing from the knots"
  else
    got=$("$SOAK" albedo --material "$name" --wetness "$a" | awk '$1 == "wet" && $2 == "albedo" && NF == 5 {print $3, $4, $5}')
    set -- $got
    if [ $# -eq 3 ]; then
      close "$1" "$b" 2e-6 "$name: knot albedo R at wetness $a = soak albedo"
      close "$3" "$d" 2e-6 "$name: knot albedo B at wetness $a = soak albedo"
    else bad "$name: soak albedo printed no wet line"; fi
  fi
done < "$SOAK_TMP/knots.txt"

# --variant: clay at the porosities of [Hnat06] Fig. 5's sweep, and copper
# under a 50 cm film ([Lag13]), each equal to the chain on a preset file that
# states the same material by hand (the loader's path, not the variant code)
# and to `soak albedo --film-thickness` (the chain's own thickness input).
PORES="0 0.1 0.2 0.3 0.4 0.5"
vargs=(--variant copper_f500=copper,film_mm=500)
for p in $PORES; do vargs+=(--variant "clay_p$(awk -v p="$p" 'BEGIN { printf "%02d", p * 100 + 0.5 }')=clay,porosity=$p"); done
# (a file of clay, copper and water only: the export's time grows with presets x liquids)
$PY - "$ROOT/c_core/data/materials.json" "$SOAK_TMP/small.json" <<'PYEOF'
import json, sys
db = json.load(open(sys.argv[1]))
db["materials"] = [m for m in db["materials"] if m["name"] in ("clay", "copper")]
db["liquids"] = [l for l in db["liquids"] if l["name"] == "water"]
json.dump(db, open(sys.argv[2], "w"), indent=1)
PYEOF
expect_exit 0 "export json with variants" -- "$SOAK" export --target json --materials "$SOAK_TMP/small.json" "${vargs[@]}" \
  -o "$SOAK_TMP/var.json"
$PY - "$SOAK_TMP/small.json" "$SOAK_TMP/var.json" "$SOAK_TMP/var_presets.json" $PORES \
  > "$SOAK_TMP/var.txt" <<'PYEOF'
import copy, json, math, sys
src, exp, out, pores = sys.argv[1], sys.argv[2], sys.argv[3], [float(x) for x in sys.argv[4:]]
db = json.load(open(src)); ex = {m["name"]: m for m in json.load(open(exp))["materials"]}
clay = next(m for m in db["materials"] if m["name"] == "clay")
lum = lambda c: 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
for p in pores:
    m = copy.deepcopy(clay); name = "clay_p%02d" % round(100 * p); m["name"] = name; m.pop("measured", None)
    m["medium"]["sigma_t_per_mm"] = [s * (1 - p) / (1 - clay["porosity"]["alpha"]) for s in m["medium"]["sigma_t_per_mm"]]
    if p == 0:   # no pores: a nonporous dielectric, as the loader reads one
        m["kind"] = "nonporous_dielectric"; del m["porosity"]; del m["roughness"]["ggx_alpha_wet"]
        del m["phase"]["wet"]; del m["wetting"]["t_fill"]
    else:
        m["porosity"]["alpha"] = p; m["roughness"]["ggx_alpha_wet"] = m["roughness"]["ggx_alpha_dry"] * math.sqrt(1 - p)
    db["materials"].append(m)
    k = ex[name]["liquids"]["water"]["knots"]; w = k["wetness"]
    i = w.index(ex[name]["saturation_wetness"])
    # pores just full: the wet state of the gallery's pots
    print("sat", name, p, ex[name]["saturation_wetness"], k["water_specular_weight"][i], k["specular_weight"][i],
          lum(k["albedo"][i]), lum(k["albedo"][0]))
    for j in (i, len(w) - 1):
        print("knot", name, repr(w[j]), *k["albedo"][j], k["ggx_alpha"][j])
k = ex["copper_f500"]["liquids"]["water"]["knots"]
print("film", "copper_f500", repr(k["wetness"][-1]), *k["albedo"][-1], ex["copper_f500"]["film_thickness_m"])
json.dump(db, open(out, "w"), indent=1)
PYEOF
prev=""
while read -r kind name a b c d e f; do
  case $kind in
    sat)
      close "$b" "$a" 1e-12 "$name: saturation wetness = porosity $a"
      close "$c" "$a" 1e-6 "$name: pores full: the water's mirror weight = porosity $a ([Hnat06] Eq. 3, G_p = 1)"
      close "$d" "$(awk -v p="$a" 'BEGIN { print 1 - p }')" 1e-6 "$name: the material's own specular weight = 1 - porosity"
      if [ "$a" = 0 ]; then close "$e" "$f" 1e-9 "$name: no pores: wet at saturation = dry"
      elif [ -n "$prev" ]; then
        awk -v x="$e" -v y="$prev" 'BEGIN { exit !(x < y) }' && ok "$name: pores full darker than the porosity before ($e < $prev)" \
          || bad "$name: pores full not darker than the porosity before ($e >= $prev)"
      fi
      prev=$e ;;
    knot)
      got=$("$SOAK" albedo --materials "$SOAK_TMP/var_presets.json" --material "$name" --wetness "$a" \
        | awk '$1 == "wet" && $2 == "albedo" && NF == 5 {print $3, $4, $5} $1 == "ggx" {print "alpha", $NF}')
      set -- $got
      if [ $# -eq 5 ]; then
        close "$1" "$b" 2e-6 "$name: albedo R at wetness $a = the chain on the hand-made preset"
        close "$3" "$d" 2e-6 "$name: albedo B at wetness $a = the chain on the hand-made preset"
        close "$5" "$e" 2e-6 "$name: GGX alpha at wetness $a = the chain on the hand-made preset"
      else bad "$name: soak albedo printed '$got'"; fi ;;
    film)
      got=$("$SOAK" albedo --materials "$SOAK_TMP/small.json" --material copper --wetness "$a" --film-thickness "$e" | awk '$1 == "wet" && $2 == "albedo" && NF == 5 {print $3, $4, $5}')
      set -- $got
      close "${1:-x}" "$b" 2e-6 "$name: albedo R under the film = soak albedo --film-thickness $e"
      close "${3:-x}" "$d" 2e-6 "$name: albedo B under the film = soak albedo --film-thickness $e" ;;
  esac
done < "$SOAK_TMP/var.txt"
expect_exit 2 "variant porosity out of range" -- "$SOAK" export --target json --variant a=clay,porosity=2
expect_stderr "porosity 2 must lie in" "message names the porosity and its range"
expect_exit 2 "variant porosity on a metal" -- "$SOAK" export --target json --variant a=copper,porosity=0.1
expect_stderr "no pores" "message says the kind has no pores"
expect_exit 2 "variant of an unknown preset" -- "$SOAK" export --target json --variant a=nosuch,film_mm=1
expect_stderr "nosuch" "message names the unknown preset"
expect_exit 2 "variant named as a preset" -- "$SOAK" export --target json --variant clay=clay,porosity=0.1
expect_stderr "exists already" "message says the name is taken"
expect_exit 2 "variant without a change" -- "$SOAK" export --target json --variant a=clay
expect_exit 2 "variant with an unknown key" -- "$SOAK" export --target json --variant a=clay,depth=1
expect_stderr "unknown setting" "message names the unknown setting"
expect_exit 2 "variant film below 0" -- "$SOAK" export --target json --variant a=clay,film_mm=-1
expect_exit 2 "variant porosity not a number" -- "$SOAK" export --target json --variant a=clay,porosity=nan

# Atomic output: a failing run leaves the previous file untouched.
echo previous > "$SOAK_TMP/keep.json"
expect_exit 1 "bad preset file" -- "$SOAK" export --target json --materials "$SOAK_TMP/nosuch.json" -o "$SOAK_TMP/keep.json"
expect_stderr "nosuch.json" "message names the preset file"
[ "$(cat "$SOAK_TMP/keep.json")" = previous ] && ok "previous output untouched" || bad "previous output changed"
expect_exit 1 "unwritable folder" -- "$SOAK" export --target json -o "$SOAK_TMP/no/such/dir/x.json"
ls -a "$SOAK_TMP" | grep -q '\.tmp' && bad "temporary left behind" || ok "no temporary left behind"

# Code through a file name (issue 51 item 2): the preset file's name reaches
# the generated POV-Ray include and OSL source only as an escaped literal.
# POV-Ray itself is the reference: it renders a scene including the export
# without running the directive text, and reads back the name unchanged.
names="$SOAK_TMP/names"; mkdir -p "$names"
small="$ROOT/tests/fuzz/data/export_names_presets.json"
evil='x";#fopen P "pwned.txt" write #write(P,"y") #fclose P #declare Z="y.json'
cp "$small" "$names/$evil"
expect_exit 0 "povray export of a preset file named with directive text" -- \
  "$SOAK" export --target povray --materials "$names/$evil" -o "$names/evil.inc"
if command -v povray >/dev/null; then
  printf '#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n#include "evil.inc"\n#fopen N "name.txt" write\n#write (N, Soak_Data_Materials_File)\n#fclose N\ncamera { location <0,0,-3> look_at 0 }\nsphere { 0, 1 pigment { rgb 1 } }\n' > "$names/s.pov"
  (cd "$names" && povray +Is.pov -D +W8 +H8 -GA +O/dev/null >/dev/null 2>&1)
  [ -e "$names/pwned.txt" ] && bad "rendering the include ran the name's #fopen/#write" \
    || ok "rendering the include wrote no pwned.txt"
  [ "$(cat "$names/name.txt" 2>/dev/null)" = "$evil" ] && ok "POV-Ray reads the file name back unchanged" \
    || bad "POV-Ray read the file name as '$(cat "$names/name.txt" 2>/dev/null)'"
else
  skip "the include rendered by POV-Ray" "povray not on PATH"
fi
nl_name=$'m.json\n#define Wetness 0\n'
cp "$small" "$names/$nl_name"
for t in osl osl-wetmap povray; do
  expect_exit 0 "$t export of a preset file named with a newline" -- \
    "$SOAK" export --target "$t" --materials "$names/$nl_name" -o "$names/nl.$t"
  grep -q '^#define Wetness' "$names/nl.$t" && bad "--target $t: the name put a raw line into the source" \
    || ok "--target $t: no raw line from the file name"
done

expect_exit 2 "missing --target" -- "$SOAK" export
expect_stderr "--target" "message names --target"
expect_exit 2 "unknown target" -- "$SOAK" export --target nosuch
expect_stderr "nosuch" "message names the target"
expect_exit 2 "empty -o" -- "$SOAK" export --target json -o ""
expect_exit 2 "unknown argument" -- "$SOAK" export --target json --bogus
if [ -w /dev/full ]; then
  expect_exit 1 "stdout on a full device" -- sh -c "\"$SOAK\" export --target json > /dev/full"
fi
finish
