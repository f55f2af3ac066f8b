"""Blender's Grease Pencil Line Art on a mesh, seen through one of our cameras (tracker issue 36).

    blender -b --factory-startup --python bench/peers/blender_lineart.py -- MESH.off \
        --eye X Y Z --target X Y Z [--up X Y Z] (--fov DEG | --ortho-height H) [--aspect A] \
        [--crease DEG] [--no-intersections] [--runs N] --out strokes.json

Reads the OFF file itself (Blender imports no OFF), builds the mesh with from_pydata (flat shaded, as
our solids are), sets a camera with our camera's eye, target, up and picture window, and adds a Grease
Pencil object whose Line Art modifier draws the mesh: contour and crease lines (crease threshold
180° − DEG, so that it marks exactly the edges our `import(..., crease: DEG)` draws: faces whose normals
differ by more than DEG), intersections, no material borders, edge marks or loose edges, occlusion level
0 only, strokes left where Line Art computes them (depth offset 0). (Line Art keeps the threshold's
cosine in a float: within ≈ 0.014° of 180° it is 1.0f, and edges between coplanar faces are marked
too.) Then evaluates it through the dependency graph, times the evaluation, and writes the evaluated
strokes (world-space points) to JSON.

The camera. Ours (core/camera/lookat_camera.cpp): forward = target − eye, right = forward × up, true up =
right × forward; `fov` spans the picture's [−1, 1] along the page's shorter side, which on the default
page (A4 landscape, 12 mm margins: a drawing area of 273 × 186 mm) is the vertical one, and the picture
is `aspect` (273/186) as wide as it is high. Blender's camera looks along its −Z with +Y up, so its
rotation has columns (right, true up, −forward). Its picture: sensor fit AUTO with a landscape
resolution of the same aspect makes the sensor width span the horizontal field, so the lens is chosen
for tan(hfov/2) = aspect · tan(fov/2). Ortho: our `height` spans the shorter (vertical) side, Blender's
ortho_scale the longer one: height · aspect. (Which lines are visible does not depend on the field at
all, only on the eye; the field sets where the frame clips.)

Timing (stdout and the JSON's "timing"): the first evaluation of the whole dependency graph (the mesh and
the Line Art), then `--runs` repetitions of: the modifier switched off and the view layer updated, the
Grease Pencil object re-evaluated without Line Art ("no_lineart_s": what is not Line Art's), and the
modifier switched on and the view layer updated ("lineart_s": Line Art's evaluation, the number
compared). The whole process is timed from outside (bench/peers/lineart_run.py).
"""
import argparse
import json
import math
import statistics
import sys
import time

import bpy
from mathutils import Matrix, Vector

# The drawing area of the default page (A4 landscape less 12 mm margins), width over height.
DEFAULT_ASPECT = (297 - 24) / (210 - 24)


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="blender -b --factory-startup --python blender_lineart.py --",
                                description="Line Art strokes of a mesh seen through one of our cameras")
    p.add_argument("mesh", help="an OFF file")
    p.add_argument("--eye", type=float, nargs=3, required=True)
    p.add_argument("--target", type=float, nargs=3, required=True)
    p.add_argument("--up", type=float, nargs=3, default=(0.0, 0.0, 1.0))
    p.add_argument("--fov", type=float, default=40.0, help="our lookat fov (degrees, the picture's height)")
    p.add_argument("--ortho-height", type=float, default=0.0,
                   help="> 0: our ortho camera of this height instead of the perspective one")
    p.add_argument("--aspect", type=float, default=DEFAULT_ASPECT,
                   help="picture width over height (default: the A4 landscape drawing area, 273/186)")
    p.add_argument("--crease", type=float, default=0.0,
                   help="our crease angle (degrees; import's default 0); Line Art's threshold is 180 - it")
    p.add_argument("--no-intersections", action="store_true",
                   help="leave Line Art's intersection lines off (to see which lines they are)")
    p.add_argument("--runs", type=int, default=5, help="timed re-evaluations after the first (0: none)")
    p.add_argument("--out", required=True, help="the strokes, JSON")
    return p.parse_args(argv)


def read_off(path):
    """Vertices and faces of an OFF file (comments after # and blank lines skipped)."""
    with open(path) as f:
        words = []
        for line in f:
            words.extend(line.split("#", 1)[0].split())
    if not words or not words[0].endswith("OFF"):
        raise SystemExit(f"{path}: not an OFF file")
    words = words[1:] if words[0] == "OFF" else [words[0][3:]] + words[1:]
    nv, nf = int(words[0]), int(words[1])
    at = 3
    vertices = []
    for _ in range(nv):
        vertices.append((float(words[at]), float(words[at + 1]), float(words[at + 2])))
        at += 3
    faces = []
    for _ in range(nf):
        n = int(words[at])
        faces.append([int(w) for w in words[at + 1:at + 1 + n]])
        at += 1 + n
    return vertices, faces


def camera_matrix(eye, target, up):
    """World matrix of a Blender camera at `eye` looking at `target`, rolled as our lookat is."""
    eye, target, up = Vector(eye), Vector(target), Vector(up)
    forward = (target - eye).normalized()
    right = forward.cross(up.normalized())
    if right.length < 1e-12:
        raise SystemExit("up is parallel to the viewing direction")
    right.normalize()
    true_up = right.cross(forward)
    m = Matrix.Identity(4)
    for row in range(3):
        m[row][0], m[row][1], m[row][2], m[row][3] = right[row], true_up[row], -forward[row], eye[row]
    return m


def main():
    args = parse_args()
    scene = bpy.context.scene
    for ob in list(bpy.data.objects):  # the factory scene's cube, light and camera
        bpy.data.objects.remove(ob, do_unlink=True)

    t_read = time.perf_counter()
    vertices, faces = read_off(args.mesh)
    mesh = bpy.data.meshes.new("mesh")
    mesh.from_pydata(vertices, [], faces)
    mesh.update()
    mesh_ob = bpy.data.objects.new("mesh", mesh)
    scene.collection.objects.link(mesh_ob)
    t_read = time.perf_counter() - t_read

    eye, target = Vector(args.eye), Vector(args.target)
    distance = (target - eye).length
    cam = bpy.data.cameras.new("camera")
    cam.sensor_fit = "AUTO"
    if args.ortho_height > 0:
        cam.type = "ORTHO"
        cam.ortho_scale = args.ortho_height * max(args.aspect, 1.0)
    else:
        cam.type = "PERSP"
        cam.sensor_width = 36.0
        half_long = math.tan(math.radians(args.fov) / 2) * max(args.aspect, 1.0)
        cam.lens = cam.sensor_width / 2 / half_long
    # Our default near plane is a small fraction of the eye-target distance and there is no far plane.
    cam.clip_start = 1e-3 * distance
    cam.clip_end = 1e3 * distance
    cam_ob = bpy.data.objects.new("camera", cam)
    scene.collection.objects.link(cam_ob)
    cam_ob.matrix_world = camera_matrix(args.eye, args.target, args.up)
    scene.camera = cam_ob
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1
    # The frame's aspect (2730 × 1860 for the default page: exactly 273/186). Line Art reads only its ratio.
    if args.aspect >= 1:
        scene.render.resolution_x, scene.render.resolution_y = max(1, round(1860 * args.aspect)), 1860
    else:
        scene.render.resolution_x, scene.render.resolution_y = 1860, max(1, round(1860 / args.aspect))

    gpd = bpy.data.grease_pencils.new("lineart")
    layer = gpd.layers.new("lines")
    layer.frames.new(scene.frame_current)
    material = bpy.data.materials.new("lineart")
    bpy.data.materials.create_gpencil_data(material)
    gpd.materials.append(material)
    gp_ob = bpy.data.objects.new("lineart", gpd)
    scene.collection.objects.link(gp_ob)
    md = gp_ob.grease_pencil_modifiers.new("lineart", "GP_LINEART")
    md.source_type = "OBJECT"
    md.source_object = mesh_ob
    md.target_layer = layer.info
    md.target_material = material
    md.use_contour = True
    md.use_crease = True
    md.crease_threshold = math.radians(180.0 - args.crease)
    md.use_material = False
    md.use_edge_mark = False
    md.use_loose = False
    md.use_light_contour = False
    md.use_shadow = False
    md.use_intersection = not args.no_intersections
    md.use_multiple_levels = False
    md.level_start = 0
    md.level_end = 0
    md.stroke_depth_offset = 0.0  # the strokes on the surfaces, not moved towards the camera

    view_layer = bpy.context.view_layer
    t0 = time.perf_counter()
    view_layer.update()  # everything: the mesh object, the camera, Line Art
    first_s = time.perf_counter() - t0

    lineart_s, no_lineart_s = [], []
    for _ in range(args.runs):
        md.show_viewport = False
        t0 = time.perf_counter()
        view_layer.update()
        no_lineart_s.append(time.perf_counter() - t0)
        md.show_viewport = True
        t0 = time.perf_counter()
        view_layer.update()
        lineart_s.append(time.perf_counter() - t0)

    t_write = time.perf_counter()
    depsgraph = bpy.context.evaluated_depsgraph_get()
    gp_eval = gp_ob.evaluated_get(depsgraph)
    world = gp_eval.matrix_world
    strokes = []
    for lay in gp_eval.data.layers:
        for frame in lay.frames:
            for stroke in frame.strokes:
                n = len(stroke.points)
                co = [0.0] * (3 * n)
                stroke.points.foreach_get("co", co)
                points = []
                for i in range(n):
                    p = world @ Vector((co[3 * i], co[3 * i + 1], co[3 * i + 2]))
                    points.append([p.x, p.y, p.z])
                strokes.append(points)
    timing = {
        "read_and_build_s": t_read,
        "first_evaluation_s": first_s,
        "lineart_s": lineart_s,
        "no_lineart_s": no_lineart_s,
        "lineart_median_s": statistics.median(lineart_s) if lineart_s else None,
        "no_lineart_median_s": statistics.median(no_lineart_s) if no_lineart_s else None,
    }
    out = {
        "format": "hlrscript.lineart/1",
        "blender": bpy.app.version_string,
        "mesh": args.mesh,
        "vertices": len(vertices),
        "faces": len(faces),
        "camera": {"eye": list(args.eye), "target": list(args.target), "up": list(args.up), "fov": args.fov,
                   "ortho_height": args.ortho_height, "aspect": args.aspect,
                   "lens_mm": cam.lens, "sensor_width_mm": cam.sensor_width},
        "settings": {"crease_threshold_deg": math.degrees(md.crease_threshold),
                     "intersections": md.use_intersection,
                     "chaining_image_threshold": md.chaining_image_threshold,
                     "overscan": md.overscan, "threads": scene.render.threads},
        "timing": timing,
        "strokes": strokes,
    }
    with open(args.out, "w") as f:
        json.dump(out, f)
    timing["write_s"] = time.perf_counter() - t_write
    points = sum(len(s) for s in strokes)
    print(f"lineart: {len(strokes)} strokes, {points} points; read+build {t_read:.3f} s, first evaluation "
          f"{first_s:.3f} s, Line Art median {timing['lineart_median_s']} s over {len(lineart_s)} runs "
          f"(without it {timing['no_lineart_median_s']} s), write {timing['write_s']:.3f} s", flush=True)


try:
    main()
except SystemExit as e:
    print(e, file=sys.stderr)
    sys.stdout.flush()
    import os
    os._exit(2)
except Exception:
    import os
    import traceback
    traceback.print_exc()
    os._exit(1)
