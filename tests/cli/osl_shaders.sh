#!/usr/bin/env bash
# The shipped OSL shaders are what `soak export` writes today (stale check),
# self-contained (Blender compiles Internal text blocks from a temporary
# folder) and offer every preset and liquid of the preset file.
. "$(dirname "$0")/lib.bash"
ROOT=${SOAK_ROOT:?}
for pair in "osl:soak_wet_surface.osl" "osl-legacy:soak_wet_surface_legacy.osl" "osl-sheet:soak_wet_sheet.osl" \
            "osl-wetmap:soak_wetmap.osl"; do
  target=${pair%%:*} file=${pair#*:}
  expect_exit 0 "export --target $target" -- "$SOAK" export --target "$target" -o "$SOAK_TMP/$file"
  if cmp -s "$SOAK_TMP/$file" "$ROOT/osl/$file"; then ok "osl/$file is current"
  else bad "osl/$file is stale: run 'make exports' (scripts/regenerate-exports.sh)"; fi
  if grep -q '^ *#include' "$ROOT/osl/$file"; then bad "osl/$file has an #include"; else ok "osl/$file is self-contained"; fi
  grep -q "Generated\|GENERATED" "$ROOT/osl/$file" && ok "osl/$file says it is generated" || bad "osl/$file lacks the generated header"
done
# The inlined math is the header the C tests compile, byte for byte.
want=$(sed -n '/^#ifndef SOAK_WET_MATH_H/,/^#endif/p' "$ROOT/osl/soak_wet_math.h")
for file in soak_wet_surface.osl soak_wet_surface_legacy.osl soak_wet_sheet.osl soak_wetmap.osl; do
  body=$(sed -n '/^#ifndef SOAK_WET_MATH_H/,/^#endif/p' "$ROOT/osl/$file")
  [ -n "$want" ] && [ "$body" = "$want" ] && ok "$file: inlined math = osl/soak_wet_math.h" || bad "$file: inlined math differs from osl/soak_wet_math.h"
done
sheets=$(grep -o 'string Preset = "[a-z_]*" \[\[ string widget = "popup", string options = "[^"]*"' "$ROOT/osl/soak_wet_sheet.osl" | sed 's/.*options = "//; s/"$//')
want_sheets=$("$SOAK" materials | awk 'NR > 3 && NF > 5 && $1 ~ /^[a-z_]+$/ && /thin_sheet/ {print $1}' | paste -sd'|')
[ -n "$want_sheets" ] && [ "$sheets" = "$want_sheets" ] && ok "soak_wet_sheet offers the thin sheets ($sheets)" || bad "soak_wet_sheet offers '$sheets', the thin sheets are '$want_sheets'"
opts=$(grep -o 'string Preset = "[a-z_]*" \[\[ string widget = "popup", string options = "[^"]*"' "$ROOT/osl/soak_wet_surface.osl" | sed 's/.*options = "//; s/"$//')
for name in $("$SOAK" materials | awk 'NR > 3 && NF > 5 && $1 ~ /^[a-z_]+$/ {print $1}'); do
  case "|$opts|" in *"|$name|"*) ok "preset $name offered";; *) bad "preset $name missing from the Preset menu ($opts)";; esac
done
finish
