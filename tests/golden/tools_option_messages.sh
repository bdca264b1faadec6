#!/usr/bin/env bash
# The tools moved to the option table (util/options.h) keep their messages: a bad option
# value gives the same one line as before (exit 1, nothing on stdout), and -version is
# answered at any option position, after a generator's positional arguments too.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
expect() {  # expected stderr line, command...
    local want=$1; shift
    local rc=0
    "$RP_BIN/$1" "${@:2}" > "$tmp/out" 2> "$tmp/err" < /dev/null || rc=$?
    if [ "$rc" -ne 1 ] || [ -s "$tmp/out" ] || [ "$(cat "$tmp/err")" != "$want" ]; then
        echo "FAIL $*: rc=$rc, stderr: $(cat "$tmp/err"), wanted: $want"; fail=1
    fi
}
expect "genbox: bad radius 'x': expected a number" genbox m n 1 1 1 -r x
expect "genbox: option -n needs a value" genbox m n 1 1 1 -n
expect "genblinds: unknown option 'x' (expected -r or +r)" genblinds m n 1 1 1 2 30 x 2
expect "genprism: bad extrusion vector component 'x': expected a number" \
    genprism m n 3 0 0 1 0 0 1 -l 0 0 x
expect "genrev: option -e needs a value" genrev m n t t 4 -e
expect "gensurf: unknown option '-x'" gensurf m n s t 's*t' 2 2 -x
expect "genworm: unknown option '-s'" genworm m n t t t .1 2 -s
expect "gensky: bad year 'x': expected an integer" gensky 3 21 12 -y x
expect "gensky: bad option '-ss'" gensky 3 21 12 -ss
expect "gensky: unknown option '+r'" gensky 3 21 12 +r 1
expect "gendaylit: option -W needs two values" gendaylit 3 21 12 -W 500
expect "gendaylit: -O must be 0 (visible W), 1 (solar W) or 2 (lumen)" gendaylit 3 21 12 -O 3 -E 300
expect "pvalue: bad exposure 'x' for option '-e'" pvalue -e x
expect "pvalue: bad size 'x' for option '-x'" pvalue -x x -y 3
expect "pvalue: missing value for option '-y'" pvalue -x 2 -y
expect "falsecolor: -n: bad number 'x'" falsecolor -n x
expect "falsecolor: -d: expected an integer, got '1.5'" falsecolor -d 1.5
expect "falsecolor: bad option 'foo'" falsecolor foo
for cmd in "gensky 3 21 12 -c -version" "gendaylit 3 21 12 -W 500 100 -version" \
           "genprism m n 3 0 0 1 0 0 1 -c -version" "genrev m n t t 4 -s -version" \
           "pvalue -h -version" "falsecolor -n 3 -version"; do
    rc=0; $RP_BIN/$cmd > "$tmp/out" 2> "$tmp/err" < /dev/null || rc=$?
    if [ "$rc" -ne 0 ] || [ "$(wc -l < "$tmp/out")" -ne 1 ] || [ -s "$tmp/err" ] ||
       ! grep -q '^RADIANCE 5\.4a ' "$tmp/out"; then
        echo "FAIL $cmd: rc=$rc, out: $(cat "$tmp/out"), err: $(cat "$tmp/err")"; fail=1
    fi
done
exit $fail
