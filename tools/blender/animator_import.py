# Opens an animator glTF export in Blender with its motion exact (docs/export.md):
#
#   blender --python tools/blender/animator_import.py -- ANIMATION.glb
#
# Blender's glTF importer (3.4, and later versions as of this writing: its source says
# "TODO manage tangent?") reads a CUBICSPLINE key's value but drops its two tangents and gives
# the key automatic handles, so free flight between bounces would be an automatic curve rather
# than the parabola the file holds. After importing, this script sets each such key's Bezier
# handles from the file's tangents: a cubic Hermite span with derivatives a and b over dt is the
# Bezier curve with handles a dt / 3 after its start and b dt / 3 before its end, which Blender
# evaluates exactly as glTF does.
import base64
import json
import struct
import sys

import bpy

COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}


def read_gltf(path):
    """The glTF JSON and its first buffer's bytes, from a .glb or a .gltf with its buffer inside."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] == b"glTF":
        offset, doc, binary = 12, None, b""
        while offset < len(data):
            length, kind = struct.unpack_from("<II", data, offset)
            offset += 8
            if kind == 0x4E4F534A:
                doc = json.loads(data[offset:offset + length])
            elif kind == 0x004E4942:
                binary = data[offset:offset + length]
            offset += length
        return doc, binary
    doc = json.loads(data)
    uri = doc["buffers"][0].get("uri", "") if doc.get("buffers") else ""
    binary = base64.b64decode(uri.split(",", 1)[1]) if uri.startswith("data:") else b""
    return doc, binary


def accessor(doc, binary, index):
    a = doc["accessors"][index]
    view = doc["bufferViews"][a["bufferView"]]
    n = COMPONENTS[a["type"]]
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    values = struct.unpack_from("<%df" % (n * a["count"]), binary, start)
    return [values[k * n:(k + 1) * n] for k in range(a["count"])]


def to_blender(path, v):
    """glTF (Y up) to Blender (Z up), as Blender's importer turns values."""
    x, y, z = v
    return (x, -z, y) if path == "translation" else (x, z, y)


def set_tangents(path_to_file):
    """Sets the handles of every CUBICSPLINE channel's keys; returns how many keys it set."""
    doc, binary = read_gltf(path_to_file)
    fps = bpy.context.scene.render.fps / bpy.context.scene.render.fps_base
    done = 0
    for animation in doc.get("animations", []):
        for channel in animation["channels"]:
            sampler = animation["samplers"][channel["sampler"]]
            path = channel["target"].get("path")
            if sampler.get("interpolation") != "CUBICSPLINE" or path not in ("translation", "scale"):
                continue
            name = doc["nodes"][channel["target"]["node"]].get("name", "")
            obj = bpy.data.objects.get(name)
            if obj is None or obj.animation_data is None or obj.animation_data.action is None:
                print("animator_import: no animated object '%s' in Blender; its tangents are left" % name)
                continue
            times = [t[0] for t in accessor(doc, binary, sampler["input"])]
            out = accessor(doc, binary, sampler["output"])
            ins = [to_blender(path, out[3 * k]) for k in range(len(times))]
            outs = [to_blender(path, out[3 * k + 2]) for k in range(len(times))]
            data_path = "location" if path == "translation" else "scale"
            for axis in range(3):
                curve = obj.animation_data.action.fcurves.find(data_path, index=axis)
                if curve is None or len(curve.keyframe_points) != len(times):
                    print("animator_import: '%s' %s: Blender's keys are not the file's; its tangents are left"
                          % (name, data_path))
                    continue
                for k, key in enumerate(curve.keyframe_points):
                    before = times[k] - times[k - 1] if k > 0 else times[1] - times[0]
                    after = times[k + 1] - times[k] if k + 1 < len(times) else before
                    frame, value = key.co
                    key.interpolation = "BEZIER"
                    key.handle_left_type = key.handle_right_type = "FREE"
                    key.handle_left = (frame - before * fps / 3.0, value - ins[k][axis] * before / 3.0)
                    key.handle_right = (frame + after * fps / 3.0, value + outs[k][axis] * after / 3.0)
                    done += 1
    return done


def import_animator_gltf(path_to_file):
    """Imports the file with Blender's importer, then its tangents."""
    result = bpy.ops.import_scene.gltf(filepath=path_to_file)
    if "FINISHED" not in result:
        raise RuntimeError("Blender did not import " + path_to_file)
    return set_tangents(path_to_file)


if __name__ == "__main__":
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(args) != 1:
        raise SystemExit("usage: blender --python animator_import.py -- ANIMATION.glb")
    # Blender 3.4's importer still says numpy.bool, which numpy 1.24 removed.
    import numpy
    if not hasattr(numpy, "bool"):
        numpy.bool = numpy.bool_
    keys = import_animator_gltf(args[0])
    print("animator_import: %s: %d keys given the file's tangents" % (args[0], keys))
