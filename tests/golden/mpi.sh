#!/bin/bash
# The MPI tools (tools/mpi/, cmake -DRP_MPI=ON) under mpirun with 1, 2 and 3 ranks on
# this machine (oversubscribed): photon maps, rtrace, rcontrib and rpict outputs the same
# bit for bit as the tools without MPI; a rank killed mid-run fails the run with mpirun's
# message and leaves no map; an error every rank meets is reported once; a request MPI
# cannot split is refused. Skipped (77) when the build has no MPI tools.
set -u
BIN="${RP_BIN:?RP_BIN not set}"
SRC="${RP_SOURCE_DIR:?RP_SOURCE_DIR not set}"
[ -x "$BIN/mpi/mkpmap" ] && command -v mpirun > /dev/null || { echo "no MPI tools: skipped"; exit 77; }
SCENE="$SRC/examples/cornell/scene.rad"
POINTS="$SRC/examples/cornell/points.txt"
VIEW=$(sed 's/^rview//' "$SRC/examples/cornell/view.vf")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }

# Containers often forbid the cross-memory attach Open MPI's shared memory uses.
export OMPI_MCA_btl_vader_single_copy_mechanism=none
runas=()
[ "$(id -u)" -eq 0 ] && runas=(--allow-run-as-root)
mpi() {  # ranks tool args...: the MPI build of tool, started by name so that the
    local n=$1; shift  # header's command line matches the plain tool's
    PATH="$BIN/mpi:$PATH" mpirun "${runas[@]}" --oversubscribe -n "$n" "$@"
}
plain() { PATH="$BIN:$PATH" "$@"; }
pixels() { sed '1,/^$/d' "$1" | od -An -tx1 | md5sum; }  # after the header (dates)

# mkpmap: global + caustic, a contribution map and a precomputed one; the whole files
# identical (each run in a folder of its own, so that the command lines in the headers
# are the same).
MK=(-apg g.pm 40k -apc c.pm 15k -apr 3 -n 2 "$SCENE")
plain mkpmap "${MK[@]}" 2> log || bad "mkpmap: $(cat log)"
plain mkpmap -apC k.pm 20k -apr 3 -n 2 "$SCENE" 2> log || bad "mkpmap -apC: $(cat log)"
# A precomputed contribution map (bins by direction), its bins beside it.
PC=(-apC p.pm 20k 40 0.5 -apr 3 -b "if(Dz,0,1)" -bn 2 -m ceiling_light -n 2 "$SCENE")
plain mkpmap "${PC[@]}" 2> log || bad "mkpmap -apC precomputed: $(cat log)"
for n in 1 2 3; do
    mkdir r$n && cd r$n || exit 1
    mpi $n mkpmap "${MK[@]}" 2> log || bad "mpirun -n $n mkpmap: $(cat log)"
    cmp -s ../g.pm g.pm || bad "$n ranks: global map differs"
    cmp -s ../c.pm c.pm || bad "$n ranks: caustic map differs"
    mpi $n mkpmap -apC k.pm 20k -apr 3 -n 2 "$SCENE" 2> /dev/null || bad "mpirun -n $n mkpmap -apC"
    cmp -s ../k.pm k.pm || bad "$n ranks: contribution map differs"
    mpi $n mkpmap "${PC[@]}" 2> /dev/null || bad "mpirun -n $n mkpmap -apC (precomputed)"
    cmp -s ../p.pm p.pm || bad "$n ranks: precomputed contribution map differs"
    cmp -s ../p.pm.rc/ceiling_light.rc p.pm.rc/ceiling_light.rc ||
        bad "$n ranks: precomputed contributions differ"
    cd .. && rm -rf r$n
done
# A spectral map set (mkpmap -cs 7: three files, one per pass of three bands), the same
# files from 2 ranks.
plain mkpmap -cs 7 -apg s.pm 20k -n 2 "$SCENE" 2> log || bad "mkpmap -cs 7: $(cat log)"
mkdir rs && cd rs || exit 1
mpi 2 mkpmap -cs 7 -apg s.pm 20k -n 2 "$SCENE" 2> log || bad "mpirun -n 2 mkpmap -cs 7: $(cat log)"
for f in s.pm s.pm.3-5 s.pm.6-6; do cmp -s ../$f $f || bad "2 ranks: spectral map file $f differs"; done
cd .. && rm -rf rs
# And the same photons as one thread without MPI.
plain mkpmap -apg g1.pm 40k -apc c1.pm 15k -apr 3 "$SCENE" 2> /dev/null
[ "$(pixels g.pm)" = "$(pixels g1.pm)" ] || bad "global map differs from one thread's"

# rtrace, rcontrib (contribution map, and classic with -c), rpict with -z.
RT=(-h -u- -ab 1 -aa 0 -ad 64 -ap g.pm 50 -ap c.pm 20)
plain rtrace "${RT[@]}" -n 2 "$SCENE" < "$POINTS" > rt 2> log || bad "rtrace: $(cat log)"
[ "$(wc -l < rt)" -eq 103 ] || bad "rtrace: $(wc -l < rt) lines"
RC=(-h -u- -ap k.pm 50 -m ceiling_light -I)
plain rcontrib "${RC[@]}" -n 2 "$SCENE" < "$POINTS" > rc 2> log || bad "rcontrib -ap: $(cat log)"
RCC=(-h -u- -c 4 -ab 1 -ad 32 -lw 1e-3 -m ceiling_light)
plain rcontrib "${RCC[@]}" -n 2 "$SCENE" < "$POINTS" > rcc 2> /dev/null || bad "rcontrib -c 4"
RP=(-u- -x 96 -y 96 -ps 4 -ab 1 -aa 0 -ad 32 -ap g.pm 50 $VIEW)
plain rpict "${RP[@]}" -z z "$SCENE" > pic 2> log || bad "rpict: $(cat log)"
for n in 2 3; do
    mpi $n rtrace "${RT[@]}" "$SCENE" < "$POINTS" > rt$n 2> log || bad "mpirun -n $n rtrace: $(cat log)"
    cmp -s rt rt$n || bad "$n ranks: rtrace output differs"
    mpi $n rcontrib "${RC[@]}" "$SCENE" < "$POINTS" > rc$n 2> log || bad "mpirun -n $n rcontrib: $(cat log)"
    cmp -s rc rc$n || bad "$n ranks: rcontrib -ap output differs"
    mpi $n rcontrib "${RCC[@]}" "$SCENE" < "$POINTS" > rcc$n 2> /dev/null || bad "mpirun -n $n rcontrib -c"
    cmp -s rcc rcc$n || bad "$n ranks: rcontrib -c 4 output differs"
    mpi $n rpict "${RP[@]}" -z z$n "$SCENE" > pic$n 2> log || bad "mpirun -n $n rpict: $(cat log)"
    [ "$(pixels pic)" = "$(pixels pic$n)" ] || bad "$n ranks: rpict pixels differ"
    cmp -s z z$n || bad "$n ranks: rpict -z depths differ"
done
[ -s pic ] && [ "$(stat -c %s z)" -eq $((96 * 96 * 4)) ] || bad "rpict outputs missing"

# A rank killed while tracing: the run fails, mpirun names the rank, no map is left
# (nor any temporary file).
mkdir killed && cd killed || exit 1
PATH="$BIN/mpi:$PATH" mpirun "${runas[@]}" --oversubscribe -n 2 sh -c \
    'if [ "$OMPI_COMM_WORLD_RANK" = 1 ]; then (sleep 0.3; kill -9 $$) & fi
     exec mkpmap -apg big.pm 10m -apr 1 "$0"' "$SCENE" > out 2> err
st=$?
[ $st -ne 0 ] || bad "killed rank: exit 0"
grep -q "rank 1 .*signal 9" err || bad "killed rank: no message naming it: $(cat err)"
[ "$(ls -A | grep -v '^out$\|^err$')" = "" ] || bad "killed rank left files: $(ls -A)"
cd .. || exit 1

# An error every rank meets is said once, by the root; the exit status is 1.
mpi 3 rtrace -h missing.rad < /dev/null > out 2> err
st=$?
[ $st -eq 1 ] || bad "missing scene: exit $st"
[ "$(grep -c '^rtrace' err)" -eq 1 ] || bad "missing scene: $(grep -c '^rtrace' err) messages: $(cat err)"
# Sequences decide per frame from files only the root sees: refused across ranks.
echo "-vp 1 1 1" | mpi 2 rpict -S 1 -x 8 -y 8 -o f%d.hdr "$SCENE" > /dev/null 2> err
grep -q "^rpict: -S and -r render in one process" err || bad "rpict -S: $(cat err)"
exit $fail
