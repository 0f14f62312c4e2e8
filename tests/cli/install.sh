#!/usr/bin/env bash
# ctest-label: slow
# Soak installed like a Debian program (README.md, "Install"):
#  - `cmake --install` into a temporary prefix, the prefix then moved, and
#    the moved copy run where it cannot see the source or build tree (both
#    hidden under empty mounts in a private mount namespace when we may, and
#    in any case the copy must name its own share/soak as the presets it
#    read): `soak materials` prints what the build tree's soak prints, `soak
#    demo` writes its files; the errors when the data folder is missing name
#    the folders tried;
#  - the manual page (`soak --man` at build time) renders without warnings
#    and lists every option that every command's --help lists;
#  - the .deb made by CPack: its Depends names the Debian package of every
#    shared library its programs need (read here with readelf and dpkg -S,
#    independently of dpkg-shlibdeps), each satisfied on this Debian; its
#    files unpacked (dpkg -x) run the demo; and `dpkg --root=DIR -i` installs
#    it into an empty root, where it runs, then removes it leaving nothing.
# The build folder is the one holding $SOAK (BUILD/bin/soak).
. "$(dirname "$0")/lib.bash"
build=$(cd "$(dirname "$SOAK")/.." && pwd)
[ -f "$build/CMakeCache.txt" ] || { skip "no CMakeCache.txt beside $SOAK's bin folder" install; finish; }
src=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")
t=$(mktemp -d /tmp/soak_install.XXXXXX)
trap 'rm -rf "$t"' EXIT
mkdir -p "$t/work"

# hidden [VAR=VALUE...] CMD...: runs CMD from $t/work with a bare environment
# (and the VARs) and, when possible, with the build and source trees (in that
# order: the build tree may lie inside the source tree) under empty mounts.
hide=0
if [ "$(id -u)" = 0 ] && command -v unshare >/dev/null &&
   unshare --mount -- sh -c "mount -t tmpfs none '$build' && mount -t tmpfs none '$src'" 2>/dev/null; then hide=1; fi
hidden() {
  local envs=(PATH=/usr/bin:/bin HOME="$t" LANG=C.UTF-8)
  while [[ $1 == *=* ]]; do envs+=("$1"); shift; done
  if [ "$hide" = 1 ]; then
    (cd "$t/work" && unshare --mount -- sh -c 'mount -t tmpfs none "$1" && mount -t tmpfs none "$2" && shift 2 && exec "$@"' \
      hide "$build" "$src" env -i "${envs[@]}" "$@")
  else
    (cd "$t/work" && env -i "${envs[@]}" "$@")
  fi
}
[ "$hide" = 1 ] && ok "source and build trees hidden from the installed copy" ||
  echo "note: cannot hide the trees (not root or no unshare); the checks of the paths read still apply"

# ---- cmake --install, moved ----
if cmake --install "$build" --prefix "$t/prefix" > "$t/install.log" 2>&1; then ok "cmake --install"; else
  bad "cmake --install: $(tail -3 "$t/install.log")"; finish; fi
mv "$t/prefix" "$t/moved"
p=$t/moved
for f in bin/soak lib/soak/libsoak_image.so lib/soak/libsoak_mesh.so share/soak/materials.json \
         share/soak/export.schema.json share/soak/scenes/default_wet_dry.json share/soak/povray/soak.inc \
         share/soak/povray/soak_materials.inc share/soak/povray/soak_mesh.inc share/man/man1/soak.1.gz; do
  [ -s "$p/$f" ] && ok "installed $f" || bad "not installed: $f"
done
if [ -f "$build/soak_blender.zip" ]; then
  cmp -s "$build/soak_blender.zip" "$p/share/soak/soak_blender.zip" && ok "installed the Blender add-on zip" ||
    bad "share/soak/soak_blender.zip missing or not the built one"
fi

# same_presets WHAT DIR: the last listing names DIR/materials.json in its
# first line and is, below it, the build tree's listing.
"$SOAK" materials | tail -n +2 > "$t/materials.build"
same_presets() {
  head -1 "$SOAK_TMP/last.out" | grep -qF "presets from $2/materials.json;" && ok "$1 read $2/materials.json" ||
    bad "$1 read other presets: $(head -1 "$SOAK_TMP/last.out")"
  tail -n +2 "$SOAK_TMP/last.out" | cmp -s - "$t/materials.build" && ok "$1 lists what the build tree's soak lists" ||
    bad "$1 lists other presets: $(tail -n +2 "$SOAK_TMP/last.out" | diff - "$t/materials.build" | head -3)"
}
expect_exit 0 "installed soak materials" -- hidden "$p/bin/soak" materials
same_presets "installed soak materials" "$p/share/soak"

expect_exit 0 "installed soak demo" -- hidden "$p/bin/soak" demo --out "$t/demo" --quick
grep -qF "every preset ($p/share/soak/materials.json)" "$SOAK_TMP/last.out" && ok "demo read the installed presets" ||
  bad "demo did not read $p/share/soak/materials.json: $(grep -m1 'every preset' "$SOAK_TMP/last.out")"
for f in albedo_table.csv swatches.png wetmap_turbulence.exr render_wet_dry.exr render_wet_dry.png; do
  [ -s "$t/demo/$f" ] && ok "demo wrote $f" || bad "demo did not write $f"
done

expect_exit 1 "SOAK_DATA_DIR naming an empty folder" -- hidden SOAK_DATA_DIR="$t/work" "$p/bin/soak" materials
expect_stderr "SOAK_DATA_DIR=$t/work" "the error names \$SOAK_DATA_DIR and its value"
mv "$p/share/soak" "$t/data"
expect_exit 1 "no data folder beside the moved copy" -- hidden "$p/bin/soak" materials
expect_stderr "tried $p/bin/../share/soak|tried $p/share/soak" "the error names the folder tried"
expect_stderr "SOAK_DATA_DIR" "the error says how to point at a data folder"
if grep -qF "$src" "$SOAK_TMP/last.err"; then bad "an installed copy looked in the source tree"; else
  ok "an installed copy never looks in the source tree"; fi
expect_exit 0 "SOAK_DATA_DIR overrides" -- hidden SOAK_DATA_DIR="$t/data" "$p/bin/soak" materials
same_presets "soak materials with SOAK_DATA_DIR" "$t/data"
mv "$t/data" "$p/share/soak"

# ---- the manual page ----
man_page=$p/share/man/man1/soak.1.gz
if command -v groff >/dev/null; then
  zcat "$man_page" | groff -man -ww -z 2> "$t/groff.err"
  [ ! -s "$t/groff.err" ] && ok "groff reads the manual page without warnings" || bad "groff: $(head -3 "$t/groff.err")"
fi
if command -v man >/dev/null; then
  LANG=C MANWIDTH=200 man -l "$man_page" 2> /dev/null | col -b > "$t/man.txt"
  cmds=$("$SOAK" --help | awk '/^commands:/ {on = 1; next} on && /^  [a-z]/ {print $1} on && /^$/ {exit}')
  kinds=$("$SOAK" bake --help | awk '/^kinds:/ {on = 1; next} on && /^  [a-z]/ {print $1} on && /^$/ {exit}')
  missing="" n=0
  for c in $cmds $(for k in $kinds; do echo "bake/$k"; done); do
    grep -q "^ *soak ${c/\// }\$" "$t/man.txt" || missing+=" section:$c"
    for o in $("$SOAK" ${c/\// } --help | grep -oE '(^|[ ,])--[a-z][a-z0-9-]*' | tr -d ' ,' | sort -u); do
      n=$((n + 1))
      grep -qe "$o" "$t/man.txt" || missing+=" $c:$o"
    done
  done
  [ -z "$missing" ] && [ "$n" -gt 50 ] && ok "the manual page has every command and all $n options of their --help" ||
    bad "the manual page lacks:$missing (of $n options)"
  grep -q "SOAK_DATA_DIR" "$t/man.txt" && ok "the manual page documents SOAK_DATA_DIR" || bad "no SOAK_DATA_DIR in the manual page"
else
  skip "man not on PATH" "manual page rendering"
fi

# ---- the .deb ----
if ! command -v cpack >/dev/null || ! command -v dpkg-shlibdeps >/dev/null || ! command -v file >/dev/null; then
  skip "cpack, dpkg-shlibdeps (dpkg-dev) or file not on PATH" ".deb"
  finish
fi
if (cd "$t" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$t/pkg" > "$t/cpack.log" 2>&1); then ok "cpack -G DEB"; else
  bad "cpack: $(tail -5 "$t/cpack.log")"; finish; fi
deb=$(ls "$t"/pkg/soak_*.deb 2>/dev/null | head -1)
[ -n "$deb" ] && ok "made $(basename "$deb") ($(du -k "$deb" | cut -f1) KiB)" || { bad "no .deb in $t/pkg"; finish; }
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
dpkg-deb -x "$deb" "$t/x"
needed=$(for f in "$t/x/usr/bin/soak" "$t"/x/usr/lib/soak/*.so; do readelf -d "$f" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'; done | sort -u)
for lib in $needed; do
  path=$(ldconfig -p | awk -v l="$lib" '$1 == l && /x86-64|x86_64/ {print $NF; exit}')
  pkg=$( [ -n "$path" ] && dpkg -S "$(readlink -f "$path")" 2>/dev/null | head -1 | cut -d: -f1)
  [ -z "$pkg" ] && pkg=$( [ -n "$path" ] && dpkg -S "$path" 2>/dev/null | head -1 | cut -d: -f1)
  if [ -z "$pkg" ]; then bad "no Debian package owns $lib"; continue; fi
  [[ ", $depends," == *", $pkg "* || ", $depends," == *", $pkg,"* || ", $depends," == *"| $pkg "* ]] &&
    ok "Depends names $pkg ($lib)" || bad "Depends lacks $pkg, the package of $lib"
done
unmet=""
IFS=',' read -ra clauses <<< "$depends"
for clause in "${clauses[@]}"; do
  met=0
  IFS='|' read -ra alts <<< "$clause"
  for alt in "${alts[@]}"; do
    read -r name op ver <<< "$(echo "$alt" | sed -E 's/[()]/ /g')"
    have=$(dpkg-query -W -f='${Version}' "$name" 2>/dev/null) || continue
    [ -z "$op" ] && { met=1; break; }
    dpkg --compare-versions "$have" "$op" "$ver" && { met=1; break; }
  done
  [ "$met" = 1 ] || unmet+=" [$clause]"
done
[ -z "$unmet" ] && ok "every Depends is met on this Debian $(cat /etc/debian_version)" || bad "Depends not met here:$unmet"

expect_exit 0 "the unpacked .deb runs the demo" -- hidden "$t/x/usr/bin/soak" demo --out "$t/demo_deb" --quick
grep -qF "every preset ($t/x/usr/share/soak/materials.json)" "$SOAK_TMP/last.out" && ok "the unpacked .deb read its own presets" ||
  bad "the unpacked .deb read other presets: $(grep -m1 'every preset' "$SOAK_TMP/last.out")"

if [ "$(id -u)" = 0 ]; then
  r=$t/root
  mkdir -p "$r/var/lib/dpkg/info" "$r/var/lib/dpkg/updates" && touch "$r/var/lib/dpkg/status"
  # Depends are met by the host (above), not by this empty root: --force-depends.
  if dpkg --root="$r" --force-depends --force-script-chrootless -i "$deb" > "$t/dpkg.log" 2>&1; then
    ok "dpkg --root=DIR -i $(basename "$deb")"
    expect_exit 0 "soak from the dpkg-installed root" -- hidden "$r/usr/bin/soak" materials
    same_presets "dpkg-installed soak materials" "$r/usr/share/soak"
    dpkg --root="$r" -L soak | grep -qx /usr/share/man/man1/soak.1.gz && ok "dpkg knows the manual page" ||
      bad "dpkg -L soak lacks the manual page"
    dpkg --root="$r" --force-script-chrootless -r soak > "$t/dpkg.log" 2>&1 && ok "dpkg -r soak" || bad "dpkg -r: $(tail -2 "$t/dpkg.log")"
    left=$(cd "$r" && find usr -type f 2>/dev/null | head -3)
    [ -z "$left" ] && ok "dpkg -r left no file" || bad "dpkg -r left: $left"
  else
    bad "dpkg --root -i: $(tail -3 "$t/dpkg.log")"
  fi
else
  skip "not root: dpkg --root -i needs it" "dpkg -i"
fi
finish
