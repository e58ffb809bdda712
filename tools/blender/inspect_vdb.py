"""Loads a .vdb written by `sandbox export` in Blender, headless, and prints what Blender sees:
each grid's name, type and index-to-object matrix, and the density's largest value (bracketed
by Blender's own Volume to Mesh modifier at rising thresholds). docs/export.md says what it showed.

    blender -b --factory-startup --python-exit-code 1 --python tools/blender/inspect_vdb.py -- F.vdb

Exits non-zero when Blender finds no `density` grid or cannot mesh it.
"""
import json
import sys

import bpy


def main():
    path = sys.argv[sys.argv.index("--") + 1]
    volume = bpy.data.volumes.new("export")
    volume.filepath = path
    if not volume.grids.load():
        raise SystemExit(f"Blender could not load {path}: {volume.grids.error_message}")
    grids = []
    for grid in volume.grids:
        grid.load()
        grids.append({"name": grid.name, "type": grid.data_type, "channels": grid.channels,
                      "index_to_object": [list(row) for row in grid.matrix_object]})
    if not any(g["name"] == "density" for g in grids):
        raise SystemExit("no density grid")

    scene = bpy.context.scene
    holder = bpy.data.objects.new("export", volume)
    scene.collection.objects.link(holder)
    mesher = bpy.data.objects.new("mesh", bpy.data.meshes.new("mesh"))
    scene.collection.objects.link(mesher)
    modifier = mesher.modifiers.new("to_mesh", "VOLUME_TO_MESH")
    modifier.object = holder
    modifier.grid_name = "density"
    modifier.resolution_mode = "GRID"

    def surface(threshold):
        modifier.threshold = threshold
        depsgraph = bpy.context.evaluated_depsgraph_get()
        depsgraph.update()
        mesh = mesher.evaluated_get(depsgraph).to_mesh()
        points = [v.co.copy() for v in mesh.vertices]
        return points

    points = surface(1e-6)
    if not points:
        raise SystemExit("Blender meshed nothing from the density grid")
    bounds = [[min(p[a] for p in points) for a in range(3)], [max(p[a] for p in points) for a in range(3)]]
    lo, hi = 1e-6, 1.0
    while surface(hi) and hi < 1e9:
        lo, hi = hi, hi * 2.0
    for _ in range(24):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if surface(mid) else (lo, mid)
    print(json.dumps({"file": path, "grids": grids, "density_max_between": [lo, hi],
                      "density_surface_bounds_object_space": bounds}, indent=1))


main()
