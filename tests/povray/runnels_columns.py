"""Runnels reach a POV-Ray render where the bake put them (issue 48 item 6).

`soak bake rain --contact-angle 30` on a vertical 0.1 m wall (128^2 texels,
30 mm/h) gathers the falling film into rivulets; the wall is rendered through
Soak_Wet_Material_UV_Fn on a mesh2 carrying the OBJ's UVs, seen straight on by
an orthographic camera whose pixel centres fall on the texel centres, under
ambient light only. Reference, read from the baked map by oiiotool (not from
the render): in the map's row ROW the runs of texels with w > 0.5 (a film
runs: w = 1), their count and centres. In the render's row ROW the runs of
pixels darker than the midpoint of the row's lightest and darkest pixels must
be as many, each centre within half a pixel of the map's.
Control: the same map on a mesh with u and v swapped (a UV layout turned by
90 degrees) gives another count, so the check can fail.

usage: runnels_columns.py SOAK ROOT TMPDIR"""
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import fail, povray, read_image, setup_args  # noqa: E402

N, L, ROW = 128, 0.1, 64

SCENE = """#version 3.7;
global_settings {{ assumed_gamma 1.0 ambient_light 1 }}
#declare Soak_Ambient = 1;
#declare Soak_Highlights = 0;
#include "soak.inc"
camera {{ orthographic location <{h}, {h}, -1> look_at <{h}, {h}, 0> right x * {L} up y * {L} }}
background {{ rgb 0 }}
#declare Wet = Soak_Map_Fn("wall.exr")
mesh2 {{ vertex_vectors {{ 4, <0, 0, 0>, <{L}, 0, 0>, <0, {L}, 0>, <{L}, {L}, 0> }}
  uv_vectors {{ 4, {uvs} }} face_indices {{ 2, <0, 1, 3>, <0, 3, 2> }} uv_mapping
  Soak_Wet_Material_UV_Fn("limestone", "water", Wet) }}
"""
UV = "<0, 0>, <1, 0>, <0, 1>, <1, 1>"
UV_SWAPPED = "<0, 0>, <0, 1>, <1, 0>, <1, 1>"


def runs(mask):
    """(start, end) index pairs of the runs of True."""
    m = np.concatenate(([False], mask, [False])).astype(int)
    d = np.diff(m)
    return list(zip(np.flatnonzero(d == 1), np.flatnonzero(d == -1)))


def centres(mask):
    return np.array([(a + b - 1) / 2 for a, b in runs(mask)])


def render_row(tmp, lib, name, uvs):
    pov = os.path.join(tmp, name + ".pov")
    with open(pov, "w") as f:
        f.write(SCENE.format(h=L / 2, L=L, uvs=uvs))
    out = os.path.join(tmp, name + ".exr")
    rc, log = povray(pov, out, N, N, lib, cwd=tmp)
    if rc != 0:
        fail(f"{name}: povray exit {rc}\n{log[-1500:]}")
    lum = read_image(out)[ROW].mean(axis=1)
    return lum < 0.5 * (lum.min() + lum.max()), lum


def main():
    soak, _root, tmp, lib = setup_args(__doc__)
    # the wall in the bake's z-up axes: x across, z up, facing -y; UV = (x, z) / L
    with open(os.path.join(tmp, "wall.obj"), "w") as f:
        f.write(f"v 0 0 0\nv {L} 0 0\nv 0 0 {L}\nv {L} 0 {L}\n"
                "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nf 1/1 2/2 4/4\nf 1/1 4/4 3/3\n")
    r = subprocess.run([soak, "bake", "rain", "wall.obj", "--up", "z", "--rainfall", "30", "--width", str(N),
                        "--height", str(N), "--rays", "4", "--contact-angle", "30", "-o", "wall.exr"],
                       cwd=tmp, capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"soak bake rain: exit {r.returncode}: {r.stderr[-1500:]}")
    out = subprocess.run(["oiiotool", "--dumpdata", "wall.exr"], cwd=tmp, capture_output=True, text=True,
                         check=True).stdout
    prefix = f"Pixel (0, {ROW}):"
    lines = out.splitlines()
    k = next(i for i, s in enumerate(lines) if s.strip().startswith(prefix))
    row = np.array([float(s.split(":")[1].split()[0]) for s in lines[k:k + N]])
    wet = row > 0.5
    ref = centres(wet)
    if not 3 <= len(ref) <= N // 4:
        fail(f"the bake's row {ROW} holds {len(ref)} runnels: not a runnel pattern to check against")
    dark, lum = render_row(tmp, lib, "wall", UV)
    got = centres(dark)
    print(f"map row {ROW}: {len(ref)} runnels at texels {ref.tolist()}")
    print(f"render row {ROW}: {len(got)} dark runs at pixels {got.tolist()} "
          f"(luminance {lum.min():.4f}..{lum.max():.4f})")
    if len(got) != len(ref) or np.abs(got - ref).max() > 0.5:
        fail("the rendered runnels are not where the baked map has them")
    dark_sw, _ = render_row(tmp, lib, "wall_swapped", UV_SWAPPED)
    n_sw = len(centres(dark_sw))
    print(f"control, u and v swapped: {n_sw} dark runs")
    if n_sw == len(ref):
        fail("control: a turned UV layout gives the same count: the check cannot tell")
    spacing = np.diff(ref).mean() * L / N * 1000
    print(f"ok: {len(got)} runnels, {spacing:.2f} mm apart on average, each within 0.5 pixel of the map's")


main()
