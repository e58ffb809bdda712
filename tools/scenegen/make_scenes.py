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


SCENES = {"demo": demo}

if __name__ == "__main__":
    wanted = sys.argv[1:] or list(SCENES)
    os.makedirs(OUT, exist_ok=True)
    for name in wanted:
        SCENES[name]().write(os.path.join(OUT, name + ".gltf"))
        print("wrote", os.path.normpath(os.path.join(OUT, name + ".gltf")))
