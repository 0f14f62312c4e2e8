#!/usr/bin/env bash
# usage: check_layers.sh CC C_CORE layer:base=dir:dir:... (one per layer; base
# is the layer it is built on, empty for the lowest)
# For each layer, compiles (syntax only) a probe including one public header
# with that layer's own include path: headers of the layer and of the layers
# under it (its base, the base's base, ...) must compile, headers of every
# other layer must not be found -- the layers above it, and the other branch
# (export is built on materials beside transport < render < bake, so neither
# side sees the other). First a self-test: for each layer, a copy of its
# include folder in which one header includes a header of a layer it must not
# see (an upward or sideways #include added) must fail to compile.
cc=$1 root=$2; shift 2
pass=0 fail=0
layers=() bases=() paths=()
for a in "$@"; do
  spec=${a%%=*}
  layers+=("${spec%%:*}"); bases+=("${spec#*:}"); paths+=("${a#*=}")
done
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
index_of() { local k; for k in "${!layers[@]}"; do [ "${layers[$k]}" = "$1" ] && { echo "$k"; return; }; done; }
sees() { # sees I J -> 0 if layer J is layer I or lies under it
  local k=$1
  while [ -n "$k" ]; do
    [ "$k" = "$2" ] && return 0
    [ -n "${bases[$k]}" ] || return 1
    k=$(index_of "${bases[$k]}")
  done
  return 1
}
probe() { # probe PATHS HEADER -> 0 if it compiles
  local flags=() d
  IFS=: read -ra dirs <<< "$1"
  for d in "${dirs[@]}"; do flags+=("-I$d"); done
  printf '#include "soak/%s"\nint soak_probe;\n' "$2" > "$tmp/p.c"
  "$cc" -std=c11 -fsyntax-only "${flags[@]}" $(pkg-config --cflags-only-I libcjson OpenImageIO 2>/dev/null) "$tmp/p.c" 2> "$tmp/err"
}
planted=0
for i in "${!layers[@]}"; do
  for j in "${!layers[@]}"; do
    sees "$i" "$j" && continue
    other=$(ls "$root/${layers[$j]}"/include/soak/*.h 2>/dev/null | head -1)
    own=$(ls "$root/${layers[$i]}"/include/soak/*.h 2>/dev/null | head -1)
    [ -n "$other" ] && [ -n "$own" ] || continue
    rm -rf "$tmp/plant" && mkdir -p "$tmp/plant" && cp -r "$root/${layers[$i]}/include/soak" "$tmp/plant/"
    { printf '#include "soak/%s"\n' "$(basename "$other")"; cat "$own"; } > "$tmp/plant/soak/$(basename "$own")"
    if probe "${paths[$i]//"$root/${layers[$i]}/include"/"$tmp/plant"}" "$(basename "$own")"; then
      fail=$((fail + 1)); echo "FAIL self-test: ${layers[$i]}'s soak/$(basename "$own") including ${layers[$j]}'s soak/$(basename "$other") compiles"
    else planted=$((planted + 1)); fi
    break
  done
done
echo "self-test: $planted planted includes of a layer not seen refused"
[ "$planted" -ge 7 ] || { echo "FAIL self-test: only $planted layers could be planted"; fail=$((fail + 1)); }
for i in "${!layers[@]}"; do
  if [ -n "${bases[$i]}" ] && [ -z "$(index_of "${bases[$i]}")" ]; then
    echo "FAIL layer ${layers[$i]}: its base ${bases[$i]} is not a layer"; fail=$((fail + 1))
  fi
done
for i in "${!layers[@]}"; do
  for j in "${!layers[@]}"; do
    for h in "$root/${layers[$j]}"/include/soak/*.h; do
      name=$(basename "$h")
      if probe "${paths[$i]}" "$name"; then got=compiles; else got=fails; fi
      if sees "$i" "$j"; then want=compiles; else want=fails; fi
      if [ "$got" = "$want" ]; then pass=$((pass + 1))
      else fail=$((fail + 1)); echo "FAIL layer ${layers[$i]}: soak/$name (${layers[$j]}) $got, want $want"; head -3 "$tmp/err"; fi
    done
  done
done
[ "${#layers[@]}" -ge 7 ] || { echo "FAIL only ${#layers[@]} layers given"; fail=$((fail + 1)); }
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
