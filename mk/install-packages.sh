#!/bin/bash
# Install the Debian packages the project needs, if any are missing.
#
#   mk/install-packages.sh <package>...
#
# Runs `apt-get update` once, and only when something is missing. Without root
# it lists the missing packages and fails.
set -euo pipefail

missing=()
for pkg in "$@"; do
    status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
    [ "$status" = "install ok installed" ] || missing+=("$pkg")
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "packages: all present ($*)"
    exit 0
fi

if [ "$(id -u)" != 0 ]; then
    echo "packages: error: missing Debian packages: ${missing[*]}" >&2
    echo "packages: install them as root: apt-get install ${missing[*]}" >&2
    exit 1
fi

echo "packages: installing ${missing[*]}"
apt-get update
DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
