#!/usr/bin/env bash
# falsecolor on a small rendering: RADIANCE's header (input history, command line,
# FORMAT), the picture-plus-legend size RADIANCE's falsecolor gives, band colours of known
# pixels (RADIANCE 5.4's bytes for the same input: falsecolor [-cp] -lw 0 -i grey.hdr),
# and one-line errors for a bad option and a missing file.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
export RAYPATH=.:$RP_SOURCE_DIR/lib
"$RP_BIN/oconv" "$RP_SOURCE_DIR/examples/cornell/scene.rad" > c.oct
"$RP_BIN/rpict" -vf "$RP_SOURCE_DIR/examples/cornell/view.vf" -x 32 -y 32 c.oct > c.hdr

"$RP_BIN/falsecolor" -i c.hdr > fc.hdr
# 100-pixel legend left of the 32 x 32 image; the unit label's top is 247 up.
[ "$("$RP_BIN/getinfo" -d fc.hdr)" = "fc.hdr: -Y 247 +X 132" ]
"$RP_BIN/getinfo" fc.hdr > info
grep -q "^		rpict -vf " info                  # the input's history, indented
grep -q "falsecolor -i c.hdr$" info
grep -q "^	FORMAT=32-bit_rle_rgbe$" info
# Standard input, contours with 5 divisions: labels 40 apart, the top one ends at 230.
"$RP_BIN/falsecolor" -cl -n 5 < c.hdr > cl.hdr
[ "$("$RP_BIN/getinfo" -d < cl.hdr)" = "-Y 230 +X 132" ]

# Four grey pixels, RGBE (g, g, g, 131) for g = 48, 80, 176, 255 (luminance 179 (g+.5)/32),
# written flat; without a legend the 4-pixel output stays flat too, so bytes can be read.
printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 4\n' > grey.hdr
printf '\060\060\060\203\120\120\120\203\260\260\260\203\377\377\377\203' >> grey.hdr
pixels() { sed '1,/^$/d' "$1" | tail -c 16 | od -An -tu1 | tr -s ' \n' ' ' | sed 's/^ //;s/ $//'; }
"$RP_BIN/falsecolor" -lw 0 -i grey.hdr > def.hdr
[ "$("$RP_BIN/getinfo" -d def.hdr)" = "def.hdr: -Y 1 +X 4" ]
[ "$(pixels def.hdr)" = "0 215 210 127 83 139 42 127 253 225 5 128 252 248 6 128" ] ||
    { echo "default colours: $(pixels def.hdr)"; exit 1; }
"$RP_BIN/falsecolor" -cp -lw 0 -i grey.hdr > cp.hdr
[ "$(pixels cp.hdr)" = "0 61 134 128 6 227 35 127 128 58 0 129 252 248 6 128" ] ||
    { echo "posterized colours: $(pixels cp.hdr)"; exit 1; }

expect_error() {  # pattern, then the arguments
    local pattern=$1; shift
    if "$RP_BIN/falsecolor" "$@" > out 2> err; then echo "falsecolor $* should fail"; exit 1; fi
    [ "$(wc -l < err)" -eq 1 ] || { cat err; exit 1; }
    grep -q "$pattern" err || { cat err; exit 1; }
}
expect_error "^falsecolor: bad option '-q'" -q -i c.hdr
expect_error "^falsecolor: .*missing.hdr" -i missing.hdr
expect_error "^falsecolor: invalid palette 'rainbow'" -pal rainbow -i c.hdr
echo ok
