#!/usr/bin/env bash
# gendaymtx and epw2wea against RADIANCE 5.4 (tests/data/gendaymtx/README.md): our
# epw2wea writes RADIANCE's .wea text and console lines; every case in cases.txt (the
# matrix header and values, ascii or binary, the -D sun and -M modifier files, the -v
# reports) is RADIANCE's byte for byte, binary values at least within 1e-6 relative;
# the EPW case runs on our own epw2wea output. Then one-line errors for bad tapes, bad
# EPW files and bad options.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
data=$RP_SOURCE_DIR/tests/data/gendaymtx
fail=0
. "$RP_SOURCE_DIR/tests/golden/lib/cases.sh"
# Run as "gendaymtx" (found on PATH), so the header's command line reads as RADIANCE's;
# in a scratch folder holding the inputs, so the files the cases write stay out of the tree.
gendaymtx() { PATH="$RP_BIN:$PATH" command gendaymtx "$@"; }
run=$tmp/run
mkdir "$run"
cp "$data"/*.wea "$data"/*.epw "$run"/
cd "$run"

# epw2wea: the same .wea text and console output; gendaymtx then reads ours.
for epw in sample london; do
    rm "$epw.wea"
    "$RP_BIN/epw2wea" "$epw.epw" "$epw.wea" > "$tmp/$epw.stdout" ||
        { echo "FAIL epw2wea $epw.epw: exit status $?"; fail=1; continue; }
    cmp -s "$epw.wea" "$data/$epw.wea" ||
        { echo "FAIL epw2wea $epw.wea differs:"; diff "$data/$epw.wea" "$epw.wea" | head -5; fail=1; }
    cmp -s "$tmp/$epw.stdout" "$data/$epw.stdout" ||
        { echo "FAIL epw2wea $epw console output differs"; fail=1; }
done

# Header bytes (up to and including the blank line) of a binary matrix.
header_bytes() { head -n "$(LC_ALL=C awk '/^$/ { print NR; exit }' "$1")" "$1" | wc -c; }
# Binary matrices that are not byte-identical: same header, values within 1e-6 relative.
binary_close() {
    local type=$1 want=$2 got=$3 hw hg
    hw=$(header_bytes "$want"); hg=$(header_bytes "$got")
    cmp -s <(head -c "$hw" "$want") <(head -c "$hg" "$got") || return 1
    paste <(tail -c +"$((hw + 1))" "$want" | od -A n -v -t "$type" | tr -s ' ' '\n' | sed '/^$/d') \
          <(tail -c +"$((hg + 1))" "$got" | od -A n -v -t "$type" | tr -s ' ' '\n' | sed '/^$/d') |
        awk 'NF != 2 { bad = 1 }
             { d = $1 - $2; if (d < 0) d = -d; m = $1 < 0 ? -$1 : $1
               if (d > 1e-6 * m && d > 1e-30) bad = 1 }
             END { exit bad || NR == 0 }'
}

n=0
while IFS='|' read -r name opts stdin; do
    n=$((n + 1))
    # shellcheck disable=SC2086
    gendaymtx $opts > "$tmp/$name.out" 2> "$tmp/$name.err" < "${stdin:-/dev/null}" ||
        { echo "FAIL $name ($opts): exit status $?: $(cat "$tmp/$name.err")"; fail=1; continue; }
    want=$data/expected/$name.out
    cmp -s "$want" "$tmp/$name.out" && continue
    case $opts in
        *-of*) binary_close f4 "$want" "$tmp/$name.out" && continue ;;
        *-od*) binary_close f8 "$want" "$tmp/$name.out" && continue ;;
    esac
    echo "FAIL $name ($opts): output differs from expected/$name.out"
    diff "$want" "$tmp/$name.out" | head -6 || true
    fail=1
done < "$data/cases.txt"
[ "$n" -ge 23 ] || { echo "FAIL: only $n cases read"; fail=1; }
for f in suns.rad mods.txt nosky.rad; do
    cmp -s "$data/expected/$f" "$f" || { echo "FAIL $f differs from expected/$f"; fail=1; }
done
cmp -s "$data/expected/stdin.err" "$tmp/stdin.err" ||
    { echo "FAIL -v reports differ:"; diff "$data/expected/stdin.err" "$tmp/stdin.err" || true; fail=1; }

# Bad weather tapes: one line naming the file and line, non-zero exit.
head -1 short.wea > nolat.wea; echo "longitude 123" >> nolat.wea
sed 's/^weather_data_file_units 1/weather_data_file_units 4/' short.wea > units.wea
sed '9s/.*/6 21 5.5 44/' short.wea > short_record.wea
sed '9s/.*/6 21 5.5 forty 71/' short.wea > word.wea
sed '9s/.*/13 21 5.5 44 71/' short.wea > month.wea
sed '9s/.*/6 21 5.5 -44 71/' short.wea > negative.wea
head -6 short.wea > empty.wea
expect_error "nolat.wea:2: weather tape format error in header" gendaymtx nolat.wea
expect_error "units.wea:6: .*must be 1, 2 or 3" gendaymtx units.wea
expect_error "short_record.wea:9: expected 'month day hour direct diffuse', got 4" \
    gendaymtx short_record.wea
expect_error "word.wea:9: expected .* as numbers" gendaymtx word.wea
expect_error "month.wea:9: bad month 13" gendaymtx month.wea
expect_error "negative.wea:9: negative direct or diffuse value" gendaymtx negative.wea
expect_error "empty.wea: no valid time steps on input" gendaymtx empty.wea
expect_error "cannot open 'nosuch.wea' for input" gendaymtx nosuch.wea
IN=units.wea expect_error "<stdin>:6: " gendaymtx -m 2
# Bad options.
expect_error "unknown option '-q'" gendaymtx -q short.wea
expect_error "unknown option '-i'" gendaymtx -i 30 short.wea
expect_error "gendaymtx: -m must be 1 or more" gendaymtx -m 0 short.wea
expect_error "missing solar disk size argument for '-5' option" gendaymtx -5 0 short.wea
expect_error "option -g needs a value" gendaymtx -g .2 .2
expect_error "too many arguments" gendaymtx short.wea test.wea
expect_error "cannot open 'nodir/suns.rad' for output" gendaymtx -D nodir/suns.rad short.wea
# Bad EPW files.
sed -n '1,7p' sample.epw > header7.epw
sed '1s/^LOCATION,Golden,CO,/LOCATION,Golden,/; 1s/,1829.0$//; 1s/,-7.0$//' sample.epw > shortloc.epw
sed '12s/^\([^,]*,[^,]*,[^,]*,[^,]*\),.*/\1/' sample.epw > shortrec.epw
sed '12s/^2004,2,/2004,Feb,/' sample.epw > wordrec.epw
expect_error "wrong number of arguments" epw2wea sample.epw
expect_error "short.wea:1: this does not seem to be an epw file" epw2wea short.wea "$tmp/x.wea"
expect_error "header7.epw:7: the file ends inside the 8 header lines" epw2wea header7.epw "$tmp/x.wea"
expect_error "shortloc.epw:1: LOCATION line has 7 fields, expected 10" \
    epw2wea shortloc.epw "$tmp/x.wea"
expect_error "shortrec.epw:12: record has 4 fields" epw2wea shortrec.epw "$tmp/x.wea"
expect_error "wordrec.epw:12: expected year, month, day and hour" epw2wea wordrec.epw "$tmp/x.wea"
expect_error "cannot open 'nosuch.epw' for input" epw2wea nosuch.epw "$tmp/x.wea"
expect_error "bad option for input arguments" epw2wea sample.epw "$tmp/x.wea" extra

"$RP_BIN/gendaymtx" -version | grep -q '^RADIANCE 5\.4a ' || { echo "FAIL -version"; fail=1; }
exit $fail
