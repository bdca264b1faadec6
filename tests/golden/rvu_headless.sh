#!/usr/bin/env bash
# rvu driven headless through its web interface, as the page drives it: it prints a
# loopback address with a token, refuses requests without the token or from another
# site, takes commands (a view change, exposure, write, a malformed one), and once
# refined with -ps 1 its written picture has rpict's pixels for the same view and
# options (photon maps included). quit and SIGTERM end it with status 0.
set -euo pipefail
tmp=$(mktemp -d)
pid=
cleanup() { [ -n "$pid" ] && kill "$pid" 2>/dev/null; rm -rf "$tmp"; }
trap cleanup EXIT
command -v curl > /dev/null || { echo "rvu headless: curl missing"; exit 77; }
cd "$RP_SOURCE_DIR/examples/cornell"
"$RP_BIN/mkpmap" -apg "$tmp/g.pm" 20k -apc "$tmp/c.pm" 20k scene.rad 2> /dev/null
# The same rendering options for both programs (rvu's defaults are not rpict's); -aa 0:
# no irradiance cache, whose records would depend on the order pixels are traced in;
# -u-: rvu samples uncorrelated by default, as RADIANCE's.
opts="-u- -dt .1 -dc .25 -dr 0 -dp 128 -ds 0 -st .3 -ss 1 -lr 6 -lw .01 -aa 0 -ad 64 -as 0
      -ap $tmp/g.pm 50 -ap $tmp/c.pm 50 -vf view.vf -x 80 -y 80 -ps 1"

start_rvu() {  # extra options
    "$RP_BIN/rvu" $opts "$@" scene.rad 2> "$tmp/err" &
    pid=$!
    for _ in $(seq 300); do grep -q "rvu: open http" "$tmp/err" && break; sleep 0.1; done
    url=$(grep -o 'http://127\.0\.0\.1:[0-9]*/?t=[0-9a-f]*' "$tmp/err")
    base=${url%%/\?t=*}; token=${url##*t=}; port=${base##*:}
    [ ${#token} -eq 32 ]
}
get() { curl -s -H "X-Rvu-Token: $token" "$base$1"; }
code() { curl -s -o /dev/null -w "%{http_code}" "$@"; }
cmd() { curl -s -H "X-Rvu-Token: $token" --data-binary "$1" "$base/command${2:-}"; }
wait_done() {
    for _ in $(seq 600); do get "/state" | grep -q '"done":true' && return 0; sleep 0.1; done
    echo "rvu never finished refining"; exit 1
}

start_rvu
# Who may ask: the token holder, naming this server, from its own page.
[ "$(code "$base/")" = 403 ]
[ "$(code "$base/?t=0$token")" = 403 ]
[ "$(code "$base/?t=$token")" = 200 ]
[ "$(code -H "X-Rvu-Token: $token" "$base/state")" = 200 ]
[ "$(code -H "X-Rvu-Token: $token" -H "Origin: http://evil.example" "$base/state")" = 403 ]
[ "$(code -H "X-Rvu-Token: $token" -H "Host: evil.example:$port" "$base/state")" = 403 ]
[ "$(code -H "Origin: http://127.0.0.1:$port" --data-binary quit "$base/command")" = 403 ]
# Malformed commands get an error and rvu goes on.
[ "$(cmd "aim zz")" = '{"ok":false,"error":"aim: bad number '"'"'zz'"'"' for magnification"}' ]
[ "$(cmd "frobnicate")" = '{"ok":false,"error":"frobnicate: unknown command"}' ]
[ "$(cmd "aim 2" "?cursor=1,x")" = '{"ok":false,"error":"bad cursor position \"1,x\""}' ]
[ "$(cmd "move")" = '{"ok":false,"pick":"Pick view center","points":1}' ]
# A new view point, then the picture at exposure 1 and 2.
[ "$(cmd "view -vp 2.75 0.5 2.75")" = '{"ok":true,"output":""}' ]
wait_done
cmd "write $tmp/a.hdr" | grep -q '"ok":true'
[ "$(cmd "exposure =+1")" = '{"ok":true,"output":"exposure 2"}' ]
cmd "write $tmp/b.hdr" | grep -q '"ok":true'
get "/picture.png" > "$tmp/shown.png"
[ "$(head -c 4 "$tmp/shown.png" | tail -c 3)" = PNG ]
[ "$(cmd quit)" = '{"ok":true,"output":"","quit":true}' ]
wait "$pid"; pid=   # status 0, or set -e ends the test

# rpict with the same view and options: the same pixels (headers differ).
"$RP_BIN/rpict" $opts -vp 2.75 0.5 2.75 scene.rad > "$tmp/r.hdr" 2> /dev/null
sed '1,/^$/d' "$tmp/a.hdr" > "$tmp/a.pix"; sed '1,/^$/d' "$tmp/r.hdr" > "$tmp/r.pix"
cmp "$tmp/a.pix" "$tmp/r.pix"
head -c 200 "$tmp/a.hdr" | grep -a -q "^rvu -vtv -vp 2.75 0.5 2.75 "
# The exposed picture: EXPOSURE=2 recorded, values doubled (to RGBE's precision).
grep -a -q "^EXPOSURE=2" "$tmp/b.hdr"
paste <("$RP_BIN/pvalue" -h -H -d -b "$tmp/a.hdr") <("$RP_BIN/pvalue" -h -H -d -b "$tmp/b.hdr") |
    awk '{ if ($1 > 0 && ($2 / $1 < 1.98 || $2 / $1 > 2.02)) bad++ } END { exit bad > 0 }'

# -o web:PORT listens there (the port just freed); SIGTERM ends it as quit does.
last=$port
start_rvu -o "web:$last"
[ "$port" = "$last" ]
# A second rvu cannot take the port while the first has it.
if "$RP_BIN/rvu" -o "web:$last" scene.rad 2> "$tmp/err2"; then exit 1; fi
[ "$(cat "$tmp/err2")" = "rvu: cannot listen on 127.0.0.1:$last" ]
kill -TERM "$pid"; wait "$pid"; pid=
echo "rvu headless: ok"
