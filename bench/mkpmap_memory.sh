#!/usr/bin/env bash
# mkpmap's peak memory and time for large global maps: a 6 x 4 x 3 m room lit by gensky's
# sun and sky through one window (its glazing the photon port), -apg at 1e6, 2e7 and 2e8
# photons, the last with -aC so that the peak stays under 4 GiB (its photons beyond the
# budget spill to a temporary file and its kd-tree is built externally). Prints per run:
# wall time, peak RSS (/usr/bin/time -v), bytes per photon above a 1000-photon run's RSS,
# and the map file's size. Not run by scripts/test: the 2e8 run takes minutes and writes a
# 5.4 GB map (plus up to 10 GB of temporary files) to $OUT.
# Usage: [COUNTS="1m 20m 200m"] [AC=100m] [N=2] [OUT=dir] [MKPMAP=binary] \
#        bench/mkpmap_memory.sh [build dir]
# AC applies to counts of 100m and more; MKPMAP compares another build (e.g. an older one).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build}/tools
mkpmap=${MKPMAP:-$bin/mkpmap}
counts=${COUNTS:-1m 20m 200m}
ac=${AC:-100m}
threads=${N:-2}
out=${OUT:-$(mktemp -d)}
[ -n "${OUT:-}" ] || trap 'rm -rf "$out"' EXIT
mkdir -p "$out"

cat > "$out/room.rad" <<'RAD'
# 6 x 4 x 3 m room, window x 1.5..4.5, z 0.9..2.4 cut into the wall y = 0 (RADIANCE's
# seam convention), glazing as the photon port; sun and sky on 21 March, 11:00, Zurich.
!gensky 3 21 11 -a 47 -o -8 -m -15 +s
skyfunc glow sky_glow
0
0
4 1 1 1 0
sky_glow source sky
0
0
4 0 0 1 180
skyfunc glow ground_glow
0
0
4 1 1 1 0
ground_glow source ground
0
0
4 0 0 -1 180
void plastic wall_white
0
0
5 0.6 0.6 0.6 0 0
void plastic floor_grey
0
0
5 0.3 0.3 0.3 0 0
void glass window_glass
0
0
3 0.96 0.96 0.96
wall_white polygon wall_south
0
0
30
    0 0 0     0 0 3     6 0 3     6 0 0     0 0 0
    1.5 0 0.9   4.5 0 0.9   4.5 0 2.4   1.5 0 2.4   1.5 0 0.9
window_glass polygon window
0
0
12
    1.5 0 0.9   1.5 0 2.4   4.5 0 2.4   4.5 0 0.9
wall_white polygon wall_north
0
0
12
    0 4 0   6 4 0   6 4 3   0 4 3
wall_white polygon wall_west
0
0
12
    0 0 0   0 4 0   0 4 3   0 0 3
wall_white polygon wall_east
0
0
12
    6 0 0   6 0 3   6 4 3   6 4 0
floor_grey polygon floor
0
0
12
    0 0 0   6 0 0   6 4 0   0 4 0
wall_white polygon ceiling
0
0
12
    0 0 3   0 4 3   6 4 3   6 0 3
RAD

# Peak RSS in kB of one mkpmap run; its log in $out/log, the map in $out/g.pm.
run() {
    /usr/bin/time -v -o "$out/time" "$mkpmap" -fo "$@" -apo window_glass -n "$threads" \
        "$out/room.rad" > "$out/log" 2>&1 || { cat "$out/log"; exit 1; }
    awk -F': ' '/Maximum resident set size/ {print $2}' "$out/time"
}
wall() { awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$out/time" |
         awk -F: '{s = 0; for (i = 1; i <= NF; i++) s = s * 60 + $i; print s}'; }
# user + system CPU seconds: on a shared machine far steadier than wall time.
cpu() { awk -F': ' '/(User|System) time/ {s += $2} END {print s}' "$out/time"; }

base=$(run -apg "$out/g.pm" 1k)
echo "mkpmap: $mkpmap, -n $threads; 1000-photon run: $base kB peak"
printf "%-8s %-6s %9s %9s %10s %12s %10s %12s\n" target -aC "wall s" "cpu s" "peak MB" \
    "bytes/phot" "file MB" "stored"
for c in $counts; do
    opt=()
    n=$(awk -v c="$c" 'BEGIN { m = 1; u = tolower(substr(c, length(c)));
        if (u == "k") m = 1e3; else if (u == "m") m = 1e6; else if (u == "g") m = 1e9;
        printf "%.0f", (m == 1 ? c : substr(c, 1, length(c) - 1)) * m }')
    [ "$n" -ge 100000000 ] && opt=(-aC "$ac")
    peak=$(run "${opt[@]}" -apg "$out/g.pm" "$c")
    stored=$(awk '/Global photons stored/ {print $1}' "$out/log")
    size=$(stat -c %s "$out/g.pm")
    awk -v c="$c" -v ac="${opt[1]:--}" -v w="$(wall)" -v u="$(cpu)" -v p="$peak" -v b="$base" \
        -v s="$stored" -v f="$size" 'BEGIN { printf "%-8s %-6s %9.1f %9.1f %10.0f %12.1f %10.0f %12d\n",
        c, ac, w, u, p / 1024, (p - b) * 1024 / s, f / 1e6, s }'
    grep "photons emitted" "$out/log" | sed 's/^/         /'
done
