#!/usr/bin/env python3
"""Checks an animator glTF export with the programs people open it with (docs/export.md):

1. `animator export FILE --to OUT` writes it;
2. the Khronos glTF Validator (tools/gltf-validator, run by Node) reports 0 errors and 0 warnings;
3. Blender (headless) imports it (tools/blender/animator_import.py), and every model's world
   position at 50 or more sampled times agrees with `animator bake --trace` to 1e-4 m (or, for a
   model so far from the origin that float32 cannot hold that, to 1e-6 of its distance).

Exit 0 when all hold; otherwise 1 with the reason (a missing Node, validator or Blender is a
failure that says how to install it)."""
import argparse
import csv
import json
import math
import os
import shutil
import struct
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def run(command, what, timeout=1200, env=None):
    print("$ " + " ".join(command), flush=True)
    r = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=timeout, env=env)
    print(r.stdout[-4000:])
    if r.returncode != 0:
        fail("%s exited with %d" % (what, r.returncode))
    return r.stdout


def gltf_json(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != b"glTF":
        return json.loads(data)
    length, kind = struct.unpack_from("<II", data, 12)
    assert kind == 0x4E4F534A
    return json.loads(data[20:20 + length])


# 4x4 matrices as lists of rows.
def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def translation(x, y, z):
    return [[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z], [0, 0, 0, 1]]


def scaling(x, y, z):
    return [[x, 0, 0, 0], [0, y, 0, 0], [0, 0, z, 0], [0, 0, 0, 1]]


def rotation(axis, degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    if axis == 0:
        return [[1, 0, 0, 0], [0, c, -s, 0], [0, s, c, 0], [0, 0, 0, 1]]
    if axis == 1:
        return [[c, 0, s, 0], [0, 1, 0, 0], [-s, 0, c, 0], [0, 0, 0, 1]]
    return [[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]


def quaternion_matrix(x, y, z, w):
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), 0],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), 0],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), 0],
            [0, 0, 0, 1]]


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--animator", required=True)
    p.add_argument("--scene", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--format", default="glb", choices=["glb", "gltf"])
    p.add_argument("--samples", type=int, default=50)
    p.add_argument("--tolerance", type=float, default=1e-4)
    p.add_argument("--blender", default="blender")
    a = p.parse_args()

    os.makedirs(a.work, exist_ok=True)
    name = os.path.splitext(os.path.basename(a.scene))[0]
    out = os.path.join(a.work, "%s.%s" % (name, a.format))
    run([a.animator, "export", a.scene, "--to", out], "animator export")

    # The validator.
    node = shutil.which("node")
    validator = os.path.join(SOURCE, "tools", "gltf-validator")
    if node is None:
        fail("Node.js is not installed (tools/install-deps.sh installs it)")
    if not os.path.isdir(os.path.join(validator, "node_modules", "gltf-validator")):
        fail("the glTF Validator is not installed in tools/gltf-validator (tools/install-deps.sh runs npm ci there)")
    report = run([node, os.path.join(validator, "validate.mjs"), out], "the glTF Validator")
    if " 0 errors, 0 warnings" not in report:
        fail("the glTF Validator found errors or warnings")

    # The bake's trace at the sampled times (and keyframe times).
    doc = gltf_json(out)
    end = 0.0
    for animation in doc.get("animations", []):
        for s in animation["samplers"]:
            end = max(end, doc["accessors"][s["input"]]["max"][0])
    trace = os.path.join(a.work, name + ".trace.csv")
    step = end / (a.samples - 1) if end > 0 else 1.0
    run([a.animator, "bake", a.scene, "--until", repr(end), "--step", repr(step), "--trace", trace], "animator bake")
    rows = list(csv.DictReader(open(trace)))
    times = sorted({float(r["t"]) for r in rows})
    if len(times) < a.samples:
        fail("the trace has %d times, fewer than %d" % (len(times), a.samples))

    # Blender.
    blender = shutil.which(a.blender)
    if blender is None:
        fail("Blender is not installed (tools/install-deps.sh installs Debian's blender and python3-numpy)")
    positions = os.path.join(a.work, name + ".blender.csv")
    # Blender's Python finds its standard library from the python3 on PATH: a pyenv one put first
    # there (by a pyenv shim running this script) would lend it one without the system's numpy.
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYENV") and not k.startswith("PYTHON")}
    env["PATH"] = os.pathsep.join(d for d in os.environ.get("PATH", "").split(os.pathsep) if ".pyenv" not in d)
    run([blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python",
         os.path.join(HERE, "blender_positions.py"), "--", out, positions] + [repr(t) for t in times], "Blender", env=env)
    blender_at = {}
    for r in csv.DictReader(open(positions)):
        blender_at[(float(r["t"]), r["name"])] = (float(r["x"]), float(r["y"]), float(r["z"]))

    # World positions from the trace: each model's T R S (X then Y then Z about its own axes)
    # under its parent's, the tree read from the file's nodes.
    parent = {}
    for n in doc["nodes"]:
        for c in n.get("children", []):
            parent[doc["nodes"][c].get("name")] = n.get("name")
    world_turn = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
    for n in doc["nodes"]:
        if n.get("name") == "animator world":
            world_turn = quaternion_matrix(*n["rotation"])
    by_time = {}
    for r in rows:
        by_time.setdefault(float(r["t"]), {})[r["model"]] = r
    # 1e-4 m, or 1e-6 of the distance from the origin where that is larger: glTF's accessors are
    # float32, which holds about 7 digits of a position and of a time (ramp_boxes.lua's box has
    # slid 38 km by 100 s, where one float32 step is 4 mm).
    def allowed(p):
        return max(a.tolerance, 1e-6 * max(abs(c) for c in p))

    worst, where, checked = 0.0, "", 0
    for t in times:
        local, world = {}, {}
        for model, r in by_time[t].items():
            f = {k: float(v) for k, v in r.items() if k not in ("model",)}
            m = translation(f["x"], f["y"], f["z"])
            for axis, key in enumerate(("rx", "ry", "rz")):
                m = matmul(m, rotation(axis, f[key]))
            local[model] = matmul(m, scaling(f["sx"], f["sy"], f["sz"]))

        def world_of(model):
            if model not in world:
                up = parent.get(model)
                world[model] = matmul(world_of(up), local[model]) if up in local else matmul(world_turn, local[model])
            return world[model]

        for model in by_time[t]:
            w = world_of(model)
            ours = (w[0][3], w[1][3], w[2][3])
            theirs = blender_at.get((t, model))
            if theirs is None:
                fail("Blender has no object '%s' at %r s" % (model, t))
            d = math.dist(ours, theirs)
            checked += 1
            if d / allowed(ours) > worst:
                worst, where = d / allowed(ours), "'%s' at %r s: bake %r, Blender %r, %.3g m apart, %.3g m allowed" % (
                    model, t, ours, theirs, d, allowed(ours))
    print("%d positions at %d times checked; the largest difference against what is allowed: %.3g (%s)" % (
        checked, len(times), worst, where))
    if worst > 1.0:
        fail("a position differs by more than 1e-4 m (or 1e-6 of its distance from the origin where that is larger)")
    print("PASSED")


if __name__ == "__main__":
    main()
