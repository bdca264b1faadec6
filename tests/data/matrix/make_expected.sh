#!/usr/bin/env bash
# Regenerates expected/<name>.out for every line of cases.txt with RADIANCE 5.4's tools:
#   bash make_expected.sh /tmp/rad/build/bin
# (run in this folder; RAYPATH must reach RADIANCE's lib for genskyvec/gendaymtx only,
# which made genskyvec.mtx and daymtx.mtx, see README.md). The golden test
# tests/golden/matrix_tools.sh replays the same lines with our tools.
set -euo pipefail
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cp "$here"/*.mtx "$here"/*.fmx "$here"/*.dmx "$here"/*.hdr "$here"/*.txt "$here"/*.flt "$work"/
gzip -dc "$here/rfmirror.mtx.gz" > "$work/rfmirror.mtx"
mkdir -p "$here/expected"
cd "$work"
# test/util's test.mtx, as its Makefile makes it (RADIANCE 5.4 has rcollate -c too).
PATH="$bin:$PATH" rcollate -t rfmirror.mtx > test.mtx
while IFS='|' read -r name mode stdin cmd; do
    PATH="$bin:$PATH" eval "$cmd" < "${stdin:-/dev/null}" > "$here/expected/$name.out" 2> /dev/null ||
        echo "$name: exit status $?" >&2
done < "$here/cases.txt"
# The two large outputs are stored compressed.
gzip -9 -n -f "$here/expected/rcollate_radiance_test.out" "$here/expected/rmtxop_radiance_test.out"
