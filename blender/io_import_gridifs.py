"""GridIFS projects in Blender: File > Import > GridIFS (.gridifs).

The attractor comes in as a point cloud (a mesh of vertices with a colour attribute "Col", drawn
as points by a Geometry Nodes modifier so that Cycles and Eevee render it), or, for a volume
project, as a Volume object holding the measure attractor's density. An animated project follows
the scene's frame. The add-on drives the gridifs Python module; its preferences say where that
module is (the build/python folder of a GridIFS build). docs/PYTHON.md says how to install it.
"""

bl_info = {
    "name": "GridIFS importer",
    "author": "GridIFS",
    "version": (1, 0, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > GridIFS (.gridifs)",
    "description": "Imports the attractor of a GridIFS project as a point cloud or a volume",
    "category": "Import-Export",
}

import importlib
import os
import sys
import tempfile

import bpy
import numpy as np
from bpy.app.handlers import persistent
from bpy.props import BoolProperty, EnumProperty, IntProperty, StringProperty
from bpy_extras.io_utils import ImportHelper

# Custom properties on imported objects, read again when the frame changes.
SOURCE_KEY = "gridifs_source"
POINTS_KEY = "gridifs_points"
SEED_KEY = "gridifs_seed"
FPS_KEY = "gridifs_fps"


def module_folder():
    prefs = bpy.context.preferences.addons.get(__name__)
    return prefs.preferences.module_folder if prefs else os.environ.get("GRIDIFS_PYTHON_DIR", "")


def load_module():
    """The gridifs module from the folder in the preferences (or GRIDIFS_PYTHON_DIR)."""
    folder = bpy.path.abspath(module_folder()) if module_folder() else ""
    if folder and folder not in sys.path:
        sys.path.insert(0, folder)
    try:
        return importlib.import_module("gridifs")
    except ImportError as e:
        raise RuntimeError(
            "the gridifs module was not found%s: set its folder (a GridIFS build's build/python) in "
            "Edit > Preferences > Add-ons > GridIFS importer (%s)" % (" in " + folder if folder else "", e)
        )


def point_material():
    """Emits the points' own colours (the attribute "Col"), so they look as GridIFS draws them."""
    material = bpy.data.materials.get("GridIFS points")
    if material:
        return material
    material = bpy.data.materials.new("GridIFS points")
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    attribute = nodes.new("ShaderNodeAttribute")
    attribute.attribute_name = "Col"
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Strength"].default_value = 1.0
    output = nodes.new("ShaderNodeOutputMaterial")
    links.new(attribute.outputs["Color"], emission.inputs["Color"])
    links.new(emission.outputs["Emission"], output.inputs["Surface"])
    return material


def points_node_group(radius):
    """Geometry Nodes: the mesh's vertices as render points with the point material."""
    name = "GridIFS points"
    group = bpy.data.node_groups.get(name)
    if group is None:
        group = bpy.data.node_groups.new(name, "GeometryNodeTree")
        group.inputs.new("NodeSocketGeometry", "Geometry")
        group.outputs.new("NodeSocketGeometry", "Geometry")
        nodes, links = group.nodes, group.links
        source = nodes.new("NodeGroupInput")
        sink = nodes.new("NodeGroupOutput")
        to_points = nodes.new("GeometryNodeMeshToPoints")
        to_points.name = "Mesh to Points"
        material = nodes.new("GeometryNodeSetMaterial")
        material.inputs["Material"].default_value = point_material()
        links.new(source.outputs["Geometry"], to_points.inputs["Mesh"])
        links.new(to_points.outputs["Points"], material.inputs["Geometry"])
        links.new(material.outputs["Geometry"], sink.inputs["Geometry"])
    group.nodes["Mesh to Points"].inputs["Radius"].default_value = radius
    return group


def fill_points(mesh, positions, colours):
    """Replaces the mesh's vertices by the points, with their colours as attribute "Col"."""
    mesh.clear_geometry()
    mesh.vertices.add(len(positions))
    mesh.vertices.foreach_set("co", positions.ravel())
    attribute = mesh.color_attributes.get("Col") or mesh.color_attributes.new("Col", "FLOAT_COLOR", "POINT")
    rgba = np.ones((len(colours), 4), dtype=np.float32)
    rgba[:, :3] = colours
    attribute.data.foreach_set("color", rgba.ravel())
    mesh.update()


def is_animated(path):
    import json

    with open(path) as f:
        return bool(json.load(f).get("tracks"))


def frame_time(scene, fps):
    return scene.frame_current / fps


def import_points(context, gridifs, path, count, seed, radius):
    project = gridifs.Project.load(path)
    fps = float(context.scene.render.fps) / float(context.scene.render.fps_base)
    animated = is_animated(path)
    time = frame_time(context.scene, fps) if animated else None
    positions, colours = project.points(count, seed=seed, time=time)
    name = os.path.splitext(os.path.basename(path))[0]
    mesh = bpy.data.meshes.new(name)
    fill_points(mesh, positions, colours)
    obj = bpy.data.objects.new(name, mesh)
    context.collection.objects.link(obj)
    modifier = obj.modifiers.new("GridIFS points", "NODES")
    modifier.node_group = points_node_group(radius)
    obj[SOURCE_KEY] = os.path.abspath(path)
    obj[POINTS_KEY] = count
    obj[SEED_KEY] = seed
    obj[FPS_KEY] = fps
    obj["gridifs_animated"] = animated
    return obj


def import_volume(context, gridifs, path, resolution):
    project = gridifs.Project.load(path)
    name = os.path.splitext(os.path.basename(path))[0]
    folder = os.path.join(bpy.app.tempdir or tempfile.gettempdir(), "gridifs")
    os.makedirs(folder, exist_ok=True)
    vdb = os.path.join(folder, name + ".vdb")
    project.volume_file(vdb, resolution)
    volume = bpy.data.volumes.new(name)
    volume.filepath = vdb
    obj = bpy.data.objects.new(name, volume)
    context.collection.objects.link(obj)
    obj[SOURCE_KEY] = os.path.abspath(path)
    return obj


def is_volume_project(path):
    import json

    with open(path) as f:
        data = json.load(f)
    return data.get("render", {}).get("mode") == "volume" or any(
        f.get("kind") == "median" for f in data.get("functions", [])
    )


@persistent
def follow_frame(scene, depsgraph=None):
    """Animated imports take the project at the scene's frame."""
    animated = [o for o in scene.objects if o.get(SOURCE_KEY) and o.get("gridifs_animated") and o.type == "MESH"]
    if not animated:
        return
    gridifs = load_module()
    for obj in animated:
        project = gridifs.Project.load(obj[SOURCE_KEY])
        positions, colours = project.points(
            int(obj[POINTS_KEY]), seed=int(obj[SEED_KEY]), time=frame_time(scene, obj[FPS_KEY])
        )
        fill_points(obj.data, positions, colours)


class ImportGridIFS(bpy.types.Operator, ImportHelper):
    """Import the attractor of a GridIFS project"""

    bl_idname = "import_scene.gridifs"
    bl_label = "Import GridIFS"
    bl_options = {"REGISTER", "UNDO", "PRESET"}

    filename_ext = ".gridifs"
    filter_glob: StringProperty(default="*.gridifs", options={"HIDDEN"})
    kind: EnumProperty(
        name="As",
        items=[
            ("AUTO", "Automatic", "A volume for volume projects, points otherwise"),
            ("POINTS", "Point cloud", "Chaos-game points with their colours"),
            ("VOLUME", "Volume", "The measure attractor's density"),
        ],
        default="AUTO",
    )
    points: IntProperty(name="Points", default=200000, min=1, max=50000000, description="Chaos-game points to import")
    seed: IntProperty(name="Seed", default=1, min=0)
    radius: bpy.props.FloatProperty(name="Point radius", default=0.004, min=0.0001, max=0.1)
    resolution: IntProperty(name="Volume resolution", default=128, min=16, max=512)

    def execute(self, context):
        try:
            gridifs = load_module()
            kind = self.kind
            if kind == "AUTO":
                kind = "VOLUME" if is_volume_project(self.filepath) else "POINTS"
            if kind == "VOLUME":
                obj = import_volume(context, gridifs, self.filepath, self.resolution)
            else:
                obj = import_points(context, gridifs, self.filepath, self.points, self.seed, self.radius)
        except Exception as e:  # the module's gridifs.Error, a missing module, an unreadable file
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        for other in context.selected_objects:
            other.select_set(False)
        obj.select_set(True)
        context.view_layer.objects.active = obj
        return {"FINISHED"}


class GridIFSPreferences(bpy.types.AddonPreferences):
    bl_idname = __name__

    module_folder: StringProperty(
        name="gridifs module folder",
        subtype="DIR_PATH",
        default=os.environ.get("GRIDIFS_PYTHON_DIR", ""),
        description="The folder that holds the gridifs module (a GridIFS build's build/python)",
    )

    def draw(self, context):
        self.layout.prop(self, "module_folder")


def menu_entry(self, context):
    self.layout.operator(ImportGridIFS.bl_idname, text="GridIFS (.gridifs)")


def register():
    bpy.utils.register_class(GridIFSPreferences)
    bpy.utils.register_class(ImportGridIFS)
    bpy.types.TOPBAR_MT_file_import.append(menu_entry)
    if follow_frame not in bpy.app.handlers.frame_change_post:
        bpy.app.handlers.frame_change_post.append(follow_frame)


def unregister():
    if follow_frame in bpy.app.handlers.frame_change_post:
        bpy.app.handlers.frame_change_post.remove(follow_frame)
    bpy.types.TOPBAR_MT_file_import.remove(menu_entry)
    bpy.utils.unregister_class(ImportGridIFS)
    bpy.utils.unregister_class(GridIFSPreferences)
