#!/usr/bin/env python3
"""gallery_claims: the measurable part of the source's description, asserted on the
gallery's own soak render scenes (scenes/gallery/) at reduced size.

[JLD99] §4.1, Fig. 5: a wet spot on paper looks darker than the dry paper when lit
from the viewer's side (Fig. 5a) and brighter when lit from behind (Fig. 5b). The
expected relation is that direction, taken from the source; the blot's and the dry
sheet's pixels are found by projecting the sheet's own wet map function
(scenes/gallery/meshes.py `blot`) through the scene's camera, never from the render.
A pass needs the difference beyond 4 standard errors of the pixel means.

[Hnat06] §4, Fig. 5: the larger alpha_poro, the darker the wet flowerpot. Each front
(wet) pot's wall is divided by the same pixels of a second render in which every pot
has alpha_poro = 0, so position and lighting cancel; alpha_poro 0.5 must come out
darker than alpha_poro 0 beyond 4 standard errors.

[JLD99] §4.3, Fig. 7: the spilled pool is glossy: it mirrors the room (here the
courtyard HDRI) where the dry oak round it does not. The pool's pixels (the spill
map's function, scenes/gallery/meshes.py `spill`, at 1) must come out brighter than
the dry table's (map 0) within 0.3 m of it, left of the glass and its shadow,
beyond 4 standard errors; rendered without the caustic photons (they light only the
glass's shadow, which neither set of pixels touches).

[Hnat06] §5 (pore schedule): a splash on a brick wall dries from its border inwards.
The gallery's four frames (soak bake drying at t = 0, 0.2, 0.4, 0.6 of the same
splash, render.sh) are rendered at reduced size with a fifth, dry, render; a pixel is
wet where it is darker than 0.85 x the dry render (2 x 2 blocks). The wet area must
fall frame by frame, and at least 90 % of each frame's wet pixels must have been wet
in the frame before (the patch shrinks, it does not move or fade as one).

usage: gallery_claims.py SOAK ROOT TMP   (exit 77 and SKIPPED: when oiiotool is missing)
"""
import json
import math
import os
import shutil
import subprocess
import sys

WIDTH, HEIGHT, SPP = 192, 108, 8
SHEET_W, SHEET_H = 210.0, 297.0      # mm, meshes.py's sheet
PENCIL_Y = (159.5 - 6, 166.5 + 6)    # paper_front.json's pencil (y, mm) and a margin
EDGE_MM = 12.0                        # keep clear of the sheet's edge


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    n = math.sqrt(dot(a, a))
    return [x / n for x in a]


def projector(cam, width, height):
    """Pinhole look-at camera, vertical fov (scenes/README.md): world point -> pixel."""
    pos = cam["position"]
    fwd = unit(sub(cam["look_at"], pos))
    right = unit(cross(fwd, cam["up"]))
    up = cross(right, fwd)
    scale = (height / 2) / math.tan(math.radians(cam["fov"]) / 2)

    def project(p):
        d = sub(p, pos)
        z = dot(d, fwd)
        return (int(width / 2 + dot(d, right) / z * scale),
                int(height / 2 - dot(d, up) / z * scale))
    return project


def classify(scene, blot):
    """Pixels wholly inside the blot (map 1) and wholly on dry sheet (map 0)."""
    project = projector(scene["camera"], WIDTH, HEIGHT)
    classes = {}
    steps = 0.5
    y = EDGE_MM
    while y <= SHEET_H - EDGE_MM:
        x = EDGE_MM
        while x <= SHEET_W - EDGE_MM:
            if not (PENCIL_Y[0] <= y <= PENCIL_Y[1]):
                w = blot(x / SHEET_W, y / SHEET_H)
                c = "wet" if w >= 1 else "dry" if w <= 0 else "edge"
            else:
                c = "edge"
            for z in (0.0, 0.1):   # both faces of the 0.1 mm sheet
                classes.setdefault(project((x, y, z)), set()).add(c)
            x += steps
        y += steps
    inside = {p: c for p, c in classes.items() if 0 <= p[0] < WIDTH and 0 <= p[1] < HEIGHT}
    wet = [p for p, c in inside.items() if c == {"wet"}]
    dry = [p for p, c in inside.items() if c == {"dry"}]
    return wet, dry


def luminance_map(exr):
    out = subprocess.run(["oiiotool", "--dumpdata", exr], check=True, capture_output=True,
                         text=True).stdout
    lum = {}
    for line in out.splitlines():
        line = line.strip()
        if not line.startswith("Pixel ("):
            continue
        head, vals = line.split("):")
        i, j = (int(v) for v in head[len("Pixel ("):].split(","))
        r, g, b = (float(v) for v in vals.split()[:3])
        lum[(i, j)] = 0.2126 * r + 0.7152 * g + 0.0722 * b   # Rec. 709 luminance
    return lum


def stats(values):
    n = len(values)
    mean = sum(values) / n
    var = sum((v - mean) ** 2 for v in values) / (n - 1)
    return mean, var / n


def pot_pixels(scene, x_pot, y_pot, width, height):
    """Pixels of a pot's outer wall facing the camera (meshes.py's lathe profile:
    radius 0.055 m at the foot to 0.08 m at 0.14 m), clear of rim and foot."""
    project = projector(scene["camera"], width, height)
    pixels = set()
    for k in range(15):
        z = 0.04 + 0.07 * k / 14
        r = 0.055 + 0.025 * z / 0.14
        for a in range(-30, 31, 3):
            t = math.radians(a)
            pixels.add(project((x_pot + r * math.sin(t), y_pot - r * math.cos(t), z)))
    return pixels


def render(soak, scene, path, width, height, spp):
    with open(path + ".json", "w") as f:
        json.dump(scene, f)
    subprocess.run([soak, "render", path + ".json", "-o", path + ".exr", "--width", str(width),
                    "--height", str(height), "--spp", str(spp), "--threads", "2", "-q"], check=True)
    return luminance_map(path + ".exr")


def table_pixels(scene, spill, width, height):
    """Pool (map 1) and dry (map 0, within 0.3 m of the pool's centre, x < 0) pixels
    of the table top (meshes.py: z = 0, u = x + 0.5, v = (y + 0.4) / 0.9)."""
    project = projector(scene["camera"], width, height)
    classes = {}
    for i in range(-100, 101):
        for j in range(-80, 101):
            x, y = i * 0.004, j * 0.004
            w = spill(x + 0.5, (y + 0.4) / 0.9)
            near = math.hypot(x + 0.05, y + 0.02) < 0.3 and x < 0
            c = "pool" if w >= 1 else "dry" if (w <= 0 and near) else "other"
            classes.setdefault(project((x, y, 0.0)), set()).add(c)
    inside = {p: c for p, c in classes.items() if 0 <= p[0] < width and 0 <= p[1] < height}
    return ([p for p, c in inside.items() if c == {"pool"}], [p for p, c in inside.items() if c == {"dry"}])


def check_cognac(soak, gallery, tmp):
    """[JLD99] Fig. 7: the pool brighter than the dry table near it (it mirrors the sky)."""
    width, height, spp = 160, 90, 8
    with open(os.path.join(gallery, "cognac_table.json")) as f:
        scene = json.load(f)
    for k in ("caustic_photons", "caustic_radius"):
        scene["render"].pop(k, None)
    subprocess.run(["oiiotool", os.path.join(tmp, "spill.pgm"), "-d", "uint16", "-o",
                    os.path.join(tmp, "spill.png")], check=True)
    from meshes import spill
    lum = render(soak, scene, os.path.join(tmp, "cognac"), width, height, spp)
    pool, dry = table_pixels(scene, spill, width, height)
    if len(pool) < 30 or len(dry) < 30:
        print(f"FAIL cognac_table: {len(pool)} pool and {len(dry)} dry pixels, want 30 each")
        return 1
    mp, vp = stats([lum[p] for p in pool])
    md, vd = stats([lum[p] for p in dry])
    margin, se = mp - md, math.sqrt(vp + vd)
    ok = margin > 4 * se
    print(f"{'ok' if ok else 'FAIL'} cognac_table: pool {mp:.4f} ({len(pool)} px), dry table {md:.4f}"
          f" ({len(dry)} px), ratio {mp / md:.2f}; [JLD99] Fig. 7: the pool mirrors the room,"
          f" margin {margin:.4f} vs 4 SE {4 * se:.4f}")
    return 0 if ok else 1


def check_bricks(soak, gallery, tmp):
    """[Hnat06]: the wet patches shrink from their borders, frame by frame."""
    width, height, spp = 120, 68, 4
    with open(os.path.join(gallery, "bricks_drying.json")) as f:
        scene = json.load(f)
    splash = os.path.join(tmp, "splash.png")
    subprocess.run([soak, "bake", "turbulence", "--width", "320", "--height", "180", "--frequency", "3",
                    "--threshold", "-0.05", "--softness", "0.25", "--seed", "11", "--threads", "2", "-o",
                    splash], check=True, stdout=subprocess.DEVNULL)
    export = os.path.join(tmp, "export.json")
    subprocess.run([soak, "export", "--target", "json", "-o", export], check=True, stdout=subprocess.DEVNULL)
    with open(export) as f:
        t_fill = next(m["t_fill"] for m in json.load(f)["materials"] if m["name"] == "brick")
    wet_map = os.path.join(tmp, "brick_wet.png")

    def blocks(lum):
        return {(i, j): sum(lum[(2 * i + a, 2 * j + b)] for a in (0, 1) for b in (0, 1))
                for i in range(width // 2) for j in range(height // 2)}
    subprocess.run(["oiiotool", "--pattern", "constant:color=0", "320x180", "1", "-d", "uint16", "-o",
                    wet_map], check=True)
    dry = blocks(render(soak, scene, os.path.join(tmp, "bricks_dry"), width, height, spp))
    wet_sets = []
    for k in (0, 2, 4, 6):
        subprocess.run([soak, "bake", "drying", splash, "--t-fill", str(t_fill), "--time", f"0.{k}",
                        "-o", wet_map], check=True, stdout=subprocess.DEVNULL)
        lum = blocks(render(soak, scene, os.path.join(tmp, f"bricks_{k}"), width, height, spp))
        wet_sets.append({p for p in lum if lum[p] < 0.85 * dry[p]})
    areas = [len(s) for s in wet_sets]
    kept = [len(wet_sets[k + 1] & wet_sets[k]) / max(1, len(wet_sets[k + 1])) for k in range(3)]
    ok = all(areas[k + 1] < areas[k] for k in range(3)) and areas[0] >= 30 and min(kept) >= 0.9
    print(f"{'ok' if ok else 'FAIL'} bricks_drying: wet blocks {areas} at t = 0, 0.2, 0.4, 0.6; wet before"
          f" {', '.join(f'{x:.2f}' for x in kept)}; [Hnat06]: shrinking from the border")
    return 0 if ok else 1


def check_flowerpots(soak, gallery, tmp):
    """[Hnat06] Fig. 5: the larger alpha_poro, the darker the wet pot. The front row's
    pots are each divided by the same pot at the same place rendered with alpha_poro = 0
    (a second render), so the lamp's distance and the view do not enter."""
    width, height, spp = 192, 108, 32
    with open(os.path.join(gallery, "flowerpot_porosity.json")) as f:
        scene = json.load(f)
    subprocess.run([sys.executable, os.path.join(gallery, "meshes.py"), tmp], check=True,
                   stdout=subprocess.DEVNULL)
    front = [(o["translate"], o["material"]) for o in scene["objects"]
             if o.get("file") == "pot.obj" and o["translate"][1] == 0.0]
    control = json.loads(json.dumps(scene))
    for name in scene["materials"]:
        if name.startswith("pot_"):
            control["materials"][name] = dict(scene["materials"]["pot_0"])
    lum = render(soak, scene, os.path.join(tmp, "pots"), width, height, spp)
    ref = render(soak, control, os.path.join(tmp, "pots_control"), width, height, spp)
    rows = []
    for (x, y, _), mat in front:
        px = [p for p in pot_pixels(scene, x, y, width, height) if p in lum]
        m, v = stats([lum[p] for p in px])
        mr, vr = stats([ref[p] for p in px])
        ratio = m / mr
        rows.append((scene["materials"][mat]["porosity"], ratio,
                     ratio * math.sqrt(v / m ** 2 + vr / mr ** 2), len(px)))
    rows.sort()
    for a, r, e, n in rows:
        print(f"  flowerpot alpha_poro {a:.1f}: wet body / same pot at alpha_poro 0 = {r:.3f}"
              f" +- {e:.3f} ({n} px)")
    (a0, r0, e0, _), (a1, r1, e1, _) = rows[0], rows[-1]
    margin, se = r0 - r1, math.sqrt(e0 ** 2 + e1 ** 2)
    ok = margin > 4 * se and len(rows) == 6
    print(f"{'ok' if ok else 'FAIL'} flowerpot_porosity: alpha_poro {a1} / {a0} = {r1 / r0:.3f};"
          f" [Hnat06] Fig. 5: darker with alpha_poro, margin {margin:.3f} vs 4 SE {4 * se:.3f}")
    return 0 if ok else 1


def main():
    soak, root, tmp = sys.argv[1:4]
    if shutil.which("oiiotool") is None:
        print("SKIPPED: oiiotool not on PATH (the gallery's meshes and maps need it)")
        return 77
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    gallery = os.path.join(root, "scenes", "gallery")
    subprocess.run([sys.executable, os.path.join(gallery, "meshes.py"), tmp], check=True,
                   stdout=subprocess.DEVNULL)
    subprocess.run(["oiiotool", os.path.join(tmp, "paper_blot.pgm"), "-d", "uint16", "-o",
                    os.path.join(tmp, "paper_blot.png")], check=True)
    sys.path.insert(0, gallery)
    from meshes import blot   # the function the wet map is written from

    failures = 0
    # scene, the source's relation of the blot to the dry sheet
    for name, brighter in (("paper_front", False), ("paper_back", True)):
        scene_file = os.path.join(tmp, name + ".json")
        shutil.copy(os.path.join(gallery, name + ".json"), scene_file)
        with open(scene_file) as f:
            scene = json.load(f)
        exr = os.path.join(tmp, name + ".exr")
        subprocess.run([soak, "render", scene_file, "-o", exr, "--width", str(WIDTH),
                        "--height", str(HEIGHT), "--spp", str(SPP), "--threads", "2", "-q"],
                       check=True)
        lum = luminance_map(exr)
        wet, dry = classify(scene, blot)
        if len(wet) < 30 or len(dry) < 30:
            print(f"FAIL {name}: {len(wet)} blot and {len(dry)} dry pixels, want 30 each")
            failures += 1
            continue
        mw, vw = stats([lum[p] for p in wet])
        md, vd = stats([lum[p] for p in dry])
        se = math.sqrt(vw + vd)
        diff = (mw - md) if brighter else (md - mw)
        verdict = "ok" if diff > 4 * se else "FAIL"
        failures += verdict == "FAIL"
        word = "brighter" if brighter else "darker"
        print(f"{verdict} {name}: blot {mw:.4f} ({len(wet)} px), dry sheet {md:.4f} "
              f"({len(dry)} px), ratio {mw / md:.3f}; [JLD99] Fig. 5: blot {word}, "
              f"margin {diff:.4f} vs 4 SE {4 * se:.4f}")
    failures += check_flowerpots(soak, gallery, tmp)
    failures += check_cognac(soak, gallery, tmp)
    failures += check_bricks(soak, gallery, tmp)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
