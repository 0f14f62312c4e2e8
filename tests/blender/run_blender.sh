#!/bin/bash
# run_blender.sh SCRIPT ARGS...: the script in headless Blender, under Xvfb
# (EEVEE needs an X server). Fails (never skips) when the Blender asked for is
# missing: the README's set-up installs all three.
#
#   SOAK_BLENDER=3.4 (default)  Debian 12's blender on PATH
#   SOAK_BLENDER=4.3            Debian 13's Blender 4.3 in the root that
#                               scripts/setup-blender-root.sh 4.3 made at
#                               $SOAK_BLENDER43_ROOT (default build/trixie-root)
#   SOAK_BLENDER=5.2            Debian sid's Blender 5.2 in the root that
#                               scripts/setup-blender-root.sh 5.2 made at
#                               $SOAK_BLENDER52_ROOT (default build/sid-root)
#   SOAK_BLENDER_UI=1           run with Blender's window (screenshots) instead of -b
#   SOAK_XVFB_FBDIR=DIR         Xvfb keeps its frame buffer in DIR/Xvfb_screen0
#                               (screenshot_panel.py --xwd: 4.x and 5.x read a
#                               black front buffer under Xvfb)
#   SOAK_BLENDER_RAW=1          ARGS are Blender's own command line, no SCRIPT
#                               (a render farm's blender-render command)
#
# In 4.3 and 5.2 the root is entered with chroot inside a private mount namespace
# (nothing stays mounted afterwards): the repository, the build folder and
# every folder an argument names are bind-mounted at their own paths, so
# arguments need no translation. A `--soak BINARY` argument (a bookworm
# program) becomes a wrapper that runs it with the host's loader and
# libraries, mounted read-only at /host/usr.
set -u
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
version=${SOAK_BLENDER:-3.4}
raw=${SOAK_BLENDER_RAW:-0}
script=""
[ "$raw" = 1 ] || { script=$1; shift; }

mode=(-b)
[ "${SOAK_BLENDER_UI:-0}" = 1 ] && mode=()
script_args() { # the blender arguments that run $script with the given arguments
  if [ "$raw" = 1 ]; then printf '%s\0' "$@"; return; fi
  printf '%s\0' "${mode[@]}" --factory-startup --python-exit-code 1 --python "$script" -- "$@"
}
mapfile -d '' blender_args < <(script_args "$@")

xvfb=()
if command -v xvfb-run >/dev/null; then
  xvfb=(xvfb-run -a -s "-screen 0 1280x1024x24${SOAK_XVFB_FBDIR:+ -fbdir $SOAK_XVFB_FBDIR}")
fi

if [ "$version" = 3.4 ]; then
  if ! command -v blender >/dev/null; then
    echo "FAIL: blender not found on PATH (make deps installs it)"
    exit 1
  fi
  exec "${xvfb[@]}" blender "${blender_args[@]}"
fi

case "$version" in
  4.3) root=${SOAK_BLENDER43_ROOT:-$repo/build/trixie-root} ;;
  5.2) root=${SOAK_BLENDER52_ROOT:-$repo/build/sid-root} ;;
  *) echo "FAIL: SOAK_BLENDER=$version: this suite runs 3.4 (host), 4.3 (Debian 13 root) and 5.2 (Debian sid root)"
     exit 1 ;;
esac
if [ ! -f "$root/.soak-blender${version/./}-ready" ]; then
  echo "FAIL: no Blender $version root at $root (make test runs scripts/setup-blender-root.sh $version)"
  exit 1
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "FAIL: Blender $version runs in a chroot, which needs root"
  exit 1
fi

# The folders to mount: the repository, the working directory and the
# existing folder nearest to every absolute argument.
binds=("$repo" "$PWD")
args=()
prev=""
for a in "$@"; do
  if [ "$prev" = "--soak" ] && [ -x "$a" ]; then
    bin=$(readlink -f "$a")
    wrap_dir="$root/opt/soak-host/$(printf '%s' "$bin" | md5sum | cut -c1-16)"
    mkdir -p "$wrap_dir"
    # a temporary of this process's own: tests of one root run in parallel
    printf '#!/bin/sh\n# %s, a Debian 12 program, with its own loader and libraries\nexec /host/usr/lib/x86_64-linux-gnu/ld-linux-x86-64.so.2 --library-path /host/usr/lib/x86_64-linux-gnu:/host/usr/lib "%s" "$@"\n' \
      "$bin" "$bin" > "$wrap_dir/soak.tmp.$$" && chmod +x "$wrap_dir/soak.tmp.$$" && mv "$wrap_dir/soak.tmp.$$" "$wrap_dir/soak"
    binds+=("$(dirname "$bin")")
    args+=("/opt/soak-host/$(basename "$wrap_dir")/soak")
    prev=$a
    continue
  fi
  case "$a" in
    /*) d=$a; while [ ! -d "$d" ]; do d=$(dirname "$d"); done; [ "$d" != / ] && binds+=("$d") ;;
  esac
  args+=("$a")
  prev=$a
done
for v in BLENDER_USER_SCRIPTS BLENDER_USER_EXTENSIONS BLENDER_USER_CONFIG TMPDIR SOAK_XVFB_FBDIR; do
  d=${!v:-}
  if [ -n "$d" ]; then mkdir -p "$d"; binds+=("$d"); fi
done
mapfile -d '' blender_args < <(script_args "${args[@]}")

# --net: a network namespace of its own (loopback only; Blender needs no
# network). Xvfb listens on an abstract socket named by its display number,
# shared by every process of a network namespace whatever its /tmp; the
# root's private /tmp hides other tests' lock files, so xvfb-run -a picks :99
# in every root. Alone in its namespace, each test's :99 is its own, and
# Blender tests of all three versions run in parallel (ctest -j).
exec unshare --mount --net --propagation private bash -euc '
  root=$1; cwd=$2; nb=$3; shift 3
  binds=("${@:1:$nb}"); shift "$nb"
  mount -t proc proc "$root/proc"
  mount --rbind /dev "$root/dev"
  mount -t tmpfs tmpfs "$root/tmp"
  mkdir -p "$root/host/usr"
  mount --bind /usr "$root/host/usr"
  mount -o remount,bind,ro "$root/host/usr"
  for d in "${binds[@]}"; do
    mkdir -p "$root$d"
    mountpoint -q "$root$d" || mount --bind "$d" "$root$d"
  done
  cd "$root$cwd"
  exec chroot "$root" bash -c "cd \"\$0\" && exec \"\$@\"" "$cwd" "$@"
' _ "$root" "$PWD" "${#binds[@]}" "${binds[@]}" "${xvfb[@]}" blender "${blender_args[@]}"
