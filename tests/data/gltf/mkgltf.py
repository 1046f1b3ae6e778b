#!/usr/bin/env python3
"""Writes the small glTF 2.0 test files of this directory.

Not needed to run the tests: its outputs are committed.  Rerun it
(python3 tests/data/gltf/mkgltf.py) after changing it.  Each file holds
one feature the reader must handle, with values the tests check exactly
(tests/test_meshio.c, tests/scene_gltf.sh); they also seed the glTF
fuzzer (tests/fuzz/corpus/gltf/).
"""
import base64, json, os, struct

HERE = os.path.dirname(os.path.abspath(__file__))

def uri(b):
    return "data:application/octet-stream;base64," + base64.b64encode(b).decode()

def f32(*v):
    return struct.pack("<%df" % len(v), *v)

def write(name, doc):
    with open(os.path.join(HERE, name), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")

def tri_box():
    # 4 vertices of a tetrahedron-ish fan, 2 triangles, positions float
    pos = f32(0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1)
    idx = struct.pack("<6H", 0, 1, 2, 0, 2, 3)
    return pos, idx

def asset():
    return {"version": "2.0", "generator": "onbstudy tests/data/gltf/mkgltf.py"}

# 1. float normals, interleaved with positions (byteStride 24), indices,
#    a node with a matrix, parent of a TRS node; both instance mesh 0.
def float_strided():
    nrm = [(0.6, 0.8, 0.0), (0.0, 0.0, 1.0), (0.0, -1.0, 0.0), (1.0, 0.0, 0.0)]
    pos = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    inter = b"".join(f32(*p) + f32(*n) for p, n in zip(pos, nrm))
    idx = struct.pack("<6H", 0, 1, 2, 0, 2, 3)
    buf = inter + idx
    write("strided.gltf", {
        "asset": asset(), "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"matrix": [2, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1], "mesh": 0, "children": [1]},
                  {"scale": [1, 1, 8], "translation": [1, 2, 3], "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
        "buffers": [{"byteLength": len(buf), "uri": uri(buf)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(inter), "byteStride": 24},
                        {"buffer": 0, "byteOffset": len(inter), "byteLength": len(idx)}],
        "accessors": [{"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                      {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 4, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]})

# 2. KHR_mesh_quantization: BYTE and SHORT normalized normals
def quantized():
    nb = struct.pack("<12b", -128, 0, 0, 127, 0, 0, 64, -64, 0, 1, 2, 3)
    nb += b"\0" * 4  # 16 bytes: stride 4 per element (3 + 1 pad)
    nb = struct.pack("<16b", -128, 0, 0, 0, 127, 0, 0, 0, 64, -64, 0, 0, 1, 2, 3, 0)
    ns = struct.pack("<16h", -32768, 0, 0, 0, 32767, 0, 0, 0, 12345, -23456, 0, 0, 1, 2, 3, 0)
    pos = struct.pack("<16h", 0, 0, 0, 0, 100, 0, 0, 0, 0, 100, 0, 0, 0, 0, 100, 0)
    buf = nb + ns + pos
    write("quantized.gltf", {
        "asset": asset(), "extensionsUsed": ["KHR_mesh_quantization"], "extensionsRequired": ["KHR_mesh_quantization"],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 2, "NORMAL": 0}},
                                   {"attributes": {"POSITION": 2, "NORMAL": 1}}]}],
        "buffers": [{"byteLength": len(buf), "uri": uri(buf)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 16, "byteStride": 4},
                        {"buffer": 0, "byteOffset": 16, "byteLength": 32, "byteStride": 8},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 32, "byteStride": 8}],
        "accessors": [{"bufferView": 0, "componentType": 5120, "normalized": True, "count": 4, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5122, "normalized": True, "count": 4, "type": "VEC3"},
                      {"bufferView": 2, "componentType": 5122, "count": 4, "type": "VEC3"}]})

# 3. sparse accessors: one over a bufferView, one without (zeros), and a
#    primitive without NORMAL (computed from its triangles)
def sparse():
    base = f32(0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1)
    sidx = struct.pack("<2H", 1, 3)
    sval = f32(1, 0, 0, 0, -1, 0)
    pos, idx = tri_box()
    buf = base + sidx + sval + pos + idx
    o = [0, len(base), len(base) + 4, len(base) + 4 + len(sval), len(base) + 4 + len(sval) + len(pos)]
    write("sparse.gltf", {
        "asset": asset(),
        "meshes": [{"primitives": [{"attributes": {"POSITION": 3, "NORMAL": 0}}, {"attributes": {"POSITION": 3, "NORMAL": 1}},
                                   {"attributes": {"POSITION": 3}, "indices": 2}]}],
        "buffers": [{"byteLength": len(buf), "uri": uri(buf)}],
        "bufferViews": [{"buffer": 0, "byteOffset": o[0], "byteLength": len(base)},
                        {"buffer": 0, "byteOffset": o[1], "byteLength": 4},
                        {"buffer": 0, "byteOffset": o[2], "byteLength": len(sval)},
                        {"buffer": 0, "byteOffset": o[3], "byteLength": len(pos)},
                        {"buffer": 0, "byteOffset": o[4], "byteLength": len(idx)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "sparse": {"count": 2, "indices": {"bufferView": 1, "componentType": 5123},
                                  "values": {"bufferView": 2}}},
                      {"componentType": 5126, "count": 4, "type": "VEC3",
                       "sparse": {"count": 2, "indices": {"bufferView": 1, "componentType": 5123},
                                  "values": {"bufferView": 2}}},
                      {"bufferView": 4, "componentType": 5123, "count": 6, "type": "SCALAR"},
                      {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC3"}]})

# 4. a .glb: two scenes (the default is 1), a rotation node
def glb():
    nrm = f32(1, 0, 0, 0, 1, 0, 0, 0, 1)
    pos = f32(0, 0, 0, 1, 0, 0, 0, 1, 0)
    binc = nrm + pos
    doc = {"asset": asset(), "scene": 1, "scenes": [{"nodes": [0]}, {"nodes": [1]}],
           "nodes": [{"mesh": 0}, {"rotation": [0, 0, 0.7071067811865476, 0.7071067811865476], "mesh": 0}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 1, "NORMAL": 0}}]}],
           "buffers": [{"byteLength": len(binc)}],
           "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                         {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"}]}
    js = json.dumps(doc).encode()
    js += b" " * (-len(js) % 4)
    binc += b"\0" * (-len(binc) % 4)
    body = struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(binc), 0x004E4942) + binc
    with open(os.path.join(HERE, "rotated.glb"), "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body)

# 5. an external buffer (read from the file's directory)
def external():
    nrm = f32(0, 0, 1, 0, 0, -1, 0.6, 0, 0.8)
    with open(os.path.join(HERE, "external buf.bin"), "wb") as f:
        f.write(nrm)
    write("external.gltf", {
        "asset": asset(),
        "meshes": [{"primitives": [{"attributes": {"NORMAL": 0}, "mode": 0}]}],
        "buffers": [{"byteLength": len(nrm), "uri": "external%20buf.bin"}],
        "bufferViews": [{"buffer": 0, "byteLength": len(nrm)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}]})

float_strided(); quantized(); sparse(); glb(); external()
