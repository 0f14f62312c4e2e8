#!/usr/bin/python3
"""POV-Ray check for tests/cli/bake_per_vertex.sh: the --per-vertex .inc
(a mesh2 with a texture per vertex, povray/soak_mesh.inc) rendered by
POV-Ray against the core's numbers.

The roofed ground (per_vertex_models.py: 9 ground vertices, the centre one
dry under the roof, the 8 others wet) is seen straight down by an
orthographic camera between the ground and the roof, lit by a uniform
ambient light alone (Soak_Ambient 1, no highlights, no reflected rays: +Q7),
so a pixel shows the pigment: at a vertex of wetness w the preset's wet
albedo times its view factor along the normal, E(w) = lerp(knots.albedo)(w)
x lerp(knots.view_factor at view_cos 1)(w), from `soak export --target json`
(the reference; the wetness per vertex from the bake's CSV, a second writer).

Checks, per channel:
- at the pixel nearest each ground vertex, |pixel - E(w_i)| <= the sum of
  named terms: interpolation, (1 - b_i) max_j |E(w_j) - E(w_i)| over the
  face's vertices (b_i: the vertex's barycentric weight at the pixel
  centre, from the STL's faces); level rounding, 0.0005 x the largest
  |dE/dw| of the knots (the .inc rounds w to 0.001); output, 2^-11 x the
  value + 1e-5 (half-float EXR, linear: assumed_gamma 1 and no gamma
  encoding in EXR);
- at pixels between the dry vertex and its wet neighbours, the render
  equals the barycentric blend sum_j b_j E(w_j) within the rounding and
  output terms (POV-Ray interpolates the three shaded textures);
- Soak_Mesh_Pigment (a user pigment, Soak_Wet_User_Texture's two layers
  in one texture) at a wet corner equals a plane of Soak_Wet_User_Material
  at that vertex's wetness, and differs from the preset's colour;
- a Soak_Mesh_Texture macro of the user's replaces soak_mesh.inc's: grey
  W gives the CSV's wetness at the wet corners within the rounding;
- E(dry) and E(wet) differ by more than 20 times those terms (the check
  can tell them apart).

usage: per_vertex_povray.py SOAK ROOT DIR INC CSV STL"""
import json
import os
import re
import subprocess
import sys

W = H = 64
PRESET = "sand"


def fail(msg):
    print("FAIL", msg)
    sys.exit(1)


def interp(xs, ys, x):
    for k in range(len(xs) - 1):
        if xs[k] <= x <= xs[k + 1]:
            f = (x - xs[k]) / (xs[k + 1] - xs[k]) if xs[k + 1] > xs[k] else 0.0
            return ys[k] + f * (ys[k + 1] - ys[k])
    return ys[0] if x < xs[0] else ys[-1]


def colour_fn(exp):
    m = next(m for m in exp["materials"] if m["name"] == PRESET)
    k = m["liquids"]["water"]["knots"]
    j = exp["view_cos"].index(1.0)
    ws = k["wetness"]

    def E(w):
        return [interp(ws, [a[c] for a in k["albedo"]], w) * interp(ws, [v[j][c] for v in k["view_factor"]], w)
                for c in range(3)]
    slope = max(abs(E(ws[i + 1])[c] - E(ws[i])[c]) / (ws[i + 1] - ws[i])
                for i in range(len(ws) - 1) if ws[i + 1] > ws[i] for c in range(3))
    return E, slope


def read_exr(path):
    out = subprocess.run(["oiiotool", "--dumpdata", path], check=True, capture_output=True, text=True).stdout
    px = {}
    for m in re.finditer(r"Pixel \((\d+), (\d+)\):\s+([-0-9.e ]+)", out):
        px[(int(m.group(1)), int(m.group(2)))] = [float(v) for v in m.group(3).split()[:3]]
    if len(px) != W * H:
        fail(f"{path}: {len(px)} pixels read")
    return px


def ground_faces(stl):
    pts = [tuple(float(v) for v in l.split()[1:]) for l in open(stl) if l.strip().startswith("vertex")]
    faces = [pts[i:i + 3] for i in range(0, len(pts), 3)]
    return [f for f in faces if all(p[1] == 0.0 for p in f)]


def bary(face, x, z):
    (x0, _, z0), (x1, _, z1), (x2, _, z2) = face
    d = (z1 - z2) * (x0 - x2) + (x2 - x1) * (z0 - z2)
    a = ((z1 - z2) * (x - x2) + (x2 - x1) * (z - z2)) / d
    b = ((z2 - z0) * (x - x2) + (x0 - x2) * (z - z2)) / d
    return a, b, 1 - a - b


def at_pixel(faces, px, py):
    """(face, weights) of the ground face holding the pixel centre (camera: x right, z up)."""
    x, z = -1 + 2 * (px + 0.5) / W, 1 - 2 * (py + 0.5) / H
    for f in faces:
        b = bary(f, x, z)
        if min(b) >= -1e-9:
            return f, b
    fail(f"pixel ({px}, {py}) at ({x}, {z}) is on no ground face")


def render(soak, root, d, inc, name="mesh2", settings="", scene=None):
    pov = os.path.join(d, f"{name}.pov")
    with open(pov, "w") as f:
        f.write(f"""#version 3.7;
global_settings {{ assumed_gamma 1.0 ambient_light 1 }}
#declare Soak_Ambient = 1;
#declare Soak_Highlights = 0;
#include "soak.inc"
#declare Soak_Mesh_Preset = "{PRESET}";
{settings}
#include "soak_mesh.inc"
#include "{os.path.basename(inc)}"
camera {{ orthographic location <0, 0.2, 0> direction <0, -1, 0> right <2, 0, 0> up <0, 0, 2> }}
background {{ rgb 0 }}
{scene or "object { Soak_Wet_Mesh Soak_Wet_Interior(Soak_Mesh_Liquid) }"}
""")
    out = os.path.join(d, f"{name}.exr")
    cmd = ["povray", f"+I{pov}", f"+O{out}", "+FE", f"+W{W}", f"+H{H}", "-D", "-V", "+WT1", "+Q7",
           f"+L{os.path.join(root, 'povray')}", f"+L{os.path.dirname(os.path.abspath(inc))}", "Output_Alpha=off"]
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=d)
    if r.returncode != 0:
        fail(f"povray exit {r.returncode}: {(r.stdout + r.stderr)[-1500:]}")
    return read_exr(out)


def user_pigment(soak, root, d, inc, wet, img, rounding, output):
    """Soak_Mesh_Pigment (Soak_Wet_User_Texture, two layers wrapped into one
    texture) at the corner vertex (-1, 0, 1), pixel (0, 0), against a plane
    of Soak_Wet_User_Material at that vertex's wetness; the preset's render
    differs there (a check that can fail)."""
    pig = "pigment { rgb <0.5, 0.3, 0.2> }"
    w = wet[(-1.0, 0.0, 1.0)]
    mesh = render(soak, root, d, inc, "user_mesh", f"#declare Soak_Mesh_Pigment = {pig};")
    flat = render(soak, root, d, inc, "user_plane", "",
                  f'plane {{ y, 0 Soak_Wet_User_Material("{PRESET}", "water", {w}, {pig}) }}')
    got, ref = mesh[(0, 0)], flat[(0, 0)]
    tol = [rounding + 2 * output(v) for v in ref]
    ok = all(abs(a - b) <= t for a, b, t in zip(got, ref, tol))
    ok = ok and max(abs(a - b) for a, b in zip(img[(0, 0)], ref)) > 0.01
    print(f"{'ok  ' if ok else 'FAIL'} Soak_Mesh_Pigment at (-1, 1) w={w:.4f}: {[round(v, 5) for v in got]} vs "
          f"Soak_Wet_User_Material {[round(v, 5) for v in ref]} (the preset's {[round(v, 5) for v in img[(0, 0)]]})")
    return not ok


def own_macro(soak, root, d, inc, wet, output):
    """A Soak_Mesh_Texture(W) of the user's, declared before soak_mesh.inc,
    replaces its own: with grey W emitted, the pixel at each wet corner is
    that vertex's wetness in the CSV within the 0.0005 rounding."""
    mine = "#macro Soak_Mesh_Texture(W) texture { pigment { rgb W } finish { ambient 1 diffuse 0 } } #end"
    img = render(soak, root, d, inc, "own_macro", mine, "object { Soak_Wet_Mesh }")
    bad = 0
    for (x, z), (px, py) in {(-1.0, 1.0): (0, 0), (1.0, -1.0): (W - 1, H - 1)}.items():
        w, got = wet[(x, 0.0, z)], img[(px, py)][0]
        ok = abs(got - w) <= 0.0005 + output(w)
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} own Soak_Mesh_Texture: pixel ({px}, {py}) = {got:.5f}, "
              f"the CSV's w = {w:.5f}")
    return bad


def main():
    if len(sys.argv) != 7:
        fail(__doc__)
    soak, root, d, inc, csv, stl = sys.argv[1:]
    # the shipped presets cut to the one rendered (its tables do not depend on the others; 4 s -> 0.5 s)
    data = json.load(open(os.path.join(root, "c_core", "data", "materials.json")))
    data["materials"] = [m for m in data["materials"] if m["name"] == PRESET]
    json.dump(data, open(os.path.join(d, "preset.json"), "w"))
    r = subprocess.run([soak, "export", "--target", "json", "--materials", os.path.join(d, "preset.json"), "-o",
                        os.path.join(d, "export.json")], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"soak export --target json: {r.stderr}")
    E, slope = colour_fn(json.load(open(os.path.join(d, "export.json"))))
    wet = {}
    for line in open(csv).read().split("\n")[1:]:
        if line.strip():
            _, x, y, z, w = line.split(",")
            wet[(float(x), float(y), float(z))] = float(w)
    faces = ground_faces(stl)
    img = render(soak, root, d, inc)
    rounding = 0.0005 * slope
    output = lambda v: 2.0 ** -11 * abs(v) + 1e-5  # noqa: E731
    bad = 0
    # the pixel nearest each ground vertex (corners, edge midpoints, centre)
    for (x, y, z), w in sorted(wet.items()):
        if y != 0.0:
            continue
        px = min(max(int((x + 1) / 2 * W), 0), W - 1)
        py = min(max(int((1 - z) / 2 * H), 0), H - 1)
        face, b = at_pixel(faces, px, py)
        i = min(range(3), key=lambda k: (face[k][0] - x) ** 2 + (face[k][2] - z) ** 2)
        ref = E(w)
        got = img[(px, py)]
        for c in range(3):
            spread = max(abs(E(wet[face[j]])[c] - ref[c]) for j in range(3))
            tol = (1 - b[i]) * spread + rounding + output(ref[c])
            ok = abs(got[c] - ref[c]) <= tol
            bad += not ok
            if not ok or c == 0:
                print(f"{'ok  ' if ok else 'FAIL'} vertex ({x:g}, {z:g}) w={w:.4f} pixel ({px}, {py}) channel {c}: "
                      f"{got[c]:.5f} vs E(w) {ref[c]:.5f}, tolerance {tol:.5f} (interpolation "
                      f"{(1 - b[i]) * spread:.5f} + rounding {rounding:.5f} + output {output(ref[c]):.5f})")
    # between the dry centre and its wet neighbours: the barycentric blend
    inside = [(W // 2 + 8, H // 2 - 1), (W // 2 - 9, H // 2), (W // 2 + 16, H // 2 + 16), (W // 2 - 5, H // 2 - 12)]
    for px, py in inside:
        face, b = at_pixel(faces, px, py)
        ref = [sum(b[j] * E(wet[face[j]])[c] for j in range(3)) for c in range(3)]
        got = img[(px, py)]
        ok = all(abs(got[c] - ref[c]) <= rounding + output(ref[c]) for c in range(3))
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} blend at pixel ({px}, {py}), weights "
              f"{', '.join(f'{v:.3f}' for v in b)}: {[round(v, 5) for v in got]} vs {[round(v, 5) for v in ref]}")
    bad += user_pigment(soak, root, d, inc, wet, img, rounding, output)
    bad += own_macro(soak, root, d, inc, wet, output)
    dry, wetc = E(0.0), E(max(wet.values()))
    gap = max(abs(a - b) for a, b in zip(dry, wetc))
    ok = gap > 20 * (rounding + output(max(dry)))
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} dry {[round(v, 4) for v in dry]} and wet {[round(v, 4) for v in wetc]} "
          f"differ by {gap:.4f}")
    if bad:
        fail(f"{bad} checks failed")
    print("PER_VERTEX_POVRAY PASS")


if __name__ == "__main__":
    main()
