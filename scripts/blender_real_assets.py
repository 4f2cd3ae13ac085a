# Exports facet's real-world test files with Blender's own exporters
# (run by scripts/make_real_assets.sh: blender -b --factory-startup --python
# THIS -- OUT_DIR). Each scene is built from an empty file, so the output
# depends only on this script and the Blender version.
import math
import sys

import bpy

out = sys.argv[sys.argv.index("--") + 1]


def empty_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, 24
    scene.render.fps = 24
    return scene


def plain_material(name, color):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (*color, 1)
    return material


def export_glb(path, **options):
    bpy.ops.export_scene.gltf(filepath=path, export_format="GLB", export_apply=True,
                              export_yup=True, **options)


def suzanne():
    # Subdivided once and triangulated, so the glb and the obj hold the same
    # triangles whatever each exporter would do with quads.
    empty_scene()
    bpy.ops.mesh.primitive_monkey_add()
    monkey = bpy.context.active_object
    monkey.name = "Suzanne"
    monkey.data.materials.append(plain_material("Skin", (0.8, 0.5, 0.3)))
    monkey.modifiers.new("Subdivision", "SUBSURF").levels = 1
    monkey.modifiers.new("Triangulate", "TRIANGULATE")
    bpy.ops.object.shade_smooth()
    export_glb(f"{out}/suzanne.glb")
    bpy.ops.wm.obj_export(filepath=f"{out}/suzanne.obj", forward_axis="NEGATIVE_Z",
                          up_axis="Y", export_normals=True, export_uv=True,
                          export_materials=True, apply_modifiers=True)


def checker_image(name, size, squares, transparent=False):
    image = bpy.data.images.new(name, size, size, alpha=True)
    pixels = []
    for y in range(size):
        for x in range(size):
            dark = ((x * squares // size) + (y * squares // size)) % 2
            if transparent:
                pixels += [0.9, 0.9, 0.9, 0.0 if dark else 1.0]
            else:
                pixels += [0.1, 0.1, 0.1, 1.0] if dark else [0.9, 0.9, 0.9, 1.0]
    image.pixels = pixels
    image.file_format = "PNG"
    image.pack()
    return image


def textured_sphere():
    # A Mapping node scaling the coordinates by 2: the exporter writes
    # KHR_texture_transform with scale [2, 2].
    empty_scene()
    bpy.ops.mesh.primitive_uv_sphere_add(segments=32, ring_count=16)
    sphere = bpy.context.active_object
    sphere.name = "Sphere"
    material = bpy.data.materials.new("Checker")
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    texture = nodes.new("ShaderNodeTexImage")
    texture.image = checker_image("checker", 64, 8)
    mapping = nodes.new("ShaderNodeMapping")
    mapping.inputs["Scale"].default_value = (2, 2, 1)
    coordinates = nodes.new("ShaderNodeTexCoord")
    links.new(coordinates.outputs["UV"], mapping.inputs["Vector"])
    links.new(mapping.outputs["Vector"], texture.inputs["Vector"])
    links.new(texture.outputs["Color"], nodes["Principled BSDF"].inputs["Base Color"])
    sphere.data.materials.append(material)
    bpy.ops.object.shade_smooth()
    export_glb(f"{out}/textured-sphere.glb")


def keyed():
    # Three things, each with an action of its own: a box moving along +X,
    # an arm bent by its armature's second bone, a sheet raised by a shape key.
    scene = empty_scene()
    bpy.ops.mesh.primitive_cube_add(size=0.5, location=(-3, 0, 0))
    box = bpy.context.active_object
    box.name = "Box"
    box.keyframe_insert("location", frame=1)
    box.location.x += 2
    box.keyframe_insert("location", frame=24)
    box.animation_data.action.name = "BoxAction"

    bpy.ops.object.armature_add(location=(0, 0, 0))
    rig = bpy.context.active_object
    rig.name = "Rig"
    bpy.ops.object.mode_set(mode="EDIT")
    first = rig.data.edit_bones[0]
    first.name = "Upper"
    first.head, first.tail = (0, 0, 0), (0, 0, 1)
    second = rig.data.edit_bones.new("Lower")
    second.head, second.tail = (0, 0, 1), (0, 0, 2)
    second.parent = first
    bpy.ops.object.mode_set(mode="OBJECT")
    bpy.ops.mesh.primitive_cube_add(size=1, location=(0, 0, 1))
    arm = bpy.context.active_object
    arm.name = "Arm"
    arm.scale = (0.15, 0.15, 1)
    bpy.ops.object.transform_apply(scale=True)
    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.mesh.subdivide(number_cuts=8)
    bpy.ops.object.mode_set(mode="OBJECT")
    arm.select_set(True)
    rig.select_set(True)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.parent_set(type="ARMATURE_AUTO")
    bpy.ops.object.mode_set(mode="POSE")
    lower = rig.pose.bones["Lower"]
    lower.rotation_mode = "XYZ"
    lower.keyframe_insert("rotation_euler", frame=1)
    lower.rotation_euler = (math.radians(90), 0, 0)
    lower.keyframe_insert("rotation_euler", frame=24)
    bpy.ops.object.mode_set(mode="OBJECT")
    rig.animation_data.action.name = "RigAction"

    bpy.ops.mesh.primitive_grid_add(x_subdivisions=8, y_subdivisions=8, size=2, location=(3, 0, 0))
    sheet = bpy.context.active_object
    sheet.name = "Sheet"
    sheet.shape_key_add(name="Basis")
    bump = sheet.shape_key_add(name="Bump")
    for vertex in bump.data:
        if vertex.co.x ** 2 + vertex.co.y ** 2 < 0.3:
            vertex.co.z += 1
    bump.value = 0
    bump.keyframe_insert("value", frame=1)
    bump.value = 1
    bump.keyframe_insert("value", frame=24)
    sheet.data.shape_keys.animation_data.action.name = "KeyAction"
    scene.frame_set(1)
    export_glb(f"{out}/keyed.glb", export_animations=True, export_skins=True,
               export_morph=True)


def features():
    # Vertex colours, emission with a strength, a camera dollying in, and
    # two lights, for the material, camera and light tests.
    scene = empty_scene()
    bpy.ops.mesh.primitive_cube_add(size=1, location=(-1, 0, 0))
    cube = bpy.context.active_object
    cube.name = "Painted"
    colors = cube.data.color_attributes.new("Col", "BYTE_COLOR", "CORNER")
    palette = [(1, 0, 0, 1), (0, 1, 0, 1), (0, 0, 1, 1), (1, 1, 0, 1), (0, 1, 1, 1), (1, 0, 1, 1)]
    for polygon in cube.data.polygons:
        for loop in polygon.loop_indices:
            colors.data[loop].color = palette[polygon.index % 6]
    painted = bpy.data.materials.new("Painted")
    painted.use_nodes = True
    attribute = painted.node_tree.nodes.new("ShaderNodeVertexColor")
    attribute.layer_name = "Col"
    painted.node_tree.links.new(attribute.outputs["Color"],
                                painted.node_tree.nodes["Principled BSDF"].inputs["Base Color"])
    cube.data.materials.append(painted)

    bpy.ops.mesh.primitive_plane_add(size=1, location=(1, 0, 0), rotation=(math.radians(90), 0, 0))
    glow = bpy.context.active_object
    glow.name = "Glow"
    emissive = plain_material("Glow", (0.05, 0.05, 0.05))
    principled = emissive.node_tree.nodes["Principled BSDF"]
    principled.inputs["Emission"].default_value = (1, 0.5, 0, 1)
    principled.inputs["Emission Strength"].default_value = 4
    glow.data.materials.append(emissive)

    bpy.ops.object.camera_add(location=(0, -6, 0.5), rotation=(math.radians(90), 0, 0))
    camera = bpy.context.active_object
    camera.name = "Camera"
    camera.data.lens_unit = "FOV"
    camera.data.angle = math.radians(50)
    camera.keyframe_insert("location", frame=1)
    camera.location.y = -4
    camera.keyframe_insert("location", frame=24)
    camera.animation_data.action.name = "CameraAction"
    scene.camera = camera

    bpy.ops.object.light_add(type="POINT", location=(0, -2, 2))
    bpy.context.active_object.name = "Lamp"
    bpy.context.active_object.data.energy = 500
    bpy.ops.object.light_add(type="SUN", rotation=(math.radians(45), 0, math.radians(30)))
    bpy.context.active_object.name = "Sun"
    bpy.context.active_object.data.energy = 2
    scene.frame_set(1)
    export_glb(f"{out}/features.glb", export_cameras=True, export_lights=True,
               export_animations=True, export_colors=True)


suzanne()
textured_sphere()
keyed()
features()
