#!/usr/bin/env python3
"""Writes the media test scenes of tests/scenes/media (run from anywhere; Python standard library only).

Every scene is plain glTF 2.0 with the NIMBUS_participating_media extension, written with
tools/scenegen/gltf_builder.py. The .gltf/.bin files are committed, so the tests never need Python;
this script records how they were made. Each scene draws its particles from its own
random.Random(seed), so rerunning it rewrites the same bytes.

unseen_*     scenes the renderer was not tuned on (tests/scenes/media/unseen_scenes_test.cpp): each
             must land within 10 % rel-RMSE of the reference. The medium's extinction is set so the
             optical depth through the cloud along the camera's line of sight is the stated `tau`.
absorber     albedo 0, no emission, no ambient, white background (absorber_test.cpp).
moving_shadow  a uniform slab of particles under a box that the test moves (moving_shadow_test.cpp).
shadow_edge  one large particle half under a plate (shadow_edge_test.cpp).
wing_through_cloud  a thin wing through a cloud's middle (seam_band_test.cpp).
wing_close   the same seen from a third as far, so media_scale=auto reduces at 96x54 (settings_walk_test.cpp).
colour_pairs  pairs of differently coloured particles whose depth order flips as the camera orbits (sheets_test.cpp).
"""
import math
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools", "scenegen"))
from gltf_builder import Builder, ellipsoid_blob, normalize  # noqa: E402

KERNEL_FALLOFF = 4.5  # rho(r) = exp(-4.5 r^2 / R^2), r < R (docs/design.md section 2)


def blob(rng, count, centre, radii, particle_radius, falloff=0.6):
    """Particles filling an ellipsoid, denser towards the middle."""
    return ellipsoid_blob(rng, count, centre, radii, particle_radius, falloff)


def optical_depth(positions, radii, densities, origin, direction, sigma=1.0):
    """Closed-form optical depth of the truncated Gaussians along a ray from origin (t >= 0)."""
    d = normalize(direction)
    tau = 0.0
    for p, r, rho in zip(positions, radii, densities):
        k = KERNEL_FALLOFF / (r * r)
        rel = [p[i] - origin[i] for i in range(3)]
        tc = sum(rel[i] * d[i] for i in range(3))
        b2 = max(0.0, sum(c * c for c in rel) - tc * tc)
        if b2 >= r * r:
            continue
        h = math.sqrt(r * r - b2)
        lo, hi = max(-h, -tc), h  # the ray starts at the origin
        if hi <= lo:
            continue
        sk = math.sqrt(k)
        tau += sigma * rho * math.exp(-k * b2) * 0.5 * math.sqrt(math.pi / k) * (math.erf(sk * hi) - math.erf(sk * lo))
    return tau


def extinction_for(tau, positions, radii, densities, eye, target):
    """The extinction that gives optical depth `tau` from the eye towards the target (and beyond)."""
    per_unit = optical_depth(positions, radii, densities, eye, [target[i] - eye[i] for i in range(3)])
    return tau / per_unit


def medium(extinction, albedo=(1.0, 1.0, 1.0), g=0.0, emission=None, phase=None):
    m = {"extinction": round(extinction, 6), "albedo": list(albedo), "g": g}
    if emission is not None:
        m["emission"] = list(emission)
    if phase is not None:
        m["phase"] = phase
    return m


def ground(b, half=15.0, colour=(0.5, 0.48, 0.45), y=0.0, offset=(0.0, 0.0, 0.0)):
    mat = b.material("ground", colour)
    b.node("ground", translation=(offset[0], offset[1] + y, offset[2]), mesh=b.plane_mesh("ground", half, half, mat))


def cloud_scene(name, seed, tau, eye, target, count, centre, radii, particle_radius, medium_args, light, env,
                with_ground=True, yfov=0.7, extra=None):
    """One blob cloud seen from `eye`, its extinction set for optical depth `tau` along the view."""
    rng = random.Random(seed)
    b = Builder()
    b.environment(*env)
    if with_ground:
        ground(b)
    pos, rad, den = blob(rng, count, centre, radii, particle_radius)
    sigma = extinction_for(tau, pos, rad, den, eye, target)
    b.node(name, ext={"medium": medium(sigma, **medium_args), "particles": b.particles(pos, rad, den)})
    light(b)
    if extra:
        extra(b, rng)
    b.camera("main", eye=eye, target=target, yfov=yfov)
    return b


SKY = ([0.4, 0.5, 0.7], [0.12, 0.14, 0.18])
DARK = ([0.03, 0.03, 0.05], [0.0, 0.0, 0.0])


def sun(direction, lux=3.0, colour=(1.0, 1.0, 1.0)):
    return lambda b: b.sun("sun", direction=direction, intensity=lux, color=colour)


# ---- unseen scenes: one idea each ------------------------------------------------------------------

def unseen_thin_haze():
    """Optically thin (tau 0.1), large soft particles, sun and sky."""
    return cloud_scene("haze", 101, 0.1, (6, 3, 9), (0, 1.5, 0), 200, (0, 1.5, 0), (3, 1.2, 2), (0.6, 1.2),
                       {"albedo": (0.9, 0.9, 0.9), "g": 0.2}, sun((0.4, -0.8, -0.45)), SKY)


def unseen_thick_cumulus():
    """Optically thick (tau 10), bright, forward scattering; it shadows the ground."""
    return cloud_scene("cumulus", 102, 10.0, (0, 5, 13), (0, 3.5, 0), 400, (0, 4, 0), (3, 1.6, 2.4), (0.7, 1.3),
                       {"albedo": (0.95, 0.95, 0.95), "g": 0.5}, sun((0.3, -0.85, -0.4)), SKY)


def unseen_backscatter():
    """g = -0.5 with the sun behind the camera; no ambient."""
    return cloud_scene("backscatter", 103, 2.0, (0, 2, 10), (0, 2, 0), 250, (0, 2, 0), (2.5, 1.5, 1.5), (0.4, 0.8),
                       {"albedo": (0.8, 0.8, 0.8), "g": -0.5}, sun((0.1, -0.3, -1.0)), ([0.05, 0.05, 0.1], [0, 0, 0]))


def unseen_forward_glow():
    """g = 0.9 looking towards the sun: strongly peaked phase function."""
    return cloud_scene("glow", 104, 1.5, (0, 2, 10), (0, 3, 0), 300, (0, 3, 0), (2.5, 1.2, 1.5), (0.3, 0.6),
                       {"albedo": (0.9, 0.9, 0.9), "g": 0.9}, sun((0.0, -0.25, 1.0)), ([0.3, 0.4, 0.6], [0.1, 0.11, 0.13]))


def unseen_rayleigh():
    """Rayleigh phase, albedo that differs per channel, a blue box beside the cloud."""
    def box(b, rng):
        blue = b.material("blue", (0.15, 0.25, 0.7))
        b.node("box", translation=(3.0, 0.75, -1.0), mesh=b.box_mesh("box", (1.5, 1.5, 1.5), blue))
    return cloud_scene("rayleigh", 105, 3.0, (5, 3, 8), (0, 2, 0), 250, (0, 2, 0), (2, 1.3, 1.6), (0.4, 0.8),
                       {"albedo": (0.6, 0.8, 1.0), "phase": "rayleigh"}, sun((-0.5, -0.6, -0.6)),
                       ([0.2, 0.25, 0.35], [0.05, 0.06, 0.08]), extra=box)


def unseen_emissive():
    """An emissive column (fire-like, low albedo) at night: a dim bluish moon, no ambient."""
    return cloud_scene("glowing", 106, 4.0, (4, 2, 6), (0, 1.5, 0), 200, (0, 1.5, 0), (0.8, 1.5, 0.8), (0.25, 0.5),
                       {"albedo": (0.3, 0.3, 0.3), "emission": (3.0, 1.2, 0.3)},
                       sun((-0.3, -0.6, -0.7), lux=0.2, colour=(0.7, 0.8, 1.0)), DARK)


def unseen_spot_into_fog():
    """A spot light from the side into a fog bank; no sun."""
    def spot(b):
        b.spot("spot", position=(-5, 4, 0.5), direction=(5, -2.5, -0.5), intensity=80.0, inner=0.2, outer=0.45,
               range_=25.0)
    return cloud_scene("fog", 107, 1.5, (5, 3, 8), (0, 1.5, 0), 300, (0, 1.5, 0), (3, 1.5, 3), (0.5, 1.0),
                       {"albedo": (0.9, 0.9, 0.9), "g": 0.3}, spot, ([0.02, 0.02, 0.03], [0.03, 0.03, 0.04]))


def unseen_point_near():
    """A warm point light just outside a small cloud."""
    def point(b):
        b.point("lamp", position=(2.2, 2.0, 0.5), intensity=20.0, range_=15.0, color=(1.0, 0.8, 0.6))
    return cloud_scene("puffs", 108, 2.0, (4, 3, 7), (0, 2, 0), 150, (0, 2, 0), (1.5, 1.5, 1.5), (0.3, 0.6),
                       {"albedo": (0.9, 0.9, 0.9), "g": 0.0}, point, ([0.03, 0.03, 0.05], [0.02, 0.02, 0.03]))


def unseen_point_inside():
    """A point light inside a thin medium (tau 0.5): the hardest case for per-particle shading."""
    def point(b):
        b.point("lamp", position=(0.0, 1.8, 0.0), intensity=8.0, color=(1.0, 0.9, 0.8))
    return cloud_scene("lit_fog", 109, 0.5, (5, 3, 7), (0, 1.8, 0), 250, (0, 1.8, 0), (2, 1.5, 2), (0.4, 0.8),
                       {"albedo": (0.8, 0.8, 0.8), "g": 0.0}, point, ([0.02, 0.02, 0.03], [0.0, 0.0, 0.0]))


def unseen_point_inside_dense():
    """A point light inside a dense cloud (tau 3), camera outside: light escapes through the thin edges."""
    def point(b):
        b.point("lamp", position=(0.3, 2.0, 0.2), intensity=15.0, range_=20.0, color=(1.0, 0.7, 0.4))
    return cloud_scene("lit_cloud", 117, 3.0, (4, 3, 6), (0, 2, 0), 200, (0, 2, 0), (1.6, 1.3, 1.6), (0.35, 0.7),
                       {"albedo": (0.9, 0.9, 0.9), "g": 0.2}, point, ([0.02, 0.02, 0.03], [0.01, 0.01, 0.015]))


def unseen_spot_inside():
    """A spot light inside a fog bank, pointing down and forward, with the camera inside the fog too."""
    def spot(b):
        b.spot("spot", position=(0.0, 3.0, -1.0), direction=(0.2, -1.0, -0.6), intensity=40.0, inner=0.25, outer=0.5)
    return cloud_scene("fog", 118, 1.0, (0, 1.6, 3), (0, 1.5, -3), 300, (0, 2, -1), (5, 2.5, 5), (0.8, 1.5),
                       {"albedo": (0.9, 0.9, 0.9), "g": 0.4}, spot, ([0.01, 0.01, 0.02], [0.0, 0.0, 0.0]), yfov=0.9)


def unseen_mesh_shadows_medium():
    """A box between the sun and the cloud: the mesh shadows the medium, both shadow the ground."""
    def box(b, rng):
        grey = b.material("slab", (0.6, 0.6, 0.6))
        b.node("slab", translation=(-0.5, 5.0, 0.2), mesh=b.box_mesh("slab", (1.6, 0.2, 1.6), grey))
    return cloud_scene("shadowed", 110, 3.0, (6, 4, 9), (0, 2.5, 0), 300, (0, 2.5, 0), (2.5, 1.0, 2.0), (0.4, 0.8),
                       {"albedo": (0.9, 0.9, 0.9), "g": 0.3}, sun((0.2, -1.0, 0.1)), SKY, extra=box)


def unseen_camera_inside():
    """The camera inside a large sparse fog, boxes around it."""
    def boxes(b, rng):
        mat = b.material("crate", (0.55, 0.42, 0.25))
        box = b.box_mesh("crate", (1.2, 1.2, 1.2), mat)
        for i, (x, z) in enumerate(((-3.0, -4.0), (2.5, -6.0), (0.5, -9.0))):
            b.node("crate%d" % i, translation=(x, 0.6, z), mesh=box)
    return cloud_scene("fog", 111, 2.0, (0, 1.5, 3), (0, 1.2, -5), 300, (0, 2, 0), (8, 3, 8), (1.2, 2.2),
                       {"albedo": (0.9, 0.9, 0.9), "g": 0.3}, sun((0.4, -0.8, -0.3)), SKY, extra=boxes, yfov=0.9)


def unseen_radius_mix():
    """Tiny (sub-pixel), medium and huge particles mixed, random densities."""
    rng = random.Random(112)
    b = Builder()
    b.environment(*SKY)
    ground(b)
    pos, rad, den = [], [], []
    for count, size in ((150, (0.05, 0.12)), (40, (0.4, 0.8)), (5, (1.5, 2.5))):
        p, r, _ = blob(rng, count, (0, 2, 0), (2.5, 1.5, 2), size)
        pos += p
        rad += r
        den += [rng.uniform(0.2, 1.0) for _ in p]
    eye, target = (5, 3, 8), (0, 2, 0)
    b.node("mix", ext={"medium": medium(extinction_for(2.0, pos, rad, den, eye, target), (0.85, 0.85, 0.85), 0.4),
                       "particles": b.particles(pos, rad, den)})
    b.sun("sun", direction=(0.4, -0.8, -0.45), intensity=3.0)
    b.camera("main", eye=eye, target=target)
    return b


def unseen_albedo_mix():
    """Black smoke (albedo 0) overlapping white smoke (albedo 1), two coloured suns."""
    rng = random.Random(113)
    b = Builder()
    b.environment([0.35, 0.45, 0.6], [0.08, 0.08, 0.1])
    ground(b)
    eye, target = (0, 2.5, 8), (0, 2, 0)
    for name, x, albedo in (("black", -0.8, 0.0), ("white", 0.8, 1.0)):
        pos, rad, den = blob(rng, 150, (x, 2, 0), (1.4, 1.2, 1.2), (0.3, 0.6))
        sigma = extinction_for(2.0, pos, rad, den, eye, (x, 2, 0))
        b.node(name, ext={"medium": medium(sigma, (albedo,) * 3, 0.2), "particles": b.particles(pos, rad, den)})
    b.sun("warm", direction=(0.7, -0.5, -0.3), intensity=2.0, color=(1.0, 0.75, 0.5))
    b.sun("cool", direction=(-0.7, -0.6, -0.2), intensity=1.5, color=(0.5, 0.7, 1.0))
    b.camera("main", eye=eye, target=target)
    return b


def unseen_transformed_node():
    """The cloud's node is rotated and uniformly scaled ×1.7: positions and radii follow."""
    rng = random.Random(114)
    b = Builder()
    b.environment(*SKY)
    ground(b)
    pos, rad, den = blob(rng, 200, (0, 0, 0), (1.6, 0.5, 0.8), (0.2, 0.45))
    scale = 1.7
    world = [[c * scale for c in p] for p in pos]
    world = [[w[0] + 1.0, w[1] + 2.0, w[2] - 1.0] for w in world]  # rotation ignored: tau is a rough target
    eye = (5, 3.5, 7)
    sigma = extinction_for(2.0, world, [r * scale for r in rad], den, eye, (1.0, 2.0, -1.0))
    angle = 0.6
    axis = normalize((0.3, 1.0, 0.2))
    q = [a * math.sin(angle / 2) for a in axis] + [math.cos(angle / 2)]
    b.node("scaled", translation=(1.0, 2.0, -1.0), rotation=q, scale=(scale, scale, scale),
           ext={"medium": medium(sigma, (0.9, 0.7, 0.5), 0.3), "particles": b.particles(pos, rad, den)})
    b.sun("sun", direction=(0.5, -0.7, -0.5), intensity=3.0)
    b.camera("main", eye=eye, target=(1.0, 2.0, -1.0))
    return b


def thin_box(name, colour, translation, rotation, size):
    """cloud_scene's `extra`: a double-sided box mesh node (material, node and mesh all `name`)."""
    def add(b, rng):
        material = b.material(name, colour, double_sided=True)
        b.node(name, translation=translation, rotation=rotation, mesh=b.box_mesh(name, size, material))
    return add


def unseen_mesh_through_medium():
    """A thin tilted plate through a thick cloud: the mesh cuts the medium (soft particles)."""
    plate = thin_box("plate", (0.8, 0.25, 0.15), (0.3, 2.1, 0.0), (0, 0, 0.0871557, 0.9961947), (6.0, 0.08, 1.6))
    return cloud_scene("cloud", 115, 4.0, (0, 4.5, 8), (0, 2, 0), 300, (0, 2, 0), (2.5, 1.2, 2.0), (0.5, 1.0),
                       {"albedo": (0.95, 0.95, 0.95), "g": 0.5}, sun((0.35, -0.6, -0.72)), SKY, extra=plate)


def unseen_far_from_origin():
    """The same kind of scene 10^5 m from the origin (double-precision transforms and particles)."""
    rng = random.Random(116)
    off = (1.0e5, 0.0, -5.0e4)
    b = Builder()
    b.environment(*SKY)
    ground(b, offset=off)
    pos, rad, den = blob(rng, 250, (0, 0, 0), (2.5, 1.3, 2.0), (0.4, 0.9))
    eye_local, target_local = (5, 3, 8), (0, 2, 0)
    # The cloud's node sits at target_local: in its frame the eye is at eye_local - target_local.
    sigma = extinction_for(2.5, pos, rad, den, [eye_local[i] - target_local[i] for i in range(3)], (0, 0, 0))
    b.node("far_cloud", translation=(off[0], off[1] + 2.0, off[2]),
           ext={"medium": medium(sigma, (0.9, 0.9, 0.9), 0.3), "particles": b.particles(pos, rad, den)})
    b.sun("sun", direction=(0.4, -0.8, -0.45), intensity=3.0)
    b.camera("main", eye=[eye_local[i] + off[i] for i in range(3)], target=[target_local[i] + off[i] for i in range(3)])
    return b


# ---- scenes of the property tests ------------------------------------------------------------------

def absorber():
    """A pure absorber before a white background: albedo 0, no emission, no ambient, a sun anyway."""
    rng = random.Random(201)
    b = Builder()
    b.environment([1.0, 1.0, 1.0], [0.0, 0.0, 0.0])
    eye, target = (0, 1, 7), (0, 1, 0)
    pos, rad, den = blob(rng, 60, (0, 1, 0), (2.0, 1.2, 1.5), (0.3, 1.0))
    b.node("soot", ext={"medium": medium(extinction_for(2.5, pos, rad, den, eye, target), (0.0, 0.0, 0.0), 0.3),
                        "particles": b.particles(pos, rad, den)})
    b.sun("sun", direction=(0.4, -0.8, -0.45), intensity=3.0)
    b.camera("main", eye=eye, target=target, yfov=0.8)
    return b


def wing_through_cloud():
    """A thin wing (6 x 0.04 x 1.3 m, rolled 6 degrees) through the middle of a cloud, sun from above
    and ahead: the wing cuts particles in two and shadows the half below it, so the band where
    the wing lies inside particles shows whether a renderer cuts a particle at the surface and keeps
    the light of its lit half from bleeding into its shadowed half (seam_band_test.cpp)."""
    wing = thin_box("wing", (0.75, 0.75, 0.78), (0.0, 2.0, 0.2), (0, 0, 0.0523360, 0.9986295), (6.0, 0.04, 1.3))
    return cloud_scene("cloud", 116, 3.0, (1.5, 3.4, 8.5), (0, 2, 0), 260, (0, 2, 0), (2.6, 1.3, 1.8), (0.45, 0.95),
                       {"albedo": (0.95, 0.95, 0.95), "g": 0.5}, sun((0.25, -0.85, -0.45)), SKY, extra=wing)


def wing_close():
    """wing_through_cloud seen from a third as far: its billboards keep 8 texels across at 1/2 even at
    96x54, so media_scale=auto reduces the media target there (settings_walk_test.cpp)."""
    wing = thin_box("wing", (0.75, 0.75, 0.78), (0.0, 2.0, 0.2), (0, 0, 0.0523360, 0.9986295), (6.0, 0.04, 1.3))
    return cloud_scene("cloud", 116, 3.0, (0.5, 2.47, 2.83), (0, 2, 0), 260, (0, 2, 0), (2.6, 1.3, 1.8), (0.45, 0.95),
                       {"albedo": (0.95, 0.95, 0.95), "g": 0.5}, sun((0.25, -0.85, -0.45)), SKY, extra=wing)


# Shared with moving_shadow_test.cpp: the slab of particles and the box's two positions.
SLAB_MIN, SLAB_MAX, SLAB_SPACING, SLAB_RADIUS = (-3.0, 1.5, -1.0), (3.0, 2.5, 1.0), 0.25, 0.4


def moving_shadow():
    """A uniform slab of particles lit from above; a box high above it (out of view) shadows part of it."""
    b = Builder()
    b.environment([0.02, 0.02, 0.03], [0.03, 0.03, 0.03])
    pos = []
    n = [int(round((SLAB_MAX[i] - SLAB_MIN[i]) / SLAB_SPACING)) + 1 for i in range(3)]
    for i in range(n[0]):
        for j in range(n[1]):
            for k in range(n[2]):
                pos.append([SLAB_MIN[0] + i * SLAB_SPACING, SLAB_MIN[1] + j * SLAB_SPACING, SLAB_MIN[2] + k * SLAB_SPACING])
    rad = [SLAB_RADIUS] * len(pos)
    den = [1.0] * len(pos)
    eye, target = (0, 2, 9), (0, 2, 0)
    b.node("slab", ext={"medium": medium(extinction_for(1.5, pos, rad, den, eye, target), (0.95, 0.95, 0.95), 0.0),
                        "particles": b.particles(pos, rad, den)})
    grey = b.material("occluder", (0.5, 0.5, 0.5))
    b.node("occluder", translation=(-1.5, 6.0, 0.0), mesh=b.box_mesh("occluder", (1.5, 0.1, 3.0), grey))
    b.sun("sun", direction=(0.15, -1.0, 0.1), intensity=3.0)
    b.camera("main", eye=eye, target=target, yfov=0.7)
    return b


def shadow_edge():
    """One large particle; a plate above it covers x < 0, so the shadow's edge plane x = 0 cuts it in half."""
    b = Builder()
    b.environment([0.05, 0.05, 0.08], [0.02, 0.02, 0.02])
    grey = b.material("plate", (0.5, 0.5, 0.5))
    b.node("plate", translation=(-2.5, 3.0, 0), mesh=b.box_mesh("plate", (5.0, 0.05, 6.0), grey))
    b.node("puff", ext={"medium": medium(1.2, (0.9, 0.9, 0.9), 0.0), "particles": b.particles([[0, 0, 0]], [2.0])})
    b.sun("sun", direction=(0.0, -1.0, 0.0), intensity=3.0)
    # Looking along (-1, 0, -1): camera rays cross the shadow's edge plane obliquely, so in the
    # reference each ray integrates a lit and a shadowed part and the edge is a smooth ramp.
    b.camera("main", eye=(6, 0, 6), target=(0, 0, 0), yfov=0.6)
    return b


# Shared with sheets_test.cpp: the camera looks at this point and orbits about the y axis through it.
POP_TARGET = (0.0, 0.0, 0.0)


def colour_pairs():
    """Pairs of dense, differently coloured particles side by side (0.25 m apart along x, at one
    depth), each colour its own node, 2.5 m in front of the orbit's pivot so that they sweep across
    the image as the camera orbits. Their depth order flips where the eye crosses the plane between
    a pair: at 0 and about +-0.95 degrees (sheets_test.cpp)."""
    b = Builder()
    b.environment([0.3, 0.3, 0.35], [0.05, 0.05, 0.05])
    radius, sigma, depth = 0.45, 8.0, 2.5  # optical depth about 3 through a centre
    pairs = ((-0.1, -0.75, ((1.0, 0.15, 0.1), (0.1, 0.9, 0.2))), (0.0, 0.0, ((0.15, 0.3, 1.0), (1.0, 0.9, 0.1))),
             (0.1, 0.75, ((0.9, 0.1, 0.9), (0.1, 0.9, 0.9))))
    for n, (mid, y, colours) in enumerate(pairs):
        for side, colour in zip((-0.125, 0.125), colours):
            b.node("pair%d_%s" % (n, "left" if side < 0 else "right"),
                   ext={"medium": medium(sigma, colour, 0.0), "particles": b.particles([[mid + side, y, depth]], [radius])})
    b.sun("sun", direction=(-0.3, -0.6, -0.75), intensity=3.0)
    b.camera("main", eye=(0.0, 0.0, 6.0), target=POP_TARGET, yfov=0.55)
    return b


SCENES = {
    "unseen_thin_haze": unseen_thin_haze,
    "unseen_thick_cumulus": unseen_thick_cumulus,
    "unseen_backscatter": unseen_backscatter,
    "unseen_forward_glow": unseen_forward_glow,
    "unseen_rayleigh": unseen_rayleigh,
    "unseen_emissive": unseen_emissive,
    "unseen_spot_into_fog": unseen_spot_into_fog,
    "unseen_point_near": unseen_point_near,
    "unseen_point_inside": unseen_point_inside,
    "unseen_point_inside_dense": unseen_point_inside_dense,
    "unseen_spot_inside": unseen_spot_inside,
    "unseen_mesh_shadows_medium": unseen_mesh_shadows_medium,
    "unseen_camera_inside": unseen_camera_inside,
    "unseen_radius_mix": unseen_radius_mix,
    "unseen_albedo_mix": unseen_albedo_mix,
    "unseen_transformed_node": unseen_transformed_node,
    "unseen_mesh_through_medium": unseen_mesh_through_medium,
    "unseen_far_from_origin": unseen_far_from_origin,
    "wing_through_cloud": wing_through_cloud,
    "wing_close": wing_close,
    "absorber": absorber,
    "moving_shadow": moving_shadow,
    "shadow_edge": shadow_edge,
    "colour_pairs": colour_pairs,
}

if __name__ == "__main__":
    wanted = sys.argv[1:] or list(SCENES)
    for name in wanted:
        SCENES[name]().write(os.path.join(HERE, name + ".gltf"))
        print("wrote", name + ".gltf")
