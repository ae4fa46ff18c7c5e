"""brdfnav materials in Blender's Cycles (Blender 3.4; docs/HOSTS.md, "Blender").

As a script, renders a material on the sphere as `brdfnav render` frames it:

    blender -b --factory-startup --python hosts/blender/brdfnav_cycles.py -- \\
        --material FILE --env MAP.exr --res N --samples S --out OUT.exr [--seed K]

(--material FILE --out OUT.exr may be repeated: one Blender, one scene, several images.)

FILE is a `brdfnav export --format cycles` file (JSON), or, where Blender's Python has PyYAML
(Debian's Blender does), a brdfnav material file (model ggx) or a `brdfnav export` YAML file
(its `ggx` equivalent when the material is of another model). OUT is a linear RGBA OpenEXR image
with the coverage in alpha: no view transform, no denoiser, no clamping.

Inside Blender (an artist's scene, or a pipeline's script):

    import brdfnav_cycles
    brdfnav_cycles.apply(bpy.context.object, brdfnav_cycles.load("chosen.json"))

builds the node tree on the object's material (created if it has none), and the operator
"brdfnav: load material" (`object.brdfnav_load_material`, registered by `register()`, which
running the file inside Blender's text editor calls) does the same from a file browser.

The node tree is, term for term, the `ggx` model of brdfnav: a Diffuse BSDF (Lambert: roughness
0) of colour rho_d plus a Glossy BSDF (or an Anisotropic BSDF when alpha_x != alpha_y) with the
GGX distribution and colour rho_s, whose Cycles roughness r and anisotropy a give back the
material's alphas: Cycles 3.4 computes alpha_x = r^2 (1 - a), alpha_y = r^2 / (1 - a) for a >= 0
and alpha_x = r^2 / (1 + a), alpha_y = r^2 (1 + a) for a < 0.
"""

import json
import math
import os
import sys

SCHEMA = "brdfnav_cycles"


class MaterialFileError(Exception):
    pass


# --- Reading materials -------------------------------------------------------------------------


def _read_document(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    try:
        return json.loads(text)
    except ValueError:
        pass
    try:
        import yaml  # PyYAML: Debian's python3-yaml, not in Blender's own builds
    except ImportError as e:
        raise MaterialFileError(
            f"{path}: not JSON, and this Python has no PyYAML to read YAML; write the file with "
            "`brdfnav export --format cycles`") from e
    try:
        return yaml.safe_load(text)
    except yaml.YAMLError as e:
        raise MaterialFileError(f"{path}: {e}") from e


def _colour(value, key, path):
    if isinstance(value, (int, float)):
        value = [value] * 3
    if not (isinstance(value, list) and len(value) == 3 and
            all(isinstance(c, (int, float)) and math.isfinite(c) and c >= 0 for c in value)):
        raise MaterialFileError(f"{path}: {key} must be three finite non-negative numbers")
    return [float(c) for c in value]


def _ggx(material, path):
    """The ggx parameters of a brdfnav material mapping (model, params, rho_d, rho_s)."""
    if not isinstance(material, dict) or material.get("model") != "ggx":
        raise MaterialFileError(f"{path}: the material is not of model ggx")
    if material.get("colorspace", "lin_rec709") != "lin_rec709":
        raise MaterialFileError(f"{path}: colours in {material.get('colorspace')}; Cycles' scene "
                                "linear space is lin_rec709")
    params = material.get("params") or {}
    out = {}
    for key in ("alpha_x", "alpha_y"):
        value = params.get(key)
        if not (isinstance(value, (int, float)) and 1e-3 <= value <= 1):
            raise MaterialFileError(f"{path}: params.{key} must be in [0.001, 1]")
        out[key] = float(value)
    out["rho_d"] = _colour(material.get("rho_d"), "rho_d", path)
    out["rho_s"] = _colour(material.get("rho_s"), "rho_s", path)
    return out


def load(path):
    """The ggx material a brdfnav file describes, as a dict with alpha_x, alpha_y, rho_d, rho_s
    and `residual` (the image distance between it and the material chosen, 0 for a ggx one)."""
    doc = _read_document(path)
    if not isinstance(doc, dict):
        raise MaterialFileError(f"{path}: not a brdfnav material or export")
    if SCHEMA in doc:  # brdfnav export --format cycles
        if doc[SCHEMA] != 1:
            raise MaterialFileError(f"{path}: {SCHEMA} version {doc[SCHEMA]} is not 1")
        m = _ggx(doc.get("material"), path)
        m["residual"] = float(doc.get("residual", 0.0))
        return m
    if "brdfnav_material" not in doc:
        raise MaterialFileError(f"{path}: not a brdfnav material or export")
    if doc.get("model") == "ggx":
        m = _ggx(doc, path)
        m["residual"] = 0.0
        return m
    equivalent = (doc.get("equivalents") or {}).get("ggx")
    if not equivalent:
        raise MaterialFileError(
            f"{path}: a {doc.get('model')} material without a ggx equivalent; export it with "
            "`brdfnav export --db DB` from a database that has the ggx model")
    m = _ggx(equivalent.get("material"), path)
    m["residual"] = float(equivalent.get("residual", 0.0))
    return m


# --- The node tree -----------------------------------------------------------------------------


def cycles_roughness(alpha_x, alpha_y):
    """(Roughness, Anisotropy) of Cycles 3.4's Anisotropic BSDF for the alphas (svm_closure.h:
    alpha_x = r^2 (1 - a), alpha_y = r^2 / (1 - a) for a >= 0, the reverse for a < 0)."""
    r2 = math.sqrt(alpha_x * alpha_y)
    if alpha_x <= alpha_y:
        anisotropy = 1 - math.sqrt(alpha_x / alpha_y)
    else:
        anisotropy = math.sqrt(alpha_y / alpha_x) - 1
    if abs(anisotropy) > 0.99:  # Cycles clamps it there
        raise MaterialFileError(f"alpha_x / alpha_y = {alpha_x / alpha_y:.4g}: Cycles' "
                                "anisotropy reaches 1e-4 .. 1e4 at most")
    return math.sqrt(r2), anisotropy


def build_node_tree(node_tree, m, tangent=None):
    """Replaces the nodes of a material's node tree by the ggx material `m` (load()'s dict).
    `tangent`: None for the Anisotropic BSDF's own tangent (Cycles' default, radial around the
    object's z axis), or a world-space vector whose projection onto the surface is the tangent x
    along which alpha_x applies."""
    nodes, links = node_tree.nodes, node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    out.location = (400, 0)
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.location = (-200, 150)
    diffuse.inputs["Color"].default_value = (*m["rho_d"], 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0  # Lambert (Oren-Nayar at sigma 0)
    if m["alpha_x"] == m["alpha_y"]:
        glossy = nodes.new("ShaderNodeBsdfGlossy")
        glossy.distribution = "GGX"
        glossy.inputs["Roughness"].default_value = math.sqrt(m["alpha_x"])
    else:
        glossy = nodes.new("ShaderNodeBsdfAnisotropic")
        glossy.distribution = "GGX"
        roughness, anisotropy = cycles_roughness(m["alpha_x"], m["alpha_y"])
        glossy.inputs["Roughness"].default_value = roughness
        glossy.inputs["Anisotropy"].default_value = anisotropy
        glossy.inputs["Rotation"].default_value = 0.0
        if tangent is not None:
            t = nodes.new("ShaderNodeCombineXYZ")
            t.location = (-400, -250)
            for axis, value in zip("XYZ", tangent):
                t.inputs[axis].default_value = value
            links.new(t.outputs["Vector"], glossy.inputs["Tangent"])
    glossy.location = (-200, -100)
    glossy.inputs["Color"].default_value = (*m["rho_s"], 1.0)
    add = nodes.new("ShaderNodeAddShader")
    add.location = (150, 0)
    links.new(diffuse.outputs["BSDF"], add.inputs[0])
    links.new(glossy.outputs["BSDF"], add.inputs[1])
    links.new(add.outputs["Shader"], out.inputs["Surface"])
    return out


def apply(obj, m, tangent=None, name="brdfnav"):
    """Gives `obj` a material (its active one, or a new one named `name`) whose node tree is the
    ggx material `m`; returns the material."""
    import bpy
    material = obj.active_material
    if material is None:
        material = bpy.data.materials.new(name)
        obj.data.materials.append(material)
    material.use_nodes = True
    build_node_tree(material.node_tree, m, tangent)
    return material


# --- The sphere as `brdfnav render` frames it --------------------------------------------------
#
# brdfnav's world has y up and the camera on +z looking toward -z; Blender's has z up. The
# rotation (x, y, z) -> (x, -z, y) takes one to the other: the camera sits on -y looking toward
# +y with z up, the sphere's tangent field (along the meridians, toward the world's up) is the
# projection of +z. brdfnav's map convention, u = 0.5 + atan2(-x, z) / (2 pi) and v = acos(y) / pi
# from the top row, is Cycles' equirectangular lookup (u = 0.5 - atan2(y, x) / (2 pi), v from the
# top) of the direction turned by +90 degrees about z.

WORLD_UP = (0.0, 0.0, 1.0)


def _sphere_mesh(bpy, resolution):
    """The unit UV sphere, smooth, fine enough that its silhouette is the circle's at every pixel
    centre: a centre is at least 1 / res^2 from the unit circle in radius, the polygon within
    pi^2 / (2 n^2) of it for n rings, so n = 2.5 res suffices. Built from arrays: Blender's
    primitive operator took 34 s for the 205,000 faces of 128 x 128."""
    from array import array
    rings = max(64, math.ceil(2.5 * resolution))
    segments = 2 * rings
    co = array("f", (0.0, 0.0, 1.0))
    for r in range(1, rings):
        z, s = math.cos(math.pi * r / rings), math.sin(math.pi * r / rings)
        for k in range(segments):
            phi = 2 * math.pi * k / segments
            co.extend((s * math.cos(phi), s * math.sin(phi), z))
    co.extend((0.0, 0.0, -1.0))
    south = len(co) // 3 - 1

    def at(r, k):  # vertex k of ring r (1 .. rings - 1)
        return 1 + (r - 1) * segments + k % segments

    loops, starts, totals = array("i"), array("i"), array("i")

    def face(*vertices):  # counter-clockwise seen from outside
        starts.append(len(loops))
        totals.append(len(vertices))
        loops.extend(vertices)

    for k in range(segments):
        face(0, at(1, k), at(1, k + 1))
        face(south, at(rings - 1, k + 1), at(rings - 1, k))
        for r in range(1, rings - 1):
            face(at(r, k), at(r + 1, k), at(r + 1, k + 1), at(r, k + 1))
    mesh = bpy.data.meshes.new("brdfnav_sphere")
    mesh.vertices.add(len(co) // 3)
    mesh.vertices.foreach_set("co", co)
    mesh.loops.add(len(loops))
    mesh.loops.foreach_set("vertex_index", loops)
    mesh.polygons.add(len(starts))
    mesh.polygons.foreach_set("loop_start", starts)
    mesh.polygons.foreach_set("loop_total", totals)
    mesh.polygons.foreach_set("use_smooth", array("b", [1]) * len(starts))
    mesh.update(calc_edges=True)
    sphere = bpy.data.objects.new("brdfnav_sphere", mesh)
    bpy.context.scene.collection.objects.link(sphere)
    return sphere


def _world(bpy, scene, env_path):
    world = bpy.data.worlds.new("brdfnav_env")
    scene.world = world
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    coords = nodes.new("ShaderNodeTexCoord")
    mapping = nodes.new("ShaderNodeMapping")
    mapping.vector_type = "VECTOR"
    mapping.inputs["Rotation"].default_value = (0.0, 0.0, math.pi / 2)
    env = nodes.new("ShaderNodeTexEnvironment")
    env.image = bpy.data.images.load(os.path.abspath(env_path))
    env.image.colorspace_settings.name = "Linear"
    env.interpolation = "Closest"  # brdfnav integrates texels as constant patches
    env.projection = "EQUIRECTANGULAR"
    background = nodes.new("ShaderNodeBackground")
    background.inputs["Strength"].default_value = 1.0
    out = nodes.new("ShaderNodeOutputWorld")
    links.new(coords.outputs["Generated"], mapping.inputs["Vector"])
    links.new(mapping.outputs["Vector"], env.inputs["Vector"])
    links.new(env.outputs["Color"], background.inputs["Color"])
    links.new(background.outputs["Background"], out.inputs["Surface"])


def sphere_scene(env_path, resolution, samples, seed=0):
    """Makes the current scene the sphere under the map as `brdfnav render` frames it, with the
    render settings of a reference image; returns the sphere, for render_sphere()."""
    import bpy
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    sphere = _sphere_mesh(bpy, resolution)

    camera_data = bpy.data.cameras.new("brdfnav_camera")
    camera_data.type = "ORTHO"
    camera_data.ortho_scale = 2.0  # the image spans [-1, 1]^2
    camera_data.clip_start, camera_data.clip_end = 0.1, 10.0
    camera = bpy.data.objects.new("brdfnav_camera", camera_data)
    camera.location = (0.0, -4.0, 0.0)
    camera.rotation_euler = (math.pi / 2, 0.0, 0.0)  # looks toward +y, z up
    scene.collection.objects.link(camera)
    scene.camera = camera
    _world(bpy, scene, env_path)

    render = scene.render
    render.engine = "CYCLES"
    render.resolution_x = render.resolution_y = resolution
    render.resolution_percentage = 100
    render.pixel_aspect_x = render.pixel_aspect_y = 1.0
    render.film_transparent = True  # alpha is the coverage
    render.image_settings.file_format = "OPEN_EXR"
    render.image_settings.color_mode = "RGBA"
    render.image_settings.color_depth = "32"
    render.image_settings.exr_codec = "ZIP"
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0

    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = samples
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.seed = seed
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.blur_glossy = 0.0
    cycles.caustics_reflective = True
    cycles.caustics_refractive = True
    # Every sample at the pixel's centre, as brdfnav's one: the narrowest filter (Blender
    # makes a box filter one pixel wide whatever its width; a Gaussian of width 0.01 spreads
    # the samples over 0.03 pixel).
    cycles.pixel_filter_type = "GAUSSIAN"
    cycles.filter_width = 0.01
    return sphere


def render_sphere(sphere, m, out_path, samples=None):
    """Renders the ggx material `m` on the sphere of sphere_scene() into an OpenEXR file, with
    `samples` per pixel instead of the scene's if given."""
    import bpy
    apply(sphere, m, tangent=WORLD_UP)
    if samples is not None:
        bpy.context.scene.cycles.samples = samples
    bpy.context.scene.render.filepath = os.path.abspath(out_path)
    bpy.ops.render.render(write_still=True)


# --- Blender's UI ------------------------------------------------------------------------------


def _operator_class():
    import bpy
    from bpy_extras.io_utils import ImportHelper

    class BRDFNAV_OT_load_material(bpy.types.Operator, ImportHelper):
        """Give the active object the material of a brdfnav export (its ggx form)"""
        bl_idname = "object.brdfnav_load_material"
        bl_label = "brdfnav: load material"
        bl_options = {"REGISTER", "UNDO"}
        filter_glob: bpy.props.StringProperty(default="*.json;*.yaml;*.yml", options={"HIDDEN"})

        def execute(self, context):
            if context.object is None:
                self.report({"ERROR"}, "no active object")
                return {"CANCELLED"}
            try:
                m = load(self.filepath)
            except (OSError, MaterialFileError) as e:
                self.report({"ERROR"}, str(e))
                return {"CANCELLED"}
            apply(context.object, m)
            if m["residual"] > 0:
                self.report({"INFO"}, f"ggx equivalent, residual {m['residual']:.4g} (image metric)")
            return {"FINISHED"}

    return BRDFNAV_OT_load_material


_registered = []


def register():
    import bpy
    if not _registered:
        _registered.append(_operator_class())
        bpy.utils.register_class(_registered[0])


def unregister():
    import bpy
    while _registered:
        bpy.utils.unregister_class(_registered.pop())


# --- Command line ------------------------------------------------------------------------------


def main(argv):
    import argparse
    parser = argparse.ArgumentParser(
        prog="blender -b --factory-startup --python brdfnav_cycles.py --",
        description="Render a brdfnav material on the sphere with Cycles, as brdfnav render.")
    parser.add_argument("--material", required=True, action="append",
                        help="export (JSON or YAML) or material; repeat with --out for more "
                             "images in one run")
    parser.add_argument("--env", required=True, help="lat-long HDR environment map")
    parser.add_argument("--res", type=int, default=128, help="image width and height")
    parser.add_argument("--samples", type=int, default=1024, help="Cycles samples per pixel")
    parser.add_argument("--seed", type=int, default=0, help="Cycles' seed")
    parser.add_argument("--out", required=True, action="append",
                        help="OpenEXR file to write, one per --material")
    args = parser.parse_args(argv)
    if not 8 <= args.res <= 4096:
        parser.error("--res must be in [8, 4096]")
    if args.samples < 1:
        parser.error("--samples must be positive")
    if len(args.out) != len(args.material):
        parser.error("give one --out per --material")
    if not all(out.lower().endswith(".exr") for out in args.out):
        parser.error("--out must end in .exr")
    if not os.path.isfile(args.env):
        parser.error(f"--env {args.env}: no such file")
    try:
        materials = [load(path) for path in args.material]
        for m in materials:
            cycles_roughness(m["alpha_x"], m["alpha_y"])
    except (OSError, MaterialFileError) as e:
        print(f"brdfnav_cycles: error: {e}", file=sys.stderr)
        return 2
    sphere = sphere_scene(args.env, args.res, args.samples, args.seed)
    for m, out in zip(materials, args.out):
        render_sphere(sphere, m, out)
    return 0


if __name__ == "__main__":
    if "--" in sys.argv:
        sys.exit(main(sys.argv[sys.argv.index("--") + 1:]))
    register()  # run from Blender's text editor: offer the operator
