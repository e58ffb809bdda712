"""A small glTF 2.0 writer for authoring Nimbus content scenes (stdlib only).

Does not: read glTF, or support anything beyond what content scenes use (meshes with
POSITION/NORMAL and optionally TEXCOORD_0/1 and COLOR_0, metallic-roughness materials with PNG
textures, KHR_texture_transform and alpha masks, cameras, KHR_lights_punctual, node animation, and
the NIMBUS_participating_media extension with particle accessors).
"""
import json
import math
import os
import struct
import zlib

EXT = "NIMBUS_participating_media"


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def quat_from_basis(right, up, back):
    """Quaternion (x, y, z, w) of the rotation whose columns are right, up, back."""
    m00, m01, m02 = right[0], up[0], back[0]
    m10, m11, m12 = right[1], up[1], back[1]
    m20, m21, m22 = right[2], up[2], back[2]
    trace = m00 + m11 + m22
    if trace > 0:
        s = 0.5 / math.sqrt(trace + 1.0)
        return [(m21 - m12) * s, (m02 - m20) * s, (m10 - m01) * s, 0.25 / s]
    if m00 > m11 and m00 > m22:
        s = 2.0 * math.sqrt(1.0 + m00 - m11 - m22)
        return [0.25 * s, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s]
    if m11 > m22:
        s = 2.0 * math.sqrt(1.0 + m11 - m00 - m22)
        return [(m01 + m10) / s, 0.25 * s, (m12 + m21) / s, (m02 - m20) / s]
    s = 2.0 * math.sqrt(1.0 + m22 - m00 - m11)
    return [(m02 + m20) / s, (m12 + m21) / s, 0.25 * s, (m10 - m01) / s]


def write_png(path, width, height, pixel):
    """An 8-bit RGBA PNG; pixel(x, y) gives (r, g, b, a) in 0..255, row 0 at the top."""
    rows = bytearray()
    for y in range(height):
        rows.append(0)
        for x in range(width):
            rows.extend(bytes(int(max(0, min(255, round(c)))) for c in pixel(x, y)))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b"")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(png)


def ellipsoid_blob(rng, count, centre, radii, particle_radius, falloff):
    """`count` particles uniform in an ellipsoid (drawn from `rng`), radii uniform in
    `particle_radius`, densities 1 - falloff * (distance from the centre / the ellipsoid's)."""
    positions, sizes, densities = [], [], []
    while len(positions) < count:
        p = [rng.uniform(-1, 1) for _ in range(3)]
        r2 = sum(c * c for c in p)
        if r2 > 1:
            continue
        positions.append([centre[i] + p[i] * radii[i] for i in range(3)])
        sizes.append(rng.uniform(*particle_radius))
        densities.append(1.0 - falloff * math.sqrt(r2))
    return positions, sizes, densities


def look_rotation(eye, target, up=(0.0, 1.0, 0.0)):
    """Rotation making a glTF camera/light (looking down local -Z) at eye look towards target."""
    forward = normalize([t - e for t, e in zip(target, eye)])
    return direction_rotation(forward, up)


def direction_rotation(forward, up=(0.0, 1.0, 0.0)):
    forward = normalize(forward)
    if abs(sum(f * u for f, u in zip(forward, up))) > 0.999:
        up = (1.0, 0.0, 0.0)
    right = normalize(cross(forward, up))
    true_up = cross(right, forward)
    back = [-c for c in forward]
    return quat_from_basis(right, true_up, back)


class Builder:
    def __init__(self):
        self.doc = {
            "asset": {"version": "2.0", "generator": "Nimbus tools/scenegen"},
            "scene": 0,
            "scenes": [{"nodes": []}],
            "nodes": [],
            "meshes": [],
            "materials": [],
            "accessors": [],
            "bufferViews": [],
            "buffers": [],
        }
        self.blob = bytearray()
        self.lights = []
        self.cameras = []
        self.animations = []
        self.root_ext = None
        self.images = {}  # uri relative to the .gltf -> (width, height, pixel function)

    # -- binary data -------------------------------------------------------------------------
    def _view(self, data, target=None):
        while len(self.blob) % 4:
            self.blob.append(0)
        view = {"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.blob.extend(data)
        self.doc["bufferViews"].append(view)
        return len(self.doc["bufferViews"]) - 1

    def accessor_floats(self, values, kind, target=None, with_bounds=False):
        comps = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[kind]
        flat = [float(c) for v in values for c in (v if comps > 1 else [v])]
        view = self._view(struct.pack("<%df" % len(flat), *flat), target)
        acc = {"bufferView": view, "componentType": 5126, "count": len(values), "type": kind}
        if with_bounds or target == 34962:
            acc["min"] = [min(flat[i::comps]) for i in range(comps)]
            acc["max"] = [max(flat[i::comps]) for i in range(comps)]
        if kind == "SCALAR" and target is None and with_bounds:
            pass
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def accessor_indices(self, indices):
        view = self._view(struct.pack("<%dI" % len(indices), *indices), 34963)
        self.doc["accessors"].append({"bufferView": view, "componentType": 5125, "count": len(indices), "type": "SCALAR"})
        return len(self.doc["accessors"]) - 1

    # -- scene objects -----------------------------------------------------------------------
    def texture(self, uri, width, height, pixel, nearest=False, mipmaps=True):
        """A PNG written beside the .gltf (at `uri`) and a texture reading it (repeat; mipmapped
        unless asked: without mipmaps the rasteriser filters as the judge does, one bilinear tap)."""
        self.images[uri] = (width, height, pixel)
        self.doc.setdefault("images", []).append({"uri": uri})
        minify = (9984 if nearest else 9987) if mipmaps else (9728 if nearest else 9729)
        self.doc.setdefault("samplers", []).append(
            {"magFilter": 9728 if nearest else 9729, "minFilter": minify, "wrapS": 10497, "wrapT": 10497})
        self.doc.setdefault("textures", []).append({"sampler": len(self.doc["samplers"]) - 1, "source": len(self.doc["images"]) - 1})
        return len(self.doc["textures"]) - 1

    @staticmethod
    def texture_info(texture, tex_coord=0, scale=None, offset=None, rotation=None):
        info = {"index": texture}
        if tex_coord:
            info["texCoord"] = tex_coord
        transform = {}
        if scale is not None:
            transform["scale"] = list(scale)
        if offset is not None:
            transform["offset"] = list(offset)
        if rotation is not None:
            transform["rotation"] = rotation
        if transform:
            info["extensions"] = {"KHR_texture_transform": transform}
        return info

    def material(self, name, color, double_sided=False, metallic=0.0, roughness=1.0, base_texture=None,
                 metallic_roughness_texture=None, emissive=None, emissive_texture=None, alpha_cutoff=None, alpha=1.0):
        """A metallic-roughness material; textures are texture_info() objects. metallic 0 and
        roughness 1 unless asked (glTF's own defaults would make a rough metal)."""
        pbr = {"baseColorFactor": list(color) + [alpha], "metallicFactor": metallic, "roughnessFactor": roughness}
        if base_texture is not None:
            pbr["baseColorTexture"] = base_texture
        if metallic_roughness_texture is not None:
            pbr["metallicRoughnessTexture"] = metallic_roughness_texture
        m = {"name": name, "pbrMetallicRoughness": pbr}
        if emissive is not None:
            m["emissiveFactor"] = list(emissive)
        if emissive_texture is not None:
            m["emissiveTexture"] = emissive_texture
        if alpha_cutoff is not None:
            m["alphaMode"] = "MASK"
            m["alphaCutoff"] = alpha_cutoff
        if double_sided:
            m["doubleSided"] = True
        for key in ("baseColorTexture", "metallicRoughnessTexture"):
            if "extensions" in pbr.get(key, {}):
                self.uses("KHR_texture_transform")
        if "extensions" in m.get("emissiveTexture", {}):
            self.uses("KHR_texture_transform")
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def uses(self, extension):
        used = self.doc.setdefault("extensionsUsed", [])
        if extension not in used:
            used.append(extension)

    def mesh(self, name, positions, normals, indices, material, uv0=None, uv1=None, colors=None):
        attributes = {"POSITION": self.accessor_floats(positions, "VEC3", 34962),
                      "NORMAL": self.accessor_floats(normals, "VEC3", 34962)}
        if uv0 is not None:
            attributes["TEXCOORD_0"] = self.accessor_floats(uv0, "VEC2", 34962)
        if uv1 is not None:
            attributes["TEXCOORD_1"] = self.accessor_floats(uv1, "VEC2", 34962)
        if colors is not None:
            attributes["COLOR_0"] = self.accessor_floats(colors, "VEC4" if len(colors[0]) == 4 else "VEC3", 34962)
        idx = self.accessor_indices(indices)
        self.doc["meshes"].append({"name": name, "primitives": [{"attributes": attributes, "indices": idx, "material": material}]})
        return len(self.doc["meshes"]) - 1

    def sphere_mesh(self, name, radius, material, columns=48, rows=24):
        positions, normals, uvs, indices = [], [], [], []
        for r in range(rows + 1):
            for c in range(columns + 1):
                theta, phi = math.pi * r / rows, 2 * math.pi * c / columns
                n = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
                normals.append(n)
                positions.append([radius * x for x in n])
                uvs.append([c / columns, r / rows])
        at = lambda r, c: r * (columns + 1) + c  # noqa: E731
        for r in range(rows):
            for c in range(columns):
                if r > 0:
                    indices += [at(r, c), at(r + 1, c), at(r, c + 1)]
                if r + 1 < rows:
                    indices += [at(r, c + 1), at(r + 1, c), at(r + 1, c + 1)]
        return self.mesh(name, positions, normals, indices, material, uv0=uvs)

    def box_mesh(self, name, size, material, uv_scale=None, colors=None):
        """A box; with uv_scale (metres per texture repeat) each face gets TEXCOORD_0 in metres /
        uv_scale, v downwards; with colors (one per face) COLOR_0."""
        hx, hy, hz = (s / 2 for s in size)
        faces = [((1, 0, 0), (0, 0, -1), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
                 ((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
                 ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0))]
        positions, normals, indices, uvs, vertex_colors = [], [], [], [], []
        half = (hx, hy, hz)
        for f, (n, u, v) in enumerate(faces):
            base = len(positions)
            for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [n[i] * half[i] + su * u[i] * half[i] + sv * v[i] * half[i] for i in range(3)]
                positions.append(p)
                normals.append(list(n))
                if uv_scale:
                    width = sum(abs(u[i]) * size[i] for i in range(3))
                    height = sum(abs(v[i]) * size[i] for i in range(3))
                    uvs.append([(su + 1) / 2 * width / uv_scale, (1 - sv) / 2 * height / uv_scale])
                if colors:
                    vertex_colors.append(list(colors[f]))
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
        return self.mesh(name, positions, normals, indices, material, uv0=uvs or None, colors=vertex_colors or None)

    def plane_mesh(self, name, half_x, half_z, material, uv_scale=None):
        positions = [[-half_x, 0, half_z], [half_x, 0, half_z], [half_x, 0, -half_z], [-half_x, 0, -half_z]]
        normals = [[0, 1, 0]] * 4
        uvs = None
        if uv_scale:
            uvs = [[p[0] / uv_scale, p[2] / uv_scale] for p in positions]
        return self.mesh(name, positions, normals, [0, 1, 2, 0, 2, 3], material, uv0=uvs)

    def node(self, name, translation=None, rotation=None, scale=None, mesh=None, camera=None, light=None,
             ext=None, root=True):
        n = {"name": name}
        if translation is not None:
            n["translation"] = [float(c) for c in translation]
        if rotation is not None:
            n["rotation"] = [float(c) for c in rotation]
        if scale is not None:
            n["scale"] = [float(c) for c in scale]
        if mesh is not None:
            n["mesh"] = mesh
        if camera is not None:
            n["camera"] = camera
        if light is not None:
            n.setdefault("extensions", {})["KHR_lights_punctual"] = {"light": light}
        if ext is not None:
            n.setdefault("extensions", {})[EXT] = ext
        self.doc["nodes"].append(n)
        index = len(self.doc["nodes"]) - 1
        if root:
            self.doc["scenes"][0]["nodes"].append(index)
        return index

    def camera(self, name, eye, target, yfov=0.7, znear=0.1, zfar=None):
        cam = {"name": name, "type": "perspective", "perspective": {"yfov": yfov, "znear": znear}}
        if zfar:
            cam["perspective"]["zfar"] = zfar
        self.cameras.append(cam)
        return self.node(name, translation=eye, rotation=look_rotation(eye, target), camera=len(self.cameras) - 1)

    def sun(self, name, direction, intensity, color=(1.0, 1.0, 1.0)):
        self.lights.append({"name": name, "type": "directional", "intensity": intensity, "color": list(color)})
        return self.node(name, rotation=direction_rotation(direction), light=len(self.lights) - 1)

    def spot(self, name, position, direction, intensity, inner, outer, range_=None, color=(1.0, 1.0, 1.0)):
        light = {"name": name, "type": "spot", "intensity": intensity, "color": list(color),
                 "spot": {"innerConeAngle": inner, "outerConeAngle": outer}}
        if range_:
            light["range"] = range_
        self.lights.append(light)
        return self.node(name, translation=position, rotation=direction_rotation(direction), light=len(self.lights) - 1)

    def point(self, name, position, intensity, range_=None, color=(1.0, 1.0, 1.0)):
        light = {"name": name, "type": "point", "intensity": intensity, "color": list(color)}
        if range_:
            light["range"] = range_
        self.lights.append(light)
        return self.node(name, translation=position, light=len(self.lights) - 1)

    def environment(self, background, ambient):
        self.root_ext = {"background": list(background), "ambient": list(ambient)}

    def particles(self, positions, radii, densities=None):
        """The `particles` object of the node extension (docs/design.md §4)."""
        p = {"position": self.accessor_floats(positions, "VEC3", with_bounds=True),
             "radius": self.accessor_floats(radii, "SCALAR")}
        if densities is not None:
            p["density"] = self.accessor_floats(densities, "SCALAR")
        return p

    def animate_translation(self, node, times, translations, name="motion"):
        t = self.accessor_floats(times, "SCALAR", with_bounds=True)
        v = self.accessor_floats(translations, "VEC3")
        self.animations.append({"name": name, "samplers": [{"input": t, "output": v, "interpolation": "LINEAR"}],
                                "channels": [{"sampler": 0, "target": {"node": node, "path": "translation"}}]})

    # -- output ------------------------------------------------------------------------------
    def write(self, path_gltf):
        import os
        base = os.path.splitext(os.path.basename(path_gltf))[0]
        doc = dict(self.doc)
        used = list(doc.pop("extensionsUsed", []))
        for uri, (width, height, pixel) in self.images.items():
            write_png(os.path.join(os.path.dirname(path_gltf), uri), width, height, pixel)
        if self.lights:
            doc.setdefault("extensions", {})["KHR_lights_punctual"] = {"lights": self.lights}
            used.append("KHR_lights_punctual")
        if self.root_ext is not None or any(EXT in n.get("extensions", {}) for n in doc["nodes"]):
            used.append(EXT)
        if self.root_ext is not None:
            doc.setdefault("extensions", {})[EXT] = self.root_ext
        if self.cameras:
            doc["cameras"] = self.cameras
        if self.animations:
            doc["animations"] = self.animations
        if used:
            doc["extensionsUsed"] = used
        for key in ("meshes", "materials"):
            if not doc[key]:
                del doc[key]
        doc["buffers"] = [{"uri": base + ".bin", "byteLength": len(self.blob)}]
        with open(os.path.join(os.path.dirname(path_gltf), base + ".bin"), "wb") as f:
            f.write(self.blob)
        with open(path_gltf, "w") as f:
            json.dump(doc, f, indent=1)
            f.write("\n")
