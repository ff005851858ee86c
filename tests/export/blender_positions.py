# Run by Blender (blender -b --factory-startup --python-exit-code 1 --python THIS -- FILE.glb OUT.csv T...):
# imports a glTF file with Blender's own importer (and the tangents it drops:
# tools/blender/animator_import.py) and writes every object's world position at
# each time T (seconds), in glTF's axes (Y up), as CSV: t,name,x,y,z.
import sys

import numpy

# Blender 3.4's glTF importer still says numpy.bool, which numpy 1.24 removed.
if not hasattr(numpy, "bool"):
    numpy.bool = numpy.bool_

import os

import bpy

sys.dont_write_bytecode = True  # nothing written into the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "blender"))
import animator_import  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
gltf, out, times = args[0], args[1], [float(t) for t in args[2:]]

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.fps, scene.render.fps_base = 1000, 1.0  # frames of a millisecond: times read back finely
animator_import.import_animator_gltf(gltf)

objects = [o for o in scene.objects]
with open(out, "w") as f:
    f.write("t,name,x,y,z\n")
    for t in times:
        frame = t * scene.render.fps / scene.render.fps_base
        whole = int(frame // 1)
        scene.frame_set(whole, subframe=frame - whole)
        for o in objects:
            p = o.matrix_world.translation
            # Blender is Z up; its importer turned glTF's (x, y, z) into (x, -z, y).
            f.write("%r,%s,%r,%r,%r\n" % (t, o.name, p.x, p.z, -p.y))
