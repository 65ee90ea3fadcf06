"""Bakes a Blender cloth scene headlessly and writes one OBJ per frame, `fdhcert audit`'s input.

  blender -b --factory-startup -P bake_cloth.py -- --scene drop|crumple --grid N --frames F \
      --out DIR [--self-collision on|off]

The scene is built from nothing (the factory scene's objects are deleted) with Blender's
defaults everywhere except what the scene needs: the cloth's resolution, the frame range, the
obstacle's Collision modifier and, for `crumple`, self-collision and the pins that crumple it.
  drop     an N x N vertex cloth (2 m square, 1 m up) falls on a UV sphere (0.5 m, at the origin);
           self-collision off (Blender's default) unless --self-collision on
  crumple  an N x N vertex cloth (2 m square, 1 m up) with self-collision, its two edges at
           x = -1 and x = +1 pinned to hooks whose empties move towards each other (to
           x = -0.25 and +0.25) while turning half a turn each in opposite senses about the x
           axis over the frames: the cloth is squeezed and twisted into folds; self-collision on
           unless --self-collision off.
With --formats the cloth is triangulated before the bake (so that every format has the same
triangles) and the animation is also exported with Blender's own bundled add-ons (export_formats).
Frame f (1..F) is written to DIR/frame_0000f.obj: object `cloth`, the evaluated cloth mesh with
the triangles Blender's collisions use (the loop triangles of frame 1, see write_frames), then
for `drop` object `obstacles`, the sphere's; world coordinates printed with 17 significant
digits. Every frame has the same topology (checked). DIR must hold no frame_*.obj yet (a longer
bake's would be read as frames of this one). Exit status 0 on success, 2 for bad arguments, 1 on
any other failure; each file is written whole (a temporary name, then a rename).
"""

import argparse
import glob
import math
import os
import sys
import tempfile
import time

import bpy
from mathutils import Matrix

CLOTH_SIZE = 2.0  # m, Blender's default plane size
CLOTH_HEIGHT = 1.0  # m above the origin
SPHERE_RADIUS = 0.5  # m
SQUEEZE_TO = 0.25  # the hooks' final |x|, m
HALF_TURN = math.pi


def parse_args(argv):
    args = argv[argv.index("--") + 1:] if "--" in argv else []
    p = argparse.ArgumentParser(prog="bake_cloth.py", description=__doc__.splitlines()[0])
    p.add_argument("--scene", choices=("drop", "crumple"), required=True)
    p.add_argument("--grid", type=int, required=True, help="vertices along each side (>= 2)")
    p.add_argument("--frames", type=int, required=True, help="frames to bake and write (>= 2)")
    p.add_argument("--out", required=True, help="folder for frame_NNNNN.obj (created)")
    p.add_argument("--formats", action="store_true",
                   help="triangulate the cloth and also write DIR/formats/: the same animation "
                        "as OBJ, PLY (io_mesh_ply), PC2 (io_export_pc2) and MDD (io_shape_mdd)")
    p.add_argument("--self-collision", choices=("on", "off"),
                   help="the cloth's self-collision (default: off for drop, on for crumple)")
    a = p.parse_args(args)
    if a.grid < 2 or a.frames < 2:
        p.error("--grid and --frames must be at least 2")
    if a.self_collision is None:
        a.self_collision = "on" if a.scene == "crumple" else "off"
    return a


def empty_scene(frames):
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, frames
    scene.frame_set(1)
    return scene


def add_cloth(grid, triangulate=False):
    """The N x N vertex grid, its transform the identity (its mesh moved up instead), so that the
    evaluated mesh's coordinates are the world's exactly as Blender computed them. Triangulated
    (each quad split in two, the vertices kept) for --formats: PLY writes faces as they are."""
    bpy.ops.mesh.primitive_grid_add(x_subdivisions=grid - 1, y_subdivisions=grid - 1,
                                    size=CLOTH_SIZE)
    obj = bpy.context.active_object
    obj.name = "cloth"
    obj.data.transform(Matrix.Translation((0.0, 0.0, CLOTH_HEIGHT)))
    if triangulate:
        import bmesh
        bm = bmesh.new()
        bm.from_mesh(obj.data)
        bmesh.ops.triangulate(bm, faces=bm.faces[:])
        bm.to_mesh(obj.data)
        bm.free()
    return obj


def add_cloth_modifier(obj, frames, self_collision):
    mod = obj.modifiers.new("Cloth", "CLOTH")
    mod.point_cache.frame_start, mod.point_cache.frame_end = 1, frames
    mod.collision_settings.use_self_collision = self_collision
    return mod


def build_drop(grid, frames, self_collision, triangulate=False):
    cloth = add_cloth(grid, triangulate)
    add_cloth_modifier(cloth, frames, self_collision)
    bpy.ops.mesh.primitive_uv_sphere_add(radius=SPHERE_RADIUS, location=(0.0, 0.0, 0.0))
    sphere = bpy.context.active_object
    sphere.name = "obstacles"
    sphere.modifiers.new("Collision", "COLLISION")
    return cloth, sphere


def add_hook(cloth, name, x, indices, frames, turn):
    """An empty at the edge's middle, hooked to the edge's vertices, keyed to move to
    x * SQUEEZE_TO and turn by `turn` about the x axis between frame 1 and the last."""
    empty = bpy.data.objects.new(name, None)
    bpy.context.scene.collection.objects.link(empty)
    empty.location = (x, 0.0, CLOTH_HEIGHT)
    bpy.context.view_layer.update()
    hook = cloth.modifiers.new(name, "HOOK")
    hook.object = empty
    hook.center = empty.location
    hook.matrix_inverse = empty.matrix_world.inverted()  # the edge stays put at frame 1
    hook.vertex_indices_set(indices)
    empty.keyframe_insert("location", frame=1)
    empty.keyframe_insert("rotation_euler", frame=1)
    empty.location = (x * SQUEEZE_TO, 0.0, CLOTH_HEIGHT)
    empty.rotation_euler = (turn, 0.0, 0.0)
    empty.keyframe_insert("location", frame=frames)
    empty.keyframe_insert("rotation_euler", frame=frames)


def build_crumple(grid, frames, self_collision, triangulate=False):
    cloth = add_cloth(grid, triangulate)
    half = CLOTH_SIZE / 2
    left = [v.index for v in cloth.data.vertices if v.co.x == -half]
    right = [v.index for v in cloth.data.vertices if v.co.x == half]
    if len(left) != grid or len(right) != grid:
        raise RuntimeError(f"expected {grid} vertices on each pinned edge, "
                           f"found {len(left)} and {len(right)}")
    pins = cloth.vertex_groups.new(name="pin")
    pins.add(left + right, 1.0, "REPLACE")
    # The hooks come before the cloth in the stack: the pinned vertices follow them.
    add_hook(cloth, "hook_left", -half, left, frames, -HALF_TURN)
    add_hook(cloth, "hook_right", half, right, frames, HALF_TURN)
    mod = add_cloth_modifier(cloth, frames, self_collision)
    mod.settings.vertex_group_mass = "pin"
    return cloth, None


def print_settings(mod, scene):
    """The cloth's settings as baked (Blender's defaults but for self-collision), for the record."""
    s, c = mod.settings, mod.collision_settings
    print(f"bake_cloth: cloth settings: quality {s.quality} steps/frame at {scene.render.fps} fps, "
          f"vertex mass {s.mass:.6g} kg, collision quality {c.collision_quality}, "
          f"distance {c.distance_min:.6g} m, self-collision "
          f"{'on' if c.use_self_collision else 'off'} (distance {c.self_distance_min:.6g} m)")


def bake():
    t = time.monotonic()
    result = bpy.ops.ptcache.bake_all(bake=True)
    if "FINISHED" not in result:
        raise RuntimeError(f"bpy.ops.ptcache.bake_all returned {result}")
    return time.monotonic() - t


def evaluated_mesh(obj, depsgraph):
    """The object's evaluated vertices in world coordinates (computed in double from Blender's
    floats), its faces (each face's loop vertex indices, the mesh's topology) and its loop
    triangles (0-based vertex indices)."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        mesh.calc_loop_triangles()
        co = [0.0] * (3 * len(mesh.vertices))
        mesh.vertices.foreach_get("co", co)
        loops = [0] * len(mesh.loops)
        mesh.loops.foreach_get("vertex_index", loops)
        sizes = [0] * len(mesh.polygons)
        mesh.polygons.foreach_get("loop_total", sizes)
        tris = [tuple(t.vertices) for t in mesh.loop_triangles]
    finally:
        evaluated.to_mesh_clear()
    m = [[float(v) for v in row] for row in evaluated.matrix_world]
    points = []
    for i in range(0, len(co), 3):
        x, y, z = co[i], co[i + 1], co[i + 2]
        points.append(tuple(r[0] * x + r[1] * y + r[2] * z + r[3] for r in m[:3]))
    return points, (len(points), loops, sizes), tris


def obj_text(meshes):
    """OBJ text of (name, points, triangles) meshes; indices count from 1 across the file."""
    lines, base = [], 1
    for name, points, tris in meshes:
        lines.append(f"o {name}")
        lines.extend("v %.17g %.17g %.17g" % p for p in points)
        lines.extend(f"f {a + base} {b + base} {c + base}" for a, b, c in tris)
        base += len(points)
    return "\n".join(lines) + "\n"


def write_whole(path, text):
    folder = os.path.dirname(path)
    fd, tmp = tempfile.mkstemp(dir=folder, prefix=".frame-", suffix=".tmp")
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def write_frames(scene, objects, frames, out, name="frame"):
    """Writes every frame (DIR/NAME_0000f.obj). The triangles are frame 1's loop triangles, every frame: Blender splits
    a quad along the diagonal its shape of the moment picks, but its cloth and collision
    modifiers collide the triangles they split once, at the first frame. Raises if a mesh's
    topology (vertices and faces) differs from its first frame's."""
    first = {}
    for frame in range(1, frames + 1):
        scene.frame_set(frame)
        depsgraph = bpy.context.evaluated_depsgraph_get()
        meshes = []
        for obj in objects:
            points, faces, tris = evaluated_mesh(obj, depsgraph)
            faces1, tris1 = first.setdefault(obj.name, (faces, tris))
            if faces != faces1:
                raise RuntimeError(f"frame {frame}: {obj.name}'s topology differs from frame 1's "
                                   f"({faces[0]} vertices, {len(faces[2])} faces; frame 1: "
                                   f"{faces1[0]} vertices, {len(faces1[2])} faces)")
            meshes.append((obj.name, points, tris1))
        write_whole(os.path.join(out, f"{name}_{frame:05d}.obj"), obj_text(meshes))
    return {name: (faces[0], tris) for name, (faces, tris) in first.items()}


def export_formats(scene, cloth, obstacle, frames, out):
    """The cloth's animation as Blender's own bundled add-ons export it, beside our OBJ frames:
      objs/cloth_0000f.obj   the cloth alone per frame (write_frames' way), and
      objs/obstacle_sphere.obj  the sphere at frame 1 (it stands still): a bake folder;
      ply/cloth_0000f.ply    io_mesh_ply, binary (its ascii prints 6 decimals, not the floats),
                             beside the same obstacle_sphere.obj;
      cloth.obj              the cloth's faces (frame 1), the mesh of the caches;
      cloth.pc2, cloth.mdd   io_export_pc2 and io_shape_mdd, every frame, world coordinates."""
    import shutil
    import types
    import io_export_pc2
    from io_mesh_ply import export_ply
    from io_shape_mdd import export_mdd
    for sub in ("objs", "ply"):
        os.makedirs(os.path.join(out, sub), exist_ok=True)
    write_frames(scene, [cloth], frames, os.path.join(out, "objs"), "cloth")
    scene.frame_set(1)
    points, _, tris = evaluated_mesh(cloth, bpy.context.evaluated_depsgraph_get())
    write_whole(os.path.join(out, "cloth.obj"), obj_text([("cloth", points, tris)]))
    if obstacle:
        points, _, tris = evaluated_mesh(obstacle, bpy.context.evaluated_depsgraph_get())
        sphere = os.path.join(out, "objs", "obstacle_sphere.obj")
        write_whole(sphere, obj_text([("obstacle_sphere", points, tris)]))
        shutil.copyfile(sphere, os.path.join(out, "ply", "obstacle_sphere.obj"))
    bpy.ops.object.select_all(action="DESELECT")
    cloth.select_set(True)
    bpy.context.view_layer.objects.active = cloth
    for frame in range(1, frames + 1):
        scene.frame_set(frame)
        export_ply.save(bpy.context, filepath=os.path.join(out, "ply", f"cloth_{frame:05d}.ply"),
                        use_ascii=False, use_selection=True, use_mesh_modifiers=True,
                        use_normals=False, use_uv_coords=False, use_colors=False)
    props = types.SimpleNamespace(rot_x90=False, world_space=True, apply_modifiers=True,
                                  range_start=1, range_end=frames, sampling="1")
    if not io_export_pc2.do_export(bpy.context, props, os.path.join(out, "cloth.pc2")):
        raise RuntimeError("io_export_pc2 failed")
    export_mdd.save(bpy.context, os.path.join(out, "cloth.mdd"), frame_start=1, frame_end=frames,
                    fps=scene.render.fps)


def main():
    a = parse_args(sys.argv)
    os.makedirs(a.out, exist_ok=True)
    if glob.glob(os.path.join(glob.escape(a.out), "frame_*.obj")):
        print(f"bake_cloth: {a.out} already holds frame_*.obj files: remove them or choose "
              "another folder", file=sys.stderr)
        sys.exit(2)
    scene = empty_scene(a.frames)
    build = build_drop if a.scene == "drop" else build_crumple
    cloth, obstacle = build(a.grid, a.frames, a.self_collision == "on", a.formats)
    print_settings(cloth.modifiers["Cloth"], scene)
    seconds = bake()
    objects = [cloth] + ([obstacle] if obstacle else [])
    topology = write_frames(scene, objects, a.frames, a.out)
    shape = ", ".join(f"{name} {n} vertices {len(t)} triangles" for name, (n, t) in
                      topology.items())
    if a.formats:
        export_formats(scene, cloth, obstacle, a.frames, os.path.join(a.out, "formats"))
    print(f"bake_cloth: {a.scene} {a.grid}x{a.grid}, self-collision {a.self_collision}, "
          f"{a.frames} frames baked in {seconds:.1f} s "
          f"by Blender {bpy.app.version_string}; {shape}; wrote {a.out}/frame_00001.obj .. "
          f"frame_{a.frames:05d}.obj")


if __name__ == "__main__":
    try:
        main()
    except SystemExit:
        raise
    except BaseException as e:  # Blender's -P would print it and exit 0: make it fail
        import traceback
        traceback.print_exc()
        print(f"bake_cloth: {e}", file=sys.stderr)
        sys.exit(1)
