#!/bin/bash
# Check that a directory is a usable AUTO-07p and say which one it is.
#
#   mk/check-auto.sh <AUTO_DIR>
#
# Accepts a built source tree (include/auto_f2c.h inside it) and an
# installed AUTO-07p whose headers sit on the compiler's default include
# path, as Debian's package auto-07p (AUTO_DIR=/usr/lib/auto-07p, headers in
# /usr/include). Needs python/auto, cmds/cmds.make and lib/libauto_c.a in
# AUTO_DIR. Prints one line: the version, where it is and where its headers are.
set -euo pipefail

dir=${1:?usage: mk/check-auto.sh <AUTO_DIR>}
die() {
    echo "auto: error: AUTO_DIR=$dir: $*" >&2
    echo "auto: error: give AUTO_DIR=<an AUTO-07p tree or install> (Debian: apt-get install auto-07p, AUTO_DIR=/usr/lib/auto-07p), or make forget-auto to build AUTO-07p from source under build/auto/" >&2
    exit 1
}

[ -d "$dir" ] || die "no such directory"
for f in python/auto/__init__.py cmds/cmds.make lib/libauto_c.a; do
    [ -f "$dir/$f" ] || die "not a built AUTO-07p (no $f)"
done
ls "$dir"/lib/*.o >/dev/null 2>&1 || die "not a built AUTO-07p (no lib/*.o)"

# The compiler and flags AUTO's run() uses (cmds.make), then where
# auto_f2c.h comes from with them.
make_var() {
    sed -n "s/^$1[[:space:]]*=[[:space:]]*//p" "$dir/cmds/cmds.make" | head -n1 |
        sed "s|\$(AUTO_DIR)|$dir|g"
}
cc=$(make_var CC)
cflags=$(make_var CFLAGS)
if [ -f "$dir/include/auto_f2c.h" ]; then
    header=$dir/include/auto_f2c.h
else
    # shellcheck disable=SC2086
    header=$(printf '#include <auto_f2c.h>\n' | ${cc:-gcc} $cflags -H -fsyntax-only -x c - 2>&1 |
             sed -n 's/^\. //p' | grep '/auto_f2c\.h$' | head -n1) || true
    [ -n "$header" ] || die "no auto_f2c.h in $dir/include nor on ${cc:-gcc}'s include path"
fi

if [ -f "$dir/CHANGELOG" ]; then
    version="AUTO-07p $(head -n1 "$dir/CHANGELOG" | sed 's/:*[[:space:]]*$//')"
    what="a source tree"
elif pkg=$(dpkg-query -S "$dir/cmds/cmds.make" 2>/dev/null | cut -d: -f1) && [ -n "$pkg" ]; then
    version="AUTO-07p $(dpkg-query -W -f='${Version}' "$pkg")"
    what="Debian package $pkg"
else
    version="AUTO-07p (version unknown)"
    what="installed, no CHANGELOG or package"
fi
echo "auto: using $version ($what) at $dir, headers $(dirname "$header")/"
