"""Runs inside Blender (tests/blender/run_blender_test): enables the GridIFS add-on, imports a
point-cloud project, a volume project and an animated one through import_scene.gridifs, follows a
frame change and renders the points with Cycles. Any failed check raises, and Blender exits 1."""
import os
import sys

import addon_utils
import bpy
import numpy as np

root, module, out = sys.argv[sys.argv.index("--") + 1:]
sys.path.insert(0, os.path.join(root, "blender"))
addon_utils.enable("io_import_gridifs", default_set=True, handle_error=None)
bpy.context.preferences.addons["io_import_gridifs"].preferences.module_folder = module
assert hasattr(bpy.ops.import_scene, "gridifs"), "the add-on did not register its operator"


def asset(*parts):
    return os.path.join(root, "assets", *parts)


# A clean scene: no default cube, light or camera.
bpy.ops.wm.read_factory_settings(use_empty=True)
addon_utils.enable("io_import_gridifs", default_set=True, handle_error=None)
bpy.context.preferences.addons["io_import_gridifs"].preferences.module_folder = module
scene = bpy.context.scene

# 1. A point cloud with its colours.
result = bpy.ops.import_scene.gridifs(filepath=asset("twisted_functions.gridifs"), points=60000, seed=3)
assert result == {"FINISHED"}, result
points = bpy.context.view_layer.objects.active
# Points that leave X are not imported, as export-points leaves them out.
assert points.type == "MESH" and 59000 < len(points.data.vertices) <= 60000, (points.type, len(points.data.vertices))
colours = points.data.color_attributes["Col"]
rgba = np.empty(len(colours.data) * 4, dtype=np.float32)
colours.data.foreach_get("color", rgba)
assert rgba.reshape(-1, 4)[:, :3].std() > 0.01, "the points should carry the project's colours"
coords = np.empty(len(points.data.vertices) * 3, dtype=np.float32)
points.data.vertices.foreach_get("co", coords)
assert 0.5 < np.abs(coords).max() < 2.0, "the points should fill about X = [-1, 1]^3"
print("ok points", len(points.data.vertices))

# 2. A volume project's measure attractor as a Volume object.
result = bpy.ops.import_scene.gridifs(filepath=asset("volumes", "cloud_creature.gridifs"), resolution=32)
assert result == {"FINISHED"}, result
volume = bpy.context.view_layer.objects.active
assert volume.type == "VOLUME", volume.type
volume.data.grids.load()
names = [g.name for g in volume.data.grids]
assert "density" in names, names
print("ok volume", names)

# 3. An animated project follows the scene's frame.
result = bpy.ops.import_scene.gridifs(filepath=asset("animation", "breathing_twist.gridifs"), points=20000)
assert result == {"FINISHED"}, result
animated = bpy.context.view_layer.objects.active
assert animated["gridifs_animated"], "breathing_twist has tracks"
first = np.empty(len(animated.data.vertices) * 3, dtype=np.float32)
animated.data.vertices.foreach_get("co", first)
scene.frame_set(scene.frame_current + 12)
later = np.empty(len(animated.data.vertices) * 3, dtype=np.float32)
animated.data.vertices.foreach_get("co", later)
assert np.abs(first - later).max() > 1e-3, "the points did not move with the frame"
print("ok animated frame", scene.frame_current)

# 4. A Cycles frame of the point cloud alone.
for obj in (volume, animated):
    obj.hide_render = True
camera_data = bpy.data.cameras.new("camera")
camera = bpy.data.objects.new("camera", camera_data)
scene.collection.objects.link(camera)
camera.location = (3.2, -3.2, 2.4)
camera.rotation_euler = (-camera.location).to_track_quat("-Z", "Y").to_euler()  # looking at the origin
scene.camera = camera
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 4
scene.cycles.use_denoising = False  # Debian builds Blender without OpenImageDenoise
scene.render.resolution_x = scene.render.resolution_y = 96
scene.render.resolution_percentage = 100
scene.render.filepath = os.path.join(out, "points.png")
scene.world = bpy.data.worlds.new("black")
scene.world.color = (0, 0, 0)
bpy.ops.render.render(write_still=True)
image = bpy.data.images.load(scene.render.filepath)
pixels = np.array(image.pixels[:], dtype=np.float32).reshape(-1, 4)
lit = (pixels[:, :3].max(axis=1) > 0.05).mean()
assert 0.01 < lit < 0.9, f"the render should show the points, not {lit:.3f} of the frame lit"
print("ok cycles render, lit fraction %.3f" % lit)
print("checked: points, volume, animation, Cycles")
