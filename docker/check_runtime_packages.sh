#!/usr/bin/env bash
# Checks docker/runtime-packages.txt against built binaries on a Debian 12 host:
# every listed package exists, and every shared library `ldd` resolves for the
# binaries belongs to a listed package or to one of their (recursive) Depends.
# Usage: docker/check_runtime_packages.sh BINARY...   (e.g. build/coupler/coupler)
set -euo pipefail
list=$(dirname "$0")/runtime-packages.txt
mapfile -t packages < <(grep -v '^#' "$list")
status=0
for p in "${packages[@]}"; do
  apt-cache show "$p" > /dev/null 2>&1 || { echo "no such package: $p"; status=1; }
done
closure=$(apt-cache depends --recurse --no-recommends --no-suggests --no-conflicts --no-breaks \
            --no-replaces --no-enhances "${packages[@]}" | grep -v '^ ' | sed 's/:.*//' | sort -u)
owner_of() {  # the package of a library path, across the /lib -> /usr/lib merge
  dpkg -S "$1" 2> /dev/null || dpkg -S "/usr$1" 2> /dev/null || dpkg -S "${1#/usr}" 2> /dev/null
}
for binary in "$@"; do
  for so in $(ldd "$binary" | grep -o '/[^ ]*\.so[^ ]*'); do
    owner=$(owner_of "$so" | head -1 | cut -d: -f1) || true
    if [ -z "$owner" ]; then
      echo "$binary: $so belongs to no package"; status=1
    elif ! grep -qx "$owner" <<< "$closure"; then
      echo "$binary: $so ($owner) is not covered by $list"; status=1
    fi
  done
done
[ "$status" = 0 ] && echo "runtime packages cover every library of: $*"
exit "$status"
