"""The bakes' defaults show something (issue 46 item 4).

1. Bake Wet Map with every setting at its default, on a 4 x 4 m ground
   under a 0.6 m board 0.3 m up (Make Wet first, as an artist does): the
   rain shadow shows. The texels under the board's middle (0.2 x 0.2 m: the
   10 degree rain cone reaches 0.3 tan 10 = 0.05 m in from its edges) and
   the open texels (more than 0.5 m from it) are found by geometry. Reference:
   the core's own bake of the same ground and board, written here as an OBJ
   (not by the add-on) and baked by `soak bake rain` for the operator's
   default duration; the add-on's contrast (open mean - sheltered mean)
   must reach 0.9 x the core's and 0.3 (a wetness step an artist sees);
   open ground equals the closed form of rain on flat ground,
   1 - exp(-(r - e) t / 0.2 mm) (soak bake rain's defaults). The core's
   bake of the old default, 600 s, is printed: its contrast is ~0.
2. Bake Rain with every setting at its default on Blender's default shot
   (frames 1-250 at 24 fps), a 2 x 2 m ground under a 0.6 m board: the
   ground gets wet. The film file on open flat ground at the rain's last
   frame equals the same closed form at t = (End - Start) x Time Scale
   (simulated seconds); the drops and film together are above 0.5 on open
   ground (visibly wet), more than twice what real time (the old
   behaviour, (End - Start) / 24 fps) would give there; the frame
   before the rain is dry; the sheltered texels stay drier than the open
   ones. The bake's wall and CPU time are printed (a benchmark's number,
   not asserted)."""
import math
import os
import resource
import subprocess
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
TMP = A["tmp"]
RAIN, EVAP, SAT = 10.0, 0.5, 2e-4          # mm/h, mm/h, m: soak bake rain's defaults
check, CHECKS = common.make_check()


def flat_film(t, rate=RAIN):
    """Wetness of open flat ground after t s of rain (no flow on the flat)."""
    return 1.0 - math.exp(-(rate - EVAP) * 1e-3 / 3600.0 * t / SAT)


def clear():
    for coll in (bpy.data.objects, bpy.data.meshes, bpy.data.materials, bpy.data.images, bpy.data.node_groups):
        for item in list(coll):
            coll.remove(item)


def plane(name, size, loc):
    bpy.ops.mesh.primitive_plane_add(size=size, location=loc)
    ob = bpy.context.object
    ob.name = name
    return ob


def wet_ground(ob):
    mat = bpy.data.materials.new(ob.name)
    common.use_nodes(mat)
    ob.data.materials.append(mat)
    bpy.context.view_layer.objects.active = ob
    for o in bpy.context.scene.objects:
        o.select_set(o == ob)
    mat.soak.preset = "concrete"
    check(bpy.ops.soak.make_wet() == {"FINISHED"}, f"Make Wet on {ob.name}")
    return mat


def pixels(img):
    px = [0.0] * (4 * img.size[0] * img.size[1])
    img.pixels.foreach_get(px)
    return px[0::4], img.size[0]


def load(path):
    img = bpy.data.images.load(path, check_existing=False)
    vals, w = pixels(img)
    bpy.data.images.remove(img)
    return vals, w


def region_means(vals, w, half, board):
    """(mean over the texels under the board's middle, mean over the open
    texels): texel centres mapped to the ground (side 2 half, UV = unit
    square), `board` = (x0, x1, y0, y1) in metres."""
    x0, x1, y0, y1 = board
    under, open_ = [], []
    for j in range(w):
        for i in range(w):
            x, y = -half + 2 * half * (i + 0.5) / w, -half + 2 * half * (j + 0.5) / w
            if x0 + 0.2 < x < x1 - 0.2 and y0 + 0.2 < y < y1 - 0.2:
                under.append(vals[j * w + i])
            elif x > x1 + 0.5 or y > y1 + 0.5 or y < y0 - 0.5:
                if abs(x) < half - 0.1 and abs(y) < half - 0.1:    # off the UV border's gutter
                    open_.append(vals[j * w + i])
    return sum(under) / len(under), sum(open_) / len(open_)


def write_obj(path, half, board, z):
    """The ground (UVs = unit square) and the board (UVs outside it: traced,
    not baked, as soak bake rain documents), Z up."""
    x0, x1, y0, y1 = board
    with open(path, "w", encoding="utf-8") as f:
        f.write(f"v {-half} {-half} 0\nv {half} {-half} 0\nv {half} {half} 0\nv {-half} {half} 0\n")
        f.write(f"v {x0} {y0} {z}\nv {x1} {y0} {z}\nv {x1} {y1} {z}\nv {x0} {y1} {z}\n")
        f.write("vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 4.5 4.5\n")
        f.write("f 1/1 2/2 3/3\nf 1/1 3/3 4/4\nf 5/5 6/5 7/5\nf 5/5 7/5 8/5\n")


def core_contrast(duration, half, board, z, size):
    obj = os.path.join(TMP, "ground_board.obj")
    write_obj(obj, half, board, z)
    out = os.path.join(TMP, f"core_{int(duration)}.exr")
    cmd = [A["soak"], "bake", "rain", obj, "--up", "z", "--duration", f"{duration:g}", "--width", str(size),
           "--height", str(size), "-o", out]
    r = subprocess.run(cmd, capture_output=True, text=True)
    check(r.returncode == 0, f"the core's bake ({' '.join(cmd[1:])}): {r.stderr.strip()[-200:]}")
    vals, w = load(out)
    return region_means(vals, w, half, board)


def test_wet_map():
    clear()
    half, z = 2.0, 0.3
    board = (-1.3, -0.7, -0.3, 0.3)
    ground = plane("Ground", 2 * half, (0, 0, 0))
    plane("Board", 0.6, (-1.0, 0.0, z))
    mat = wet_ground(ground)
    rna = bpy.ops.soak.bake_wetmap.get_rna_type().properties
    duration, size = rna["duration"].default, rna["size"].default
    t0 = time.time()
    check(bpy.ops.soak.bake_wetmap("EXEC_DEFAULT") == {"FINISHED"}, "Bake Wet Map with its defaults")
    print(f"Bake Wet Map default ({duration:g} s of rain, {size} px): {time.time() - t0:.2f} s wall")
    vals, w = pixels(mat.soak.wet_map)
    under, open_ = region_means(vals, w, half, board)
    c_under, c_open = core_contrast(duration, half, board, z, size)
    o_under, o_open = core_contrast(600.0, half, board, z, size)
    print(f"core, the old default 600 s: under {o_under:.3f}, open {o_open:.3f}, contrast {o_open - o_under:.3f}")
    want = flat_film(duration)
    check(abs(open_ - want) < 0.03,
          f"open ground {open_:.3f} = 1 - exp(-(r - e) t / 0.2 mm) = {want:.3f} at the default {duration:g} s")
    contrast, core = open_ - under, c_open - c_under
    check(contrast >= 0.9 * core and contrast >= 0.3,
          f"the default wet map shows the rain shadow: open {open_:.3f} - sheltered {under:.3f} = {contrast:.3f} "
          f"(the core's bake of the same scene: {c_open:.3f} - {c_under:.3f} = {core:.3f}; 600 s: "
          f"{o_open - o_under:.3f})")


def test_rain():
    clear()
    sc = bpy.context.scene
    sc.frame_start, sc.frame_end = 1, 250           # Blender's default shot
    sc.render.fps, sc.render.fps_base = 24, 1.0
    half, z = 1.0, 0.3
    board = (-0.8, -0.2, -0.3, 0.3)
    ground = plane("Yard", 2 * half, (0, 0, 0))
    plane("Bench", 0.6, (-0.5, 0.0, z))
    wet_ground(ground)
    s = sc.soak_rain
    first, end, spf = s.start_frame, s.end_frame, s.seconds_per_frame
    t0, c0 = time.time(), resource.getrusage(resource.RUSAGE_CHILDREN)
    check(bpy.ops.soak.bake_rain() == {"FINISHED"}, "Bake Rain with its defaults")
    c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (c1.ru_utime + c1.ru_stime) - (c0.ru_utime + c0.ru_stime)
    print(f"Bake Rain default ({sc.frame_end - first + 1} frames, {s.size} px, {spf:g} s per frame): "
          f"{time.time() - t0:.2f} s wall, {cpu:.2f} s CPU in soak")
    img = next(i for i in bpy.data.images if i.get("soak_rain_for") == ground.name and "drops" in i.name)
    folder = img["soak_rain_folder"]

    def wetness(frame):
        d, w = load(os.path.join(folder, f"drops.{frame:04d}.exr"))
        f, _ = load(os.path.join(folder, f"film.{frame:04d}.exr"))
        return [max(a, b) for a, b in zip(d, f)], f, w

    both, film, w = wetness(first)
    check(max(both) == 0.0, f"frame {first} (the rain starts): dry")
    both, film, w = wetness(end)
    t = (end - first) * spf
    _, film_open = region_means(film, w, half, board)
    want = flat_film(t)
    check(abs(film_open - want) < 0.01 * want + 1e-3,
          f"frame {end}: film on open flat ground {film_open:.4f} = 1 - exp(-(r - e) t / 0.2 mm) = {want:.4f} "
          f"at t = {t:g} simulated s")
    real = flat_film((end - first) / 24.0)
    under, open_ = region_means(both, w, half, board)
    check(open_ > 0.5 and real < 0.5 * open_,
          f"the default rain wets the ground visibly: open wetness {open_:.3f} at frame {end} "
          f"(in real time it would be {real:.3f})")
    check(under < open_ - 0.3, f"sheltered {under:.3f} drier than open {open_:.3f}")


def main():
    os.makedirs(TMP, exist_ok=True)
    common.install_addon(A["addon"])
    common.preferences().soak_path = A["soak"]
    test_wet_map()
    test_rain()
    print(f"test_bakes_show: {len(CHECKS)} checks passed")


main()
