#!/usr/bin/env python3
"""Writes the hard-case scenes of tests/stability/ (one glTF + .bin each) and the seeded "unseen"
variants in unseen/. The files are committed, so the tests need no Python; rerun after editing a case.

    generate_stability_scenes.py                      # the hard cases and unseen/ (seed 2024)
    generate_stability_scenes.py --unseen DIR --seed N --count K   # K other variants into DIR

tests/stability/hard_case_test.cpp says, per scene, what could go wrong and which code prevents it;
unseen_variants_test.cpp renders every scene in unseen/ (or $NIMBUS_STABILITY_SCENES) with the same
assertions. Variants only use the scene's first camera at time 0 (no emitters), so any file this
script writes with another seed is a valid input for that test.
"""
import argparse
import math
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools", "scenegen"))
from gltf_builder import Builder, ellipsoid_blob  # noqa: E402

# Optical depth through the centre of one particle of peak extinction σ and radius R: ≈ 0.8355·σR.
CENTRE_COLUMN = math.sqrt(math.pi / 4.5) * math.erf(math.sqrt(4.5))


def blob(rng, count, centre, radii, particle_radius):
    """Particles uniform in an ellipsoid (seeded), densities falling off towards its rim."""
    return ellipsoid_blob(rng, count, centre, radii, particle_radius, falloff=0.5)


def write(b, path):
    """Builder.write, minus the empty buffer a scene without binary data would get (glTF refuses a
    buffer of byteLength 0)."""
    b.write(path)
    if b.blob:
        return
    import json
    with open(path) as f:
        doc = json.load(f)
    for key in ("buffers", "bufferViews", "accessors"):
        doc.pop(key, None)
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    os.remove(os.path.splitext(path)[0] + ".bin")


def medium(extinction, g=0.3, albedo=0.9):
    return {"extinction": extinction, "albedo": [albedo, albedo, albedo], "g": g}


def ground(b, half=30.0, y=0.0, colour=(0.5, 0.5, 0.48), offset=(0.0, 0.0, 0.0)):
    mat = b.material("ground", colour)
    return b.node("ground", translation=(offset[0], offset[1] + y, offset[2]), mesh=b.plane_mesh("ground", half, half, mat))


def column_extinction(column, positions, sizes, densities):
    """σ that gives the densest column of the cloud (through the blob's middle) the optical depth `column`.

    Estimated as the mean particle's centre column times the number of particles a ray through the
    middle crosses (projected area sum over the blob's cross-section)."""
    n = len(positions)
    mean_r = sum(sizes) / n
    mean_d = sum(densities) / n
    xs = [p[0] for p in positions]
    ys = [p[1] for p in positions]
    area = max(max(xs) - min(xs), 2 * mean_r) * max(max(ys) - min(ys), 2 * mean_r) * math.pi / 4
    crossings = max(1.0, n * math.pi * mean_r * mean_r / area)
    return column / (CENTRE_COLUMN * mean_r * mean_d * crossings * 0.6)


# ----------------------------------------------------------------------------------------------
# Hard cases (one function per scene; the docstring is what the scene exercises)
# ----------------------------------------------------------------------------------------------

def optical_depth_1e4():
    """A cloud whose densest column has optical depth ~1e4: every transmittance underflows to 0."""
    rng = random.Random(1)
    b = Builder()
    b.environment(background=[0.4, 0.5, 0.7], ambient=[0.15, 0.17, 0.2])
    ground(b)
    pos, rad, den = blob(rng, 60, (0, 2.2, 0), (2.0, 1.2, 1.6), (0.6, 1.0))
    b.node("cloud", ext={"medium": medium(column_extinction(1e4, pos, rad, den)), "particles": b.particles(pos, rad, den)})
    b.sun("sun", direction=(0.4, -0.8, -0.45), intensity=3.0)
    b.camera("main", eye=(6.5, 4.0, 8.0), target=(0, 2.0, 0), yfov=0.75)
    return b


def optical_depth_1e_5():
    """A cloud whose densest column has optical depth ~1e-5: 1 − e^−τ cancels in float without expm1.
    Black background, no ambient, no mesh: the medium's in-scattering is the whole image."""
    rng = random.Random(2)
    b = Builder()
    b.environment(background=[0.0, 0.0, 0.0], ambient=[0.0, 0.0, 0.0])
    pos, rad, den = blob(rng, 60, (0, 0, 0), (2.0, 1.2, 1.6), (0.6, 1.0))
    b.node("cloud", ext={"medium": medium(column_extinction(1e-5, pos, rad, den)), "particles": b.particles(pos, rad, den)})
    b.sun("sun", direction=(0.3, -0.5, -0.81), intensity=3.0)
    b.camera("main", eye=(5.0, 2.0, 7.0), target=(0, 0, 0), yfov=0.75)
    return b


def camera_inside_cloud():
    """Camera "inside" at the middle of a cloud of large particles; camera "near_plane" with a 1.5 m
    near plane just outside it, so particles straddle the near plane."""
    rng = random.Random(3)
    b = Builder()
    b.environment(background=[0.35, 0.45, 0.7], ambient=[0.15, 0.17, 0.2])
    ground(b)
    pos, rad, den = blob(rng, 120, (0, 3.0, 0), (4.0, 2.2, 4.0), (1.0, 1.8))
    b.node("cloud", ext={"medium": medium(0.25, g=0.4), "particles": b.particles(pos, rad, den)})
    b.sun("sun", direction=(0.35, -0.75, -0.55), intensity=3.0)
    b.camera("inside", eye=(0.3, 3.1, 0.2), target=(2.0, 2.0, -5.0), yfov=0.9, znear=0.1)
    b.camera("near_plane", eye=(0.0, 3.5, 5.2), target=(0, 2.8, 0), yfov=0.8, znear=1.5)
    return b


def surface_through_centres():
    """A ground plane exactly through the centres of a grid of particles and of a lone particle:
    the plane cuts each kernel in half, and a block's front equals its back where it is cut."""
    b = Builder()
    b.environment(background=[0.4, 0.5, 0.7], ambient=[0.15, 0.17, 0.2])
    ground(b, colour=(0.55, 0.5, 0.45))
    pos, rad, den = [], [], []
    for i in range(5):
        for j in range(5):
            pos.append([-2.4 + 1.2 * i, 0.0, -2.4 + 1.2 * j])
            rad.append(0.6)
            den.append(1.0)
    pos.append([4.5, 0.0, 1.0])  # the lone particle: a block of its own
    rad.append(0.8)
    den.append(1.0)
    b.node("cloud", ext={"medium": medium(3.0, g=0.2), "particles": b.particles(pos, rad, den)})
    b.sun("sun", direction=(0.3, -0.8, -0.5), intensity=3.0)
    b.camera("main", eye=(3.0, 4.5, 8.0), target=(0.5, 0, 0), yfov=0.8)
    # Grazing: the eye a hair above the plane, looking along it.
    b.camera("grazing", eye=(0.0, 0.05, 9.0), target=(0.0, 0.05, 0.0), yfov=0.6)
    return b


def light_directions():
    """The sun straight down; cameras looking along it ("parallel": the light comes from behind the
    eye), against it ("antiparallel": looking into the sun) and across it ("perpendicular")."""
    rng = random.Random(5)
    b = Builder()
    b.environment(background=[0.05, 0.06, 0.1], ambient=[0.05, 0.05, 0.06])
    pos, rad, den = blob(rng, 80, (0, 0, 0), (2.5, 1.5, 2.0), (0.5, 0.9))
    b.node("cloud", ext={"medium": medium(1.5, g=0.6), "particles": b.particles(pos, rad, den)})
    b.sun("sun", direction=(0.0, -1.0, 0.0), intensity=3.0)
    b.camera("parallel", eye=(0.0, 9.0, 0.0), target=(0.0, 0.0, 0.0), yfov=0.8)
    b.camera("antiparallel", eye=(0.0, -9.0, 0.0), target=(0.0, 0.0, 0.0), yfov=0.8)
    b.camera("perpendicular", eye=(0.0, 0.0, 9.0), target=(0.0, 0.0, 0.0), yfov=0.8)
    return b


def spot_in_cloud():
    """A spot light at the middle of a cloud, shining down and sideways onto the ground."""
    rng = random.Random(6)
    b = Builder()
    b.environment(background=[0.03, 0.04, 0.07], ambient=[0.02, 0.02, 0.03])
    ground(b)
    pos, rad, den = blob(rng, 100, (0, 3.0, 0), (2.5, 1.5, 2.0), (0.5, 1.0))
    b.node("cloud", ext={"medium": medium(0.8, g=0.3), "particles": b.particles(pos, rad, den)})
    b.spot("spot", position=(0.1, 3.05, -0.05), direction=(0.45, -1.0, 0.2), intensity=60.0, inner=0.35, outer=0.6)
    b.camera("main", eye=(7.0, 4.5, 8.5), target=(0.5, 2.0, 0), yfov=0.8)
    return b


def spot_near_ray():
    """A spot light inside a dense particle (σ 73 /m, R 0.82 m) cut by the ground, and the camera
    inside the same particle 0.2 m from the light: rays of the pixels around (98, 7) at 160×90 pass
    1–8 mm from the light, across the cone's apex. (An unseen variant that exposed a reference bug,
    moved to the origin.)"""
    b = Builder()
    b.environment(background=[0.0, 0.0, 0.0], ambient=[0.02, 0.02, 0.02])
    ground(b, half=60.0)
    b.node("particle", ext={"medium": medium(73.35187, g=0.5, albedo=0.5),
                            "particles": b.particles([[0.41735223, 0.0, 0.33607158]], [0.81802058])})
    b.spot("spot", position=(0.04090103, 0.24540621, 0.0), direction=(0.5, -1.0, 0.35), intensity=36.658895,
           inner=0.35, outer=0.7)
    eye = (0.13538629, 0.27077258, 0.20309944)
    b.camera("main", eye=eye, target=(eye[0] - 0.5, eye[1] - 0.45, eye[2] - 0.74), yfov=0.8, znear=0.027077258)
    return b


def far_from_origin(offset):
    """The same small scene (ground, box, cloud, sun, camera) translated by `offset`."""
    rng = random.Random(7)
    b = Builder()
    b.environment(background=[0.4, 0.5, 0.7], ambient=[0.15, 0.17, 0.2])
    ground(b, half=20.0, offset=offset)
    box = b.material("box", (0.7, 0.2, 0.15))
    b.node("box", translation=(offset[0] - 2.0, offset[1] + 0.75, offset[2] - 1.0), mesh=b.box_mesh("box", (1.5, 1.5, 1.5), box))
    # Particle positions are float accessors: they stay small (local); the node carries the offset.
    pos, rad, den = blob(rng, 80, (0, 0, 0), (2.0, 1.0, 1.5), (0.4, 0.8))
    b.node("cloud", translation=(offset[0] + 0.5, offset[1] + 2.0, offset[2]),
           ext={"medium": medium(1.2, g=0.4), "particles": b.particles(pos, rad, den)})
    b.sun("sun", direction=(0.4, -0.75, -0.5), intensity=3.0)
    eye = (6.0, 4.0, 8.0)
    target = (0.0, 1.5, 0.0)
    b.camera("main", eye=[eye[i] + offset[i] for i in range(3)], target=[target[i] + offset[i] for i in range(3)],
             yfov=0.8)
    return b


def zero_particles():
    """Media that draw nothing: a cloud whose densities are all 0 (left out of rendering) and an
    emitter that bursts 20 short-lived particles at t = 0 (none before the first step, none after 0.3 s)."""
    b = Builder()
    b.environment(background=[0.4, 0.5, 0.7], ambient=[0.15, 0.17, 0.2])
    ground(b)
    box = b.material("box", (0.2, 0.4, 0.7))
    b.node("box", translation=(0, 0.75, 0), mesh=b.box_mesh("box", (1.5, 1.5, 1.5), box))
    b.node("empty_cloud", ext={"medium": medium(2.0),
                               "particles": b.particles([[0, 2, 0], [1, 2, 0]], [0.5, 0.7], [0.0, 0.0])})
    b.node("puff", translation=(1.5, 1.0, 0.5),
           ext={"medium": medium(3.0), "emitter": {"seed": 1, "rate": 0, "bursts": [{"time": 0.0, "count": 20}],
                                                   "lifetime": 0.3, "max_particles": 20, "radius": 0.4,
                                                   "shape": {"type": "sphere", "radius": 0.6}}})
    b.sun("sun", direction=(0.4, -0.8, -0.45), intensity=3.0)
    b.camera("main", eye=(5.0, 3.5, 6.0), target=(0, 1.0, 0), yfov=0.8)
    return b


def one_particle():
    """A single particle above the ground, lit by the sun, casting its shadow."""
    b = Builder()
    b.environment(background=[0.4, 0.5, 0.7], ambient=[0.15, 0.17, 0.2])
    ground(b)
    b.node("particle", ext={"medium": medium(2.5, g=0.3), "particles": b.particles([[0.0, 1.5, 0.0]], [1.2])})
    b.sun("sun", direction=(0.4, -0.8, -0.45), intensity=3.0)
    b.camera("main", eye=(4.0, 3.0, 5.0), target=(0, 1.0, 0), yfov=0.8)
    return b


def million_particles():
    """10⁶ particles (one burst, radius 1 cm: far below a pixel) filling an 8 m box; one step (1/60 s)."""
    b = Builder()
    b.environment(background=[0.3, 0.4, 0.6], ambient=[0.12, 0.13, 0.16])
    b.node("swarm", translation=(0, 0, 0),
           ext={"medium": medium(60.0, g=0.3),
                "emitter": {"seed": 9, "max_particles": 1000000, "rate": 0,
                            "bursts": [{"time": 0.0, "count": 1000000}], "lifetime": 100.0, "radius": 0.01,
                            "shape": {"type": "box", "size": [8.0, 8.0, 8.0]}}})
    b.sun("sun", direction=(0.4, -0.8, -0.45), intensity=3.0)
    b.camera("main", eye=(9.0, 6.0, 12.0), target=(0, 0, 0), yfov=0.8)
    return b


def phase_extremes():
    """Two clouds, g = +0.99 (left) and g = −0.99 (right); cameras looking towards and away from the sun."""
    rng = random.Random(10)
    b = Builder()
    b.environment(background=[0.02, 0.03, 0.05], ambient=[0.03, 0.03, 0.04])
    for name, g, x in (("forward", 0.99, -2.5), ("backward", -0.99, 2.5)):
        pos, rad, den = blob(rng, 50, (0, 0, 0), (1.8, 1.2, 1.5), (0.5, 0.8))
        b.node(name, translation=(x, 0, 0), ext={"medium": medium(1.0, g=g), "particles": b.particles(pos, rad, den)})
    # The sun low, shining along −Z: "towards_sun" looks along +Z into it, "away_from_sun" along −Z.
    b.sun("sun", direction=(0.05, -0.25, -1.0), intensity=3.0)
    b.camera("towards_sun", eye=(0.0, 0.5, -11.0), target=(0.0, -0.3, 0.0), yfov=0.8)
    b.camera("away_from_sun", eye=(0.0, 1.5, 11.0), target=(0.0, 0.0, 0.0), yfov=0.8)
    return b


def subpixel_particles():
    """3000 particles of radius 4 mm seen from 12 m (a pixel is ~10 cm): most rays miss them all."""
    rng = random.Random(11)
    b = Builder()
    b.environment(background=[0.05, 0.06, 0.1], ambient=[0.1, 0.1, 0.12])
    ground(b, colour=(0.3, 0.3, 0.3))
    pos, rad, den = blob(rng, 3000, (0, 2.0, 0), (2.5, 1.5, 2.5), (0.003, 0.005))
    b.node("dust", ext={"medium": medium(400.0, g=0.2), "particles": b.particles(pos, rad, den)})
    b.sun("sun", direction=(0.4, -0.8, -0.45), intensity=3.0)
    b.camera("main", eye=(7.0, 5.0, 9.0), target=(0, 1.8, 0), yfov=0.8)
    return b


def larger_than_screen():
    """One particle of radius 400 m whose silhouette is larger than the screen (camera outside it),
    and a normal one in front of the ground."""
    b = Builder()
    b.environment(background=[0.4, 0.5, 0.7], ambient=[0.15, 0.17, 0.2])
    ground(b, half=2000.0)
    b.node("giant", ext={"medium": medium(0.003, g=0.3), "particles": b.particles([[0.0, 200.0, -470.0]], [400.0])})
    b.node("puff", ext={"medium": medium(2.0, g=0.3), "particles": b.particles([[1.0, 1.5, 0.0]], [1.0])})
    b.sun("sun", direction=(0.4, -0.8, -0.45), intensity=3.0)
    b.camera("main", eye=(0.0, 2.5, 8.0), target=(0.0, 4.0, -10.0), yfov=0.8, znear=0.1)
    return b


def spot_in_opaque_cloud():
    """Unseen variant 2 of seed 8: 40 particles of 60–120 m and optical depth 1e4 around a spot
    light, g = 0.99. A lamp inside the medium lists its neighbours, and the correction of their
    compositing order was e^τ of a τ = 1e4 particle: inf, then NaN pixels in both modes."""
    rng = random.Random(8)
    for index in range(3):
        _, b = unseen_variant(rng, index)
    return b


def inside_towards_sun():
    """Unseen variant 7 of seed 15: the camera inside one particle of optical depth 30, 1e5 m from
    the origin, looking up into the sun; g = 0.99. Along the sun, the light's optical depth falls
    as the view's grows, so every point of the ray sends the same light: one e^−τl at the layer's
    shading point made the phase peak 3× too dark."""
    rng = random.Random(15)
    for index in range(8):
        _, b = unseen_variant(rng, index)
    return b


def spot_beside_opaque_specks():
    """Unseen variant 2 of seed 11: 2000 particles of 4–8 mm and optical depth ~1e4 each around a
    spot light, g = −0.5, on black with a faint ambient. The slices are 4 cm apart and wider than a
    particle per texel, so a particle's own optical depth spread over them shadowed its own lit
    side: the two or three lit pixels beside the spot were black in both modes."""
    rng = random.Random(11)
    for index in range(3):
        _, b = unseen_variant(rng, index)
    return b


def glory_of_dense_particle():
    """Unseen variant 4 of seed 23: one particle of optical depth 1e4 and radius 0.7 m over the ground,
    seen straight down along the sun, g = −0.99: its glory (the backscatter peak, ~690) is the image.
    The slices' planes 4 cm apart each held thousands of its optical depth, read linearly across its
    lit skin: the glory was 18."""
    rng = random.Random(23)
    for index in range(5):
        _, b = unseen_variant(rng, index)
    return b


def cloud_top_along_sun():
    """Unseen variant 4 of seed 25: 150 overlapping particles of 60–120 m, the densest column of
    optical depth 1e4, seen straight down along the sun, g = −0.5. Sorted by their centres, a dense
    particle whose front lies tens of metres in front of another's was drawn behind it, so each
    layer lay behind another's dense tail and the lit top came out at the ambient."""
    rng = random.Random(25)
    for index in range(5):
        _, b = unseen_variant(rng, index)
    return b


HARD_CASES = {
    "optical_depth_1e4": optical_depth_1e4,
    "optical_depth_1e-5": optical_depth_1e_5,
    "camera_inside_cloud": camera_inside_cloud,
    "surface_through_centres": surface_through_centres,
    "light_directions": light_directions,
    "spot_in_cloud": spot_in_cloud,
    "spot_near_ray": spot_near_ray,
    "spot_in_opaque_cloud": spot_in_opaque_cloud,
    "inside_towards_sun": inside_towards_sun,
    "spot_beside_opaque_specks": spot_beside_opaque_specks,
    "glory_of_dense_particle": glory_of_dense_particle,
    "cloud_top_along_sun": cloud_top_along_sun,
    "far_from_origin": lambda: far_from_origin((1.0e5, 1.0e5, -1.0e5)),
    "far_from_origin_at_origin": lambda: far_from_origin((0.0, 0.0, 0.0)),
    "zero_particles": zero_particles,
    "one_particle": one_particle,
    "million_particles": million_particles,
    "phase_extremes": phase_extremes,
    "subpixel_particles": subpixel_particles,
    "larger_than_screen": larger_than_screen,
}


# ----------------------------------------------------------------------------------------------
# Unseen variants: seeded random combinations of the hard cases' parameters
# ----------------------------------------------------------------------------------------------

def unseen_variant(rng, index):
    """One random combination of the hard cases' parameters; returns (name, Builder). Every choice
    is drawn from `rng`, so a seed fixes the set."""
    column = rng.choice([1e-5, 1e-2, 1.0, 30.0, 1e4])   # optical depth of the densest column
    size = rng.choice(["subpixel", "normal", "huge"])    # particle radius against a pixel / the screen
    light = rng.choice(["parallel", "antiparallel", "perpendicular", "oblique", "spot_inside"])
    g = rng.choice([-0.99, -0.5, 0.0, 0.5, 0.99])
    count = rng.choice([500, 2000]) if size == "subpixel" else rng.choice([1, 2, 40, 150])
    far = rng.random() < 0.4                            # the whole scene ~1e5 m from the origin
    inside = size != "subpixel" and rng.random() < 0.3  # the camera inside the cloud
    through = rng.random() < 0.4                        # the ground exactly through the particle centres
    albedo = rng.choice([0.5, 0.9, 1.0])
    offset = (rng.uniform(0.8e5, 1.2e5), rng.uniform(-1e4, 1e4), rng.uniform(-1.2e5, -0.8e5)) if far else (0.0, 0.0, 0.0)

    # Huge particles (60–120 m) come with a scene scaled up around them; sub-pixel ones (4–8 mm) fill
    # a smaller blob, so that a few percent of the pixel rays still hit one.
    scale = 40.0 if size == "huge" else 1.0
    radii = {"subpixel": (0.004, 0.008), "normal": (0.4, 1.0), "huge": (60.0, 120.0)}[size]
    extent = [e * scale * (0.5 if size == "subpixel" else 1.0) for e in (2.5, 1.4, 2.0)]
    centre_y = 0.0 if through else 1.8 * scale
    if count <= 2:
        pos = [[rng.uniform(-0.5, 0.5) * r, 0.0, rng.uniform(-0.5, 0.5) * r] for r in [radii[1]] * count]
        rad = [rng.uniform(*radii) for _ in range(count)]
        den = [1.0] * count
    else:
        pos, rad, den = blob(rng, count, (0, 0, 0), extent, radii)
        if through:
            for p in pos:
                p[1] = 0.0  # every centre exactly on the ground plane
    # The cloud's bounding radius: the camera stands back far enough for it to fill ~60% of the view.
    reach = max(math.sqrt(sum(c * c for c in p)) + r for p, r in zip(pos, rad))

    b = Builder()
    # A thin medium or a spot-lit one would vanish against a sky: a black background then, so the
    # medium carries the image, and ambient light so that all of it shows (not only a phase peak).
    dark = column <= 1e-2 or light == "spot_inside"
    b.environment(background=[0.0, 0.0, 0.0] if dark else [0.35, 0.45, 0.7],
                  ambient=([0.02] * 3 if light == "spot_inside" else [0.3] * 3) if dark else [0.12, 0.14, 0.18])
    sigma = column_extinction(column, pos, rad, den)
    b.node("cloud", translation=(offset[0], offset[1] + centre_y, offset[2]),
           ext={"medium": medium(sigma, g=g, albedo=albedo), "particles": b.particles(pos, rad, den)})
    if through or not dark:
        ground(b, half=60.0 * scale, y=0.0 if through else -0.05 * scale, offset=offset)

    # The sun shines straight down; the camera looks along it, against it, across it, or obliquely.
    view = {"parallel": (0.0, -1.0, 0.0), "antiparallel": (0.0, 1.0, 0.0), "perpendicular": (0.0, 0.0, -1.0),
            "oblique": (-0.6, -0.5, -0.62), "spot_inside": (-0.5, -0.45, -0.74)}[light]
    view = [c / math.sqrt(sum(v * v for v in view)) for c in view]
    if light == "spot_inside":
        # Among the particles (above the ground when it cuts them), shining down and sideways.
        mean_r = sum(rad) / len(rad)
        b.spot("spot", position=(offset[0] + 0.05 * mean_r, offset[1] + centre_y + (0.3 if through else 0.02) * mean_r,
                                 offset[2]),
               direction=(0.5, -1.0, 0.35), intensity=20.0 * reach * reach, inner=0.35, outer=0.7)
    else:
        b.sun("sun", direction=(0.0, -1.0, 0.0), intensity=3.0)
    if inside:
        eye = [0.1 * reach, centre_y + (0.2 if through else 0.02) * reach, 0.15 * reach]
    else:
        dist = 1.6 * reach / math.tan(0.4)
        eye = [-view[0] * dist, centre_y - view[1] * dist, -view[2] * dist]
    target = [eye[i] + view[i] for i in range(3)] if inside else [0.0, centre_y, 0.0]
    b.camera("main", eye=[eye[i] + offset[i] for i in range(3)], target=[target[i] + offset[i] for i in range(3)],
             yfov=0.8, znear=min(0.05 * scale, 0.02 * reach))
    tags = [size, "tau%g" % column, light, "g%+.2f" % g, "n%d" % count]
    tags += [t for t, on in (("far", far), ("inside", inside), ("through", through)) if on]
    name = "variant_%02d_" % index + "_".join(tags)
    return name.replace("+", "p").replace("-", "m").replace(".", "_"), b


def write_unseen(out_dir, seed, count):
    os.makedirs(out_dir, exist_ok=True)
    rng = random.Random(seed)
    for i in range(count):
        name, b = unseen_variant(rng, i)
        write(b, os.path.join(out_dir, name + ".gltf"))
        print("wrote", os.path.relpath(os.path.join(out_dir, name + ".gltf")))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--unseen", help="only write unseen variants, into this folder")
    parser.add_argument("--seed", type=int, default=2024, help="seed of the unseen variants")
    parser.add_argument("--count", type=int, default=10, help="number of unseen variants")
    args = parser.parse_args()
    if args.unseen:
        write_unseen(args.unseen, args.seed, args.count)
        return
    for name, make in HARD_CASES.items():
        write(make(), os.path.join(HERE, name + ".gltf"))
        print("wrote", name + ".gltf")
    write_unseen(os.path.join(HERE, "unseen"), args.seed, args.count)


if __name__ == "__main__":
    main()
