#!/bin/bash
# Golden test: our oconv writes RADIANCE's octrees byte for byte. For each of the 14
# models of ../shared/radiance-tests (cases/NAME.files: the scene files in rad's order),
# our `oconv FILES` and `oconv -f FILES`, run in renders/ with RAYPATH=.:../lib, must have
# the SHA-256 of RADIANCE 5.4's octrees, which were made there with
#     mapfile -t files < ../cases/NAME.files
#     (exec -a oconv oconv "${files[@]}") > NAME.oct        # digest: first column
#     (exec -a oconv oconv -f "${files[@]}") > NAME.octf    # digest: second column
# (RADIANCE's binaries first on PATH, for its oconv and the generators the files run).
# inst.oct is the octree of RADIANCE's Makefile test `test-oconv` (`radcompare
# ref/inst.oct inst.oct`; rad -n inst.rif shows the oconv command), whose ref/inst.oct
# the shared folder lacks. Our generators (xform, genbox, ...) stand in for RADIANCE's.
set -u
. "$(dirname "$0")/lib/shared.sh"
require_shared radiance-tests/cases
BIN="${RP_BIN:?RP_BIN not set}"
SHARED="${RP_SHARED_DIR:?RP_SHARED_DIR not set}/radiance-tests"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

digests='
combined f4fad0d1e849635bc51062f20df8b401c662ae2cc91ff4389d8255def12cd04d 9abd763fbcf85bf935c817008a3ebec776df61f0deef4f3e9a23fde51f23d872
dielectric 1d8122add42255aac9204afa730ab5a9e2c8a6d3dd913c363f7e69c6f879ea28 dec1fd28fc00793e0a0169cb04cce1c26cc0f5af6c2c003f1910354030c06c18
glass 0709fb787440a8a367e846cbc63969185d9209304bc5be06ade9d1847062fc20 0e66027c473304f2704631702db1fe98953a24c76719fbc0b34168674d67f9e5
inst 54301af0ea1349f8a317cb30807214b6eb098422ea11a47f1ebe916238789241 76a8c5912c749df8b3d027ee0132271a235be0b9069bf33e9df8c8283ccef51a
mesh 78c8c8c305ff1c647f955b67a7b96cfac85796e6ac7210e7c1955ff7b576f587 e10ff566585a9f2d47d2ea475110ab168bd0ddb61d9b557f19f8839994f0e0c6
mirror 5370a096811c1f9fba611c1f49d5fd91dc8e07fe2044dcf72c6b8cffe9fee5bd c120f4745ba301b53a5b3f12c96124f023ba78c685b9f21f1ba791d9e0927303
mist 572fea1ccfed33b1d17efb24731e725132656a55ed905ebeba98e9673fe75d22 f0bb70cc07ffc9f0bc1fb09ad2e333316455531ca870c0831351915b44f9f249
mixtex 1f3ad550c53def3779dc83e9f6f668e261f0d44d3ba0b6184c5d72db6d7023fd e53dbf210c3fa501611f94a0be0272c78e2dadb969e34d6d2de540a3d797ea2e
patterns bf6a768700a5531704f9e54c1d9854806895c0410a285db9819cad925588dc7c 0a3686a4f8116168e8a9149009ae9391887fa312d436e40021ed81d18ff1c634
prism1 937d4f48fc0556cac6b715745bec082eaba00b26dc6aefdb06daec7111d9e4f5 0518f32233e8dda7aea72510af81d39a985bd51990486ed83527e4bb79eec200
prism2 7574197b81b1df365976fca632e156032e1bdb3e743580ae1276d9e5ef168219 8bcbc4861619d2da6d5d714fa3d4ba25d29b895ebbb83a248cd09c1b8f477238
tfunc e10a4c6bcc3c5375afe15fabbb24892740d9dc05af63070017be3bb4ae16c7be 6bc1e25f5dd26fb76be92e9787e9691a2d5badb7c3b514fadf65654efd69cdde
trans d7a9ae3ee8ccb75c9b9338b7bee6adcbc474e68d046ba5f49e38a34279a02290 6cc912b7e377df5b94c38acaf1d806d9f56ee79d232624e3ea2fe9a9f910fddc
trans2 a09b3d203a47f539b7b61f49ed3ad132086b4c3a8d018f88364ec2774206233e f6a80b4b328a72095a8ddc2b7b5b1aee23151a8cb21f3e88fc07d125cd88eee5
'

cd "$SHARED/renders" || exit 1
export RAYPATH=.:../lib
export PATH="$BIN:/usr/bin:/bin"
while read -r name named frozen; do
    [ -n "$name" ] || continue
    mapfile -t files < "../cases/$name.files"
    (exec -a oconv "$BIN/oconv" "${files[@]}") > "$tmp/$name.oct" 2> "$tmp/err" ||
        { echo "FAIL: $name: oconv: $(head -1 "$tmp/err")"; fail=1; continue; }
    got=$(sha256sum < "$tmp/$name.oct" | cut -c1-64)
    [ "$got" = "$named" ] || { echo "FAIL: $name: octree differs from RADIANCE's"; fail=1; }
    (exec -a oconv "$BIN/oconv" -f "${files[@]}") 2> /dev/null | sha256sum | cut -c1-64 > "$tmp/f"
    [ "$(cat "$tmp/f")" = "$frozen" ] || { echo "FAIL: $name: frozen octree differs from RADIANCE's"; fail=1; }
done <<< "$digests"
[ $fail -eq 0 ] && echo "oconv: 28 octrees identical to RADIANCE's"
exit $fail
