#!/usr/bin/env bash
# Installs a Soak .deb into a fresh minimal Debian 12 root and runs the demo
# there: `apt-get install ./soak_*.deb` must bring every library it needs
# (its Depends) and `soak demo` must run with nothing else of the machine.
# Not part of make test (about 5 minutes and 1 GB: debootstrap plus the
# libraries); run it on a package before publishing it. As root:
#   scripts/check-deb-clean-root.sh build/soak_0.1.0_amd64.deb [ROOT]
# ROOT (default: a new folder under /tmp) is removed afterwards unless given.
set -euo pipefail
deb=$(readlink -f "${1:?usage: $0 SOAK.deb [ROOT]}")
[ "$(id -u)" = 0 ] || { echo "check-deb-clean-root: needs root (debootstrap, chroot)" >&2; exit 2; }
command -v debootstrap > /dev/null || { echo "check-deb-clean-root: debootstrap not on PATH" >&2; exit 2; }
root=${2:-}
keep=1
[ -n "$root" ] || { root=$(mktemp -d /tmp/soak-deb-root.XXXXXX); keep=0; }
mirror=$(sed -n "s/^URIs: //p" /etc/apt/sources.list.d/debian.sources 2>/dev/null | head -1)
cleanup() {
  mountpoint -q "$root/proc" && umount "$root/proc"
  [ "$keep" = 1 ] || rm -rf "$root" "$root.debootstrap.log"
}
trap cleanup EXIT
[ -x "$root/usr/bin/apt-get" ] ||
  debootstrap --variant=minbase bookworm "$root" "${mirror:-http://deb.debian.org/debian}" > "$root.debootstrap.log"
cp "$deb" "$root/tmp/soak.deb"
mount -t proc proc "$root/proc"
chroot "$root" bash -c 'apt-get update -qq &&
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends /tmp/soak.deb > /tmp/apt.log'
chroot "$root" bash -c 'cd /tmp && soak --version && soak demo --out /tmp/demo --quick > /tmp/demo.log &&
  grep -q "every preset (/usr/share/soak/materials.json)" /tmp/demo.log && ls /tmp/demo/render_wet_dry.png'
echo "check-deb-clean-root: $(basename "$deb") installs on Debian $(cat "$root/etc/debian_version") and soak demo runs"
