#!/usr/bin/env bash
# clang-format check of the project's C (CONTRIBUTING.md, "Style"): every
# .c/.h under c_core/ and tests/c/ must be as clang-format (.clang-format at
# the top) writes it, except the files listed in tests/style/unformatted.txt,
# the ones not yet reformatted (reformat one, then delete its line; a listed
# file that has become clean fails too, so the list only shrinks).
# Usage: check_format.sh SOURCE_DIR [CLANG_FORMAT]
#        check_format.sh --fix SOURCE_DIR FILE...   (reformat files in place)
set -u
if [ "${1:-}" = "--fix" ]; then
  shift; src=$1; shift
  cd "$src" && exec clang-format -i --style=file "$@"
fi
src=${1:?usage: check_format.sh SOURCE_DIR [CLANG_FORMAT]}
cf=${2:-clang-format}
if ! command -v "$cf" >/dev/null 2>&1; then
  echo "SKIPPED: $cf not found (Debian package clang-format; scripts/install-deps.sh test)"
  exit 77
fi
cd "$src" || exit 2
list=tests/style/unformatted.txt
bad=0; checked=0
while IFS= read -r f; do
  checked=$((checked + 1))
  listed=0
  grep -qxF "$f" "$list" && listed=1
  if "$cf" --style=file "$f" | cmp -s - "$f"; then
    if [ $listed = 1 ]; then
      echo "$f: now formatted: delete its line from $list"
      bad=1
    fi
  elif [ $listed = 0 ]; then
    echo "$f: not as clang-format writes it (tests/style/check_format.sh --fix . $f); first differences:"
    "$cf" --style=file "$f" | diff "$f" - | head -n 12
    bad=1
  fi
done < <(git ls-files 'c_core/*.c' 'c_core/*.h' 'tests/c/*.c' 'tests/c/*.h' 2>/dev/null ||
         find c_core tests/c -name '*.[ch]' | sort)
while IFS= read -r f; do
  case "$f" in ''|'#'*) continue ;; esac
  [ -f "$f" ] || { echo "$list: $f does not exist: delete its line"; bad=1; }
done < "$list"
n_listed=$(grep -cv '^\(#\|$\)' "$list")
echo "check_format: $checked C files, $n_listed not yet reformatted (listed), $([ $bad = 0 ] && echo ok || echo FAILED)"
exit $bad
