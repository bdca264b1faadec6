#!/bin/bash
# RADIANCE 6 spectral patterns in RGB rendering (issue 50): spectrum, specfile, specfunc
# and specdata over glows of radiance 1 (tests/data/spectral/spectral.rad), each seen
# straight on by rtrace -ab 0, against RADIANCE 6.1a (LBNL-ETA/Radiance master, bcffc2b5):
#   oconv spectral.rad > s.oct; rtrace -h -ab 0 s.oct < rays
# The specfunc is sampled at jittered wavelengths, so its value is the mean of 4000 rays
# (standard error under 0.2 %). RADIANCE 6.1a integrates its CIE tables as the observer
# shifted about 1.5 nm toward the red and truncates band edges to whole nanometres; we
# integrate the CIE 1931 table exactly (util/spectrum.cpp). With the same shift ours
# reproduce RADIANCE's to 0.1 %; without it, these spectra differ by up to 2.8 % in a
# channel (cyan's red), so each channel must be within 4 % of RADIANCE's. (A steeper
# peak, 60 nm wide, differs by 5.5 % in blue for that reason alone.)
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$SRC/tests/data/spectral" || exit 1
export RAYPATH="$SRC/tests/data/spectral:$SRC/lib"
"$BIN/oconv" spectral.rad > "$tmp/s.oct" || exit 1
printf '%s\n' "0.5 0.5 0.5 0 0 -1" "0.5 0.5 1.5 0 0 -1" "0 0.5 3.5 0 0 -1" \
    "0.25 0.5 3.5 0 0 -1" "0.999 0.5 3.5 0 0 -1" > "$tmp/rays"
"$BIN/rtrace" -h -ab 0 "$tmp/s.oct" < "$tmp/rays" > "$tmp/out" 2> "$tmp/err" || {
    cat "$tmp/err"; exit 1; }
for i in $(seq 4000); do echo "0.5 0.5 2.5 0 0 -1"; done |
    "$BIN/rtrace" -h -ab 0 "$tmp/s.oct" 2> /dev/null |
    awk '{r += $1; g += $2; b += $3} END {printf "%.6e\t%.6e\t%.6e\n", r / NR, g / NR, b / NR}' \
        >> "$tmp/out"
cat > "$tmp/ref" << 'EOF'
rise         5.076927e-01 2.588542e-01 1.256980e-01
cyan         7.066982e-02 3.639408e-01 8.462546e-01
blend_x0     5.076927e-01 2.588542e-01 1.256980e-01
blend_x.25   4.807608e-01 2.941506e-01 1.942061e-01
blend_x1     4.000724e-01 3.998989e-01 3.994565e-01
peak_mean    6.012686e-01 8.870657e-01 3.551545e-01
EOF
paste "$tmp/ref" "$tmp/out" | awk '
    {
        for (c = 0; c < 3; ++c) {
            ref = $(2 + c); got = $(5 + c); d = (got - ref) / ref
            printf "%-11s %s RADIANCE %.5f ours %.5f (%+.2f %%)\n", $1, substr("RGB", c + 1, 1),
                ref, got, 100 * d
            if (d > 0.04 || d < -0.04) bad = 1
        }
    }
    END { exit bad }' || { echo "FAIL: a channel differs from RADIANCE 6.1a by more than 4 %"; exit 1; }
# The blend's ends are the two rows of its table: x = 0 is the rise, x = 1 flat grey.
awk 'NR == 1 {r = $1; g = $2; b = $3}
     NR == 3 {d = (r - $1) ^ 2 + (g - $2) ^ 2 + (b - $3) ^ 2; exit d > 1e-10}' "$tmp/out" ||
    { echo "FAIL: specdata at x = 0 is not the spectrum of its first row"; exit 1; }
echo ok
