"""Bake Rain (issue 37): the drops and ripples bakes wired into a wet
material and animated over the scene's frames, checked by rendering.

A 0.5 m plane (UVs = the unit square) under a straight-down orthographic
camera whose 256 x 256 pixels are the maps' texels; a board above its left
part shelters it. Scene at 2 fps (frame = 0.5 s), rain 50 mm/h from frame 3
to 29, the scene to 40 (drying after the rain). Cycles, 1 sample, a pixel
filter of 0.01 px: each pixel reads its texel's centre. A probe (Emission,
black world, Standard view) shows a socket of the wired tree; the reference
is the baked file of the frame the scene frame must show, read on its own
(an image of one file, not the sequence):

 1. the group's Wet Map input at frames 1 (before the rain: the first file,
    all dry), 12, 29 and 40 equals max(drops.<frame>.exr, film.<frame>.exr)
    (frames before the rain start show the start); the film file on the
    open flat ground at frame 12 is the closed form of rain on a flat
    surface, 1 - exp(-(r - e) t / saturation) (soak bake rain's defaults:
    evaporation 0.5 mm/h, saturation 0.2 mm);
 2. the group's Liquid output (Schedule off, Wetness 1, Puddle Level p)
    equals min(w / p, 1) of that file (the group's documented formula),
    after changing Puddle Level (the flood threshold follows by its driver);
 3. the normal entering the group is normalize(2 c - 1) of ripples.<k>.exr,
    k = (frame - scene start) mod 64, where w >= p, and the plane's +Z
    elsewhere (tangent +X, bitangent +Y for the plane's UVs);
 3b. only the flipbooks the camera needs are wired (ripple_reach): this
    camera's pixel (0.5 m / 256 = 2 mm) is under half the rings'
    wavelength (8.55 mm), so the plane is near: one ripple image node, the
    sharp one, labelled "Ripples: near only" (the checks of 3); baked with
    a 4 m orthographic view (15.6 mm pixels) it is far: the far flipbook
    alone, and the same render shows ripples_far.<k>.exr; baked with a
    perspective camera whose near..far band it spans, both and the blend,
    each flipbook shown when the blend's distances are moved past the
    plane; the rule itself on a perspective camera (nearest box point and
    farthest corner against near and far) and the far distance of a 50 mm
    lens on a 36 mm sensor at 1920 px (3.75e-4 rad a pixel): 22.8 m;
 4. sheltered texels (under the board) stay dry while open ones get wet;
 4b. a steep face (a 0.3 m roof tilted 70 degrees, its own bake, 32 x 32
    texels, Shelter by Scene off, seen face-on by the orthographic camera)
    reads the falling film:
    its film file is w = 1 where the film runs (more than 1 um: the rain
    puts r cos(70 deg) = 4.8 um/s on it; the physics is the core's test,
    test_bake_rain_frames) while the flat ground at the same time is at 0.27,
    and the rendered Wet Map there equals max(drops, film);
 5. all or nothing: a failing soak, a failing wiring half-way and a
    backwards frame range leave the node tree as it was (common.tree_state),
    with no new image and no stray driver; a second bake replaces the first
    one's nodes and images; undo of a third (3c's) brings back the second's tree;
 6. the panel's Runnels and Splashes reach the bakes (issue 48): the roof of
    4b baked again at 128 x 128 (2.3 mm texels) without them and with
    Runnels = From Preset (the material's preset, sand: 20 degrees, whose
    minimum wetting rate is far above the roof's film) and Splashes:
    the film file at frame 12 runs (w = 1) on fewer than 60 % of the texels
    it ran on without (the film gathered into rivulets, dry between them)
    and still runs somewhere; the drops file at the rain's end differs (the
    splashes' secondary drops; same seed); Contact Angle 30 degrees gives
    `--contact-angle 30`."""
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

A = common.args()
TMP = A["tmp"]
N = 256                  # render pixels = drops texels = ripple texels
SIZE_M = 0.5             # the plane's side = the ripple tile: one tile over the UV square
FPS = 2
START, END, LAST = 3, 29, 40
TOL = 2e-3               # EXR half values through a linear lookup at the texel centre +- 0.005 px
check, CHECKS = common.make_check()


def scene():
    for coll in (bpy.data.objects, bpy.data.meshes, bpy.data.materials, bpy.data.cameras, bpy.data.lights,
                 bpy.data.worlds, bpy.data.node_groups, bpy.data.images):
        for item in list(coll):
            coll.remove(item)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.device = "CPU"
    sc.cycles.samples = 1
    sc.cycles.use_denoising = False
    sc.cycles.filter_width = 0.01
    sc.render.fps, sc.render.fps_base = FPS, 1.0
    sc.frame_start, sc.frame_end = 1, LAST
    world = bpy.data.worlds.new("W")
    common.use_nodes(world)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    sc.world = world
    common.ortho_exr_camera(sc, N, N, SIZE_M, z=2.0)
    bpy.ops.mesh.primitive_plane_add(size=SIZE_M)
    board = bpy.context.object
    board.name = "Board"
    board.scale = (0.4, 1.4, 1)          # over x in [-0.275, -0.075]: u in [0, 0.35] of the ground
    board.location = (-0.175, 0, 0.05)
    bpy.ops.mesh.primitive_plane_add(size=SIZE_M)
    plane = bpy.context.object
    plane.name = "Ground"
    mat = bpy.data.materials.new("Wet ground")
    common.use_nodes(mat)
    plane.data.materials.append(mat)
    return sc, plane, board, mat


def read(path):
    img = bpy.data.images.load(path, check_existing=False)
    px = [0.0] * (4 * img.size[0] * img.size[1])
    img.pixels.foreach_get(px)
    w = img.size[0]
    bpy.data.images.remove(img)
    return px, w


def render(sc, mat, socket, frame, vector=False):
    """The probe: `socket` (a value or a normal mapped to 0.5 n + 0.5) as
    emission, rendered at `frame`; returns RGBA pixels."""
    t = mat.node_tree
    out = next(n for n in t.nodes if n.type == "OUTPUT_MATERIAL" and n.is_active_output)
    keep = out.inputs["Surface"].links[0].from_socket
    em = t.nodes.new("ShaderNodeEmission")
    made = [em]
    if vector:
        ma = t.nodes.new("ShaderNodeVectorMath")
        ma.operation = "MULTIPLY_ADD"
        ma.inputs[1].default_value = (0.5, 0.5, 0.5)
        ma.inputs[2].default_value = (0.5, 0.5, 0.5)
        t.links.new(socket, ma.inputs[0])
        t.links.new(ma.outputs["Vector"], em.inputs["Color"])
        made.append(ma)
    else:
        t.links.new(socket, em.inputs["Color"])
    t.links.new(em.outputs["Emission"], out.inputs["Surface"])
    sc.frame_set(frame)
    path = os.path.join(TMP, f"probe_{frame}.exr")
    sc.render.filepath = path
    bpy.ops.render.render(write_still=True)
    t.links.new(keep, out.inputs["Surface"])
    for n in made:
        t.nodes.remove(n)
    px, _ = read(path)
    return px


def folder(plane):
    img = next(i for i in bpy.data.images if i.get("soak_rain_for") == plane.name and "drops" in i.name)
    return img["soak_rain_folder"]


def wet_refs(plane, frame, n=N):
    """(max(drops, film), drops, film) of the baked files of `frame`."""
    drops, w = read(os.path.join(folder(plane), f"drops.{frame:04d}.exr"))
    film, wf = read(os.path.join(folder(plane), f"film.{frame:04d}.exr"))
    check(w == n and wf == n, f"drops and film maps {w}, {wf} wide")
    return [max(a, b) for a, b in zip(drops, film)], drops, film


def check_wet(sc, mat, gn, plane, frame, expect_file):
    ref, drops, film = wet_refs(plane, expect_file)
    got = render(sc, mat, gn.inputs["Wet Map"].links[0].from_socket, frame)
    err = max(abs(got[i] - ref[i]) for i in range(0, len(ref), 4))
    mean = sum(ref[i] for i in range(0, len(ref), 4)) / (N * N)
    above = sum(1 for i in range(0, len(ref), 4) if film[i] > drops[i] + 0.01)
    check(err < TOL, f"frame {frame}: rendered wetness = max(drops, film).{expect_file:04d}.exr (max |diff| "
                     f"{err:.2e}, mean wetness {mean:.3f}, film wetter at {above} texels)")
    return ref, drops, film, mean


def flat_film(t):
    """soak bake rain's wetness of open flat ground after t s of 50 mm/h
    (evaporation 0.5 mm/h, saturation 0.2 mm; no flow on the flat)."""
    return 1.0 - math.exp(-(50.0 - 0.5) * 1e-3 / 3600.0 * t / 2e-4)


def check_flat_film(film, frame):
    open_ = [film[4 * (y * N + x)] for y in range(8, N - 8) for x in range(int(0.6 * N), N - 8)]
    got, want = sum(open_) / len(open_), flat_film((frame - START) / FPS)
    spread = max(abs(v - want) for v in open_)
    check(abs(got - want) < 0.01 * want and spread < 0.03,
          f"frame {frame}: film file on the open flat ground {got:.4f} (max |diff| {spread:.1e}) against "
          f"1 - exp(-(r - e) t / 0.2 mm) = {want:.4f}")


def check_liquid(sc, mat, gn, ref, frame, level):
    mat.soak.puddle_level = level      # the panel's control: the flood threshold follows it
    gn.inputs["Schedule"].default_value = 0.0
    gn.inputs["Wetness"].default_value = 1.0
    got = render(sc, mat, gn.outputs["Liquid"], frame)
    err = max(abs(got[i] - min(ref[i] / level, 1.0)) for i in range(0, len(ref), 4))
    check(err < TOL / level, f"frame {frame}: Liquid = min(w / {level}, 1) (max |diff| {err:.2e})")


def check_normal(sc, mat, gn, plane, ref, frame, level, flipbook="ripples", min_bent=1e-3):
    k = (frame - sc.frame_start) % 64
    rip, w = read(os.path.join(folder(plane), f"{flipbook}.{k:04d}.exr"))
    check(w == N, f"ripple frame {w} wide")
    got = render(sc, mat, gn.inputs["Normal"].links[0].from_socket, frame, vector=True)
    worst, flooded, bent = 0.0, 0, 0.0
    for p in range(N * N):
        if ref[4 * p] >= level:
            n = [2.0 * rip[4 * p + c] - 1.0 for c in range(3)]
            ln = math.sqrt(sum(c * c for c in n))
            n = [c / ln for c in n]
            flooded += 1
            bent = max(bent, 1.0 - n[2])
        else:
            n = [0.0, 0.0, 1.0]
        g = [2.0 * got[4 * p + c] - 1.0 for c in range(3)]
        worst = max(worst, max(abs(a - b) for a, b in zip(g, n)))
    check(flooded > 100 and bent > min_bent, f"{flipbook}, frame {frame}: {flooded} flooded texels, ripples tilt up to "
                                         f"{math.degrees(math.acos(1 - bent)):.1f} deg")
    check(worst < 4 * TOL, f"frame {frame}: rendered normal = {flipbook}.{k:04d}.exr where w >= {level}, +Z "
                           f"elsewhere (max |diff| {worst:.2e})")
    return bent


def ripple_nodes(mat):
    """(the ripple image nodes' image names, the ripple Normal Map's reach tag and label, Map Range or None)."""
    t = mat.node_tree
    rain = [n for n in t.nodes if n.get("soak_role") == "rain"]
    imgs = sorted(n.image.name for n in rain if n.type == "TEX_IMAGE" and "ripples" in n.image.name)
    nm = next(n for n in rain if n.type == "NORMAL_MAP")
    mr = next((n for n in rain if n.get("soak_rain_far")), None)
    return imgs, nm.get("soak_rain_reach"), nm.label, mr


def check_reach(mat, reach, label, want):
    imgs, got, lab, mr = ripple_nodes(mat)
    kinds = sorted("far" if "ripples_far" in i else "sharp" for i in imgs)
    check(got == reach and lab == f"Ripples: {label}" and kinds == want and (mr is not None) == (len(want) == 2),
          f"{reach}: ripple image nodes {imgs}, label '{lab}', blend {'wired' if mr else 'absent'}")


def bake_with(sc, seed, setup):
    """Bake Rain with the camera changed by `setup`, then the test's
    orthographic camera back (the wiring stays: it follows only a re-bake)."""
    cd = sc.camera.data
    keep = (cd.type, cd.ortho_scale, cd.lens, cd.sensor_width, cd.sensor_fit)
    setup(cd)
    sc.soak_rain.seed = seed
    try:
        ok = bpy.ops.soak.bake_rain() == {"FINISHED"}
    finally:
        cd.type, cd.ortho_scale, cd.lens, cd.sensor_width, cd.sensor_fit = keep
    check(ok, f"Bake Rain (seed {seed})")


def persp(lens):
    def setup(cd):
        cd.type, cd.lens, cd.sensor_width, cd.sensor_fit = "PERSP", lens, 36.0, "AUTO"
    return setup


def check_far_only(sc, mat, gn, plane, level, bent_sharp):
    """3b: an orthographic camera whose pixel (4 m / 256 = 15.6 mm) is over
    half the wavelength (8.55 mm) puts the plane far: the far flipbook
    alone; rendered with the test's camera, the normal is ripples_far."""
    def wide(cd):
        cd.ortho_scale = 4.0
    bake_with(sc, 8, wide)
    check_reach(mat, "FAR", "far only", ["far"])
    ref, _ = read(os.path.join(folder(plane), f"drops.{END:04d}.exr"))
    bent_far = check_normal(sc, mat, gn, plane, ref, END, level, "ripples_far", 1e-6)
    check(bent_far < 0.5 * bent_sharp, f"far ripples tilt less (1 - n.z up to {bent_far:.2e}, sharp {bent_sharp:.2e})")
    return ref


def check_band(sc, mat, gn, plane, ref, level):
    """3c: a 45 mm lens on 36 mm at 256 px (pixel 0.8 / 256 rad): far =
    8.55 mm / (0.8 / 256) = 2.736 m, near 1.368 m; the plane 2 m below
    spans 2.000..2.031 m: both flipbooks and the blend, at those distances;
    the blend's ends moved past the plane show each flipbook."""
    bake_with(sc, 8, persp(45.0))
    check_reach(mat, "BAND", "near to far blend", ["far", "sharp"])
    _, _, _, mr = ripple_nodes(mat)
    near, far = mr.inputs["From Min"].default_value, mr.inputs["From Max"].default_value
    want = 0.0171 / 2 / (0.8 / N)
    check(abs(far - want) < 1e-3 * want and abs(near - want / 2) < 1e-3 * want,
          f"blend from {near:.3f} m to {far:.3f} m (expected {want / 2:.3f}, {want:.3f})")
    mr.inputs["From Min"].default_value, mr.inputs["From Max"].default_value = 1e-4, 2e-4
    check_normal(sc, mat, gn, plane, ref, END, level, "ripples_far", 1e-6)
    mr.inputs["From Min"].default_value, mr.inputs["From Max"].default_value = 1e5, 2e5
    check_normal(sc, mat, gn, plane, ref, END, level)
    mr.inputs["From Min"].default_value, mr.inputs["From Max"].default_value = near, far


def check_reach_rule(sc, plane):
    """ripple_reach on its own (no bake): the 45 mm camera of 3c (near
    1.368 m, far 2.736 m) straight above the 0.5 m plane's centre at height
    h: all near at 1.0 (corners 1.06 m), all far at 2.75, the band at 2.72
    (the centre nearer than far, though all four corners, 2.743 m, are
    beyond it); the plane stood up (rotated 90 deg about x) seen from 2.74
    m and 2.72 m along y: far, band. The 50 mm lens at 1920 px puts far
    at 8.55 mm / 3.75e-4 rad = 22.8 m."""
    rain = sys.modules["soak.rain"]
    cd, co = sc.camera.data, sc.camera
    keep = (cd.type, cd.lens, cd.sensor_width, cd.sensor_fit, co.location.copy(), co.rotation_euler.copy(),
            plane.rotation_euler.copy(), sc.render.resolution_x, sc.render.resolution_y)
    persp(45.0)(cd)
    try:
        dist = rain.far_distances(sc)
        got = []
        for loc, rot, prot in (((0, 0, 1.0), (0, 0, 0), (0, 0, 0)), ((0, 0, 2.75), (0, 0, 0), (0, 0, 0)),
                               ((0, 0, 2.72), (0, 0, 0), (0, 0, 0)),
                               ((0, 2.74, 0), (-math.pi / 2, 0, 0), (math.pi / 2, 0, 0)),
                               ((0, 2.72, 0), (-math.pi / 2, 0, 0), (math.pi / 2, 0, 0))):
            co.location, co.rotation_euler, plane.rotation_euler = loc, rot, prot
            bpy.context.view_layer.update()
            got.append(rain.ripple_reach(sc, [plane], dist))
        sc.render.resolution_x, sc.render.resolution_y = 1920, 1080
        cd.lens = 50.0
        wide = rain.far_distances(sc)
    finally:
        (cd.type, cd.lens, cd.sensor_width, cd.sensor_fit, co.location, co.rotation_euler, plane.rotation_euler,
         sc.render.resolution_x, sc.render.resolution_y) = keep
        bpy.context.view_layer.update()
    check(got == ["NEAR", "FAR", "BAND", "FAR", "BAND"], f"reach by the nearest and farthest box points: {got}")
    want = 0.0171 / 2 / (36.0 / 50.0 / 1920)
    check(abs(wide[1] - want) < 1e-3 * want and abs(wide[0] - want / 2) < 1e-3 * want,
          f"50 mm lens, 1920 px: far ripples from {wide[0]:.2f} m to {wide[1]:.2f} m "
          f"(expected {want / 2:.2f}, {want:.2f})")


def check_shelter(ref):
    # the board covers u in [0, 0.35]; margins for the rain's cone (0.05 m up) and the splats (up to 5 cm)
    under = [ref[4 * (y * N + x)] for y in range(40, N - 40) for x in range(int(0.04 * N), int(0.22 * N))]
    open_ = [ref[4 * (y * N + x)] for y in range(N) for x in range(int(0.6 * N), N)]
    mu, mo = sum(under) / len(under), sum(open_) / len(open_)
    check(mo > 0.2 and mu < 0.02 * mo, f"sheltered texels mean wetness {mu:.4f}, open ones {mo:.3f}")


ROOF_M, ROOF_N, ROOF_TILT = 0.3, 32, 70.0


def check_steep(sc):
    """4b (see the module's docstring): a roof at 70 degrees, its own bake."""
    bpy.ops.mesh.primitive_plane_add(size=ROOF_M, location=(3.0, 0.0, 0.5), rotation=(math.radians(ROOF_TILT), 0, 0))
    roof = bpy.context.object
    roof.name = "Roof"
    mat = bpy.data.materials.new("Wet roof")
    common.use_nodes(mat)
    roof.data.materials.append(mat)
    check(bpy.ops.soak.make_wet() == {"FINISHED"}, "Make Wet on the roof")
    s = sc.soak_rain
    s.size, s.rays = ROOF_N, 4
    s.shelter = False                  # nothing near: the path without a shelter (the film still needs the mesh)
    op = sys.modules["soak.operators.rain"]
    keep = op.RIPPLE_SIZE
    op.RIPPLE_SIZE = ROOF_N            # the ripples are not looked at here: 32 x 32 (0.7 s of CPU, 20 s at 256)
    try:
        check(bpy.ops.soak.bake_rain() == {"FINISHED"}, "Bake Rain on the roof")
    finally:
        op.RIPPLE_SIZE = keep
    gn = next(n for n in mat.node_tree.nodes if n.type == "GROUP")
    cam = sc.camera                         # face-on: image x, y = the roof's u, v
    cam.rotation_euler = roof.rotation_euler
    cam.location = roof.location + 2.0 * (roof.matrix_world.to_3x3() @ roof.data.polygons[0].normal)
    cam.data.ortho_scale = ROOF_M
    sc.render.resolution_x = sc.render.resolution_y = ROOF_N
    frame = 12
    ref, drops, film = wet_refs(roof, frame, ROOF_N)
    got = render(sc, mat, gn.inputs["Wet Map"].links[0].from_socket, frame)
    err = max(abs(got[i] - ref[i]) for i in range(0, len(ref), 4))
    def rows(lo, hi):       # texels of rows lo..hi-1 (row 0 = v 0, the roof's foot), off the edges
        return [4 * (y * ROOF_N + x) for y in range(lo, hi) for x in range(1, ROOF_N - 1)]
    runs = [i for i in rows(1, ROOF_N - 1) if film[i] > 0.999]
    up = [i for i in rows(ROOF_N // 2, ROOF_N - 1) if film[i] > 0.999]
    q = ROOF_N // 4
    top = sum(film[i] for i in rows(ROOF_N - q, ROOF_N - 1)) / ((q - 1) * (ROOF_N - 2))
    flat = flat_film((frame - START) / FPS)
    check(len(runs) > 4 * ROOF_N and not up and top < 0.5 and flat < 0.5,
          f"the {ROOF_TILT:g} deg roof's film file at frame {frame}: w = 1 on {len(runs)} texels, all in the lower "
          f"half (the flow collects downhill), mean {top:.3f} in the top quarter; flat ground {flat:.3f}")
    low = min(got[i] for i in runs)
    film_wetter = sum(1 for i in runs if film[i] > drops[i] + 0.01)
    check(err < TOL and low > 0.999 - TOL and film_wetter > len(runs) // 2,
          f"the roof reads the film: rendered wetness = max(drops, film) (max |diff| {err:.2e}), >= {low:.4f} "
          f"where the film runs, wetter than the drops at {film_wetter} of those {len(runs)} texels")


def roof_files(sc, roof, runnels, splashes):
    """Bakes the roof with the panel's Runnels and Splashes; its film file of
    frame 12 and drops file of the rain's end."""
    s = sc.soak_rain
    s.runnels, s.splashes = runnels, splashes
    op = sys.modules["soak.operators.rain"]
    keep = op.RIPPLE_SIZE
    op.RIPPLE_SIZE = 32                # the ripples are not looked at here
    try:
        check(bpy.ops.soak.bake_rain() == {"FINISHED"}, f"Bake Rain on the roof, Runnels {runnels}, Splashes "
                                                         f"{splashes}")
    finally:
        op.RIPPLE_SIZE = keep
    film, _ = read(os.path.join(folder(roof), "film.0012.exr"))
    drops, _ = read(os.path.join(folder(roof), f"drops.{END:04d}.exr"))
    return film, drops


def check_runnels_splashes(sc):
    """6 (see the module's docstring)."""
    roof = bpy.data.objects["Roof"]
    bpy.context.view_layer.objects.active = roof
    s = sc.soak_rain
    s.size = 128
    op = sys.modules["soak.operators.rain"]
    s.runnels, s.contact_angle = "CUSTOM", math.radians(30.0)
    opts = op.runnel_options(s, "brick")
    check(opts == ["--contact-angle", "30"], f"Contact Angle 30 degrees passes {opts}")
    film0, drops0 = roof_files(sc, roof, "OFF", False)
    preset = roof.active_material.soak.preset
    film1, drops1 = roof_files(sc, roof, "PRESET", True)
    n = 128
    inner = [4 * (y * n + x) for y in range(2, n // 2) for x in range(4, n - 4)]    # the lower half, off the edges
    runs0 = sum(1 for i in inner if film0[i] > 0.999)
    runs1 = sum(1 for i in inner if film1[i] > 0.999)
    changed = sum(1 for i in range(0, len(drops0), 4) if abs(drops0[i] - drops1[i]) > 1e-6)
    check(runs0 > len(inner) // 2 and 0 < runs1 < 0.6 * runs0,
          f"Runnels From Preset ({preset}) reach the film bake: the film runs on {runs1} of {len(inner)} texels "
          f"of the roof's lower half against {runs0} without")
    check(changed > 0, f"Splashes reach the drops bake: {changed} texels of drops.{END:04d} differ")
    s.runnels, s.splashes, s.size = "OFF", False, ROOF_N


def rain_state(mat):
    ad = mat.node_tree.animation_data
    drivers = sorted(fc.data_path for fc in ad.drivers) if ad else []
    return common.tree_state(mat.node_tree), sorted(i.name for i in bpy.data.images), drivers


def refusal(op):
    """The error an operator reports (bpy.ops raises it in the background),
    or None when it did not refuse."""
    try:
        r = op()
    except RuntimeError as e:
        return str(e)
    return None if r != {"CANCELLED"} else "cancelled without a message"


def check_refusals(sc, mat, plane):
    before = rain_state(mat)
    s = sc.soak_rain
    s.start_frame, s.end_frame = 20, 10
    msg = refusal(bpy.ops.soak.bake_rain)
    check(msg is not None and "before it starts" in msg and rain_state(mat) == before,
          f"a backwards frame range is refused ({msg}), nothing changed")
    s.start_frame, s.end_frame = START, END
    prefs = common.preferences()
    prefs.soak_path = "/bin/false"
    msg = refusal(bpy.ops.soak.bake_rain)
    check(msg is not None and "failed (exit 1)" in msg and rain_state(mat) == before,
          f"a failing soak leaves the material as it was ({msg})")
    prefs.soak_path = A["soak"]
    rain = sys.modules["soak.rain"]         # the installed add-on's (soak_install aliases it)
    orig = rain._flood_mix

    def broken(*a):
        orig(*a)
        raise RuntimeError("provoked failure half-way")
    rain._flood_mix = broken
    try:
        msg = refusal(bpy.ops.soak.bake_rain)
    finally:
        rain._flood_mix = orig
    after = rain_state(mat)
    if after != before:
        import difflib
        print("\n".join(difflib.unified_diff(str(before).split(", "), str(after).split(", "), lineterm="")))
    check(msg is not None and "provoked" in msg and after == before,
          f"a wiring that fails half-way leaves the tree, images and drivers as they were ({msg})")


def check_undo(sc, gn, plane, ref, level):
    """Undo of a Bake Rain (the band bake of 3c, checked before the undo)
    puts back the tree of the bake before it (far only), whose images still
    find their frames."""
    mat = bpy.data.materials["Wet ground"]
    bpy.ops.ed.undo_push(message="before the third bake")
    before = common.tree_state(mat.node_tree)
    check_band(sc, mat, gn, plane, ref, level)
    bpy.ops.ed.undo_push(message="third bake")
    bpy.ops.ed.undo()
    mat = bpy.data.materials["Wet ground"]
    tex = [n for n in mat.node_tree.nodes if n.type == "TEX_IMAGE" and n.image is not None]
    files = [bpy.path.abspath(n.image.filepath) for n in tex]
    check(common.tree_state(mat.node_tree) == before and len(tex) == 3 and all(os.path.isfile(f) for f in files),
          f"undo of Bake Rain restores the tree; its images find their frames ({len(tex)} image nodes)")


def main():
    os.makedirs(TMP, exist_ok=True)
    common.install_addon(A["addon"])
    common.preferences().soak_path = A["soak"]
    sc, plane, board, mat = scene()
    bpy.ops.wm.save_as_mainfile(filepath=os.path.join(TMP, "rain.blend"))   # the frames go to //soak_rain
    bpy.context.view_layer.objects.active = plane
    plane.select_set(True)
    check(bpy.ops.soak.bake_rain.poll() is False, "Bake Rain is greyed out on a dry material")
    check(bpy.ops.soak.make_wet() == {"FINISHED"}, "Make Wet")
    s = sc.soak_rain
    s.rate, s.start_frame, s.end_frame, s.size, s.seed, s.rays = 50.0, START, END, N, 7, 16
    s.map_size, s.dry_time = 0.0, 20.0
    s.seconds_per_frame = 1.0 / FPS      # real time: the checks below put frame f at (f - START) / FPS s
    check(bpy.ops.soak.bake_rain() == {"FINISHED"}, "Bake Rain")
    board.hide_render = True          # the probe camera looks through it
    check(mat.soak.wetness_source == "IMAGE" and mat.soak.wet_map is not None
          and mat.soak.wet_map.source == "SEQUENCE", "the panel's Source shows the drops sequence")
    rain_nodes = sorted(n.name for n in mat.node_tree.nodes if n.get("soak_role") == "rain")
    gn = next(n for n in mat.node_tree.nodes if n.type == "GROUP")
    *_, m1 = check_wet(sc, mat, gn, plane, 1, START)
    check(m1 == 0.0, "before the rain the surface is dry")
    _, drops12, film12, _ = check_wet(sc, mat, gn, plane, 12, 12)
    check_flat_film(film12, 12)
    ref_end, drops_end, _, m_end = check_wet(sc, mat, gn, plane, END, END)
    *_, m_last = check_wet(sc, mat, gn, plane, LAST, LAST)
    check(m_last < m_end, f"drying after the rain: mean {m_end:.3f} -> {m_last:.3f}")
    check_shelter(ref_end)
    check_liquid(sc, mat, gn, ref_end, END, 0.6)
    check_reach(mat, "NEAR", "near only", ["sharp"])
    bent = check_normal(sc, mat, gn, plane, drops_end, END, 0.6)     # ripples where the drops flood
    check_normal(sc, mat, gn, plane, drops12, 12, 0.6)
    check_reach_rule(sc, plane)
    check_refusals(sc, mat, plane)
    old = sorted(i.name for i in bpy.data.images if i.get("soak_rain_for"))
    ref8 = check_far_only(sc, mat, gn, plane, 0.6, bent)
    now = sorted(n.name for n in mat.node_tree.nodes if n.get("soak_role") == "rain")
    imgs = [i for i in bpy.data.images if i.get("soak_rain_for")]
    check(len(now) == len(rain_nodes) and not set(now) & set(rain_nodes) and len(imgs) == 3,
          f"the second bake replaced the first's nodes ({len(now)}) and images ({old} -> {[i.name for i in imgs]})")
    check_undo(sc, gn, plane, ref8, 0.6)
    mat = bpy.data.materials["Wet ground"]
    check(bpy.ops.soak.make_dry() == {"FINISHED"} and not any(n.get("soak_role") for n in mat.node_tree.nodes),
          "Make Dry removes the rain's nodes")
    check_steep(bpy.context.scene)          # undo replaced the scene's Python object
    check_runnels_splashes(bpy.context.scene)
    print(f"PASS: {len(CHECKS)} checks (Blender {bpy.app.version_string})")


main()
