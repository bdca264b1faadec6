#!/usr/bin/env bash
# cmake --install into a fresh prefix: the tools in bin, the .cal library in
# lib/radphoton, man pages in share/man/man1, the README in share/doc/radphoton; and the
# installed tools find their library from their own location (RAYPATH unset, run from a
# folder with no lib/): a function file that exists only in the installed library is
# found and used.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
build=$(cd "$RP_BIN/.." && pwd)
cmake --install "$build" --prefix "$tmp/p" > "$tmp/install.log"
p=$tmp/p
fail=0
for t in mkpmap rtrace rpict rcontrib oconv pmapdump getinfo obj2mesh gensky xform; do
    [ -x "$p/bin/$t" ] || { echo "FAIL: $p/bin/$t not installed"; fail=1; }
    [ -f "$p/share/man/man1/$t.1" ] || { echo "FAIL: no man page for $t"; fail=1; }
done
for f in rayinit.cal skybright.cal perezlum.cal; do
    [ -f "$p/lib/radphoton/$f" ] || { echo "FAIL: $f not in lib/radphoton"; fail=1; }
done
[ -f "$p/share/doc/radphoton/README.md" ] || { echo "FAIL: README not installed"; fail=1; }
man -l "$p/share/man/man1/mkpmap.1" > /dev/null 2>&1 ||
    { echo "FAIL: man cannot read the mkpmap page"; fail=1; }
[ "$fail" -eq 0 ] || exit 1

# probe.cal lives only in the installed library: a glow whose brightness is probe() = 3.
echo 'probe = 3;' > "$p/lib/radphoton/probe.cal"
mkdir "$tmp/run" && cd "$tmp/run"
cat > scene.rad <<'RAD'
void brightfunc b 2 probe probe.cal 0 0
b glow g 0 0 4 1 1 1 0
g source s 0 0 4 0 0 1 180
RAD
out=$(echo '0 0 0 0 0 1' | env -u RAYPATH -u RADPHOTON_LIB "$p/bin/rtrace" -h -ov scene.rad)
echo "rtrace through the installed library: $out"
awk -v s="$out" 'BEGIN { split(s, v, /[ \t]+/); exit !(v[1] > 2.99 && v[1] < 3.01) }' ||
    { echo "FAIL: expected radiance 3 from the installed probe.cal, got '$out'"; exit 1; }
"$p/bin/mkpmap" -version
