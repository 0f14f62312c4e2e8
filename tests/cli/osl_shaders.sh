#!/usr/bin/env bash
# The shipped OSL shaders and osl/soak_wet_math.h are what `soak export` writes
# today (stale check), self-contained (Blender compiles Internal text blocks
# from a temporary folder) and offer every preset and liquid of the preset file.
. "$(dirname "$0")/lib.bash"
ROOT=${SOAK_ROOT:?}
for pair in "osl:soak_wet_surface.osl" "osl-legacy:soak_wet_surface_legacy.osl" "osl-sheet:soak_wet_sheet.osl" \
            "osl-wetmap:soak_wetmap.osl" "osl-math:soak_wet_math.h"; do
  target=${pair%%:*} file=${pair#*:}
  expect_exit 0 "export --target $target" -- "$SOAK" export --target "$target" -o "$SOAK_TMP/$file"
  if cmp -s "$SOAK_TMP/$file" "$ROOT/osl/$file"; then ok "osl/$file is current"
  else bad "osl/$file is stale: run 'make exports' (scripts/regenerate-exports.sh)"; fi
  if grep -q '^ *#include' "$ROOT/osl/$file"; then bad "osl/$file has an #include"; else ok "osl/$file is self-contained"; fi
  grep -q "Generated\|GENERATED" "$ROOT/osl/$file" && ok "osl/$file says it is generated" || bad "osl/$file lacks the generated header"
done
# The inlined math is the core's header the C tests compile, whole and byte
# for byte.
core_math=c_core/export/src/soak_wet_math.h
for file in soak_wet_surface.osl soak_wet_surface_legacy.osl soak_wet_sheet.osl soak_wetmap.osl soak_wet_math.h; do
  if python3 -c 'import sys; m = open(sys.argv[1]).read(); sys.exit(0 if m and m in open(sys.argv[2]).read() else 1)' \
       "$ROOT/$core_math" "$ROOT/osl/$file"; then ok "$file: inlined math = $core_math"
  else bad "$file: inlined math differs from $core_math"; fi
done
sheets=$(grep -o 'string Preset = "[a-z_]*" \[\[ string widget = "popup", string options = "[^"]*"' "$ROOT/osl/soak_wet_sheet.osl" | sed 's/.*options = "//; s/"$//')
want_sheets=$("$SOAK" materials | awk 'NR > 3 && NF > 5 && $1 ~ /^[a-z_]+$/ && /thin_sheet/ {print $1}' | paste -sd'|')
[ -n "$want_sheets" ] && [ "$sheets" = "$want_sheets" ] && ok "soak_wet_sheet offers the thin sheets ($sheets)" || bad "soak_wet_sheet offers '$sheets', the thin sheets are '$want_sheets'"
opts=$(grep -o 'string Preset = "[a-z_]*" \[\[ string widget = "popup", string options = "[^"]*"' "$ROOT/osl/soak_wet_surface.osl" | sed 's/.*options = "//; s/"$//')
for name in $("$SOAK" materials | awk 'NR > 3 && NF > 5 && $1 ~ /^[a-z_]+$/ {print $1}'); do
  case "|$opts|" in *"|$name|"*) ok "preset $name offered";; *) bad "preset $name missing from the Preset menu ($opts)";; esac
done
finish
