#!/bin/bash
# Build AUTO-07p from source under a given directory.
#
#   mk/build-auto.sh <build-dir> [<tarball>]
#
# Without <tarball>, the Debian source package auto-07p is downloaded with
# `apt-get source --download-only` into <build-dir>/download and its
# .orig.tar.gz is checked against the Checksums-Sha256 field of the .dsc.
# The tree is unpacked to <build-dir>/07p (the AUTO_DIR) and built there.
set -euo pipefail

build_dir=$1
patches=$(cd "$(dirname "$0")/auto-patches" && pwd)
tarball=${2:-}
mkdir -p "$build_dir"
build_dir=$(cd "$build_dir" && pwd)

die() { echo "build-auto: error: $*" >&2; exit 1; }

fetch_debian_source() {
    local src_list=/etc/apt/sources.list.d/mlg-shimmy-src.sources
    local download=$build_dir/download
    mkdir -p "$download"
    if ! ls "$download"/auto-07p_*.orig.tar.* >/dev/null 2>&1 || ! ls "$download"/auto-07p_*.dsc >/dev/null 2>&1; then
        # apt-get update and source need root (else apt's lock error hides this hint)
        [ "$(id -u)" = 0 ] || die "downloading the AUTO-07p source with apt-get needs root; as another user pass AUTO_SRC=<auto-07p tarball> (built here) or AUTO_DIR=<an AUTO-07p tree already built>"
        if [ ! -f "$src_list" ]; then
            echo "build-auto: adding deb-src entries in $src_list"
            sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources > "$src_list"
        fi
        apt-get update
        # Only the .dsc and the .orig tarball are used; the Debian diff
        # (.debian.tar.xz) is often gone from the mirror, and apt's "E: Failed to
        # fetch ... 404" for it read as fatal: its output goes to a log, shown
        # only when what is needed did not arrive.
        local log=$download/apt-get-source.log
        if ! (cd "$download" && apt-get source --download-only auto-07p) >"$log" 2>&1; then
            if ls "$download"/auto-07p_*.dsc "$download"/auto-07p_*.orig.tar.* >/dev/null 2>&1; then
                echo "build-auto: the .dsc and .orig tarball arrived, not all of the Debian source package (the Debian diff is not needed here; apt-get's output: $log)"
            else
                cat "$log" >&2
                die "apt-get source auto-07p did not download the .dsc and .orig tarball (its output above, and in $log)"
            fi
        fi
    fi
    local dsc orig
    dsc=$(ls "$download"/auto-07p_*.dsc 2>/dev/null | head -n1) || true
    orig=$(ls "$download"/auto-07p_*.orig.tar.* 2>/dev/null | head -n1) || true
    [ -n "$dsc" ] || die "no .dsc downloaded into $download"
    [ -n "$orig" ] || die "no .orig tarball downloaded into $download"
    local expected actual
    expected=$(awk -v f="$(basename "$orig")" '
        /^Checksums-Sha256:/ { in_sum = 1; next }
        /^[^ ]/ { in_sum = 0 }
        in_sum && $3 == f { print $1 }' "$dsc")
    [ -n "$expected" ] || die "$(basename "$orig") not listed in Checksums-Sha256 of $dsc"
    actual=$(sha256sum "$orig" | cut -d' ' -f1)
    if [ "$actual" != "$expected" ]; then
        die "sha256 mismatch for $orig: got $actual, .dsc says $expected"
    fi
    echo "build-auto: $(basename "$orig") sha256 $actual matches $(basename "$dsc")"
    tarball=$orig
}

if [ -n "$tarball" ]; then
    [ -f "$tarball" ] || die "AUTO_SRC=$tarball: no such file"
    echo "build-auto: using AUTO_SRC=$tarball, sha256 $(sha256sum "$tarball" | cut -d' ' -f1)"
else
    fetch_debian_source
fi

# Unpack, then move the tree root (the directory holding `configure`; auto/07p
# in the Debian tarball) to <build-dir>/07p, the AUTO_DIR the Makefile expects.
auto_dir=$build_dir/07p
unpack=$build_dir/unpack
rm -rf "$auto_dir" "$unpack"
mkdir -p "$unpack"
tar -xf "$tarball" -C "$unpack"
configure=$(find "$unpack" -maxdepth 3 -name configure -type f | head -n1)
[ -n "$configure" ] || die "no configure script found in $tarball"
mv "$(dirname "$configure")" "$auto_dir"
rm -rf "$unpack"

cd "$auto_dir"
# Our fixes to AUTO's source (mk/auto-patches/README.md says what each fixes).
for fix in "$patches"/*.patch; do
    echo "build-auto: applying $(basename "$fix")"
    patch -p1 --quiet --forward < "$fix" || die "$(basename "$fix") does not apply to $tarball"
done
# The dfsg tarball drops tek2ps/, but configure still wants tek2ps/Makefile.in.
if [ ! -f tek2ps/Makefile.in ]; then
    mkdir -p tek2ps
    printf 'all:\n\nclean:\n' > tek2ps/Makefile.in
fi
./configure --disable-plaut --disable-plaut04 --disable-tek2ps --disable-gui \
    --with-optimization-flags="-O2 -fallow-argument-mismatch"
# No -j: the Fortran module build order breaks in parallel.
make -j1
echo "build-auto: AUTO-07p built in $auto_dir"
