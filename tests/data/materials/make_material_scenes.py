#!/usr/bin/env python3
"""Writes the material test scenes beside this script (run from anywhere):

metal_rough_spheres.gltf: a smaller equivalent of Khronos MetalRoughSpheres, factors only: a
5 × 3 grid of spheres, roughness 0.1 … 0.9 along x, metallic 0, 0.5, 1 along y, under one sun and
a grey ambient, seen head-on by an orthographic camera.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "..", "tools", "scenegen"))
from gltf_builder import Builder  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def metal_rough_spheres():
    b = Builder()
    b.environment(background=[0.05, 0.05, 0.06], ambient=[0.1, 0.1, 0.1])
    shared = None  # every sphere reads the first one's accessors, with its own material
    for row, metallic in enumerate((0.0, 0.5, 1.0)):
        for column, roughness in enumerate((0.1, 0.3, 0.5, 0.7, 0.9)):
            material = b.material("m%.1f_r%.1f" % (metallic, roughness), (0.9, 0.6, 0.3), metallic=metallic, roughness=roughness)
            name = "sphere_%d_%d" % (row, column)
            if shared is None:
                mesh = shared = b.sphere_mesh(name, 1.0, material, 64, 32)
            else:
                primitive = dict(b.doc["meshes"][shared]["primitives"][0], material=material)
                b.doc["meshes"].append({"name": name, "primitives": [primitive]})
                mesh = len(b.doc["meshes"]) - 1
            b.node(name, translation=(2.2 * (column - 2), 2.2 * (1 - row), 0.0), mesh=mesh)
    b.sun("sun", direction=(-0.35, -0.45, -0.82), intensity=3.0)
    b.doc.setdefault("cameras", [])
    b.cameras.append({"name": "front", "type": "orthographic",
                      "orthographic": {"xmag": 6.0, "ymag": 3.6, "znear": 0.1, "zfar": 100.0}})
    b.node("front", translation=(0.0, 0.0, 20.0), camera=len(b.cameras) - 1)
    return b


if __name__ == "__main__":
    metal_rough_spheres().write(os.path.join(HERE, "metal_rough_spheres.gltf"))
    print("wrote", os.path.join(HERE, "metal_rough_spheres.gltf"))
