#!/usr/bin/env bash
# Puts Debian 12's qemu-system-arm (7.2) in a private prefix WITHOUT dpkg, for
# machines where `apt-get install qemu-system-arm` is not possible: on this
# project's machines a qemu-utils 10.0 backport is preinstalled and Breaks
# qemu-system-common < 8.0, so apt would remove qemu-utils (or refuse when it
# is named). Uses only `apt-get download` (needs `apt-get update` first) and
# `dpkg-deb -x`; touches nothing outside PREFIX.
#
#   bash firmware/get-qemu.sh [PREFIX]   # default $HOME/.cache/gjk2d-qemu
#   export PATH="$PREFIX/bin:$PATH"
set -euo pipefail
PREFIX="${1:-$HOME/.cache/gjk2d-qemu}"
if [ -x "$PREFIX/bin/qemu-system-arm" ] && "$PREFIX/bin/qemu-system-arm" --version >/dev/null 2>&1; then
  echo "qemu-system-arm already in $PREFIX/bin"; exit 0
fi
PKGS="qemu-system-arm qemu-system-common qemu-system-data libcapstone4 libfdt1 libslirp0
  libpmem1 libdaxctl1 libndctl6 libibverbs1 librdmacm1 libnl-3-200 libnl-route-3-200
  libspice-server1 libusb-1.0-0 libusbredirparser1 libvdeplug2 libbrlapi0.8 libcacard0
  libsndio7.0 liborc-0.4-0 libgstreamer-plugins-base1.0-0 libexecs0"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
(cd "$work" && chmod 777 . && apt-get download $PKGS >/dev/null)
mkdir -p "$PREFIX/root" "$PREFIX/bin"
for deb in "$work"/*.deb; do dpkg-deb -x "$deb" "$PREFIX/root"; done
cat > "$PREFIX/bin/qemu-system-arm" <<WRAP
#!/bin/sh
LD_LIBRARY_PATH="$PREFIX/root/usr/lib/x86_64-linux-gnu:$PREFIX/root/lib/x86_64-linux-gnu\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}" exec "$PREFIX/root/usr/bin/qemu-system-arm" "\$@"
WRAP
chmod +x "$PREFIX/bin/qemu-system-arm"
"$PREFIX/bin/qemu-system-arm" --version | head -1
