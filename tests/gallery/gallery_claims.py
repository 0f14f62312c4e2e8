#!/usr/bin/env python3
"""gallery_claims: the measurable part of the source's description, asserted on the
gallery's own soak render scenes (scenes/gallery/) at reduced size.

[JLD99] §4.1, Fig. 5: a wet spot on paper looks darker than the dry paper when lit
from the viewer's side (Fig. 5a) and brighter when lit from behind (Fig. 5b). The
expected relation is that direction, taken from the source; the blot's and the dry
sheet's pixels are found by projecting the sheet's own wet map function
(scenes/gallery/meshes.py `blot`) through the scene's camera, never from the render.
A pass needs the difference beyond 4 standard errors of the pixel means.

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
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
