#!/usr/bin/env bash
# flake8 over the project's Python (CONTRIBUTING.md, "Style"; the rules in
# .flake8 at the top: Debian 12 packages flake8, not ruff).
# Usage: check_lint.sh SOURCE_DIR [FLAKE8]
set -u
src=${1:?usage: check_lint.sh SOURCE_DIR [FLAKE8]}
fl=${2:-flake8}
if ! command -v "$fl" >/dev/null 2>&1; then
  echo "SKIPPED: $fl not found (Debian package flake8; scripts/install-deps.sh test)"
  exit 77
fi
cd "$src" || exit 2
mapfile -t files < <(git ls-files '*.py' 2>/dev/null || find . -name '*.py' -not -path './build*' | sort)
if "$fl" --config .flake8 "${files[@]}"; then
  echo "check_lint: ${#files[@]} Python files, flake8 clean"
  exit 0
fi
echo "check_lint: flake8 found the problems above in ${#files[@]} Python files"
exit 1
