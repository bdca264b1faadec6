#!/usr/bin/env bash
# mkillum against RADIANCE 5.4's, on the scene in tests/data/mkillum (README.md there):
# for each case of cases.sh, the primitives it writes and every data file have the words
# of RADIANCE's stored output exactly and its numbers within 6 sqrt(2) of their standard
# deviation over 16 RADIANCE runs (both are Monte Carlo estimates; README.md); then the
# same output with -n 2 and from standard input, -defaults, a rendering of the result,
# and one-line errors.
set -euo pipefail
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
data=$RP_SOURCE_DIR/tests/data/mkillum
# shellcheck source=../data/mkillum/cases.sh disable=SC2154
source "$data/cases.sh"
# shellcheck source=lib/cases.sh
source "$RP_SOURCE_DIR/tests/golden/lib/cases.sh"
cd "$data"
fail=0
"$RP_BIN/oconv" -f scene.rad windows.rad > "$tmp/scene.oct"

# The words of a file, one a line, without mkillum's command line.
words() { grep -v '^# mkillum -' "$1" | tr -s ' \t' '\n' | sed '/^$/d'; }

# compare WANT GOT: prints "numbers worst failures" (worst: the largest difference as a
# fraction of its tolerance) or why the files cannot be compared. The tolerance of a
# number is 6 sqrt(2) sigma (ours and RADIANCE's are independent estimates) plus what
# printing and single precision leave (RADIANCE sums in float): 1e-4 relative, 2e-6.
compare() {
    paste -d '|' <(words "$1") "$1.sigma" <(words "$2") | awk -F '|' '
        BEGIN { worst = 0 }
        NF != 3 || $1 == "" || $3 == "" { print "different length at word " NR; exit 1 }
        $2 == "-" { if ($1 != $3) { print "word " NR ": " $3 " for " $1; exit 1 }; next }
        { d = $3 - $1; if (d < 0) d = -d
          a = $1 < 0 ? -$1 : $1
          tol = 6 * sqrt(2) * $2 + 1e-4 * a + 2e-6
          if (d > tol) bad++
          if (d / tol > worst) worst = d / tol
          n++ }
        END { printf "%d %.2f %d\n", n, worst, bad }'
}

run_case() {  # name options input outputs, in folder $tmp/$name
    local name=$1 opts=$2 input=$3 outputs=$4 dir=$tmp/$1
    mkdir -p "$dir"
    ln -s "$tmp/scene.oct" "$dir/scene.oct"
    cp "$input" "$dir/"
    # shellcheck disable=SC2086
    if ! (cd "$dir" && PATH="$RP_BIN:$PATH" mkillum -u- $opts scene.oct "<" "$input" \
        > "$name.out" 2> err); then
        echo "FAIL $name: $(cat "$dir/err")"; fail=1; return
    fi
    grep -qx "# mkillum -u- $opts scene.oct" "$dir/$name.out" ||
        { echo "FAIL $name: no command line"; fail=1; }
    local total=0 worst=0 f result
    for f in $name.out $outputs; do
        if [ ! -f "$dir/$f" ]; then echo "FAIL $name: no $f"; fail=1; continue; fi
        if ! result=$(compare "expected/$name/$f" "$dir/$f"); then
            echo "FAIL $name $f: $result"; fail=1; continue
        fi
        read -r n w bad <<< "$result"
        [ "$bad" -eq 0 ] ||
            { echo "FAIL $name $f: $bad of $n numbers off (worst $w of the tolerance)"; fail=1; }
        total=$((total + n))
        worst=$(awk -v a="$worst" -v b="$w" 'BEGIN { print (b > a ? b : a) }')
    done
    echo "$name: $total numbers, the farthest $worst of its tolerance from RADIANCE's"
}

while IFS='|' read -r name opts input outputs; do
    run_case "$name" "$opts" "$input" "$outputs"
done <<< "$mkillum_cases"

# Two threads give the same output; standard input the same as "<" (-u-: a fixed seed).
mkdir -p "$tmp/n2"
(cd "$tmp/n2" && "$RP_BIN/mkillum" -n 2 -u- -ab 0 "$tmp/scene.oct" "<" "$data/windows.rad" \
    > windows.out 2> /dev/null) || { echo "FAIL -n 2: exit status $?"; fail=1; }
for f in windows.out win.dat win1.dat shadeR.dat; do
    cmp -s <(grep -v '^# .*mkillum -' "$tmp/n2/$f") <(grep -v '^# mkillum -' "$tmp/windows/$f") ||
        { echo "FAIL -n 2: $f differs"; fail=1; }
done
mkdir -p "$tmp/stdin"
(cd "$tmp/stdin" && "$RP_BIN/mkillum" -u- -ab 0 "$tmp/scene.oct" < "$data/misc.rad" \
    > misc.out 2> /dev/null) || { echo "FAIL standard input: exit status $?"; fail=1; }
cmp -s <(grep -v '^# .*mkillum -' "$tmp/stdin/misc.out") \
    <(grep -v '^# mkillum -' "$tmp/misc/misc.out") || { echo "FAIL standard input"; fail=1; }
cmp -s <("$RP_BIN/mkillum" -defaults) expected/defaults.txt || { echo "FAIL -defaults"; fail=1; }
"$RP_BIN/mkillum" -version | grep -q '^RADIANCE 5\.4a ' || { echo "FAIL -version"; fail=1; }

# The result renders as a light source: at a point in front of the window (facing it,
# -ab 0) the window's illum adds to the sun through it about what RADIANCE's rtrace
# finds for the same kind of file (0.483 in red: 16.433 with it, 15.950 without).
(cd "$tmp/windows" && "$RP_BIN/oconv" "$data/scene.rad" windows.out > with.oct &&
    "$RP_BIN/oconv" "$data/scene.rad" "$data/windows.rad" > without.oct &&
    for oct in with without; do
        echo '1 0 1 -1 0 0' | RAYPATH=.:$RP_SOURCE_DIR/lib "$RP_BIN/rtrace" -h -I -ab 0 "$oct.oct"
    done > render.txt) || { echo "FAIL rendering the output"; fail=1; }
awk 'NR == 1 { a = $1 } NR == 2 { d = a - $1 } END { exit !(NR == 2 && d > .43 && d < .53) }' \
    "$tmp/windows/render.txt" || { echo "FAIL rendering: $(cat "$tmp/windows/render.txt")"; fail=1; }

# Spectral sampling (RADIANCE 6's -cs): every pass computed, the data written in RGB. A
# warm spectral lamp over a teal floor lights a window from below; -cs 9 makes the
# window's mean radiance (the illum's last real arguments) higher than -cs 3 by what rtrace
# finds for the irradiance under it (-pY, -cs 9 over -cs 3: 1.112 for ours and RADIANCE
# 6.1a's rtrace; we measured 1.109 for mkillum), within 3 %.
mkdir -p "$tmp/spectral" && (cd "$tmp/spectral" &&
    printf '%s\n' 'void spectrum warm 0 0 7 380 780 0.2 0.5 1 1.4 1.8' \
        'warm light lamp 0 0 3 100 100 100' 'lamp sphere bulb 0 0 4 0 0 3 0.2' \
        'void spectrum teal 0 0 7 380 780 .1 .6 .7 .3 .1' \
        'teal plastic tealfloor 0 0 5 .7 .7 .7 0 0' \
        'tealfloor polygon floor 0 0 12 -2 -2 0  2 -2 0  2 2 0  -2 2 0' \
        'void plastic grey 0 0 5 .5 .5 .5 0 0' \
        'grey polygon wall 0 0 12 -2 2 0  2 2 0  2 2 3  -2 2 3' > s.rad &&
    printf '%s\n' 'void glass g 0 0 3 .9 .9 .9' \
        'g polygon win 0 0 12 -0.5 -0.5 1  0.5 -0.5 1  0.5 0.5 1  -0.5 0.5 1' > w.rad &&
    "$RP_BIN/oconv" s.rad w.rad > s.oct &&
    for cs in 3 9; do
        RAYPATH=.:$RP_SOURCE_DIR/lib "$RP_BIN/mkillum" -ab 1 -ad 256 -cs $cs s.oct < w.rad |
            awk '/^3 / { print $2 }'
    done > means.txt) || { echo "FAIL mkillum -cs"; fail=1; }
awk 'NR == 1 { a = $1 } NR == 2 { r = $1 / a } END { printf "mkillum -cs 9 over -cs 3: %.3f\n", r
     exit !(NR == 2 && r > 1.112 * 0.97 && r < 1.112 * 1.03) }' "$tmp/spectral/means.txt" ||
    { echo "FAIL mkillum -cs 9: $(cat "$tmp/spectral/means.txt")"; fail=1; }

# Errors: one line, naming the file and line where there is one.
printf '# fine\n#@mkillum i=glass d=x\n' > "$tmp/bad_option.rad"
printf '#@mkillum i=glass\nglass polygon p\n0\n0\n9 0 0 0 1 0 0 1 1\n' > "$tmp/short.rad"
printf 'void plastc p\n0\n0\n5 .5 .5 .5 0 0\n' > "$tmp/bad_type.rad"
expect_error "missing octree argument" mkillum -ab 0
expect_error "nosuch.oct" mkillum nosuch.oct
expect_error "unknown option '-e'" mkillum -e err.txt "$tmp/scene.oct"
expect_error "use '< file1 file2 ..'" mkillum "$tmp/scene.oct" windows.rad
expect_error "bad_option.rad:2: bad #@mkillum option 'd=x'" mkillum "$tmp/scene.oct" "<" \
    "$tmp/bad_option.rad"
expect_error "short.rad:2: .*polygon 'p'" mkillum "$tmp/scene.oct" "<" "$tmp/short.rad"
expect_error "bad_type.rad:1: unknown type 'plastc'" mkillum "$tmp/scene.oct" "<" \
    "$tmp/bad_type.rad"
expect_error "nosuch.rad" mkillum "$tmp/scene.oct" "<" nosuch.rad
exit $fail
