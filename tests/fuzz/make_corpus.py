#!/usr/bin/env python3
"""Writes the scene fuzz target's seed corpus (tests/fuzz/corpus/scene/) from files already in the
repository: the content scenes, the tests' malformed files and the third-party models of
tests/data. Each becomes one self-contained file (its buffers and images as data URIs), since the
fuzz entry reads one file from memory; a few are also written as .glb. Files over MAX_BYTES are
left out: a fuzzer mutates small inputs fastest.

Usage: tests/fuzz/make_corpus.py   (rewrites corpus/scene; the other corpora are written by hand)
"""
import base64
import json
import os
import struct
import urllib.parse

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
OUT = os.path.join(ROOT, "tests", "fuzz", "corpus", "scene")
MAX_BYTES = 24 * 1024
SOURCES = [
    "content/scenes",
    "tests/data/malformed",
    "tests/data/media_scenes",
    "tests/data/scenes",
    "tests/data/khronos/Box",
    "tests/data/tinygltf/BoundsChecking",
    "tests/data/tinygltf/Cube",
    "tests/data/tinygltf/CubeImageUriSpaces",
    "tests/data/tinygltf/Extensions-issue97",
    "tests/data/tinygltf/Extensions-overwrite-issue261",
    "tests/data/tinygltf/regression",
    "tests/data/tinygltf/SparseMorphTargets-issue280",
    "tests/data/tinygltf",
]
GLB_TOO = {"smoke.gltf", "campfire.gltf", "fog_smoke.gltf", "animated.gltf", "unseen_spot_inside.gltf"}
MEDIA_TYPES = {".bin": "application/octet-stream", ".png": "image/png", ".jpg": "image/jpeg", ".jpeg": "image/jpeg"}


def embed(gltf, folder):
    """Replaces every relative URI that names an existing file with a data URI of its bytes."""
    for array in ("buffers", "images"):
        for item in gltf.get(array, []):
            uri = item.get("uri") if isinstance(item, dict) else None
            if not isinstance(uri, str) or uri.startswith("data:"):
                continue
            path = os.path.join(folder, urllib.parse.unquote(uri))
            if os.path.isfile(path):
                kind = MEDIA_TYPES.get(os.path.splitext(path)[1].lower(), "application/octet-stream")
                item["uri"] = "data:%s;base64,%s" % (kind, base64.b64encode(open(path, "rb").read()).decode())
    return gltf


def glb(gltf):
    """The scene as one GLB, buffer 0 (a data URI) moved into the BIN chunk."""
    gltf = json.loads(json.dumps(gltf))
    bin_chunk = b""
    buffers = gltf.get("buffers", [])
    if buffers and buffers[0].get("uri", "").startswith("data:"):
        bin_chunk = base64.b64decode(buffers[0]["uri"].split(",", 1)[1])
        del buffers[0]["uri"]
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    bin_chunk += b"\0" * (-len(bin_chunk) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text
    if bin_chunk:
        chunks += struct.pack("<I4s", len(bin_chunk), b"BIN\0") + bin_chunk
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def write(name, data):
    if len(data) > MAX_BYTES:
        return False
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(data)
    return True


def main():
    os.makedirs(OUT, exist_ok=True)
    for old in os.listdir(OUT):
        os.remove(os.path.join(OUT, old))
    written, skipped = 0, []
    for source in SOURCES:
        folder = os.path.join(ROOT, source)
        prefix = source.replace("tests/data/", "").replace("/", "_")
        for name in sorted(os.listdir(folder)):
            path = os.path.join(folder, name)
            if not os.path.isfile(path):
                continue
            raw = open(path, "rb").read()
            if name.endswith(".glb"):
                ok = write(prefix + "_" + name, raw)
            elif name.endswith(".gltf"):
                try:
                    gltf = json.loads(raw)
                except ValueError:
                    ok = write(prefix + "_" + name, raw)  # malformed on purpose: as it is
                else:
                    gltf = embed(gltf, folder) if isinstance(gltf, dict) else gltf
                    data = json.dumps(gltf, separators=(",", ":")).encode()
                    ok = write(prefix + "_" + name, data)
                    if ok and name in GLB_TOO:
                        written += write(prefix + "_" + name[:-5] + ".glb", glb(gltf))
            else:
                continue
            written += ok
            if not ok:
                skipped.append(source + "/" + name)
    print("wrote %d seeds to %s; over %d bytes, left out: %s" % (written, OUT, MAX_BYTES, ", ".join(skipped) or "none"))


if __name__ == "__main__":
    main()
