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

# Atomic output: a failing run leaves the previous file untouched.
echo previous > "$SOAK_TMP/keep.json"
expect_exit 1 "bad preset file" -- "$SOAK" export --target json --materials "$SOAK_TMP/nosuch.json" -o "$SOAK_TMP/keep.json"
expect_stderr "nosuch.json" "message names the preset file"
[ "$(cat "$SOAK_TMP/keep.json")" = previous ] && ok "previous output untouched" || bad "previous output changed"
expect_exit 1 "unwritable folder" -- "$SOAK" export --target json -o "$SOAK_TMP/no/such/dir/x.json"
ls -a "$SOAK_TMP" | grep -q '\.tmp' && bad "temporary left behind" || ok "no temporary left behind"

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
