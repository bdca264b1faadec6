# Irradiance at points with Blender Cycles (tested with Blender 3.4.1, Debian package).
#
#   blender -b --factory-startup --python render_irradiance.py -- \
#       --rad room_open.rad [--rad slats_lambertian.rad] --mode total|direct \
#       --samples N --px P --reps R --seed-base B --out results.jsonl [--sensors 0-80] [--test-open]
#
# Scene: read from the RADIANCE files given with --rad (only `plastic` with zero specularity
# -> Lambertian Diffuse BSDF of that reflectance, `polygon`, `light` + `source` -> Sun lamp).
# Sensors: points.txt (80 lines x y z dx dy dz) + one ceiling point (2 2.5 2.999, facing down).
#
# Method per sensor: a 1 mm x 1 mm white (albedo 1) Lambertian square centred on the sensor,
# facing the sensor direction, visible ONLY to camera rays (casts no shadow, reflects nothing
# into the scene).  An orthographic camera 0.5 mm in front of it, ortho scale 0.5 mm, P x P
# pixels, all on the receiver.  Irradiance = pi * mean pixel radiance.  The render is written
# as a 32-bit float OpenEXR (scene-linear, independent of the view transform) and read back.
# Each repeat r of sensor i uses seed = seed_base + 1000*r + i.
# Output: one JSON line per (sensor, repeat) with the irradiance and the per-pixel values.

import bpy, math, sys, os, json, time, array, argparse
from mathutils import Vector

argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
ap = argparse.ArgumentParser()
ap.add_argument('--rad', action='append', default=[])
ap.add_argument('--points', default='../../../../shared/validation/bsdf/points.txt')
ap.add_argument('--mode', choices=['total', 'direct'], default='total')
ap.add_argument('--samples', type=int, default=256)
ap.add_argument('--px', type=int, default=8)
ap.add_argument('--reps', type=int, default=1)
ap.add_argument('--rep-start', type=int, default=0)
ap.add_argument('--seed-base', type=int, default=0)
ap.add_argument('--sensors', default='')
ap.add_argument('--out', required=True)
ap.add_argument('--tmp', default='/tmp/cycles_irr')
ap.add_argument('--test-open', action='store_true',
                help='sanity check: no room, one receiver in the open facing the sun')
args = ap.parse_args(argv)

RGBW = (0.265, 0.670, 0.065)  # RADIANCE luminance weights (the scene is grey anyway)

# ---------------------------------------------------------------- RADIANCE reader
def read_rad(path):
    toks = []
    with open(path) as f:
        for line in f:
            line = line.split('#', 1)[0]
            if line.strip().startswith('!'):
                raise ValueError('commands not supported: ' + line)
            toks += line.split()
    prims, i = [], 0
    while i < len(toks):
        mod, typ, name = toks[i:i + 3]; i += 3
        n = int(toks[i]); sargs = toks[i + 1:i + 1 + n]; i += 1 + n
        n = int(toks[i]); i += 1 + n  # integer args (always 0 here)
        n = int(toks[i]); rargs = [float(x) for x in toks[i + 1:i + 1 + n]]; i += 1 + n
        prims.append((mod, typ, name, sargs, rargs))
    return prims

materials, polygons, lights, sources = {}, [], {}, []
for p in args.rad:
    for mod, typ, name, s, r in read_rad(p):
        if typ == 'plastic':
            assert r[3] == 0 and r[4] == 0, 'only Lambertian plastic supported'
            materials[name] = r[:3]
        elif typ == 'light':
            lights[name] = r[:3]
        elif typ == 'polygon':
            polygons.append((mod, name, [tuple(r[k:k + 3]) for k in range(0, len(r), 3)]))
        elif typ == 'source':
            sources.append((mod, name, r))
        else:
            raise ValueError('unsupported type ' + typ)

# ---------------------------------------------------------------- sensors
sensors = []
with open(args.points) as f:
    for line in f:
        v = [float(x) for x in line.split()]
        if len(v) == 6:
            sensors.append(v)
sensors.append([2.0, 2.5, 2.999, 0.0, 0.0, -1.0])  # ceiling sensor
if args.test_open:
    sensors = []

# ---------------------------------------------------------------- scene
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
world = bpy.data.worlds.new('black')
world.use_nodes = True
bg = world.node_tree.nodes['Background']
bg.inputs['Color'].default_value = (0, 0, 0, 1)
bg.inputs['Strength'].default_value = 0.0
scene.world = world

def diffuse_material(name, rgb):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nt = m.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new('ShaderNodeOutputMaterial')
    d = nt.nodes.new('ShaderNodeBsdfDiffuse')
    d.inputs['Color'].default_value = (rgb[0], rgb[1], rgb[2], 1.0)
    d.inputs['Roughness'].default_value = 0.0  # Lambert
    nt.links.new(d.outputs['BSDF'], out.inputs['Surface'])
    return m

def add_mesh(name, verts, faces, mat):
    me = bpy.data.meshes.new(name)
    me.from_pydata([Vector(v) for v in verts], [], faces)
    me.update()
    me.materials.append(mat)
    ob = bpy.data.objects.new(name, me)
    scene.collection.objects.link(ob)
    return ob

mats = {k: diffuse_material(k, v) for k, v in materials.items()}
if not args.test_open:
    for mod, name, verts in polygons:
        add_mesh(name, verts, [list(range(len(verts)))], mats[mod])

# sun(s)
assert len(sources) == 1
mod, name, r = sources[0]
L = lights[mod][0]
dvec = Vector(r[:3]).normalized()           # direction toward the sun
half = math.radians(r[3]) / 2.0
omega = 2.0 * math.pi * 2.0 * math.sin(half / 2.0) ** 2   # 2 pi (1 - cos(half)), exact
E_sun = L * omega                            # normal irradiance, W/m2
ld = bpy.data.lights.new('sun', 'SUN')
ld.energy = E_sun                            # Cycles sun strength = irradiance W/m2
ld.angle = math.radians(r[3])
ld.cycles.cast_shadow = True
ld.cycles.use_multiple_importance_sampling = True
sun = bpy.data.objects.new('sun', ld)
scene.collection.objects.link(sun)
sun.rotation_mode = 'QUATERNION'
sun.rotation_quaternion = dvec.to_track_quat('Z', 'Y')  # lamp emits along its local -Z
print('SUN direction', tuple(dvec), 'omega', omega, 'E_sun', E_sun, 'cos_z', dvec.z)

if args.test_open:
    # one receiver in empty space facing the sun, and one tilted 60 degrees away
    n60 = (dvec.to_track_quat('Z', 'Y') @ Vector((math.sin(math.radians(60)), 0, math.cos(math.radians(60))))).normalized()
    sensors = [[0, 0, 0] + list(dvec), [1, 1, 1] + list(n60)]

# receivers (camera rays only)
white = diffuse_material('receiver_white', (1.0, 1.0, 1.0))
hs = 0.0005
for i, s in enumerate(sensors):
    n = Vector(s[3:]).normalized()
    q = n.to_track_quat('Z', 'Y')
    c = Vector(s[:3])
    verts = [c + q @ Vector((x, y, 0)) for x, y in ((-hs, -hs), (hs, -hs), (hs, hs), (-hs, hs))]
    ob = add_mesh('receiver%03d' % i, verts, [[0, 1, 2, 3]], white)
    ob.visible_camera = True
    ob.visible_diffuse = False
    ob.visible_glossy = False
    ob.visible_transmission = False
    ob.visible_volume_scatter = False
    ob.visible_shadow = False

cd = bpy.data.cameras.new('cam')
cd.type = 'ORTHO'
cd.ortho_scale = 0.0005
cd.clip_start = 1e-5
cd.clip_end = 0.01
cam = bpy.data.objects.new('cam', cd)
scene.collection.objects.link(cam)
scene.camera = cam
cam.rotation_mode = 'QUATERNION'

# ---------------------------------------------------------------- render settings
scene.render.engine = 'CYCLES'
cy = scene.cycles
cy.device = 'CPU'
cy.samples = args.samples
cy.use_adaptive_sampling = False
cy.use_denoising = False
cy.sample_clamp_direct = 0.0
cy.sample_clamp_indirect = 0.0
cy.blur_glossy = 0.0
cy.caustics_reflective = True
cy.caustics_refractive = True
cy.light_sampling_threshold = 0.0
cy.use_animated_seed = False
cy.use_auto_tile = False
if args.mode == 'total':
    cy.max_bounces = 64; cy.diffuse_bounces = 64
    cy.glossy_bounces = 64; cy.transmission_bounces = 64
else:  # direct only: light reaching the receiver straight from the sun
    cy.max_bounces = 0; cy.diffuse_bounces = 0
    cy.glossy_bounces = 0; cy.transmission_bounces = 0
cy.volume_bounces = 0
cy.transparent_max_bounces = 8
scene.render.resolution_x = args.px
scene.render.resolution_y = args.px
scene.render.resolution_percentage = 100
scene.render.film_transparent = False
scene.render.use_compositing = False
scene.render.use_sequencer = False
scene.display_settings.display_device = 'sRGB'
scene.view_settings.view_transform = 'Standard'
scene.view_settings.look = 'None'
scene.view_settings.exposure = 0.0
scene.view_settings.gamma = 1.0
scene.render.image_settings.file_format = 'OPEN_EXR'
scene.render.image_settings.color_depth = '32'
scene.render.image_settings.exr_codec = 'ZIP'
scene.render.image_settings.color_mode = 'RGBA'
os.makedirs(args.tmp, exist_ok=True)

if args.sensors:
    a, b = args.sensors.split('-')
    todo = range(int(a), int(b) + 1)
else:
    todo = range(len(sensors))

out = open(args.out, 'a')
t0 = time.time()
for rep in range(args.rep_start, args.rep_start + args.reps):
    for i in todo:
        s = sensors[i]
        n = Vector(s[3:]).normalized()
        cam.location = Vector(s[:3]) + 0.0005 * n
        cam.rotation_quaternion = (-n).to_track_quat('-Z', 'Y')  # camera looks along its -Z
        seed = args.seed_base + 1000 * rep + i
        cy.seed = seed
        fn = os.path.join(args.tmp, 'r_%d_%d.exr' % (os.getpid(), i))
        scene.render.filepath = fn
        t1 = time.time()
        bpy.ops.render.render(write_still=True)
        img = bpy.data.images.load(fn)
        npx = img.size[0] * img.size[1]
        buf = array.array('f', [0.0]) * (npx * 4)
        img.pixels.foreach_get(buf)
        bpy.data.images.remove(img)
        os.remove(fn)
        pix = [math.pi * (RGBW[0] * buf[4 * k] + RGBW[1] * buf[4 * k + 1] + RGBW[2] * buf[4 * k + 2])
               for k in range(npx)]
        E = sum(pix) / npx
        rec = dict(sensor=i, rep=rep, seed=seed, mode=args.mode, samples=args.samples, px=args.px,
                   E=E, pix=pix, rgb0=[buf[0], buf[1], buf[2]], secs=time.time() - t1)
        out.write(json.dumps(rec) + '\n'); out.flush()
        print('SENSOR %d rep %d E %.6g (%.2fs)' % (i, rep, E, time.time() - t1), flush=True)
print('TOTAL_SECONDS %.1f' % (time.time() - t0))
