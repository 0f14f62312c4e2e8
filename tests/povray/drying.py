"""Drying in POV-Ray matches `soak bake drying`: Soak_Drying_Map_Fn reads the
baker's start map as written (--start-map: 1 - t0 on wet texels, 0 on dry ones)
and Soak_T_Fill(Preset) from soak_materials.inc; the baked frames (`soak bake
drying` at the preset's t_fill from `soak export --target json`, the same mask)
are the reference.

A soft-edged mask (a blob whose edge ramps over 6 texels) is baked twice: the
start map, and frames at four times. POV-Ray shows the wetness function flat
(ambient 1, orthographic over the unit square) at the map's resolution, pixel
centres on texel centres, and at twice that resolution, where the reference is
the baked frame interpolated bilinearly (a wet ring left by interpolating t0 across
the wet region's border, a tide line, shows there). Pass: >= 99.9 % of the pixels
of every frame within 1/255; a control reading t0 through an interpolated map
(Soak_Drying_Fn) must miss that share.

usage: drying.py SOAK ROOT TMPDIR"""
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import export_json, fail, povray, read_image, setup_args  # noqa: E402

NX, NY = 48, 32
PRESET = "sand"
TIMES = [0.15, 0.4, 0.75]


def write_mask(path):
    """16-bit grey PNG (through a PGM): an off-centre ellipse, its edge a 6-texel ramp."""
    x, y = np.meshgrid(np.arange(NX) + 0.5, np.arange(NY) + 0.5)
    r = np.sqrt(((x - 20) / 15) ** 2 + ((y - 15) / 11) ** 2)
    v = np.clip((1.15 - r) / 0.35, 0, 1)
    pgm = path + ".pgm"
    with open(pgm, "wb") as f:
        f.write(f"P5\n{NX} {NY}\n65535\n".encode())
        f.write((v * 65535).astype(">u2").tobytes())
    run(["oiiotool", pgm, "-d", "uint16", "-o", path])


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"{' '.join(cmd)}: exit {r.returncode}\n{r.stderr[-1500:]}")


# control: t0 = 1 - (the start map interpolated), through Soak_Drying_Fn: the tide line
OLD = """#declare S = Soak_Map_Fn("start.png")
#declare Wet = Soak_Drying_Fn(function {{ select(S(x, y, z) - 1e-6, 0, 1) }}, function {{ 1 - S(x, y, z) }},
  Soak_T_Fill("{preset}"), {t})"""


def pov_scene(t, control=False):
    wet = (OLD.format(preset=PRESET, t=t) if control
           else f'#declare Wet = Soak_Drying_Map_Fn("start.png", Soak_T_Fill("{PRESET}"), {t})')
    return f"""#version 3.7;
global_settings {{ assumed_gamma 1.0 ambient_light 1 }}
#include "soak.inc"
camera {{ orthographic location <0.5, 0.5, 5> look_at <0.5, 0.5, 0> right -x up y sky y }}
{wet}
plane {{ z, 0 pigment {{ function {{ min(Wet(x, y, z), 1 - 1e-6) }} color_map {{ [0 rgb 0] [1 rgb 1] }} }}
  finish {{ ambient 1 diffuse 0 }} }}
"""


def upsample2(img):
    """Bilinear at the pixel centres of a 2x image, edge texels clamped (texel-centre convention)."""
    h, w = img.shape

    def coords(n):
        a = np.clip((np.arange(2 * n) + 0.5) / 2 - 0.5, 0, n - 1)
        i0 = np.floor(a).astype(int)
        return i0, np.minimum(i0 + 1, n - 1), a - i0
    x0, x1, fx = coords(w)
    y0, y1, fy = coords(h)
    top = img[y0][:, x0] * (1 - fx) + img[y0][:, x1] * fx
    bot = img[y1][:, x0] * (1 - fx) + img[y1][:, x1] * fx
    return top * (1 - fy)[:, None] + bot * fy[:, None]


def main():
    soak, root, tmp, lib = setup_args(__doc__)
    exp = export_json(soak, tmp)
    t_fill = next(m for m in exp["materials"] if m["name"] == PRESET)["t_fill"]
    mask = os.path.join(tmp, "mask.png")
    write_mask(mask)
    run([soak, "bake", "drying", mask, "--start-map", "--t-fill", str(t_fill), "--threads", "1",
         "-o", os.path.join(tmp, "start.png")])
    bad = 0
    for k, t in enumerate(TIMES):
        ref_path = os.path.join(tmp, f"dry_{k}.exr")
        run([soak, "bake", "drying", mask, "--t-fill", str(t_fill), "--time", str(t), "--float", "--threads", "1",
             "-o", ref_path])
        ref = read_image(ref_path)[:, :, 0]
        pov = os.path.join(tmp, f"dry_{k}.pov")
        with open(pov, "w") as f:
            f.write(pov_scene(t))
        for scale, want in ((1, ref), (2, upsample2(ref))):
            out = os.path.join(tmp, f"pov_{k}_{scale}.exr")
            rc, log = povray(pov, out, NX * scale, NY * scale, lib, cwd=tmp)
            if rc != 0:
                fail(f"povray {pov}: exit {rc}\n{log[-1500:]}")
            got = read_image(out)[:, :, 0]
            err = np.abs(got - want)
            share = float(np.mean(err <= 1 / 255))
            wet_share = float(np.mean(want > 1 / 255))
            ok = share >= 0.999
            bad += not ok
            print(f"t {t:.2f} {scale}x: {share * 100:.2f} % of {err.size} pixels within 1/255 (worst {err.max():.4f}; "
                  f"wet {wet_share * 100:.0f} % of the frame): {'ok' if ok else 'FAIL'}")
        if k == 1:
            if not (0.05 < float(np.mean(ref > 1 / 255)) < 0.95):
                fail("the mid-time frame is not partly dry: the test would not see a drying front")
            # the control (t0 interpolated) must show the tide line the test is there to catch
            with open(pov, "w") as f:
                f.write(pov_scene(t, control=True))
            out = os.path.join(tmp, f"control_{k}.exr")
            rc, log = povray(pov, out, NX * 2, NY * 2, lib, cwd=tmp)
            if rc != 0:
                fail(f"povray {pov} (control): exit {rc}\n{log[-1500:]}")
            share = float(np.mean(np.abs(read_image(out)[:, :, 0] - upsample2(ref)) <= 1 / 255))
            ok = share < 0.999
            bad += not ok
            print(f"control, t0 interpolated (Soak_Drying_Fn): {share * 100:.2f} % within 1/255 "
                  f"(must be < 99.9 %: the tide line): {'ok' if ok else 'FAIL'}")
    if bad:
        fail(f"{bad} frames disagree with soak bake drying")
    print("PASS")


if __name__ == "__main__":
    main()
