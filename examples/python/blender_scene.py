"""A Blender scene built from a GridIFS project, run inside Blender:

    blender -b --factory-startup --python examples/python/blender_scene.py -- PROJECT OUT.png [FRAME]

It enables the GridIFS add-on from blender/, imports the project as a point cloud through
File > Import > GridIFS, adds a camera and a ground plane, and renders a frame with Cycles.
GRIDIFS_PYTHON_DIR names the module's folder (default: build/python of this checkout).
"""
import math
import os
import sys

import addon_utils
import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
project = args[0] if args else os.path.join(ROOT, "assets", "twisted_functions.gridifs")
output = os.path.abspath(args[1] if len(args) > 1 else "gridifs_blender.png")
frame = int(args[2]) if len(args) > 2 else 1

bpy.ops.wm.read_factory_settings(use_empty=True)
sys.path.insert(0, os.path.join(ROOT, "blender"))
addon_utils.enable("io_import_gridifs", default_set=True)
prefs = bpy.context.preferences.addons["io_import_gridifs"].preferences
prefs.module_folder = os.environ.get("GRIDIFS_PYTHON_DIR", os.path.join(ROOT, "build", "python"))

bpy.ops.import_scene.gridifs(filepath=project, kind="POINTS", points=400000, radius=0.003)
scene = bpy.context.scene

bpy.ops.mesh.primitive_plane_add(size=6, location=(0, 0, -1.05))
camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
scene.collection.objects.link(camera)
camera.location = (3.0, -3.0, 1.8)
camera.rotation_euler = (math.radians(68), 0, math.radians(45))
scene.camera = camera
sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
sun.data.energy = 2.0
scene.collection.objects.link(sun)

scene.world = bpy.data.worlds.new("World")
scene.world.color = (0.02, 0.02, 0.03)
scene.render.engine = "CYCLES"
scene.cycles.samples = 32
scene.cycles.use_denoising = False  # Debian builds Blender without OpenImageDenoise
scene.render.resolution_x, scene.render.resolution_y = 640, 480
scene.render.resolution_percentage = 50
scene.render.filepath = output
scene.frame_set(frame)  # an animated project's points follow the frame (the add-on's handler)
bpy.ops.render.render(write_still=True)
print(output)
