#!/usr/bin/env python3
"""Writes the volume scenes of tests/scenes/media/volume_test.cpp (glTF + .bin each; committed, so
the tests need no Python). Rerun after editing a case.

  absorber_box      a rotated box of pure absorber before a white background, no lights: every pixel
                    is the background times e^(-sigma L) for the chord L through the box
  lit_ellipsoid     a scattering ellipsoid over a ground, sun-lit: its light and its shadow
  mixed             a volume and a particle cloud together
  dense_white_box   albedo 1, tau 1e4 across (a path that never ends at albedo 1 must end)
  camera_inside     the camera inside a volume
  far_from_origin   a volume 1e5 m from the origin
  thin_slab         a slab 1e-3 m thick, seen edge-on and face-on
  noise_value       an ellipsoid of fractal value noise over a ground, its edges faded, drifting
  noise_sines       a box of Gardner's sums of sines with coverage, beside particles
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools", "scenegen"))
sys.path.insert(0, os.path.join(HERE, "..", "stability_scenes"))
from gltf_builder import Builder, ellipsoid_blob  # noqa: E402
from generate_stability_scenes import write  # noqa: E402


def volume(shape, size, extinction, albedo=0.9, g=0.3):
    return {"medium": {"extinction": extinction, "albedo": [albedo] * 3, "g": g}, "volume": {"shape": shape, "size": list(size)}}


def ground(b, half=20.0, y=0.0, offset=(0.0, 0.0, 0.0)):
    mat = b.material("ground", (0.5, 0.5, 0.48))
    return b.node("ground", translation=(offset[0], offset[1] + y, offset[2]), mesh=b.plane_mesh("ground", half, half, mat))


def absorber_box():
    b = Builder()
    b.environment(background=[1.0, 1.0, 1.0], ambient=[0.0, 0.0, 0.0])
    b.node("box", translation=(0.0, 1.0, 0.0), rotation=(0.0, math.sin(0.26), 0.0, math.cos(0.26)),
           ext=volume("box", (2.0, 1.2, 1.5), 0.8, albedo=0.0))
    b.camera("main", eye=(2.5, 2.2, 4.5), target=(0.0, 1.0, 0.0), yfov=0.6)
    return b


def lit_ellipsoid():
    b = Builder()
    b.environment(background=[0.35, 0.45, 0.65], ambient=[0.12, 0.14, 0.2])
    ground(b)
    b.node("puff", translation=(0.0, 1.6, 0.0), ext=volume("ellipsoid", (2.4, 1.6, 2.0), 1.5, albedo=0.9, g=0.5))
    b.sun("sun", direction=(0.45, -0.7, -0.5), intensity=3.0)
    b.camera("main", eye=(3.0, 2.5, 5.5), target=(0.0, 1.2, 0.0), yfov=0.7)
    return b


def mixed():
    import random
    rng = random.Random(33)
    b = Builder()
    b.environment(background=[0.35, 0.45, 0.65], ambient=[0.12, 0.14, 0.2])
    ground(b)
    b.node("fog_bank", translation=(0.0, 0.5, 0.0), ext=volume("box", (6.0, 1.0, 4.0), 0.6, albedo=0.95, g=0.2))
    p, r, d = ellipsoid_blob(rng, 120, (0.5, 2.0, 0.0), (1.6, 0.9, 1.2), (0.3, 0.6), falloff=0.5)
    b.node("cloud", ext={"medium": {"extinction": 2.0, "albedo": [0.9] * 3, "g": 0.5}, "particles": b.particles(p, r, d)})
    b.sun("sun", direction=(0.35, -0.6, -0.7), intensity=3.0)
    b.camera("main", eye=(3.5, 3.0, 7.0), target=(0.0, 1.0, 0.0), yfov=0.75)
    return b


def dense_white_box():
    b = Builder()
    b.environment(background=[0.3, 0.4, 0.6], ambient=[0.1, 0.1, 0.1])
    ground(b)
    b.node("block", translation=(0.0, 1.0, 0.0), ext=volume("box", (1.0, 1.0, 1.0), 1e4, albedo=1.0, g=0.0))
    b.sun("sun", direction=(0.3, -0.8, -0.5), intensity=3.0)
    b.camera("main", eye=(2.0, 2.0, 3.0), target=(0.0, 1.0, 0.0), yfov=0.7)
    return b


def camera_inside():
    b = Builder()
    b.environment(background=[0.3, 0.4, 0.6], ambient=[0.1, 0.1, 0.12])
    ground(b)
    b.node("fog", translation=(0.0, 1.5, 0.0), ext=volume("ellipsoid", (8.0, 3.0, 8.0), 0.3, albedo=0.9, g=0.6))
    b.sun("sun", direction=(0.2, -0.7, -0.7), intensity=3.0)
    b.camera("main", eye=(0.5, 1.6, 1.0), target=(0.0, 1.0, -4.0), yfov=0.9)
    return b


def far_from_origin():
    b = Builder()
    offset = (1e5, 20.0, -1e5)
    b.environment(background=[0.3, 0.4, 0.6], ambient=[0.1, 0.1, 0.12])
    ground(b, offset=offset)
    b.node("puff", translation=(offset[0], offset[1] + 1.5, offset[2]), ext=volume("ellipsoid", (2.0, 1.5, 2.0), 2.0))
    b.sun("sun", direction=(0.4, -0.7, -0.5), intensity=3.0)
    b.camera("main", eye=(offset[0] + 3.0, offset[1] + 2.5, offset[2] + 5.0), target=(offset[0], offset[1] + 1.2, offset[2]), yfov=0.7)
    return b


def thin_slab():
    b = Builder()
    b.environment(background=[0.3, 0.4, 0.6], ambient=[0.1, 0.1, 0.12])
    ground(b)
    b.node("edge_on", translation=(-1.0, 1.0, 0.0), ext=volume("box", (1.5, 1.5, 1e-3), 500.0))
    b.node("face_on", translation=(1.2, 1.0, 0.0), rotation=(0.0, math.sin(0.6), 0.0, math.cos(0.6)), ext=volume("box", (1e-3, 1.5, 1.5), 500.0))
    b.sun("sun", direction=(0.3, -0.7, -0.6), intensity=3.0)
    b.camera("main", eye=(0.0, 1.5, 4.0), target=(0.0, 1.0, 0.0), yfov=0.8)
    return b


def noise_value():
    b = Builder()
    b.environment(background=[0.35, 0.45, 0.65], ambient=[0.12, 0.14, 0.2])
    ground(b)
    v = volume("ellipsoid", (4.0, 2.0, 3.0), 3.0, albedo=0.95, g=0.5)
    v["volume"]["noise"] = {"kind": "value", "octaves": 4, "frequency": 0.8, "seed": 11, "gain": 0.5, "coverage": 0.35,
                            "falloff": 0.3, "velocity": [0.6, 0.0, 0.2]}
    b.node("cumulus", translation=(0.0, 2.0, 0.0), ext=v)
    b.sun("sun", direction=(0.45, -0.65, -0.6), intensity=3.0)
    b.camera("main", eye=(3.5, 3.0, 6.5), target=(0.0, 1.8, 0.0), yfov=0.75)
    return b


def noise_sines():
    import random
    rng = random.Random(34)
    b = Builder()
    b.environment(background=[0.35, 0.45, 0.65], ambient=[0.12, 0.14, 0.2])
    ground(b)
    v = volume("box", (5.0, 1.5, 3.0), 1.5, albedo=0.9, g=0.3)
    v["volume"]["noise"] = {"kind": "sines", "octaves": 4, "frequency": 0.35, "seed": 5, "coverage": 0.2, "falloff": 0.2}
    b.node("haze", translation=(0.0, 1.0, 0.0), rotation=(0.0, math.sin(0.2), 0.0, math.cos(0.2)), ext=v)
    p, r, d = ellipsoid_blob(rng, 80, (1.5, 2.4, 0.3), (1.0, 0.6, 0.8), (0.25, 0.5), falloff=0.5)
    b.node("puff", ext={"medium": {"extinction": 3.0, "albedo": [0.85] * 3, "g": 0.4}, "particles": b.particles(p, r, d)})
    b.sun("sun", direction=(0.3, -0.7, -0.65), intensity=3.0)
    b.camera("main", eye=(3.0, 3.5, 7.0), target=(0.0, 1.2, 0.0), yfov=0.75)
    return b


SCENES = {"absorber_box": absorber_box, "lit_ellipsoid": lit_ellipsoid, "mixed": mixed, "dense_white_box": dense_white_box,
          "camera_inside": camera_inside, "far_from_origin": far_from_origin, "thin_slab": thin_slab, "noise_value": noise_value,
          "noise_sines": noise_sines}

if __name__ == "__main__":
    for name in sys.argv[1:] or list(SCENES):
        write(SCENES[name](), os.path.join(HERE, name + ".gltf"))
        print("wrote", name)
