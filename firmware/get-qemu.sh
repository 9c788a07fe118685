#!/usr/bin/env bash
# Puts Debian 12's qemu-system-arm and qemu-system-riscv32 (7.2) in a private
# prefix WITHOUT dpkg, for machines where `apt-get install qemu-system-arm
# qemu-system-misc` is not possible: on this project's machines a qemu-utils
# 10.0 backport is preinstalled and Breaks qemu-system-common < 8.0, so apt
# would remove qemu-utils (or refuse when it is named). Uses only
# `apt-get download` (needs `apt-get update` first) and `dpkg-deb -x`;
# touches nothing outside PREFIX. Each emulator is fetched only if missing.
#
#   bash firmware/get-qemu.sh [PREFIX]   # default $HOME/.cache/gjk2d-qemu
#   export PATH="$PREFIX/bin:$PATH"
set -euo pipefail
PREFIX="${1:-$HOME/.cache/gjk2d-qemu}"
works() { [ -x "$PREFIX/bin/$1" ] && "$PREFIX/bin/$1" --version >/dev/null 2>&1; }
# What both emulators need that a minimal Debian 12 lacks: QEMU's shared
# files and the libraries they link.
COMMON="qemu-system-common qemu-system-data libcapstone4 libfdt1 libslirp0
  libpmem1 libdaxctl1 libndctl6 libibverbs1 librdmacm1 libnl-3-200 libnl-route-3-200
  libspice-server1 libusb-1.0-0 libusbredirparser1 libvdeplug2 libbrlapi0.8 libcacard0
  libsndio7.0 liborc-0.4-0 libgstreamer-plugins-base1.0-0 libexecs0"
# qemu-system-misc holds the RISC-V emulators (46 MB).
MISC="qemu-system-misc libaio1 libbpf1 libfuse3-3 libgmp10 libnuma1 liburing2"
pkgs=""
works qemu-system-arm || pkgs="$pkgs qemu-system-arm"
works qemu-system-riscv32 || pkgs="$pkgs $MISC"
if [ -z "$pkgs" ]; then
  echo "qemu-system-arm and qemu-system-riscv32 already in $PREFIX/bin"; exit 0
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
(cd "$work" && chmod 777 . && apt-get download $COMMON $pkgs >/dev/null)
mkdir -p "$PREFIX/root" "$PREFIX/bin"
for deb in "$work"/*.deb; do dpkg-deb -x "$deb" "$PREFIX/root"; done
for emulator in qemu-system-arm qemu-system-riscv32; do
  cat > "$PREFIX/bin/$emulator" <<WRAP
#!/bin/sh
LD_LIBRARY_PATH="$PREFIX/root/usr/lib/x86_64-linux-gnu:$PREFIX/root/lib/x86_64-linux-gnu\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}" exec "$PREFIX/root/usr/bin/$emulator" "\$@"
WRAP
  chmod +x "$PREFIX/bin/$emulator"
  "$PREFIX/bin/$emulator" --version | head -1
done
