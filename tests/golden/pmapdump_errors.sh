#!/bin/bash
# Golden test for pmapdump on hand-made files (no other tool needed): a one-photon map of
# each type at the origin (exact scene / ASCII output, default colours, the zero-extent
# radius), per-map option reset, and the one-line errors with exit 1 and no output for a
# text file, a truncated map, a missing file, -c with -f, bad values and mixed -P.
set -u
DUMP="${RP_BIN:?RP_BIN not set}/pmapdump"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }
check() {  # name expected-file actual-file
    if ! diff -u "$2" "$3"; then
        bad "$1"
    fi
}

# RADIANCE "3.1k" map: header, version string, 8-byte photon count 1, then the fixed
# binary header (13 portable floats + 4-byte primary count) and one 27-byte photon record,
# all zero: one photon at the origin with zero flux.
onemap() {  # file type
    { printf '#?RADIANCE\nhand made\nFORMAT=Radiance_%s_kdT_Photon_Map\nVERSION=3.1k\n\n3.1k\0' "$2"
      printf '\0\0\0\0\0\0\0\1'
      head -c 96 /dev/zero; } > "$1"
}
for t in Global PreComp Caustic Volume Direct Contrib; do onemap "$t.pm" "$t"; done

# Scene output: RADIANCE's comment line, glow material with the default colour, one
# sphere of radius 0.05 * radscale (zero-extent map); the -r applies to the first map only.
cat > expect_scene <<EOF
# $DUMP -r 2 Global.pm Caustic.pm

void glow mat.global
0
0
4 0.25 0.25 2 0

mat.global sphere obj.global
0
0
4 0 0 0 0.1

# $DUMP -r 2 Global.pm Caustic.pm

void glow mat.caustic
0
0
4 1 0.1 0.1 0

mat.caustic sphere obj.caustic
0
0
4 0 0 0 0.05

EOF
"$DUMP" -r 2 Global.pm Caustic.pm > out_scene 2> err_scene || bad "scene exit $?: $(cat err_scene)"
check "scene output" expect_scene out_scene

# ASCII output, default colour per type; -c and -f only for the map they precede.
printf '0\t0\t0\t0.25\t0.25\t2\n0\t0\t0\t0.1\t1\t1\n0\t0\t0\t1\t0.1\t0.1\n0\t0\t0\t0.1\t1\t0.1\n0\t0\t0\t1\t0.1\t1\n0\t0\t0\t1\t1\t0.1\n0\t0\t0\t0.5\t0.5\t0.5\n0\t0\t0\t0\t0\t0\n0\t0\t0\t0.25\t0.25\t2\n' > expect_ascii
"$DUMP" -a Global.pm -a PreComp.pm -a Caustic.pm -a Volume.pm -a Direct.pm -a Contrib.pm \
    -a -c .5 .5 .5 Global.pm -a -f Global.pm -a Global.pm > out_ascii 2> err_ascii \
    || bad "ascii exit $?: $(cat err_ascii)"
check "ascii output" expect_ascii out_ascii

# PLY: header and one 15-byte vertex (0 0 0, colour 32 32 255).
"$DUMP" -P Global.pm > out.ply 2> err_ply || bad "ply exit $?: $(cat err_ply)"
head -n 2 out.ply | tr -d '\r' > ply_head
printf 'ply\nformat binary_little_endian 1.0\n' > expect_ply_head
check "ply header" expect_ply_head ply_head
grep -aq '^element vertex 1$' out.ply || bad "ply vertex count"
tail -c 3 out.ply | od -An -tu1 | tr -s ' ' > ply_rgb
echo ' 32 32 255' > expect_ply_rgb
check "ply colour" expect_ply_rgb ply_rgb

# Errors: exactly one line on stderr, exit 1, nothing on stdout (all maps are validated
# before anything is written, so the good Global.pm first produces no output either).
printf 'just some text\n' > notes.txt
printf '#?RADIANCE\nFORMAT=Radiance_Global_kdT_Photon_Map\nVERSION=3.1k\n\n3.1k\0\0\0\0\0\0\0\0\1\0\0\0' > cut.pm
expect_error() {  # expected-stderr args...
    local want="$1"
    shift
    "$DUMP" "$@" > out_e 2> err_e
    local st=$?
    [ "$st" -eq 1 ] || bad "exit $st (want 1) for: $*"
    [ -s out_e ] && bad "output written for: $*"
    [ "$(wc -l < err_e)" -eq 1 ] || bad "not one error line for: $*: $(cat err_e)"
    grep -qF -- "$want" err_e || bad "for: $*: want '$want', got '$(cat err_e)'"
}
expect_error "pmapdump: notes.txt: " Global.pm notes.txt
expect_error "pmapdump: cut.pm: truncated photon map" Global.pm cut.pm
expect_error "pmapdump: missing.pm: can't open" Global.pm missing.pm
expect_error "pmapdump: Global.pm: -c and -f are mutually exclusive" -c 1 0 0 -f Global.pm
expect_error "pmapdump: Global.pm: -c and -f are mutually exclusive" -f -c 1 0 0 Global.pm
expect_error "pmapdump: invalid number of points/spheres 'lots'" -n lots Global.pm
expect_error "pmapdump: invalid radius scale '-1'" -r -1 Global.pm
expect_error "pmapdump: unknown option -q" -q Global.pm
expect_error "pmapdump: options after the last photon map" Global.pm -n 5
expect_error "pmapdump: Caustic.pm: -P given for other photon maps" -P Global.pm Caustic.pm
"$DUMP" > /dev/null 2> err_usage && bad "exit 0 without arguments"
grep -q "Usage:" err_usage || bad "usage message"

exit $fail
