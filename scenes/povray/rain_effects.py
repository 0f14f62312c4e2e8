"""POV-Ray pictures of runnels and splashes (issue 48) from the same bakes as
Blender's scenes/blender/rain_runnels.py, for docs/rain.md.

/usr/bin/python3 scenes/povray/rain_effects.py build/bin/soak docs/images/povray_rain_effects.png [TMPDIR]

The bakes are the commands Blender's Bake Rain runs for that script's scene
(blender_addon/soak/operators/rain.py: film_command, drops_command; 30 mm/h
from frame 1 to 40 at 4 fps, seed 0, no shelter), on the same meshes:
- the slab: Blender's 0.3 m plane leaning at 80 degrees (its OBJ as the add-on
  exports it, z up), `soak bake rain --frames` at 512^2, frame 50 (2.5 s
  after the rain), without and with `--contact-angle 30`;
- the yard: `soak bake drops` at 1024^2 over 0.3 m, frame 40 (the rain's
  end), without and with `--splash`.
Panels 1-2: the slab, limestone, Soak_Wet_Material_UV_Fn over the film
frame's wet map. Panels 3-4: a 5 cm patch of the yard from 8 cm, concrete,
Soak_Wet_Drops_Material (Spot 0.1) over the drops frame. Blender's cameras
and sun, Blender's z-up axes turned into POV-Ray's y-up ones (x, z, y).
300 x 300 a panel (3 x 3 rays a pixel), 4-pixel white gaps; outputs through a temporary + rename."""
import math
import os
import shutil
import subprocess
import sys
import tempfile

W = 300
SS = 3                                          # rays a pixel: SS x SS
FIRST, RAIN_END, SLAB_FRAME, FPS = 1, 40, 50, 4
RATE, SIZE = 30.0, 0.3
DURATION = (RAIN_END - FIRST) / FPS            # the add-on's rain_seconds: 9.75 s
TILT = math.radians(80.0)

COMMON = """#version 3.7;
global_settings {{ assumed_gamma 1.0 ambient_light 1 max_trace_level 5 }}
#declare Soak_Ambient = 0.32;
#include "soak.inc"
background {{ rgb <0.275, 0.31, 0.375> }}
// Blender's sun: 3 W/m^2 from (-0.6, -0.5, 0.6) (z up); a point-like sun, not its 8 degrees
light_source {{ <-0.6, 0.6, -0.5> * 1000 rgb 3 / pi parallel point_at 0 }}
camera {{ perspective location {loc} look_at {at} right x up y sky y angle {angle} }}
{body}
"""


def slab_obj(path):
    """Blender's primitive plane (size 1, scale 0.3, vertices 0..3 and its loop
    order 0, 1, 3, 2) rotated 80 degrees about x and lifted by 0.15 sin 80,
    at x = -2, as the add-on's export_scene_obj writes it (world space, z up)."""
    c, s = math.cos(TILT), math.sin(TILT)
    h = SIZE / 2
    with open(path, "w") as f:
        for x, y in ((-h, -h), (h, -h), (-h, h), (h, h)):
            f.write(f"v {-2.0 + x:.9g} {y * c:.9g} {h * s + y * s:.9g}\n")
        f.write("vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 4/3\nf 1/1 4/3 3/4\n")


def slab_mesh2():
    """The same slab in POV-Ray's y-up axes: Blender (x, y, z) -> (x, z, y)."""
    c, s = math.cos(TILT), math.sin(TILT)
    h = SIZE / 2
    vs = [(-2.0 + x, h * s + y * s, y * c) for x, y in ((-h, -h), (h, -h), (-h, h), (h, h))]
    vtext = ", ".join(f"<{a:.9g}, {b:.9g}, {d:.9g}>" for a, b, d in vs)
    return (f"mesh2 {{ vertex_vectors {{ 4, {vtext} }} uv_vectors {{ 4, <0, 0>, <1, 0>, <0, 1>, <1, 1> }}\n"
            "  face_indices { 2, <0, 1, 3>, <0, 3, 2> } uv_mapping\n")


def run(cmd, cwd):
    r = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"rain_effects: {' '.join(cmd)} failed ({r.returncode}):\n{r.stdout[-2000:]}{r.stderr[-2000:]}")
    return r.stdout + r.stderr


def bakes(soak, tmp):
    slab_obj(os.path.join(tmp, "slab.obj"))
    for tag, extra in (("film_off", []), ("film_on", ["--contact-angle", "30"])):
        run([soak, "bake", "rain", "slab.obj", "--up", "z", "--rainfall", f"{RATE:.9g}", "--duration",
             f"{DURATION:.9g}", "--fps", str(FPS), "--width", "512", "--height", "512", "--rays", "4",
             "--seed", "0", "--frames", f"{SLAB_FRAME}-{SLAB_FRAME}", "--frame-origin", str(FIRST),
             "-o", f"{tag}.%04d.exr"] + extra, tmp)
    for tag, extra in (("drops_off", []), ("drops_on", ["--splash"])):
        run([soak, "bake", "drops", "--rate", f"{RATE:.9g}", "--duration", f"{DURATION:.9g}", "--fps", str(FPS),
             "--map-size", f"{SIZE:.9g}", "--width", "1024", "--height", "1024", "--seed", "0", "--dry-time", "2",
             "--frames", f"{RAIN_END}-{RAIN_END}", "--frame-origin", str(FIRST), "-o", f"{tag}.%04d.exr"] + extra,
            tmp)


def scenes():
    """name -> scene text. Blender's 50 mm lens on its 36 mm sensor: 39.6 degrees."""
    angle = math.degrees(2 * math.atan(18.0 / 50.0))
    out = {}
    for tag in ("film_off", "film_on"):
        body = (f'#declare Wet = Soak_Map_Fn("{tag}.{SLAB_FRAME:04d}.exr")\n' + slab_mesh2()
                + '  Soak_Wet_Material_UV_Fn("limestone", "water", Wet) }\n')
        out[tag] = COMMON.format(loc="<-2, 0.2, -0.75>", at="<-2, 0.15, 0>", angle=f"{angle:.6f}", body=body)
    t = RAIN_END / FPS         # Soak_Drops_Fn's frame = Time x Fps
    for tag in ("drops_off", "drops_on"):
        body = (f'#declare Drops = Soak_Drops_Fn("{tag}.", ".exr", {FPS}, {t:.9g}, {RAIN_END}, {RAIN_END}, 0)\n'
                f"#declare Wet = Soak_Place_Fn(Drops, {SIZE:.9g}, transform {{ translate <1.85, 0, -0.15> }})\n"
                "box { <1.85, -0.01, -0.15>, <2.15, 0, 0.15>\n"
                "  Soak_Wet_Drops_Material(\"concrete\", \"water\", Wet, 0.1) }\n")
        out[tag] = COMMON.format(loc="<2, 0.08, -0.02>", at="<2, 0, 0>", angle=f"{angle:.6f}", body=body)
    return out


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    soak, final = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    lib = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "povray")
    tmp = os.path.abspath(sys.argv[3]) if len(sys.argv) == 4 else tempfile.mkdtemp(prefix="rain_effects.")
    os.makedirs(tmp, exist_ok=True)
    bakes(soak, tmp)
    panels = []
    for tag, text in scenes().items():
        with open(os.path.join(tmp, tag + ".pov"), "w") as f:
            f.write(text)
        # SS x SS rays a pixel on a grid, averaged in linear light (a box filter): the runnels are
        # narrower than a pixel, and adaptive antialiasing misses them between its first rays
        run(["povray", f"+I{tag}.pov", f"+O{tag}.exr", "+FE", f"+W{W * SS}", f"+H{W * SS}", "-D", "-V", "+WT2",
             f"+L{lib}", "-A", "-GA", "Output_Alpha=off"], tmp)
        run(["oiiotool", f"{tag}.exr", "--resize:filter=box", f"{W}x{W}", "--colorconvert", "linear", "sRGB",
             "-d", "uint8", "-o", f"{tag}.png"], tmp)
        panels.append(os.path.join(tmp, tag + ".png"))
    strip = os.path.join(tmp, "strip.png")
    run(["oiiotool"] + panels + ["--mosaic:pad=4", "4x1", "--ch", "R,G,B", "-d", "uint8", "-o", strip], tmp)
    # the mosaic's gaps are black: paint them white as in Blender's strip
    run(["oiiotool", strip, "--fill:color=1,1,1", "4x300+300+0", "--fill:color=1,1,1", "4x300+604+0",
         "--fill:color=1,1,1", "4x300+908+0", "-d", "uint8", "-o", strip], tmp)
    part = final + ".part.png"
    shutil.copyfile(strip, part)
    if os.path.getsize(part) > 400 * 1024:
        run([sys.executable, os.path.join(os.path.dirname(lib), "scripts", "png_palette.py"), part], tmp)
    os.replace(part, final)
    print(f"wrote {final} ({os.path.getsize(final)} bytes); bakes and panels in {tmp}")


main()
