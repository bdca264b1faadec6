#!/usr/bin/env bash
# Remakes expected/ with RADIANCE 5.4 (the tests never run RADIANCE; see README.md):
# RADIANCE's oconv freezes the scene, then its mkillum runs each case RUNS times, a
# second apart (mkillum's -u+ sampling is seeded with the time). Run 1's outputs are the
# reference; each number's sample standard deviation over all runs goes beside it.
#   RADIANCE_BIN=/path/to/radiance/bin tests/data/mkillum/make_refs.sh
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
export PATH=${RADIANCE_BIN:-/tmp/rad/build/bin}:$PATH
runs=${RUNS:-16}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$here"
oconv -f scene.rad windows.rad > "$tmp/scene.oct"
# shellcheck source=cases.sh
source ./cases.sh  # mkillum_cases: name|options|input|outputs
for k in $(seq 1 "$runs"); do
    while IFS='|' read -r name opts input outputs; do
        dir=$tmp/$k/$name
        mkdir -p "$dir"
        ln -s "$tmp/scene.oct" "$dir/scene.oct"
        cp "$input" "$dir/"
        # shellcheck disable=SC2086
        (cd "$dir" && mkillum $opts scene.oct "<" "$input" > "$name.out" 2> /dev/null)
    done <<< "$mkillum_cases"
    sleep 1
done
while IFS='|' read -r name opts input outputs; do
    mkdir -p "expected/$name"
    for f in $name.out $outputs; do
        cp "$tmp/1/$name/$f" "expected/$name/$f"
        # One line per word of the file (mkillum's command line left out): "-" for a
        # word that is not a number, else the standard deviation over the runs.
        for k in $(seq 1 "$runs"); do
            grep -v '^# mkillum -' "$tmp/$k/$name/$f" | tr -s ' \t' '\n' | sed '/^$/d' \
                > "$tmp/$k.words"
        done
        paste "$tmp"/[0-9]*.words | awk -v runs="$runs" '
            BEGIN { num = "^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$" }
            NF != runs { print "make_refs: runs differ in length" > "/dev/stderr"; exit 1 }
            $1 !~ num { for (k = 2; k <= NF; k++) if ($k != $1) {
                            print "make_refs: runs differ: " $1 " " $k > "/dev/stderr"; exit 1 }
                        print "-"; next }
            { s = 0; for (k = 1; k <= NF; k++) s += $k; m = s / NF
              v = 0; for (k = 1; k <= NF; k++) v += ($k - m) ^ 2
              printf "%.3g\n", sqrt(v / (NF - 1)) }' > "expected/$name/$f.sigma"
        rm -f "$tmp"/[0-9]*.words
    done
done <<< "$mkillum_cases"
