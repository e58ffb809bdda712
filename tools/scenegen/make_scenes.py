#!/usr/bin/env python3
"""Regenerates the authored content scenes in content/scenes/ (run from anywhere).

Each scene is plain glTF 2.0 plus the NIMBUS_participating_media extension; the files are the
source of truth and are committed, this script only records how they were authored.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from gltf_builder import Builder  # noqa: E402

OUT = os.path.join(os.path.dirname(__file__), "..", "..", "content", "scenes")


def demo():
    """Issue 2's default scene: ground, a few boxes, a sun and a camera."""
    b = Builder()
    b.environment(background=[0.45, 0.55, 0.75], ambient=[0.12, 0.14, 0.18])
    ground = b.material("ground", (0.55, 0.52, 0.48))
    red = b.material("red", (0.75, 0.12, 0.1))
    white = b.material("white", (0.8, 0.8, 0.8))
    blue = b.material("blue", (0.15, 0.25, 0.7))
    b.node("ground", mesh=b.plane_mesh("ground", 20, 20, ground))
    b.node("box_red", translation=(0, 1, 0), mesh=b.box_mesh("box_2m", (2, 2, 2), red))
    b.node("tower_white", translation=(-3.5, 2, -2), mesh=b.box_mesh("tower", (1.2, 4, 1.2), white))
    b.node("slab_blue", translation=(3, 0.4, 1.5), rotation=(0, 0.3826834, 0, 0.9238795),
           mesh=b.box_mesh("slab", (2.5, 0.8, 1.2), blue))
    b.sun("sun", direction=(0.55, -0.75, -0.35), intensity=3.0)
    b.camera("main", eye=(9, 6, 11), target=(0, 1, 0), yfov=0.65)
    return b


def blob_cloud(rng, count, centre, radii, particle_radius=(0.35, 0.7)):
    """Particles filling an ellipsoid, denser towards the middle (a cumulus-like blob)."""
    import math
    positions, sizes, densities = [], [], []
    while len(positions) < count:
        p = [rng.uniform(-1, 1) for _ in range(3)]
        r2 = sum(c * c for c in p)
        if r2 > 1:
            continue
        positions.append([centre[i] + p[i] * radii[i] for i in range(3)])
        sizes.append(rng.uniform(*particle_radius))
        densities.append(1.0 - 0.6 * math.sqrt(r2))
    return positions, sizes, densities


def cloud():
    """Issue 5's cloud crossed by a thin wing: a static particle cloud above the ground."""
    import random
    rng = random.Random(5)
    b = Builder()
    b.environment(background=[0.35, 0.48, 0.72], ambient=[0.15, 0.18, 0.24])
    ground = b.material("ground", (0.45, 0.5, 0.4))
    metal = b.material("wing", (0.7, 0.7, 0.72), double_sided=True)
    b.node("ground", mesh=b.plane_mesh("ground", 40, 40, ground))
    positions, sizes, densities = blob_cloud(rng, 2000, (0, 4, 0), (4.0, 2.2, 3.0))
    b.node("cloud", ext={"medium": {"extinction": 2.5, "albedo": [0.95, 0.95, 0.95], "g": 0.5},
                         "particles": b.particles(positions, sizes, densities)})
    b.node("wing", translation=(0.5, 4.1, 0), rotation=(0, 0, 0.0871557, 0.9961947),
           mesh=b.box_mesh("wing", (9.0, 0.08, 1.6), metal))
    b.sun("sun", direction=(0.4, -0.8, -0.45), intensity=3.0)
    b.camera("main", eye=(0, 5.5, 14), target=(0, 3.8, 0), yfov=0.7)
    return b


SCENES = {"demo": demo, "cloud": cloud}

if __name__ == "__main__":
    wanted = sys.argv[1:] or list(SCENES)
    os.makedirs(OUT, exist_ok=True)
    for name in wanted:
        SCENES[name]().write(os.path.join(OUT, name + ".gltf"))
        print("wrote", os.path.normpath(os.path.join(OUT, name + ".gltf")))
