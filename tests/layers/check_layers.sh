#!/usr/bin/env bash
# usage: check_layers.sh CC C_CORE layer=dir:dir:... (lowest layer first)
# For each layer, compiles (syntax only) a probe including one public header
# with that layer's own include path: headers of the layer and below must
# compile, headers of any layer above must not be found.
cc=$1 root=$2; shift 2
pass=0 fail=0
layers=() paths=()
for a in "$@"; do layers+=("${a%%=*}"); paths+=("${a#*=}"); done
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
probe() { # probe PATHS HEADER -> 0 if it compiles
  local flags=() d
  IFS=: read -ra dirs <<< "$1"
  for d in "${dirs[@]}"; do flags+=("-I$d"); done
  printf '#include "soak/%s"\nint soak_probe;\n' "$2" > "$tmp/p.c"
  "$cc" -std=c11 -fsyntax-only "${flags[@]}" $(pkg-config --cflags-only-I libcjson OpenImageIO 2>/dev/null) "$tmp/p.c" 2> "$tmp/err"
}
for i in "${!layers[@]}"; do
  for j in "${!layers[@]}"; do
    for h in "$root/${layers[$j]}"/include/soak/*.h; do
      name=$(basename "$h")
      if probe "${paths[$i]}" "$name"; then got=compiles; else got=fails; fi
      if [ "$j" -le "$i" ]; then want=compiles; else want=fails; fi
      if [ "$got" = "$want" ]; then pass=$((pass + 1))
      else fail=$((fail + 1)); echo "FAIL layer ${layers[$i]}: soak/$name (${layers[$j]}) $got, want $want"; head -3 "$tmp/err"; fi
    done
  done
done
[ "${#layers[@]}" -ge 6 ] || { echo "FAIL only ${#layers[@]} layers given"; fail=$((fail + 1)); }
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
