#!/usr/bin/env python3
"""A diffuse box room described once, rendered by mjray and by Blender's Cycles path tracer, to
compare mjray's global illumination with an independent renderer by scale-free ratios: on the
back wall, total light over direct light, and the red/green ratio beside the red wall.

Run bench/cycles_twin.sh (it calls this file three ways):
  python3 cycles_twin.py lua OUT.lua                     the room as an mjray scene
  blender -b --factory-startup -P cycles_twin.py -- OUTDIR SAMPLES
                                                         Cycles renders (total and direct-only,
                                                         EXR) and their patch means, OUTDIR/cycles.json
  python3 cycles_twin.py compare OUTDIR                  mjray's PPMs against cycles.json

The room: diffuse boxes (Lambertian, albedo kd), a point light with inverse-square falloff, no
ambient light; closed, so no background is seen (Cycles' world is black). Coordinates are mjray's (y up); Blender's are (x, -z, y).
"""
import json
import math
import os
import sys

WIDTH, HEIGHT, FOVY = 160, 120, 50.0
EYE, VIEW = (0.0, 2.0, -5.5), (0.0, 0.0, 1.0)
LIGHT, LIGHT_COLOUR = (0.3, 3.4, -0.2), (1.0, 1.0, 1.0)
WHITE, RED = (0.75, 0.75, 0.75), (0.75, 0.08, 0.06)
BOXES = [  # (lo, hi, kd): the room's shell x, z in [-2, 2], y in [0, 4], and a block
    ((-2.5, -0.5, -6.5), (2.5, 0.0, 2.5), WHITE),   # floor
    ((-2.5, 4.0, -6.5), (2.5, 4.5, 2.5), WHITE),    # ceiling
    ((-2.5, 0.0, 2.0), (2.5, 4.0, 2.5), WHITE),     # back wall
    ((-2.5, 0.0, -6.5), (2.5, 4.0, -6.0), WHITE),   # wall behind the camera
    ((2.0, 0.0, -6.0), (2.5, 4.0, 2.0), RED),       # +x: on the camera's left
    ((-2.5, 0.0, -6.0), (-2.0, 4.0, 2.0), WHITE),   # -x
    ((-1.2, 0.0, 0.3), (-0.2, 1.6, 1.3), WHITE),    # a block
]
# Patches of the image (x0, y0, x1, y1 in pixels from the top left): the back wall's middle,
# and the back wall next to the red wall.
PATCHES = {"back_wall": (70, 30, 90, 50), "beside_red": (47, 30, 53, 60)}


def lua_scene(path):
    lines = ["-- Written by bench/cycles_twin.py: the room of the Cycles comparison.",
             "local root = gr.node('root')"]
    for i, (lo, hi, kd) in enumerate(BOXES):
        lines += [f"local at{i} = gr.node('at{i}')", f"at{i}:translate({lo[0]}, {lo[1]}, {lo[2]})",
                  f"local size{i} = gr.node('size{i}')",
                  f"size{i}:scale({hi[0] - lo[0]}, {hi[1] - lo[1]}, {hi[2] - lo[2]})",
                  f"local box{i} = gr.cube('box{i}')", f"box{i}:set_material(gr.material({{{kd[0]}, {kd[1]}, {kd[2]}}}, {{0, 0, 0}}, 1))",
                  f"size{i}:add_child(box{i})", f"at{i}:add_child(size{i})", f"root:add_child(at{i})"]
    lines += [f"gr.render(root, 'twin.ppm', {WIDTH}, {HEIGHT}, {{{EYE[0]}, {EYE[1]}, {EYE[2]}}}, "
              f"{{{VIEW[0]}, {VIEW[1]}, {VIEW[2]}}}, {{0, 1, 0}}, {FOVY}, {{0, 0, 0}},",
              f"          {{gr.light({{{LIGHT[0]}, {LIGHT[1]}, {LIGHT[2]}}}, {{{LIGHT_COLOUR[0]}, {LIGHT_COLOUR[1]}, "
              f"{LIGHT_COLOUR[2]}}}, {{0, 0, 1}})}})"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def patch_means(pixel, patch):
    """Mean (r, g, b) over a patch; pixel(x, y) gives the colour at x, y from the top left."""
    x0, y0, x1, y1 = patch
    total = [0.0, 0.0, 0.0]
    for y in range(y0, y1):
        for x in range(x0, x1):
            c = pixel(x, y)
            for k in range(3):
                total[k] += c[k]
    n = (x1 - x0) * (y1 - y0)
    return [t / n for t in total]


def ratios(total, direct):
    """The two scale-free numbers from the patch means of a total and a direct-only render."""
    back_total, back_direct = total["back_wall"], direct["back_wall"]
    beside = total["beside_red"]
    return {"total_over_direct": sum(back_total) / sum(back_direct), "red_over_green_beside_red": beside[0] / beside[1]}


def blender_main(outdir, samples):
    import bpy
    from mathutils import Vector

    def b(p):  # mjray (x, y, z) → Blender (x, -z, y)
        return (p[0], -p[2], p[1])

    scene = bpy.context.scene
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    for lo, hi, kd in BOXES:
        centre = b(tuple((l + h) / 2 for l, h in zip(lo, hi)))
        half = b(tuple((h - l) / 2 for l, h in zip(lo, hi)))
        bpy.ops.mesh.primitive_cube_add(size=2, location=centre, scale=tuple(abs(v) for v in half))
        material = bpy.data.materials.new("kd")
        material.use_nodes = True
        nodes = material.node_tree.nodes
        nodes.clear()
        diffuse = nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = (kd[0], kd[1], kd[2], 1)
        diffuse.inputs["Roughness"].default_value = 0
        out = nodes.new("ShaderNodeOutputMaterial")
        material.node_tree.links.new(diffuse.outputs["BSDF"], out.inputs["Surface"])
        bpy.context.active_object.data.materials.append(material)
    light_data = bpy.data.lights.new("lamp", type="POINT")
    light_data.energy = 100
    light_data.shadow_soft_size = 0
    light = bpy.data.objects.new("lamp", light_data)
    light.location = b(LIGHT)
    scene.collection.objects.link(light)
    camera_data = bpy.data.cameras.new("camera")
    camera_data.sensor_fit = "VERTICAL"
    camera_data.angle = math.radians(FOVY)
    camera = bpy.data.objects.new("camera", camera_data)
    camera.location = b(EYE)
    camera.rotation_euler = Vector(b(VIEW)).to_track_quat("-Z", "Y").to_euler()  # looks along -Z, image up +Y
    scene.collection.objects.link(camera)
    scene.camera = camera
    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0
    scene.world = world
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False
    scene.cycles.sample_clamp_direct = 0
    scene.cycles.sample_clamp_indirect = 0
    scene.cycles.caustics_reflective = False
    scene.cycles.caustics_refractive = False
    scene.cycles.diffuse_bounces = 64
    scene.render.resolution_x, scene.render.resolution_y = WIDTH, HEIGHT
    scene.render.resolution_percentage = 100
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0
    scene.view_settings.gamma = 1
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    means = {}
    for name, bounces in (("total", 64), ("direct", 0)):
        scene.cycles.max_bounces = bounces
        path = os.path.join(outdir, f"cycles_{name}.exr")
        scene.render.filepath = path
        bpy.ops.render.render(write_still=True)
        image = bpy.data.images.load(path)
        pixels = list(image.pixels)  # RGBA, rows from the bottom
        w, h = image.size

        def pixel(x, y, pixels=pixels, w=w, h=h):
            i = ((h - 1 - y) * w + x) * 4
            return pixels[i:i + 3]

        means[name] = {k: patch_means(pixel, p) for k, p in PATCHES.items()}
    with open(os.path.join(outdir, "cycles.json"), "w") as f:
        json.dump({"samples": samples, "means": means, "ratios": ratios(means["total"], means["direct"])}, f, indent=1)


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    parts, i = [], 0
    while len(parts) < 4:  # magic, width, height, maxval, separated by whitespace
        while data[i:i + 1].isspace():
            i += 1
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        parts.append(data[i:j])
        i = j
    i += 1
    w, h, maxval = int(parts[1]), int(parts[2]), int(parts[3])
    pixels = data[i:]
    return lambda x, y: [pixels[(y * w + x) * 3 + k] / maxval for k in range(3)]


def compare(outdir):
    with open(os.path.join(outdir, "cycles.json")) as f:
        cycles = json.load(f)
    means = {name: {k: patch_means(read_ppm(os.path.join(outdir, f"mjray_{name}.ppm")), p) for k, p in PATCHES.items()}
             for name in ("total", "direct")}
    mjray = ratios(means["total"], means["direct"])
    for key, value in mjray.items():
        reference = cycles["ratios"][key]
        print(json.dumps({"ratio": key, "mjray": round(value, 4), "cycles": round(reference, 4),
                          "relative_difference": round(value / reference - 1, 4)}))


if __name__ == "__main__":
    if "--" in sys.argv:  # inside Blender
        args = sys.argv[sys.argv.index("--") + 1:]
        blender_main(args[0], int(args[1]))
    elif sys.argv[1] == "lua":
        lua_scene(sys.argv[2])
    elif sys.argv[1] == "compare":
        compare(sys.argv[2])
