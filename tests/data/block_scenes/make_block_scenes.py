#!/usr/bin/env python3
"""Writes the unseen cloud + thin-mesh scenes the blocks-mode scene tests judge (tests/scenes/blocks).

Seeded (one random.Random per scene, seed = BASE_SEED + index), so rerunning rewrites the same files
bit for bit; the files are committed and are the source of truth. Each scene: a static particle cloud
(blob, flat layer, twin lobes, tower or a tilted cigar; thin to moderately thick; small to large
particles), a thin mesh node named "wing" (a wing-like slab or a square plate) cutting through the
cloud at a random orientation that the camera does not see edge-on, a ground plane, a sun from a
random direction, sometimes a point light beside the cloud, and a camera looking at the cloud.

Usage: make_block_scenes.py [--check]   (--check: report the scene parameters without writing)
"""
import math
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools", "scenegen"))
from gltf_builder import Builder  # noqa: E402

BASE_SEED = 9000
COUNT = 10
# Scenes of later seeds (BASE_SEED values 9100-9900 were judged, not committed) kept because one
# caught a fault: (base seed, index).
#   9700/07: a wing 0.6 m from a lamp, in front of a dense particle whose block lies behind it; the
#            block's light impostor darkened the wing by 12% (block_partition.h kMaxLampImpostorSpread).
#   9700/08: a tower of 1.0–1.6 m particles whose blocks overlap along the view, and 9800/01: blocks
#            of about ten small dense particles in sunlight. block_shading=smooth fails their seam
#            band (the compositing order; uniform shading points); the default, seam, passes.
KEPT = [(9700, 7), (9700, 8), (9800, 1)]
SHAPES = ["blob", "layer", "twin", "tower", "cigar"]
# Central optical depth along a diameter, thin to moderately thick, spread over the scenes.
OPTICAL_DEPTHS = [0.6, 1.0, 1.5, 2.2, 3.0, 4.0, 5.5, 7.0, 9.0, 12.0]
PARTICLE_RADII = [(0.3, 0.6), (0.5, 0.9), (0.8, 1.3), (1.0, 1.6)]


def quat_mul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz]


def axis_angle(axis, angle):
    s = math.sin(angle / 2)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(angle / 2)]


def rotate(q, v):
    """Rotates vector v by unit quaternion q (x, y, z, w)."""
    p = quat_mul(quat_mul(q, [v[0], v[1], v[2], 0.0]), [-q[0], -q[1], -q[2], q[3]])
    return p[:3]


def unit_ball(rng):
    while True:
        p = [rng.uniform(-1, 1) for _ in range(3)]
        r2 = sum(c * c for c in p)
        if r2 <= 1:
            return p, r2


def cloud_particles(rng, shape, count, radii_range):
    """Particle centres (relative to the cloud centre), radii and densities; the cloud's half extents."""
    positions, sizes, densities = [], [], []
    if shape == "blob":
        ext = [rng.uniform(2.8, 3.8), rng.uniform(1.6, 2.2), rng.uniform(2.2, 3.0)]
    elif shape == "layer":
        ext = [rng.uniform(4.0, 5.0), rng.uniform(0.7, 1.0), rng.uniform(3.2, 4.2)]
    elif shape == "twin":
        ext = [rng.uniform(1.8, 2.3), rng.uniform(1.5, 1.9), rng.uniform(1.8, 2.3)]
    elif shape == "tower":
        ext = [rng.uniform(1.6, 2.1), rng.uniform(2.8, 3.4), rng.uniform(1.6, 2.1)]
    else:  # cigar, tilted below
        ext = [rng.uniform(3.8, 4.6), rng.uniform(1.1, 1.4), rng.uniform(1.1, 1.4)]
    tilt = axis_angle([0, 0, 1], rng.uniform(0.3, 0.6)) if shape == "cigar" else [0, 0, 0, 1]
    offset = ext[0] * 0.85
    while len(positions) < count:
        p, r2 = unit_ball(rng)
        local = [p[i] * ext[i] for i in range(3)]
        if shape == "twin":
            local[0] += offset if len(positions) % 2 else -offset
        positions.append(rotate(tilt, local))
        sizes.append(rng.uniform(*radii_range))
        # Denser towards the middle for blobs and towers, more uniform for layers.
        falloff = 0.3 if shape == "layer" else 0.6
        densities.append(1.0 - falloff * math.sqrt(r2))
    half = [ext[0] + (offset if shape == "twin" else 0.0), ext[1], ext[2]]
    if shape == "cigar":
        half = [ext[0], ext[0] * math.sin(0.6) + ext[1], ext[2]]
    return positions, sizes, densities, half


def extinction_for(optical_depth, positions, sizes, densities, half):
    """σ giving roughly `optical_depth` along the cloud's shortest horizontal diameter."""
    volume = 4.0 / 3.0 * math.pi * half[0] * half[1] * half[2]
    kernel_mass = sum(0.97 * (math.pi / 4.5) ** 1.5 * r ** 3 * d for r, d in zip(sizes, densities))
    mean_extinction_per_sigma = kernel_mass / volume
    path = 2.0 * min(half[0], half[2])
    return optical_depth / (mean_extinction_per_sigma * path)


def scene(index, base_seed=BASE_SEED):
    rng = random.Random(base_seed + index)
    shape = SHAPES[index % len(SHAPES)]
    radii_range = PARTICLE_RADII[rng.randrange(len(PARTICLE_RADII))]
    mean_radius = sum(radii_range) / 2
    count = int(min(900, max(150, rng.uniform(0.5, 1.0) * 260 / mean_radius ** 1.5)))
    centre = [rng.uniform(-1.0, 1.0), rng.uniform(4.5, 6.0), rng.uniform(-1.0, 1.0)]
    positions, sizes, densities, half = cloud_particles(rng, shape, count, radii_range)
    optical_depth = OPTICAL_DEPTHS[(index * 7) % len(OPTICAL_DEPTHS)]
    sigma = extinction_for(optical_depth, positions, sizes, densities, half)
    albedo = rng.uniform(0.8, 0.99)
    g = rng.choice([0.0, 0.3, 0.5, 0.7])

    b = Builder()
    sky = [rng.uniform(0.3, 0.45), rng.uniform(0.42, 0.55), rng.uniform(0.65, 0.8)]
    b.environment(background=sky, ambient=[c * rng.uniform(0.3, 0.45) for c in sky])
    ground = b.material("ground", (rng.uniform(0.35, 0.5), rng.uniform(0.4, 0.52), rng.uniform(0.3, 0.42)))
    wing_colour = rng.choice([(0.8, 0.25, 0.15), (0.15, 0.35, 0.8), (0.85, 0.75, 0.2), (0.2, 0.7, 0.3)])
    wing_material = b.material("wing", wing_colour, double_sided=True)
    b.node("ground", mesh=b.plane_mesh("ground", 40, 40, ground))
    b.node("cloud", translation=centre,
           ext={"medium": {"extinction": round(sigma, 6), "albedo": [albedo] * 3, "g": g},
                "particles": b.particles(positions, sizes, densities)})

    # Camera: a random azimuth, looking slightly down at the cloud from outside it.
    radius = max(half) + radii_range[1]
    azimuth = rng.uniform(0, 2 * math.pi)
    elevation = rng.uniform(0.12, 0.45)
    distance = 2.3 * radius + 2.0
    eye = [centre[0] + distance * math.cos(elevation) * math.sin(azimuth), centre[1] + distance * math.sin(elevation),
           centre[2] + distance * math.cos(elevation) * math.cos(azimuth)]
    view = [centre[i] - eye[i] for i in range(3)]
    view_len = math.sqrt(sum(c * c for c in view))
    view = [c / view_len for c in view]

    # The thin mesh: a wing (long slab) or a square plate, through the cloud, never seen edge-on.
    kind = "plate" if index % 3 == 2 else "wing"
    while True:
        q = quat_mul(axis_angle([0, 1, 0], rng.uniform(0, 2 * math.pi)),
                     quat_mul(axis_angle([1, 0, 0], rng.uniform(-0.9, 0.9)), axis_angle([0, 0, 1], rng.uniform(-0.5, 0.5))))
        normal = rotate(q, [0, 1, 0])
        if abs(sum(n * v for n, v in zip(normal, view))) > 0.35:
            break
    thickness = rng.uniform(0.05, 0.1)
    if kind == "wing":
        size = (2.2 * max(half[0], half[2]) * rng.uniform(0.9, 1.2), thickness, rng.uniform(1.6, 2.6))
    else:
        side = 1.6 * min(half[0], half[2]) * rng.uniform(0.9, 1.15)
        size = (side, thickness, side)
    wing_at = [centre[i] + rng.uniform(-0.25, 0.25) * half[i] for i in range(3)]
    b.node("wing", translation=wing_at, rotation=q, mesh=b.box_mesh("wing", size, wing_material))

    sun_azimuth = rng.uniform(0, 2 * math.pi)
    sun_elevation = rng.uniform(0.35, 1.25)
    sun_dir = [-math.cos(sun_elevation) * math.sin(sun_azimuth), -math.sin(sun_elevation), -math.cos(sun_elevation) * math.cos(sun_azimuth)]
    b.sun("sun", direction=sun_dir, intensity=rng.uniform(2.5, 4.0))
    point = index % 3 == 1
    if point:
        p, _ = unit_ball(rng)
        n = math.sqrt(sum(c * c for c in p)) or 1.0
        at = [centre[i] + p[i] / n * half[i] * rng.uniform(1.1, 1.4) for i in range(3)]
        at[1] = max(at[1], 1.0)
        b.point("lamp", position=at, intensity=rng.uniform(15.0, 45.0), color=(1.0, 0.8, 0.55))
    b.camera("main", eye=eye, target=centre, yfov=0.7)
    info = {"shape": shape, "particles": count, "radii": radii_range, "optical_depth": optical_depth, "sigma": round(sigma, 4),
            "albedo": round(albedo, 3), "g": g, "mesh": kind, "point_light": point}
    return b, info


def main():
    check = "--check" in sys.argv[1:]
    scenes = [(BASE_SEED, index, "block_scene_%02d" % index) for index in range(COUNT)]
    scenes += [(seed, index, "block_scene_%d_%02d" % (seed, index)) for seed, index in KEPT]
    for seed, index, name in scenes:
        b, info = scene(index, seed)
        if not check:
            b.write(os.path.join(HERE, name + ".gltf"))
        print(name, " ".join("%s=%s" % kv for kv in info.items()))


if __name__ == "__main__":
    main()
