#!/usr/bin/env python3
"""Writes the small glTF files the asset tests load (tests/data/scenes, malformed, images).

Run from anywhere: python3 tests/data/generate_test_data.py. Standard library only. The outputs are
committed; rerun after editing a case here. tests/unit/assets/*_test.cpp state the values they expect.
"""
import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
FLOAT, UBYTE, USHORT, UINT = 5126, 5121, 5123, 5125


# ---------------------------------------------------------------- glTF building ----------------
class Gltf:
    """Accumulates one binary buffer; accessors are appended as tightly packed, 4-byte aligned views."""

    def __init__(self):
        self.doc = {"asset": {"version": "2.0", "generator": "nimbus generate_test_data.py"}}
        self.blob = bytearray()

    def _array(self, key):
        return self.doc.setdefault(key, [])

    def add(self, key, obj):
        arr = self._array(key)
        arr.append(obj)
        return len(arr) - 1

    def view(self, data):
        while len(self.blob) % 4:
            self.blob.append(0)
        offset = len(self.blob)
        self.blob += data
        return self.add("bufferViews", {"buffer": 0, "byteOffset": offset, "byteLength": len(data)})

    def accessor(self, values, gltf_type, component=FLOAT, normalized=False, count=None, **extra):
        fmt = {FLOAT: "f", UBYTE: "B", USHORT: "H", UINT: "I"}[component]
        data = struct.pack("<%d%s" % (len(values), fmt), *values)
        n = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[gltf_type]
        acc = {"bufferView": self.view(data), "componentType": component,
               "count": count if count is not None else len(values) // n, "type": gltf_type}
        if normalized:
            acc["normalized"] = True
        acc.update(extra)
        return self.add("accessors", acc)

    def finish_embedded(self):
        if self.blob and "buffers" not in self.doc:
            self.doc["buffers"] = [{"byteLength": len(self.blob),
                                    "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.blob)).decode()}]
        return self.doc


def flat(vectors):
    return [c for v in vectors for c in v]


def write_json(path, doc):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def write_bytes(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data)


def glb(doc, blob):
    text = json.dumps(doc).encode()
    text += b" " * ((4 - len(text) % 4) % 4)
    blob = bytes(blob) + b"\0" * ((4 - len(blob) % 4) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text
    if blob:
        chunks += struct.pack("<I4s", len(blob), b"BIN\0") + blob
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


# ---------------------------------------------------------------- PNG writing -------------------
def png(width, height, color_type, bit_depth, rows):
    """rows: list of bytes per row (already in the PNG sample layout)."""
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)
    raw = b"".join(b"\0" + r for r in rows)
    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, color_type, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def write_images():
    # Images live beside the files that use them: a URI may not leave the glTF file's folder.
    scenes, malformed = os.path.join(HERE, "scenes", "images"), os.path.join(HERE, "malformed", "images")
    # 2x2 each; the tests check the expanded RGBA8 of pixel (x=1, y=0) and (0, 1).
    write_bytes(os.path.join(scenes, "grey.png"), png(2, 2, 0, 8, [bytes([10, 200]), bytes([30, 40])]))
    write_bytes(os.path.join(scenes, "grey_alpha.png"), png(2, 2, 4, 8, [bytes([10, 11, 200, 201]), bytes([30, 31, 40, 41])]))
    rgb = png(2, 2, 2, 8, [bytes([1, 2, 3, 4, 5, 6]), bytes([7, 8, 9, 10, 11, 12])])
    write_bytes(os.path.join(scenes, "rgb.png"), rgb)
    write_bytes(os.path.join(malformed, "rgb.png"), rgb)
    write_bytes(os.path.join(scenes, "rgba16.png"),
                png(2, 2, 6, 16, [struct.pack(">8H", 0, 0, 0, 65535, 65535, 32896, 0, 65535),
                                  struct.pack(">8H", 0, 65535, 0, 0, 257, 514, 771, 1028)]))
    # Claims 20000 x 1 pixels: refused as absurd before any pixel is decoded.
    write_bytes(os.path.join(malformed, "too_wide.png"), png(20000, 1, 0, 8, [bytes(20000)]))
    write_bytes(os.path.join(malformed, "not_an_image.png"), b"this is not a PNG file\n")


# ---------------------------------------------------------------- valid scenes ------------------
def quad_positions():
    return [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)]


def scene_primitives():
    g = Gltf()
    prims = []
    # 0: TRIANGLE_STRIP quad, no normals, no indices -> 2 triangles, flat +Z normals, 6 unwelded vertices.
    prims.append({"attributes": {"POSITION": g.accessor(flat(quad_positions()), "VEC3")}, "mode": 5})
    # 1: TRIANGLE_FAN around vertex 0, indexed: 5 fan vertices -> 3 triangles.
    fan = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (-1, 1, 0)]
    prims.append({"attributes": {"POSITION": g.accessor(flat(fan), "VEC3")},
                  "indices": g.accessor([0, 1, 2, 3, 4], "SCALAR", USHORT), "mode": 6})
    # 2: POINTS and 3: LINES are dropped with a warning.
    prims.append({"attributes": {"POSITION": g.accessor(flat(fan), "VEC3")}, "mode": 0})
    prims.append({"attributes": {"POSITION": g.accessor(flat(fan[:4]), "VEC3")}, "mode": 1})
    # 4: degenerate triangles without normals: collinear, then all three points equal.
    degenerate = [(0, 0, 0), (1, 0, 0), (2, 0, 0), (5, 5, 5), (5, 5, 5), (5, 5, 5)]
    prims.append({"attributes": {"POSITION": g.accessor(flat(degenerate), "VEC3")}})
    # 5: indexed triangle with (unnormalized) normals and UNSIGNED_BYTE normalized texcoords.
    prims.append({"attributes": {"POSITION": g.accessor(flat([(0, 0, 0), (2, 0, 0), (0, 3, 0)]), "VEC3"),
                                 "NORMAL": g.accessor(flat([(0, 0, 2), (0, 0, 2), (0, 0, 2)]), "VEC3"),
                                 "TEXCOORD_0": g.accessor([0, 0, 255, 0, 0, 51], "VEC2", UBYTE, normalized=True)},
                  "indices": g.accessor([0, 1, 2], "SCALAR", UBYTE), "material": 0})
    g.add("meshes", {"name": "Primitives", "primitives": prims})
    # Mesh 1: sparse POSITION over a base view (vertex 2 moved to z = 7), and a view-less sparse one.
    base = g.accessor(flat([(0, 0, 0), (1, 0, 0), (0, 1, 0)]), "VEC3")
    sparse_idx = g.view(struct.pack("<H", 2))
    sparse_val = g.view(struct.pack("<3f", 0, 1, 7))
    g.doc["accessors"][base]["sparse"] = {"count": 1, "indices": {"bufferView": sparse_idx, "componentType": USHORT},
                                          "values": {"bufferView": sparse_val}}
    zeros = g.add("accessors", {"componentType": FLOAT, "count": 3, "type": "VEC3",
                                "sparse": {"count": 2, "indices": {"bufferView": g.view(struct.pack("<2B", 1, 2)), "componentType": UBYTE},
                                           "values": {"bufferView": g.view(struct.pack("<6f", 4, 0, 0, 0, 4, 0))}}})
    g.add("meshes", {"name": "Sparse", "primitives": [{"attributes": {"POSITION": base}}, {"attributes": {"POSITION": zeros}}]})
    g.add("materials", {"name": "Red", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1]}, "doubleSided": True})
    g.doc["nodes"] = [{"name": "Primitives", "mesh": 0}, {"name": "Sparse", "mesh": 1, "translation": [10, 0, 0]}]
    g.doc["scenes"] = [{"nodes": [0, 1]}]
    g.doc["scene"] = 0
    write_json(os.path.join(HERE, "scenes", "primitives.gltf"), g.finish_embedded())


def scene_lights_cameras():
    g = Gltf()
    g.accessor(flat([(-1, 0, -1), (1, 0, -1), (0, 0, 1)]), "VEC3")
    g.add("meshes", {"name": "Floor", "primitives": [{"attributes": {"POSITION": 0}}]})
    s = math.sqrt(0.5)
    g.doc["cameras"] = [
        {"name": "WideCam", "type": "perspective", "perspective": {"yfov": 1.0, "znear": 0.1, "zfar": 100, "aspectRatio": 1.5}},
        {"name": "TopCam", "type": "orthographic", "orthographic": {"xmag": 2, "ymag": 3, "znear": 0, "zfar": 50}},
    ]
    g.doc["extensionsUsed"] = ["KHR_lights_punctual", "NIMBUS_participating_media"]
    g.doc["extensions"] = {
        "KHR_lights_punctual": {"lights": [
            {"name": "Sun", "type": "directional", "color": [1, 0.9, 0.8], "intensity": 3},
            {"name": "Bulb", "type": "point", "intensity": 100, "range": 20},
            {"type": "spot", "color": [0, 1, 0], "intensity": 50, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}},
        ]},
        "NIMBUS_participating_media": {"background": [0.1, 0.2, 0.3], "ambient": [0.01, 0.02, 0.03],
                                       "extras": {"quality": "another tool's data"}},
    }
    g.doc["nodes"] = [
        {"name": "Floor", "mesh": 0, "children": [5]},
        # A camera node that comes before the other: picked first.
        {"name": "Overview", "camera": 0, "translation": [0, 2, 10]},
        {"name": "Top", "camera": 1, "translation": [0, 10, 0], "rotation": [-s, 0, 0, s]},
        # Sun pointing straight down: rotate -90 deg about X turns -Z into -Y.
        {"name": "SunNode", "rotation": [-s, 0, 0, s], "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"name": "BulbNode", "translation": [1, 2, 3], "extensions": {"KHR_lights_punctual": {"light": 1}}},
        {"name": "SpotNode", "translation": [0, 5, 0], "rotation": [-s, 0, 0, s], "scale": [2, 2, 2],
         "extensions": {"KHR_lights_punctual": {"light": 2},
                        "NIMBUS_participating_media": {"medium": {"extinction": 2, "albedo": [0.5, 0.5, 1.0], "g": 0.25},
                                                       "emitter": {}, "big": 5000000000, "tags": []}}},
        {"name": "NotInScene", "camera": 0, "extensions": {"KHR_lights_punctual": {"light": 0}}},
    ]
    g.doc["scenes"] = [{"nodes": [0, 1, 2, 3, 4]}, {"nodes": [6]}]
    g.doc["scene"] = 0
    write_json(os.path.join(HERE, "scenes", "lights_cameras.gltf"), g.finish_embedded())


def scene_animated():
    g = Gltf()
    times = g.accessor([0.0, 1.0, 3.0], "SCALAR")
    translation = g.accessor(flat([(0, 0, 0), (2, 0, 0), (2, 4, 0)]), "VEC3")
    # Rotation about Y: 0, 90 and 180 degrees (x, y, z, w).
    s = math.sqrt(0.5)
    rotation = g.accessor(flat([(0, 0, 0, 1), (0, s, 0, s), (0, 1, 0, 0)]), "VEC4")
    # Cubic scale: in-tangent, value, out-tangent per key.
    cubic = g.accessor(flat([(0, 0, 0), (1, 1, 1), (3, 0, 0),
                             (0, 0, 0), (2, 2, 2), (0, 0, 0),
                             (0, 0, 0), (4, 4, 4), (0, 0, 0)]), "VEC3")
    g.doc["nodes"] = [
        {"name": "Mover", "children": [1]},
        {"name": "Child", "translation": [0, 0, 1]},
        {"name": "Turner"},
        {"name": "Grower"},
        {"name": "Spinner"},
    ]
    g.doc["animations"] = [{"name": "All", "samplers": [
        {"input": times, "output": translation},
        {"input": times, "output": rotation, "interpolation": "STEP"},
        {"input": times, "output": cubic, "interpolation": "CUBICSPLINE"},
        {"input": times, "output": rotation},
    ], "channels": [
        {"sampler": 0, "target": {"node": 0, "path": "translation"}},
        {"sampler": 1, "target": {"node": 2, "path": "rotation"}},
        {"sampler": 2, "target": {"node": 3, "path": "scale"}},
        {"sampler": 3, "target": {"node": 4, "path": "rotation"}},
        {"sampler": 0, "target": {"path": "translation"}},  # no node: ignored, as glTF says
    ]}]
    write_json(os.path.join(HERE, "scenes", "animated.gltf"), g.finish_embedded())


def scene_images():
    """Four external PNGs of different channel layouts, one data-URI PNG and one in a buffer view."""
    g = Gltf()
    rgb = open(os.path.join(HERE, "scenes", "images", "rgb.png"), "rb").read()
    g.doc["images"] = [{"uri": "images/grey.png"}, {"uri": "images/grey_alpha.png"}, {"uri": "images/rgb.png"},
                       {"uri": "images/rgba16.png"},
                       {"uri": "data:image/png;base64," + base64.b64encode(rgb).decode()},
                       {"bufferView": g.view(rgb), "mimeType": "image/png", "name": "in a buffer view"}]
    g.doc["samplers"] = [{"magFilter": 9728, "minFilter": 9986, "wrapS": 33071, "wrapT": 33648}]
    g.doc["textures"] = [{"source": i, "sampler": 0} for i in range(6)]
    g.doc["textures"][5] = {"source": 5}
    write_json(os.path.join(HERE, "scenes", "images.gltf"), g.finish_embedded())


def scene_glb():
    g = Gltf()
    pos = g.accessor(flat([(0, 0, 0), (1, 0, 0), (0, 1, 0)]), "VEC3")
    g.add("meshes", {"primitives": [{"attributes": {"POSITION": pos}}]})
    g.doc["nodes"] = [{"mesh": 0}]
    g.doc["buffers"] = [{"byteLength": len(g.blob)}]
    data = glb(g.doc, g.blob)
    write_bytes(os.path.join(HERE, "scenes", "triangle.glb"), data)
    # Same content, named .gltf: the loader decides by content.
    write_bytes(os.path.join(HERE, "scenes", "triangle_glb_named.gltf"), data)
    return g, data


# ---------------------------------------------------------------- malformed ---------------------
def triangle_base():
    g = Gltf()
    pos = g.accessor(flat([(0, 0, 0), (1, 0, 0), (0, 1, 0)]), "VEC3")
    g.add("meshes", {"primitives": [{"attributes": {"POSITION": pos}}]})
    g.doc["nodes"] = [{"name": "Tri", "mesh": 0}]
    return g


def malformed(name, mutate, base=triangle_base):
    g = base()
    mutate(g)
    write_json(os.path.join(HERE, "malformed", name), g.finish_embedded())


def with_lights(g, lights):
    g.doc["extensions"] = {"KHR_lights_punctual": {"lights": lights}}
    g.doc["nodes"][0]["extensions"] = {"KHR_lights_punctual": {"light": 0}}


def write_malformed(glb_data):
    nan = struct.unpack("<f", struct.pack("<I", 0x7FC00000))[0]

    def nan_translation(g):
        t = g.accessor([0.0, 1.0], "SCALAR")
        v = g.accessor([0, 0, 0, 0, nan, 0], "VEC3")
        g.doc["animations"] = [{"samplers": [{"input": t, "output": v}],
                                "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}]
    malformed("nan_translation.gltf", nan_translation)

    def nan_position(g):
        g.doc["accessors"][0]["bufferView"] = g.view(struct.pack("<9f", 0, 0, 0, 1, nan, 0, 0, 1, 0))
    malformed("nan_position.gltf", nan_position)

    # JSON cannot hold NaN; a number too large for a double is refused by the JSON parser itself.
    with open(os.path.join(HERE, "malformed", "overflow_translation.gltf"), "w") as f:
        f.write('{"asset": {"version": "2.0"},\n "nodes": [{"name": "Far",\n  "translation": [0, 1e400, 0]}]}\n')

    malformed("negative_light_intensity.gltf", lambda g: with_lights(g, [{"name": "Lamp", "type": "point", "intensity": -5}]))
    malformed("unknown_light_type.gltf", lambda g: with_lights(g, [{"type": "area"}]))
    malformed("negative_light_range.gltf", lambda g: with_lights(g, [{"type": "point", "range": -1}]))
    malformed("spot_cone_order.gltf",
              lambda g: with_lights(g, [{"type": "spot", "spot": {"innerConeAngle": 0.7, "outerConeAngle": 0.5}}]))
    malformed("spot_cone_too_wide.gltf", lambda g: with_lights(g, [{"type": "spot", "spot": {"outerConeAngle": 2.0}}]))

    def light_index(g):
        with_lights(g, [{"type": "point"}])
        g.doc["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 3
    malformed("light_index_out_of_range.gltf", light_index)

    def accessor_range(g):
        g.doc["accessors"][0]["count"] = 4  # the view holds 3 VEC3 floats (36 bytes)
    malformed("accessor_out_of_range.gltf", accessor_range)

    def accessor_absurd(g):
        g.doc["accessors"][0]["count"] = 2 ** 28 + 1
    malformed("accessor_absurd_count.gltf", accessor_absurd)

    def bad_stride(g):
        g.doc["bufferViews"][0]["byteStride"] = 8
    malformed("stride_too_small.gltf", bad_stride)

    def index_value(g):
        g.doc["meshes"][0]["primitives"][0]["indices"] = g.accessor([0, 1, 7], "SCALAR", USHORT)
    malformed("index_out_of_range.gltf", index_value)

    def position_vec2(g):
        g.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = g.accessor([0, 0, 1, 0, 0, 1], "VEC2")
    malformed("position_not_vec3.gltf", position_vec2)

    def missing_file(g):
        g.finish_embedded()
        g.doc["buffers"][0]["uri"] = "missing.bin"
    malformed("missing_buffer_file.gltf", missing_file)

    def missing_image(g):
        g.doc["images"] = [{"uri": "no%20such%20image.png"}]
    malformed("missing_image_file.gltf", missing_image)

    def too_wide(g):
        g.doc["images"] = [{"uri": "images/too_wide.png"}]
    malformed("image_too_large.gltf", too_wide)

    def not_image(g):
        g.doc["images"] = [{"uri": "images/not_an_image.png", "name": "Garbage"}]
    malformed("image_not_decodable.gltf", not_image)

    def outside_folder(g):
        g.doc["images"] = [{"uri": "images/../../scenes/images/rgb.png", "name": "Elsewhere"}]
    malformed("image_outside_folder.gltf", outside_folder)

    def node_cycle(g):
        g.doc["nodes"] = [{"name": "A", "children": [1]}, {"name": "B", "children": [2]}, {"name": "C", "children": [0]}]
    malformed("node_cycle.gltf", node_cycle)

    def two_parents(g):
        g.doc["nodes"] = [{"name": "A", "children": [2]}, {"name": "B", "children": [2]}, {"name": "C"}]
    malformed("node_two_parents.gltf", two_parents)

    def self_child(g):
        g.doc["nodes"][0]["children"] = [0]
    malformed("node_own_child.gltf", self_child)

    def bad_background(g):
        g.doc["extensions"] = {"NIMBUS_participating_media": {"background": [1, 2]}}
    malformed("bad_background.gltf", bad_background)

    def root_typo(g):
        g.doc["extensions"] = {"NIMBUS_participating_media": {"ambeint": [1, 1, 1]}}
    malformed("root_typo.gltf", root_typo)

    def unknown_scattering(g):
        g.doc["extensions"] = {"NIMBUS_participating_media": {"scattering": "double"}}
    malformed("unknown_scattering.gltf", unknown_scattering)

    def negative_ambient(g):
        g.doc["extensions"] = {"NIMBUS_participating_media": {"ambient": [0.1, -0.2, 0.1]}}
    malformed("negative_ambient.gltf", negative_ambient)

    def camera_fov(g):
        g.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0, "znear": 0.1}}]
    malformed("camera_zero_yfov.gltf", camera_fov)

    def camera_far(g):
        g.doc["cameras"] = [{"name": "Cam", "type": "perspective", "perspective": {"yfov": 1, "znear": 1, "zfar": 0.5}}]
    malformed("camera_zfar_before_znear.gltf", camera_far)

    def camera_near(g):
        g.doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 1, "znear": -1}}]
    malformed("camera_negative_znear.gltf", camera_near)

    def node_mesh(g):
        g.doc["nodes"][0]["mesh"] = 5
    malformed("node_mesh_out_of_range.gltf", node_mesh)

    def node_string_translation(g):
        g.doc["nodes"][0]["translation"] = "up"
    malformed("translation_not_array.gltf", node_string_translation)

    def matrix_and_trs(g):
        g.doc["nodes"][0]["matrix"] = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
        g.doc["nodes"][0]["scale"] = [2, 2, 2]
    malformed("matrix_and_trs.gltf", matrix_and_trs)

    def times_order(g):
        t = g.accessor([0.0, 2.0, 1.0], "SCALAR")
        v = g.accessor([0] * 9, "VEC3")
        g.doc["animations"] = [{"samplers": [{"input": t, "output": v}],
                                "channels": [{"sampler": 0, "target": {"node": 0, "path": "scale"}}]}]
    malformed("animation_times_decrease.gltf", times_order)

    def cubic_count(g):
        t = g.accessor([0.0, 1.0], "SCALAR")
        v = g.accessor([0] * 6, "VEC3")  # CUBICSPLINE needs 3 values per key
        g.doc["animations"] = [{"samplers": [{"input": t, "output": v, "interpolation": "CUBICSPLINE"}],
                                "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}]
    malformed("animation_output_count.gltf", cubic_count)

    def bad_interpolation(g):
        t = g.accessor([0.0, 1.0], "SCALAR")
        v = g.accessor([0] * 6, "VEC3")
        g.doc["animations"] = [{"samplers": [{"input": t, "output": v, "interpolation": "SMOOTH"}],
                                "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}]
    malformed("animation_unknown_interpolation.gltf", bad_interpolation)

    def required_ext(g):
        g.doc["extensionsRequired"] = ["KHR_draco_mesh_compression"]
    malformed("unsupported_required_extension.gltf", required_ext)

    def bad_base64(g):
        g.finish_embedded()
        uri = g.doc["buffers"][0]["uri"]
        g.doc["buffers"][0]["uri"] = uri[:60] + "!" + uri[61:]
    malformed("bad_base64.gltf", bad_base64)

    def short_data_uri(g):
        g.finish_embedded()
        g.doc["buffers"][0]["byteLength"] += 4
    malformed("buffer_length_mismatch.gltf", short_data_uri)

    def texcoord_missing(g):
        g.doc["images"] = [{"uri": "images/rgb.png"}]
        g.doc["textures"] = [{"source": 0}]
        g.doc["materials"] = [{"name": "Textured", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
        g.doc["meshes"][0]["primitives"][0]["material"] = 0
    malformed("texture_without_texcoord.gltf", texcoord_missing)

    def base_color_range(g):
        g.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorFactor": [1, 2, 0, 1]}}]
    malformed("base_color_out_of_range.gltf", base_color_range)

    def negative_cutoff(g):
        g.doc["materials"] = [{"name": "Leaves", "alphaMode": "MASK", "alphaCutoff": -0.5}]
        g.doc["meshes"][0]["primitives"][0]["material"] = 0
    malformed("alpha_cutoff_negative.gltf", negative_cutoff)

    def emissive_texcoord_missing(g):
        g.doc["images"] = [{"uri": "images/rgb.png"}]
        g.doc["textures"] = [{"source": 0}]
        g.doc["materials"] = [{"name": "Lamp", "emissiveTexture": {"index": 0, "texCoord": 1}}]
        uv = g.accessor([0, 0, 1, 0, 0, 1], "VEC2")
        g.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv
        g.doc["meshes"][0]["primitives"][0]["material"] = 0
    malformed("emissive_texcoord_missing.gltf", emissive_texcoord_missing)

    def color_as_scalar(g):
        g.doc["meshes"][0]["name"] = "Painted"
        g.doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = g.accessor([0.5, 0.5, 0.5], "SCALAR")
    malformed("color_wrong_type.gltf", color_as_scalar)

    def blend(g):
        g.doc["materials"] = [{"name": "Glass", "alphaMode": "BLEND"}]
        g.doc["meshes"][0]["primitives"][0]["material"] = 0
    malformed("alpha_blend.gltf", blend)

    def transform_bad(g):
        g.doc["images"] = [{"uri": "images/rgb.png"}]
        g.doc["textures"] = [{"source": 0}]
        g.doc["materials"] = [{"name": "Tiled", "pbrMetallicRoughness": {"baseColorTexture": {
            "index": 0, "extensions": {"KHR_texture_transform": {"scale": [2]}}}}}]
    malformed("texture_transform_bad_scale.gltf", transform_bad)

    def glb1(g):
        g.doc["asset"]["version"] = "1.0"
    malformed("gltf_version_1.gltf", glb1)

    with open(os.path.join(HERE, "malformed", "syntax_error.gltf"), "w") as f:
        f.write('{"asset": {"version": "2.0"},\n "nodes": [{"name": "Oops",}]\n}\n')

    # A .glb cut short, and one whose header lies about its version.
    write_bytes(os.path.join(HERE, "malformed", "truncated.glb"), glb_data[:len(glb_data) - 20])
    write_bytes(os.path.join(HERE, "malformed", "glb_version_1.glb"), glb_data[:4] + struct.pack("<I", 1) + glb_data[8:])
    write_bytes(os.path.join(HERE, "malformed", "empty.gltf"), b"")


def main():
    write_images()
    scene_primitives()
    scene_lights_cameras()
    scene_animated()
    scene_images()
    _, glb_data = scene_glb()
    write_malformed(glb_data)


if __name__ == "__main__":
    main()
