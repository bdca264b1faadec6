#!/usr/bin/env bash
# Mesh and instance benchmark scenes (not run by tests; see bench/README_mesh.md).
# Usage: [N_BIG=2237] [N_SMALL=224] bench/mesh_scenes.sh [scratch dir] [build dir]
# Generates, into the scratch dir (default /tmp/rp_bench_mesh):
#   big.obj/big.rtm/big.oct      N_BIG^2 grid heightfield (2237 -> ~10 M triangles) + sun + sky
#   tiny.rtm/tiny.oct            the same scene with a 968-triangle mesh (memory baseline)
#   small.rtm/chair.oct          N_SMALL^2 grid (224 -> ~100 k triangles) frozen in an octree
#   inst.oct                     chair.oct placed 1000 times (40x25 grid, rotated) + sun + sky
#   one.oct                      chair.oct placed once (memory baseline for inst.oct)
#   big.rays / inst.rays         200 k rays from above the surface, random downward directions
#   bigroom.oct / instroom.oct   big / inst closed in a room with four lamps (for mkpmap:
#                                the open scenes let reflected photons escape)
# All with radphoton's tools (build/tools). For a comparison with another implementation,
# run its oconv on the same .rtm files and .rad scenes in a directory of its own (its
# instances need a chair.oct from its own `oconv -f chair.rad`): see bench/README_mesh.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:-/tmp/rp_bench_mesh}
bin=${2:-$root/build}/tools
nbig=${N_BIG:-2237}
nsmall=${N_SMALL:-224}
nrays=${N_RAYS:-200000}
mkdir -p "$dir"
cd "$dir"
T() { /usr/bin/time -f "  $1: %e s %M kB" "${@:2}"; }

cat > mat.rad <<'RAD'
void plastic wavy 0 0 5 .6 .55 .5 .02 .05
RAD
cat > sky.rad <<'RAD'
void light sun 0 0 3 1e6 1e6 1e6
sun source s 0 0 4 .3 .2 1 .5
void glow skyglow 0 0 4 .5 .6 .8 0
skyglow source sky 0 0 4 0 0 1 180
RAD

mesh() {  # mesh N name
    python3 "$root/bench/gen_mesh_obj.py" "$1" 100 "$2.obj"
    T "obj2mesh $2 ($1^2 grid)" "$bin/obj2mesh" -a mat.rad "$2.obj" "$2.rtm"
}
[ -s big.rtm ] || mesh "$nbig" big
[ -s small.rtm ] || mesh "$nsmall" small
[ -s tiny.rtm ] || mesh 23 tiny

printf 'void mesh big 1 big.rtm 0 0\n' > big.rad
printf 'void mesh big 1 tiny.rtm 0 0\n' > tiny.rad
printf 'void mesh m 1 small.rtm 0 0\n' > chair.rad
python3 - <<'PY'
import math
with open("inst.rad", "w") as f:
    k = 0
    for j in range(25):
        for i in range(40):
            ang = (37 * k) % 360
            f.write("void instance c_%d 7 chair.oct -rz %d -t %g %g 0 0 0\n"
                    % (k, ang, (i - 19.5) * 150.0, (j - 12) * 150.0, ))
            k += 1
with open("one.rad", "w") as f:
    f.write("void instance c_0 7 chair.oct -rz 0 -t 0 0 0 0 0\n")
PY
python3 - "$nrays" <<'PY'
import math, random, sys
n = int(sys.argv[1])
def rays(name, hx, hy, seed):
    r = random.Random(seed)
    with open(name, "w") as f:
        out = []
        for _ in range(n):
            x, y, z = r.uniform(-hx, hx), r.uniform(-hy, hy), r.uniform(1, 20)
            # uniform over the part of the lower hemisphere at least ~17 deg below
            # the horizon (most rays hit the surface, few graze it)
            dz = -r.uniform(0.3, 1.0)
            phi = r.uniform(0, 2 * math.pi)
            s = math.sqrt(max(0.0, 1 - dz * dz))
            out.append("%.4f %.4f %.4f %.6f %.6f %.6f\n"
                       % (x, y, z, s * math.cos(phi), s * math.sin(phi), dz))
        f.write("".join(out))
rays("big.rays", 45, 45, 1)
rays("inst.rays", 40 * 75, 25 * 75, 2)
PY

T "oconv big" "$bin/oconv" sky.rad big.rad > big.oct
T "oconv tiny" "$bin/oconv" sky.rad tiny.rad > tiny.oct
T "oconv chair" "$bin/oconv" -f chair.rad > chair.oct
T "oconv inst" "$bin/oconv" sky.rad inst.rad > inst.oct
T "oconv one" "$bin/oconv" sky.rad one.rad > one.oct

# Closed rooms with four lamps around the big mesh and around the 1000 instances.
room() {  # room NAME X Y Z LAMP_RADIANCE LAMP_RADIUS LAMP_X LAMP_Y LAMP_Z
    cat > "$1.rad" <<RAD
void plastic wall 0 0 5 .5 .5 .5 0 0
!genbox wall room $2 $3 $4 -i | xform -t -$(( $2 / 2 )) -$(( $3 / 2 )) -5
void light lamp 0 0 3 $5 $5 $5
lamp sphere l1 0 0 4 -$7 -$8 $9 $6
lamp sphere l2 0 0 4 $7 -$8 $9 $6
lamp sphere l3 0 0 4 -$7 $8 $9 $6
lamp sphere l4 0 0 4 $7 $8 $9 $6
RAD
}
room room 110 110 25 2e4 .5 20 20 15
room instroom 6200 4000 60 2e6 2 1500 1000 45
PATH="$bin:$PATH" T "oconv bigroom" "$bin/oconv" room.rad big.rad > bigroom.oct
PATH="$bin:$PATH" T "oconv instroom" "$bin/oconv" instroom.rad inst.rad > instroom.oct

ls -l "$dir"
