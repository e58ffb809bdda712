#!/usr/bin/env python3
"""Regenerates the authored content scenes in content/scenes/ (run from anywhere).

Each scene is plain glTF 2.0 plus the NIMBUS_participating_media extension; the files are the
source of truth and are committed, this script only records how they were authored.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from gltf_builder import Builder, ellipsoid_blob  # noqa: E402

OUT = os.path.join(os.path.dirname(__file__), "..", "..", "content", "scenes")

# Water clouds absorb almost nothing in the visible and scatter strongly forwards (Mie scattering
# by droplets of ~10 um: g 0.85-0.9); the clouds below take those values.
WATER_CLOUD_ALBEDO = [0.999, 0.999, 0.999]
WATER_CLOUD_G = 0.85


# -- procedural textures (sRGB bytes; tools/scenegen writes them as PNG beside the scene) ---------


def _hash(*values):
    """A repeatable pseudo-random number in [0, 1) from integers (no global random state)."""
    h = 2166136261
    for v in values:
        h = ((h ^ (v & 0xFFFFFFFF)) * 16777619) & 0xFFFFFFFF
    return h / 4294967296.0


def paving(x, y):
    """64×64: 4×4 stone slabs with grout, each slab its own shade."""
    tx, ty = x // 16, y // 16
    if x % 16 in (0, 15) or y % 16 in (0, 15):
        return (118, 112, 104, 255)
    shade = 0.88 + 0.24 * _hash(tx, ty) + 0.04 * (_hash(x, y, 7) - 0.5)
    return (186 * shade, 178 * shade, 166 * shade, 255)


def bricks(x, y):
    """64×64: 8 courses of running-bond bricks in mortar."""
    course = y // 8
    shift = 8 if course % 2 else 0
    bx = (x + shift) // 16
    if y % 8 == 7 or (x + shift) % 16 == 15:
        return (196, 188, 172, 255)
    shade = 0.85 + 0.3 * _hash(bx, course)
    return (168 * shade, 66 * shade, 48 * shade, 255)


def facade(x, y):
    """32×64 per storey: light concrete with one dark window."""
    if 8 <= x < 24 and 16 <= y < 44:
        return (40, 48, 58, 255)
    return (205 + 10 * _hash(x, y), 202 + 10 * _hash(x, y, 1), 196, 255)


def facade_light(x, y):
    """The facade's emissive texture: its window lit, warm."""
    if 9 <= x < 23 and 17 <= y < 43:
        return (255, 214, 160, 255)
    return (0, 0, 0, 255)


def brushed(x, y):
    """16×16 metallic-roughness texture: roughness (green) in bands, metal (blue) everywhere."""
    return (0, 120 + 70 * _hash(y), 255, 255)


def demo():
    """Issue 2's default scene: ground, a few boxes, a sun and a camera. Issue 37 gave the
    buildings and ground real materials: paving and bricks (textures), a steel slab (metallic,
    its roughness from a texture) and a tower whose windows glow (emissive texture)."""
    b = Builder()
    b.environment(background=[0.45, 0.55, 0.75], ambient=[0.12, 0.14, 0.18])
    paving_tex = b.texture("textures/paving.png", 64, 64, paving)
    bricks_tex = b.texture("textures/bricks.png", 64, 64, bricks)
    facade_tex = b.texture("textures/facade.png", 32, 64, facade)
    facade_light_tex = b.texture("textures/facade_light.png", 32, 64, facade_light)
    brushed_tex = b.texture("textures/brushed.png", 16, 16, brushed)
    ground = b.material("ground", (0.85, 0.85, 0.85), roughness=0.9, base_texture=b.texture_info(paving_tex))
    red = b.material("red", (1.0, 1.0, 1.0), roughness=0.8, base_texture=b.texture_info(bricks_tex))
    white = b.material("white", (1.0, 1.0, 1.0), roughness=0.7, base_texture=b.texture_info(facade_tex),
                       emissive=(1.0, 0.8, 0.5), emissive_texture=b.texture_info(facade_light_tex))
    blue = b.material("blue", (0.56, 0.6, 0.68), metallic=1.0, roughness=1.0,
                      metallic_roughness_texture=b.texture_info(brushed_tex))
    b.node("ground", mesh=b.plane_mesh("ground", 20, 20, ground, uv_scale=4.0))
    b.node("box_red", translation=(0, 1, 0), mesh=b.box_mesh("box_2m", (2, 2, 2), red, uv_scale=1.0))
    b.node("tower_white", translation=(-3.5, 2, -2), mesh=b.box_mesh("tower", (1.2, 4, 1.2), white, uv_scale=1.2))
    b.node("slab_blue", translation=(3, 0.4, 1.5), rotation=(0, 0.3826834, 0, 0.9238795),
           mesh=b.box_mesh("slab", (2.5, 0.8, 1.2), blue, uv_scale=0.8))
    b.sun("sun", direction=(0.55, -0.75, -0.35), intensity=3.0)
    b.camera("main", eye=(9, 6, 11), target=(0, 1, 0), yfov=0.65)
    return b


def blob_cloud(rng, count, centre, radii, particle_radius=(0.35, 0.7)):
    """Particles filling an ellipsoid, denser towards the middle (a cumulus-like blob)."""
    return ellipsoid_blob(rng, count, centre, radii, particle_radius, falloff=0.6)


def cloud():
    """Issue 5's cloud crossed by a thin wing: a static particle cloud above the ground."""
    import random
    rng = random.Random(5)
    b = Builder()
    b.environment(background=[0.35, 0.48, 0.72], ambient=[0.15, 0.18, 0.24])
    ground = b.material("ground", (0.45, 0.5, 0.4))
    metal = b.material("wing", (0.8, 0.25, 0.15), double_sided=True)
    b.node("ground", mesh=b.plane_mesh("ground", 40, 40, ground))
    # Large particles, as billboard clouds are usually built: a plane cutting one is clearly visible
    # when particles are drawn as flat billboards (the seam blocks remove).
    positions, sizes, densities = blob_cloud(rng, 500, (0, 4, 0), (3.6, 1.8, 2.6), particle_radius=(0.9, 1.5))
    b.node("cloud", ext={"medium": {"extinction": 0.8, "albedo": WATER_CLOUD_ALBEDO, "g": WATER_CLOUD_G},
                         "particles": b.particles(positions, sizes, densities)})
    b.node("wing", translation=(0.5, 4.1, 0), rotation=(0, 0, 0.0871557, 0.9961947),
           mesh=b.box_mesh("wing", (9.0, 0.08, 2.2), metal))
    b.sun("sun", direction=(0.35, -0.6, -0.72), intensity=3.0)
    b.camera("main", eye=(0, 8.5, 12.5), target=(0, 3.8, 0), yfov=0.7)
    return b


def cumulus():
    """Issue 5's benchmark cloud: 8000 particles (the seed's count) in a few merged cumulus blobs."""
    import random
    rng = random.Random(8000)
    b = Builder()
    b.environment(background=[0.32, 0.46, 0.74], ambient=[0.16, 0.19, 0.26])
    ground = b.material("ground", (0.4, 0.46, 0.36))
    b.node("ground", mesh=b.plane_mesh("ground", 60, 60, ground))
    positions, sizes, densities = [], [], []
    blobs = [((0, 9, 0), (6.0, 3.0, 4.5), 3400), ((-5, 8, 1), (3.5, 2.2, 3.0), 1600), ((5, 8.5, -1), (4.0, 2.5, 3.2), 1800),
             ((1, 11.5, 0), (3.0, 2.0, 2.5), 1200)]
    for centre, radii, count in blobs:
        p, r, d = blob_cloud(rng, count, centre, radii, particle_radius=(0.45, 0.9))
        positions += p
        sizes += r
        densities += d
    b.node("cumulus", ext={"medium": {"extinction": 1.2, "albedo": WATER_CLOUD_ALBEDO, "g": WATER_CLOUD_G},
                           "particles": b.particles(positions, sizes, densities)})
    b.sun("sun", direction=(-0.45, -0.55, -0.7), intensity=3.0)
    b.camera("main", eye=(0, 7, 26), target=(0, 9, 0), yfov=0.75)
    return b


def smoke():
    """Issue 4: a smoke column beside a building that shadows part of it; the smoke shadows the ground."""
    b = Builder()
    b.environment(background=[0.42, 0.52, 0.7], ambient=[0.14, 0.16, 0.2])
    ground = b.material("ground", (0.5, 0.48, 0.44))
    concrete = b.material("concrete", (0.62, 0.6, 0.57))
    b.node("ground", mesh=b.plane_mesh("ground", 30, 30, ground))
    b.node("building", translation=(-2.6, 2.25, -0.5), mesh=b.box_mesh("building", (2.5, 4.5, 4.0), concrete))
    b.node("chimney", translation=(0, 0.05, 0),
           ext={"medium": {"extinction": 6.0, "albedo": [0.7, 0.7, 0.7], "g": 0.3},
                "emitter": {"preset": "smoke", "seed": 7, "rate": 30, "max_particles": 600,
                            "shape": {"type": "disc", "radius": 0.4},
                            "velocity": [0.0, 0.9, 0.0], "wind": [0.35, 0.0, 0.0]}})
    # Low sun from the building's side: its shadow crosses the lower half of the column.
    b.sun("sun", direction=(0.8, -0.42, 0.3), intensity=3.0)
    b.camera("main", eye=(4.0, 4.2, 14.0), target=(0.6, 3.4, 0), yfov=0.72)
    return b


def campfire():
    """Issue 4: a campfire (emissive rising fire) with smoke above, at dusk."""
    b = Builder()
    b.environment(background=[0.08, 0.1, 0.18], ambient=[0.04, 0.045, 0.07])
    ground = b.material("ground", (0.35, 0.3, 0.25))
    wood = b.material("wood", (0.3, 0.18, 0.1))
    stone = b.material("stone", (0.45, 0.45, 0.45))
    b.node("ground", mesh=b.plane_mesh("ground", 15, 15, ground))
    log = b.box_mesh("log", (1.4, 0.18, 0.18), wood)
    for i, angle in enumerate((0.0, 1.05, 2.1)):
        import math
        b.node("log%d" % i, translation=(0, 0.1, 0), rotation=(0, math.sin(angle / 2), 0, math.cos(angle / 2)), mesh=log)
    rock = b.box_mesh("rock", (0.35, 0.25, 0.3), stone)
    for i in range(8):
        import math
        a = i * math.pi / 4
        b.node("rock%d" % i, translation=(0.95 * math.cos(a), 0.12, 0.95 * math.sin(a)), mesh=rock)
    b.node("fire", translation=(0, 0.15, 0),
           ext={"medium": {"extinction": 8.0, "albedo": [0.2, 0.2, 0.2], "g": 0.0},
                "emitter": {"preset": "fire", "seed": 3, "shape": {"type": "disc", "radius": 0.35}}})
    b.node("smoke", translation=(0, 1.2, 0),
           ext={"medium": {"extinction": 3.0, "albedo": [0.55, 0.55, 0.55], "g": 0.2},
                "emitter": {"preset": "smoke", "seed": 4, "rate": 10, "shape": {"type": "disc", "radius": 0.2}}})
    b.sun("moon", direction=(-0.3, -0.6, -0.74), intensity=0.3, color=(0.7, 0.8, 1.0))
    b.point("fire_light", position=(0, 0.7, 0), intensity=6.0, range_=12.0, color=(1.0, 0.55, 0.2))
    b.camera("main", eye=(3.2, 2.2, 5.0), target=(0, 1.0, 0), yfov=0.75)
    return b


def cumulus_aircraft():
    """Issue 5's benchmark cloud with an airliner-sized aircraft flying through it: the 1280x720
    comparison with a mesh inside the medium, where blocks shade the seam exactly (block_shading=seam)."""
    b = cumulus()
    hull = b.material("hull", (0.75, 0.76, 0.78))
    # Level, heading 30° off the view, its tail out of the main blob and a wing tip out of its far side.
    aircraft = b.node("aircraft", translation=(-3.0, 9.2, 1.0), rotation=(0, 0.258819, 0, 0.9659258))
    fuselage = b.node("fuselage", mesh=b.box_mesh("fuselage", (9.0, 1.0, 1.0), hull), root=False)
    wing = b.node("wing", translation=(0.5, 0, 0), mesh=b.box_mesh("wing", (2.2, 0.15, 11.0), hull), root=False)
    b.doc["nodes"][aircraft]["children"] = [fuselage, wing]
    return b


def jet():
    """Issue 4: a jet crossing the sky (glTF animation) leaving a vapour trail from its tail."""
    b = Builder()
    b.environment(background=[0.3, 0.45, 0.75], ambient=[0.2, 0.24, 0.32])
    hull = b.material("hull", (0.75, 0.76, 0.78))
    jet = b.node("jet", translation=(-40, 30, -20))
    b.doc["nodes"][jet]["children"] = []
    fuselage = b.node("fuselage", mesh=b.box_mesh("fuselage", (6.0, 0.9, 0.9), hull), root=False)
    wings = b.node("wings", translation=(0.3, 0, 0), mesh=b.box_mesh("wings", (1.6, 0.12, 7.0), hull), root=False)
    tail = b.node("trail", translation=(-3.2, 0, 0), root=False,
                  ext={"medium": {"extinction": 1.5, "albedo": [0.92, 0.92, 0.92], "g": 0.6},
                       "emitter": {"preset": "vapor_trail", "seed": 11, "rate": 120, "max_particles": 2000}})
    b.doc["nodes"][jet]["children"] = [fuselage, wings, tail]
    # 80 m in 8 s along +X (10 m/s; slow so the trail stays in frame at test times).
    b.animate_translation(jet, [0.0, 8.0], [(-40, 30, -20), (40, 30, -20)], name="flight")
    # The sun ahead of the camera, low: the trail scatters it forwards (g = 0.6) and glows.
    b.sun("sun", direction=(0.15, -0.45, 0.88), intensity=3.0)
    b.camera("main", eye=(0, 27, 12), target=(-2, 30, -20), yfov=0.9)
    return b


def explosion():
    """Issue 4: an explosion: a burst fireball that cools into rising smoke, among a few crates."""
    b = Builder()
    b.environment(background=[0.5, 0.56, 0.66], ambient=[0.16, 0.17, 0.2])
    ground = b.material("ground", (0.42, 0.4, 0.36))
    crate = b.material("crate", (0.55, 0.42, 0.25))
    b.node("ground", mesh=b.plane_mesh("ground", 30, 30, ground))
    box = b.box_mesh("crate", (1.2, 1.2, 1.2), crate)
    for i, (x, z) in enumerate(((-4.0, -1.0), (3.5, -2.0), (-2.0, 3.5))):
        b.node("crate%d" % i, translation=(x, 0.6, z), mesh=box)
    b.node("explosion", translation=(0, 0.5, 0),
           ext={"medium": {"extinction": 5.0, "albedo": [0.4, 0.4, 0.4], "g": 0.1},
                "emitter": {"preset": "explosion", "seed": 21}})
    b.sun("sun", direction=(0.5, -0.75, -0.43), intensity=3.0)
    b.camera("main", eye=(6.0, 4.0, 11.0), target=(0, 2.0, 0), yfov=0.8)
    return b


def fog_smoke():
    """Issue 27: a smoke plume in height fog: the fog lies in the valley, the plume rises out of it."""
    b = Builder()
    b.environment(background=[0.5, 0.58, 0.72], ambient=[0.12, 0.13, 0.16])
    b.root_ext["fog"] = {"mode": "height", "color": [0.62, 0.66, 0.74], "density": 0.035, "base": 0.0, "falloff": 0.5}
    ground = b.material("ground", (0.45, 0.47, 0.4))
    stone = b.material("stone", (0.6, 0.58, 0.55))
    b.node("ground", mesh=b.plane_mesh("ground", 80, 80, ground))
    for i, (x, z, h) in enumerate([(-6, -8, 5.0), (7, -14, 7.0), (-12, -22, 9.0), (4, -30, 6.0)]):
        b.node("rock_%d" % i, translation=(x, h / 2, z), mesh=b.box_mesh("rock_%d" % i, (3.0, h, 3.0), stone))
    b.node("plume", translation=(0.5, 0.05, -4.0),
           ext={"medium": {"extinction": 5.0, "albedo": [0.75, 0.75, 0.75], "g": 0.3},
                "emitter": {"preset": "smoke", "seed": 11, "rate": 26, "max_particles": 500,
                            "shape": {"type": "disc", "radius": 0.4},
                            "velocity": [0.0, 1.0, 0.0], "wind": [0.3, 0.0, 0.0]}})
    b.sun("sun", direction=(0.5, -0.55, -0.65), intensity=3.0)
    b.camera("main", eye=(3.0, 2.2, 12.0), target=(0.5, 3.2, -6.0), yfov=0.8)
    return b


def slabs(x, y):
    """8×8: large paving slabs, each its own shade (read magnified: no minification to filter)."""
    shade = 0.8 + 0.3 * _hash(x, y, 3)
    return (176 * shade, 170 * shade, 160 * shade, 255)


def coarse_bricks(x, y):
    """16×16: 4 courses of two bricks, for a wall seen magnified."""
    course = y // 4
    shift = 4 if course % 2 else 0
    if y % 4 == 3 or (x + shift) % 8 == 7:
        return (196, 188, 172, 255)
    shade = 0.85 + 0.3 * _hash((x + shift) // 8, course)
    return (168 * shade, 66 * shade, 48 * shade, 255)


def lattice(x, y):
    """16×16 fence: bars two texels wide around square holes (alpha 0)."""
    bar = x % 8 < 2 or y % 8 < 2
    return (150, 150, 146, 255 if bar else 0)


def courtyard():
    """Issue 37: every mesh material feature beside smoke. Paving read through
    KHR_texture_transform, a brick wall read through TEXCOORD_1, a lattice fence cut out by its alpha
    (MASK, double-sided) that shadows the ground and the smoke, three steel spheres from rough to
    polished, crates painted by COLOR_0, and a glowing sign (emissive). The samplers ask for no
    mipmaps, so the judge (one ray per pixel, one bilinear tap) and the rasteriser filter alike."""
    b = Builder()
    b.environment(background=[0.5, 0.6, 0.78], ambient=[0.14, 0.15, 0.18])
    slabs_tex = b.texture("textures/slabs.png", 8, 8, slabs, mipmaps=False)
    bricks_tex = b.texture("textures/coarse_bricks.png", 16, 16, coarse_bricks, mipmaps=False)
    lattice_tex = b.texture("textures/lattice.png", 16, 16, lattice, mipmaps=False)
    ground = b.material("paving", (1.0, 1.0, 1.0), roughness=0.85,
                        base_texture=b.texture_info(slabs_tex, scale=(0.5, 0.5), rotation=0.3, offset=(0.1, 0.2)))
    brick = b.material("brick", (1.0, 1.0, 1.0), roughness=0.8, base_texture=b.texture_info(bricks_tex, tex_coord=1))
    fence = b.material("fence", (0.9, 0.9, 0.9), metallic=1.0, roughness=0.5, alpha_cutoff=0.5, double_sided=True,
                       base_texture=b.texture_info(lattice_tex))
    painted = b.material("painted", (1.0, 1.0, 1.0), roughness=0.6)
    sign = b.material("sign", (0.1, 0.1, 0.1), roughness=0.4, emissive=(1.0, 0.45, 0.15))
    b.node("ground", mesh=b.plane_mesh("ground", 7, 7, ground, uv_scale=1.0))
    # The wall: the bricks read TEXCOORD_1 (2 m per repeat); TEXCOORD_0 (0.5 m per repeat, bricks
    # four times smaller) is there to be ignored.
    wall_mesh = b.box_mesh("wall", (12.0, 3.0, 0.4), brick, uv_scale=2.0)
    primitive = b.doc["meshes"][wall_mesh]["primitives"][0]
    primitive["attributes"]["TEXCOORD_1"] = primitive["attributes"].pop("TEXCOORD_0")
    small = b.doc["meshes"][b.box_mesh("unused", (12.0, 3.0, 0.4), brick, uv_scale=0.5)]["primitives"][0]["attributes"]
    primitive["attributes"]["TEXCOORD_0"] = small["TEXCOORD_0"]
    b.doc["meshes"].pop()  # only its accessor is kept
    b.node("wall", translation=(0, 1.5, -4.5), mesh=wall_mesh)
    b.node("sign", translation=(-2.5, 2.2, -4.28), mesh=b.box_mesh("sign", (1.6, 0.5, 0.04), sign))
    b.node("fence", translation=(2.2, 1.0, -1.0), rotation=(0, 0.2588190, 0, 0.9659258),
           mesh=b.box_mesh("fence", (3.0, 2.0, 0.02), fence, uv_scale=0.75))
    for i, roughness in enumerate((0.9, 0.55, 0.25)):
        steel = b.material("steel_%d" % i, (0.75, 0.74, 0.72), metallic=1.0, roughness=roughness)
        b.node("sphere_%d" % i, translation=(-3.4 + 1.3 * i, 0.55, 1.2), mesh=b.sphere_mesh("sphere_%d" % i, 0.55, steel))
    faces = [(0.8, 0.2, 0.15, 1), (0.2, 0.6, 0.25, 1), (0.9, 0.8, 0.3, 1), (0.3, 0.3, 0.3, 1), (0.2, 0.35, 0.8, 1), (0.7, 0.4, 0.8, 1)]
    crate = b.box_mesh("crate", (0.9, 0.9, 0.9), painted, colors=faces)
    for i, (x, z, turn) in enumerate(((-1.2, -2.6, 0.2), (3.6, 1.4, -0.35))):
        b.node("crate_%d" % i, translation=(x, 0.45, z), rotation=(0, math.sin(turn / 2), 0, math.cos(turn / 2)), mesh=crate)
    b.node("chimney", translation=(0.8, 0.05, -2.6),
           ext={"medium": {"extinction": 4.0, "albedo": [0.75, 0.75, 0.75], "g": 0.3},
                "emitter": {"preset": "smoke", "seed": 37, "rate": 14, "max_particles": 300,
                            "shape": {"type": "disc", "radius": 0.3}, "velocity": [0.0, 0.8, 0.0], "wind": [0.35, 0.0, 0.15]}})
    b.sun("sun", direction=(-0.45, -0.7, -0.55), intensity=3.0)
    b.camera("main", eye=(5.5, 5.0, 8.0), target=(0.2, 0.9, -1.0), yfov=0.75)
    return b


def steam():
    """Issue 35's demo: a white steam plume from a plant's stack drifting over the roofs beside it,
    in a low afternoon sun: the plume scatters many times (albedo 0.995) and shadows the roofs and
    the ground, the stack and the hall shadow the plume's base."""
    b = Builder()
    b.environment(background=[0.36, 0.5, 0.76], ambient=[0.12, 0.15, 0.22])
    ground = b.material("ground", (0.42, 0.41, 0.38))
    brick = b.material("brick", (0.55, 0.3, 0.22))
    concrete = b.material("concrete", (0.62, 0.6, 0.56))
    roof = b.material("roof", (0.3, 0.32, 0.35))
    b.node("ground", mesh=b.plane_mesh("ground", 60, 60, ground))
    b.node("hall", translation=(-4.0, 2.5, -1.0), mesh=b.box_mesh("hall", (7.0, 5.0, 5.0), concrete))
    b.node("hall_roof", translation=(-4.0, 5.1, -1.0), mesh=b.box_mesh("hall_roof", (7.4, 0.2, 5.4), roof))
    b.node("stack", translation=(0.5, 5.0, -1.0), mesh=b.box_mesh("stack", (1.0, 10.0, 1.0), brick))
    b.node("store", translation=(7.5, 2.0, -3.0), mesh=b.box_mesh("store", (5.0, 4.0, 6.0), concrete))
    b.node("store_roof", translation=(7.5, 4.1, -3.0), mesh=b.box_mesh("store_roof", (5.4, 0.2, 6.4), roof))
    b.node("plume", translation=(0.5, 10.0, -1.0),
           ext={"medium": {"extinction": 5.0, "albedo": [0.995, 0.995, 0.995], "g": 0.8},
                "emitter": {"preset": "smoke", "seed": 17, "rate": 24, "max_particles": 700, "lifetime": [6.0, 9.0],
                            "shape": {"type": "disc", "radius": 0.45}, "velocity": [0.0, 2.2, 0.0],
                            "radius": [[0.0, 0.45], [1.0, 1.9]], "wind": [0.9, 0.0, 0.15],
                            "albedo_over_life": [[0.0, 0.995, 0.995, 0.995]]}})
    b.sun("sun", direction=(-0.55, -0.5, -0.67), intensity=3.0, color=(1.0, 0.95, 0.88))
    b.camera("main", eye=(13.0, 5.0, 17.0), target=(3.0, 10.0, -1.5), yfov=0.9)
    return b


def cumulus_field():
    """Issues 33 and 35: a field of cumulus from the ellipsoid generator over a plain, lit by a low
    sun that the main camera looks towards (silver linings, dark bases), with an airliner flying
    through the nearest cloud; the camera "sunlit" looks along the sun at the clouds' lit sides."""
    b = Builder()
    b.environment(background=[0.34, 0.47, 0.72], ambient=[0.13, 0.17, 0.27])
    plain = b.material("plain", (0.36, 0.4, 0.3))
    b.node("plain", mesh=b.plane_mesh("plain", 400, 400, plain))
    clouds = [((-30, 34, -70), (26, 14, 20), 1), ((8, 30, -55), (22, 12, 18), 2), ((42, 36, -95), (30, 15, 22), 3),
              ((-62, 38, -120), (28, 14, 22), 4), ((20, 40, -140), (34, 16, 26), 5)]
    for i, (centre, size, seed) in enumerate(clouds):
        b.node("cumulus_%d" % i, translation=centre,
               ext={"medium": {"extinction": 4.0, "albedo": WATER_CLOUD_ALBEDO, "g": WATER_CLOUD_G},
                    "generator": {"kind": "ellipsoids", "seed": seed, "particles": 2200, "size": list(size), "radius": [1.2, 2.4],
                                  "ellipsoids": 6}})
    hull = b.material("hull", (0.78, 0.79, 0.8))
    # Level, crossing the nearest cloud left to right, its nose out of the cloud's far side.
    aircraft = b.node("aircraft", translation=(4.0, 30.5, -55.0), rotation=(0, 0.2588190, 0, 0.9659258))
    fuselage = b.node("fuselage", mesh=b.box_mesh("fuselage", (18.0, 2.0, 2.0), hull), root=False)
    wing = b.node("wing", translation=(1.0, 0, 0), mesh=b.box_mesh("wing", (4.0, 0.3, 22.0), hull), root=False)
    b.doc["nodes"][aircraft]["children"] = [fuselage, wing]
    # The sun 12 degrees above the horizon, ahead of the main camera.
    b.sun("sun", direction=(0.08, -0.208, 0.975), intensity=3.0, color=(1.0, 0.93, 0.84))
    b.camera("main", eye=(0, 8, 10), target=(-2, 32, -80), yfov=0.62)
    b.camera("sunlit", eye=(-5, 40, -250), target=(0, 34, -90), yfov=0.5)
    return b


SCENES = {"demo": demo, "cloud": cloud, "cumulus": cumulus, "cumulus_aircraft": cumulus_aircraft, "smoke": smoke, "campfire": campfire,
          "jet": jet, "explosion": explosion, "fog_smoke": fog_smoke, "courtyard": courtyard, "cumulus_field": cumulus_field,
          "steam": steam}

# Times at which the scenes are rendered for tests and the demo (emitters need time to fill).
TIMES = {"steam": 8.0, "smoke": 8.0, "campfire": 4.0, "jet": 6.0, "explosion": 0.8, "fog_smoke": 8.0, "courtyard": 6.0}

if __name__ == "__main__":
    wanted = sys.argv[1:] or list(SCENES)
    os.makedirs(OUT, exist_ok=True)
    for name in wanted:
        SCENES[name]().write(os.path.join(OUT, name + ".gltf"))
        print("wrote", os.path.normpath(os.path.join(OUT, name + ".gltf")))
