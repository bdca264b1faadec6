# Floor irradiance per channel in a room lit by a ceiling lamp through a coloured pane,
# Cycles path tracing (tests/data/coloured_glass/README.md). Room 4x4x3 Lambertian 0.6 (inward), lamp 0.8 m square at z 2.99
# emitting downward only, pane 1.6 m square at z 2.2 as a 1 cm slab: transparent surfaces
# (no refraction, no reflection: RADIANCE glass with index ~1) and homogeneous absorption
# giving transmissivity (tr, tg, tb) straight through, d^(1/cos) obliquely.
import bpy, math, sys, os, json, time, array, argparse
from mathutils import Vector
argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
ap = argparse.ArgumentParser()
ap.add_argument('--trans', default='0.1,0.9,0.1')
ap.add_argument('--samples', type=int, default=1024)
ap.add_argument('--px', type=int, default=6)
ap.add_argument('--points', required=True)
ap.add_argument('--out', required=True)
ap.add_argument('--seed', type=int, default=0)
ap.add_argument('--filter', action='store_true',
                help='the pane as a thin filter of angle-independent transmission')
args = ap.parse_args(argv)
tr = [float(x) for x in args.trans.split(',')]
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
world = bpy.data.worlds.new('black'); world.use_nodes = True
world.node_tree.nodes['Background'].inputs['Strength'].default_value = 0.0
scene.world = world

def material(name):
    m = bpy.data.materials.new(name); m.use_nodes = True
    nt = m.node_tree
    for n in list(nt.nodes): nt.nodes.remove(n)
    return m, nt, nt.nodes.new('ShaderNodeOutputMaterial')

def diffuse(name, rgb):
    m, nt, out = material(name)
    d = nt.nodes.new('ShaderNodeBsdfDiffuse')
    d.inputs['Color'].default_value = (rgb[0], rgb[1], rgb[2], 1); d.inputs['Roughness'].default_value = 0
    nt.links.new(d.outputs['BSDF'], out.inputs['Surface']); return m

def add_mesh(name, verts, faces, mat):
    me = bpy.data.meshes.new(name); me.from_pydata([Vector(v) for v in verts], [], faces); me.update()
    me.materials.append(mat); ob = bpy.data.objects.new(name, me); scene.collection.objects.link(ob); return ob

wall = diffuse('wall', (0.6, 0.6, 0.6))
# room: faces with normals inward
V = [(0,0,0),(4,0,0),(4,4,0),(0,4,0),(0,0,3),(4,0,3),(4,4,3),(0,4,3)]
F = [[0,1,2,3],[4,7,6,5],[0,4,5,1],[1,5,6,2],[2,6,7,3],[3,7,4,0]]
add_mesh('room', V, F, wall)
# lamp: emission towards -z only (backfacing black); strength chosen so radiance = 1 (units cancel)
m, nt, out = material('lamp')
em = nt.nodes.new('ShaderNodeEmission'); em.inputs['Strength'].default_value = 1.0
geo = nt.nodes.new('ShaderNodeNewGeometry'); mix = nt.nodes.new('ShaderNodeMixShader')
tp = nt.nodes.new('ShaderNodeBsdfTransparent'); tp.inputs['Color'].default_value = (0, 0, 0, 1)
nt.links.new(geo.outputs['Backfacing'], mix.inputs['Fac'])
nt.links.new(em.outputs['Emission'], mix.inputs[1]); nt.links.new(tp.outputs['BSDF'], mix.inputs[2])
nt.links.new(mix.outputs['Shader'], out.inputs['Surface'])
add_mesh('lamp', [(1.6,1.6,2.99),(2.4,1.6,2.99),(2.4,2.4,2.99),(1.6,2.4,2.99)], [[0,3,2,1]], m)
if args.filter:
    # A thin filter: RADIANCE glass of index ~1 whose colour comes from a pattern passes
    # light by that colour at every angle.
    m, nt, out = material('pane')
    tb = nt.nodes.new('ShaderNodeBsdfTransparent')
    tb.inputs['Color'].default_value = (tr[0], tr[1], tr[2], 1)
    nt.links.new(tb.outputs['BSDF'], out.inputs['Surface'])
    add_mesh('pane', [(1.2,1.2,2.2),(2.8,1.2,2.2),(2.8,2.8,2.2),(1.2,2.8,2.2)], [[0,1,2,3]], m)
else:
    # pane slab
    t = 0.01
    m, nt, out = material('pane')
    tb = nt.nodes.new('ShaderNodeBsdfTransparent'); tb.inputs['Color'].default_value = (1, 1, 1, 1)
    nt.links.new(tb.outputs['BSDF'], out.inputs['Surface'])
    sig = [-math.log(x) / t for x in tr]; D = max(sig)
    va = nt.nodes.new('ShaderNodeVolumeAbsorption')
    va.inputs['Color'].default_value = (1 - sig[0] / D, 1 - sig[1] / D, 1 - sig[2] / D, 1)
    va.inputs['Density'].default_value = D
    nt.links.new(va.outputs['Volume'], out.inputs['Volume'])
    z0, z1 = 2.2 - t / 2, 2.2 + t / 2
    PV = [(1.2,1.2,z0),(2.8,1.2,z0),(2.8,2.8,z0),(1.2,2.8,z0),(1.2,1.2,z1),(2.8,1.2,z1),(2.8,2.8,z1),(1.2,2.8,z1)]
    PF = [[0,3,2,1],[4,5,6,7],[0,1,5,4],[1,2,6,5],[2,3,7,6],[3,0,4,7]]  # outward
    add_mesh('pane', PV, PF, m)

sensors = [[float(x) for x in l.split()] for l in open(args.points) if l.strip()]
white = diffuse('receiver', (1, 1, 1)); hs = 0.0005
for i, s in enumerate(sensors):
    n = Vector(s[3:]).normalized(); q = n.to_track_quat('Z', 'Y'); c = Vector(s[:3])
    verts = [c + q @ Vector((x, y, 0)) for x, y in ((-hs,-hs),(hs,-hs),(hs,hs),(-hs,hs))]
    ob = add_mesh('rcv%03d' % i, verts, [[0,1,2,3]], white)
    ob.visible_camera = True
    for a in ('visible_diffuse','visible_glossy','visible_transmission','visible_volume_scatter','visible_shadow'):
        setattr(ob, a, False)
cd = bpy.data.cameras.new('cam'); cd.type = 'ORTHO'; cd.ortho_scale = 0.0005; cd.clip_start = 1e-5; cd.clip_end = 0.01
cam = bpy.data.objects.new('cam', cd); scene.collection.objects.link(cam); scene.camera = cam
cam.rotation_mode = 'QUATERNION'
scene.render.engine = 'CYCLES'; cy = scene.cycles; cy.device = 'CPU'; cy.samples = args.samples
cy.use_adaptive_sampling = False; cy.use_denoising = False
cy.sample_clamp_direct = 0.0; cy.sample_clamp_indirect = 0.0
cy.max_bounces = 32; cy.diffuse_bounces = 32; cy.glossy_bounces = 32; cy.transmission_bounces = 32
cy.volume_bounces = 0; cy.transparent_max_bounces = 32
cy.caustics_reflective = True; cy.caustics_refractive = True
scene.render.resolution_x = args.px; scene.render.resolution_y = args.px; scene.render.resolution_percentage = 100
scene.view_settings.view_transform = 'Standard'; scene.view_settings.look = 'None'
scene.render.image_settings.file_format = 'OPEN_EXR'; scene.render.image_settings.color_depth = '32'
out = open(args.out, 'a')
for i, s in enumerate(sensors):
    n = Vector(s[3:]).normalized()
    cam.location = Vector(s[:3]) + 0.0005 * n
    cam.rotation_quaternion = (-n).to_track_quat('-Z', 'Y')
    cy.seed = args.seed * 1000 + i
    fn = '/tmp/cyc/r_%d_%d.exr' % (os.getpid(), i); scene.render.filepath = fn
    t1 = time.time(); bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(fn); npx = img.size[0] * img.size[1]
    buf = array.array('f', [0.0]) * (npx * 4); img.pixels.foreach_get(buf)
    bpy.data.images.remove(img); os.remove(fn)
    rgb = [math.pi * sum(buf[4 * k + c] for k in range(npx)) / npx for c in range(3)]
    out.write(json.dumps(dict(sensor=i, rgb=rgb, secs=time.time() - t1)) + '\n'); out.flush()
    print('SENSOR', i, rgb, '%.1fs' % (time.time() - t1), flush=True)
