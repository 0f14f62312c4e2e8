"""soak.inc input guards: every bad argument stops POV-Ray with #error naming
it (exit 1, never POV-Ray's assertion 134 or segfault 139); doubtful input
warns; wetness functions outside [0, 1] are clamped, not wrapped; every preset
and liquid renders at the wetness edges. Subsurface: POV-Ray 3.7's crash paths
(an object with subsurface parsed before global_settings: segfault 139; a zero
pigment or translucency channel, diffuse 0: assertion 134, shown here on raw
scenes) are unreachable through the macros: #error before the settings, clamped
tables render finite, metals #error.

usage: guards.py SOAK ROOT TMPDIR"""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import fail, povray, read_image, setup_args  # noqa: E402

HEAD = """#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 1 }
#declare Soak_Ambient = 0.2;
#include "soak.inc"
camera { orthographic location <0.5,0.5,5> look_at <0.5,0.5,0> up y right -x sky y }
light_source { <0.3,0.2,1>*1e4 rgb 1 parallel point_at 0 }
sky_sphere { pigment { rgb 0.2 } }
"""

BAD = [  # (snippet, the argument the message must name)
    ('box { <0,0,-1>, <1,1,0> Soak_Wet_Material("sandd", "water", 0.5) }', 'Preset = "sandd"'),
    ('box { <0,0,-1>, <1,1,0> Soak_Wet_Material("sand", "watr", 0.5) }', 'Liquid = "watr"'),
    ('box { <0,0,-1>, <1,1,0> Soak_Wet_Material("sand", "water", -0.1) }', "Wetness = -0.1"),
    ('box { <0,0,-1>, <1,1,0> Soak_Wet_Material("sand", "water", 1.5) }', "Wetness = 1.5"),
    ('box { <0,0,-1>, <1,1,0> Soak_Wet_User_Material("clay", "water", 2, pigment { rgb 0.5 }) }', "Wetness = 2"),
    ('#declare W = function { x }\n#declare T0 = function { 0 }\n'
     '#declare S = Soak_Schedule_Fn(W, T0, -1, clock)', "T_Fill = -1"),
    ('#declare W = function { x }\nbox { <0,0,-1>, <1,1,0> Soak_Puddle_Material("sand", "water", W, 0, '
     'normal { bumps 0.1 }) }', "Level = 0"),
    ('#declare W = function { x }\nbox { <0,0,-1>, <1,1,0> Soak_Puddle_Material("sand", "water", W, 1.2, '
     'normal { bumps 0.1 }) }', "Level = 1.2"),
    ('#declare W = function { x }\nbox { <0,0,-1>, <1,1,0> texture { pigment { rgb 0.5 } '
     'Soak_Spill_Normal(W, -1) } }', "Amount = -1"),
    ('#declare C = Soak_Wet_Colour("sand", "water", 0.5, <1.2, 0.5, 0.5>);', "Colour = <1.2"),
    ('#declare C = Soak_Wet_Colour("sand", "water", 0.5, <0.5, -0.1, 0.5>);', "Colour = <0.5"),
    # media (thin sheets)
    ('box { 0, 1 hollow Soak_Clear_Texture() interior { Soak_Media_Raw(-1, 0, 0, 0, 1) } }', "Sigma_S = <-1"),
    ('box { 0, 1 hollow Soak_Clear_Texture() interior { Soak_Media_Raw(1, <0, 0, -0.5>, 0, 0, 1) } }', "Sigma_A = <0"),
    ('box { 0, 1 hollow Soak_Clear_Texture() interior { Soak_Media_Raw(1, 0, 1, 0, 1) } }', "G1 = 1"),
    ('box { 0, 1 hollow Soak_Clear_Texture() interior { Soak_Media_Raw(1, 0, 0, -1, 1) } }', "G2 = -1"),
    ('box { 0, 1 hollow Soak_Clear_Texture() interior { Soak_Media_Raw(1, 0, 0.5, 0, 1.5) } }', "W = 1.5"),
    ('box { 0, 1 hollow Soak_Sheet_Material("copper", "water", 0.5) }', 'Preset = "copper" is a metal'),
    ('box { 0, 1 hollow Soak_Sheet_Material("cotton", "water", -0.5) }', "Wetness = -0.5"),
    ('#declare W = function { x }\nbox { 0, 1 hollow Soak_Sheet_Material_Fn("cotton", "water", W, 2) }',
     "Phase_Wetness = 2"),
    ('object { Soak_Sheet_Object("cotton", "water", 0.5, 0) }', "Thickness_mm = 0"),
    ('#declare F = Soak_Df3_Fn("x.df3", <0, 4, 4>, 1)', "Dims = <0"),
    # placement and drying maps (the checks run before the file is opened)
    ('#declare F = Soak_Map_Placed_Fn("m.png", transform { }, 3, 0)', "Map_Type = 3"),
    ('#declare F = Soak_Map_Placed_Fn("m.png", transform { }, 0, 2)', "Tile = 2"),
    ('#declare F = Soak_Drying_Map_Fn("s.png", 1.5, 0.5)', "T_Fill = 1.5"),
    ('#declare F = Soak_Drying_Map_Fn("s.png", -0.1, 0.5)', "T_Fill = -0.1"),
    ('#declare Soak_Media_Lobes_Max = 1;\n'
     'box { 0, 1 hollow Soak_Clear_Texture() interior { Soak_Media_Raw(1, 0, 0, 0, 1) } }', "Soak_Media_Lobes_Max = 1"),
    # rain: drops as water, far ripples (the checks run before any file is opened)
    ('#declare W = function { x }\nbox { <0,0,-1>, <1,1,0> Soak_Wet_Drops_Material("brick", "water", W, 0) }',
     "Spot = 0"),
    ('#declare W = function { x }\nbox { <0,0,-1>, <1,1,0> Soak_Wet_Drops_Material("brick", "water", W, 1.5) }',
     "Spot = 1.5"),
    ('#declare D = Soak_Ripple_Far_Distance(0, 67.38, 640);', "Wavelength = 0"),
    ('#declare D = Soak_Ripple_Far_Distance(0.017, 180, 640);', "Angle = 180"),
    ('#declare D = Soak_Ripple_Far_Distance(0.017, 67.38, 0);', "Width = 0"),
    ('#declare N = Soak_Ripple_Normal_Far("r.", "f.", ".exr", 4, 1, 0, 0.01, 0, <0, 0, 1>, 3);', "Tile = 0"),
    ('#declare N = Soak_Ripple_Normal_Far("r.", "f.", ".exr", 4, 1, 0, 0.01, 0.5, <0, 0, 1>, -1);', "Far = -1"),
]

SSS_HEAD = """#version 3.7;
#declare Soak_Subsurface_Samples = <10, 4>;
#include "soak.inc"
camera { location <0, -5, 3> look_at 0 }
light_source { <3, -2, 10> rgb 1 }
"""
SSS_SET = "global_settings { assumed_gamma 1.0 Soak_Subsurface_Settings() }\n"
SSS_BAD = [  # (scene after SSS_HEAD, what the message must name)
    ('sphere { 0, 1 Soak_Wet_Subsurface_Material("marble", "water", 0) }\n' + SSS_SET,
     "subsurface material before global_settings"),
    ('sphere { 0, 1 Soak_Wet_Subsurface_Material("marble", "water", 0) }\n', "before global_settings"),
    (SSS_SET + 'sphere { 0, 1 Soak_Wet_Subsurface_Material("copper", "water", 0.5) }', 'Preset = "copper"'),
    (SSS_SET + 'sphere { 0, 1 Soak_Wet_User_Subsurface_Material("aluminium", "water", 0.5, pigment { rgb 0.5 }) }',
     'Preset = "aluminium"'),
    (SSS_SET + 'sphere { 0, 1 Soak_Wet_Subsurface_Material("marble", "water", 1.2) }', "Wetness = 1.2"),
    (SSS_SET + 'sphere { 0, 1 Soak_Wet_Subsurface_Material("marble", "wat", 1) }', 'Liquid = "wat"'),
    ('#declare Soak_Mm_Per_Unit = 0;\n' + SSS_SET, "Soak_Mm_Per_Unit = 0"),
    ('#declare Soak_Subsurface_Samples = <0, 5>;\n' + SSS_SET, "Soak_Subsurface_Samples = <0"),
]
# POV-Ray's own crash paths, written raw (no macros): they must still crash for the guards above to mean anything
# (exit codes as Python sees them: -11 = SIGSEGV, the shell's 139; -6 = SIGABRT, the assertion, 134)
SSS_RAW = [
    ("before global_settings", 'sphere { 0, 1 pigment { rgb 0.5 } finish { diffuse 1 subsurface { translucency 0.3 } } '
     'interior { ior 1.33 } }\nglobal_settings { subsurface { samples 10, 4 } }', -11),
    ("zero pigment channel", 'global_settings { subsurface { samples 10, 4 } }\nsphere { 0, 1 pigment { rgb <0.5, 0, 0.5> } '
     'finish { diffuse 1 subsurface { translucency 0.3 } } interior { ior 1.33 } }', -6),
    ("zero translucency channel", 'global_settings { subsurface { samples 10, 4 } }\nsphere { 0, 1 pigment { rgb 0.5 } '
     'finish { diffuse 1 subsurface { translucency <0.3, 0, 0.3> } } interior { ior 1.33 } }', -6),
]

WARN = [
    ('#declare W = function { x }\nbox { <0,0,-1>, <1,1,0> texture { pigment { rgb 0.5 } '
     'Soak_Spill_Normal(W, 3) } }', "very strong bump"),
    ('object { Soak_Sheet_Object("paper", "water", 1, 0.8) }', "media scatter once"),
    ('box { <0,0,-1>, <1,1,0> Soak_Wet_User_Material("clay", "water", 0.5, pigment { rgb <1.2, 0.5, 0.5> }) }',
     "User_Pigment has channels from 0.5000 to 1.2000"),
    ('box { <0,0,-1>, <1,1,0> Soak_Wet_User_Material("clay", "water", 0.5, '
     'pigment { gradient x color_map { [0 rgb -0.2] [1 rgb 0.5] } }) }', "User_Pigment has channels from -0.2000"),
]


def write(tmp, name, body):
    path = os.path.join(tmp, name + ".pov")
    with open(path, "w") as f:
        f.write(HEAD + body + "\n")
    return path


def write_raw(tmp, name, text):
    path = os.path.join(tmp, name + ".pov")
    with open(path, "w") as f:
        f.write(text + "\n")
    return path


def render(tmp, lib, name, body, size=4):
    pov = write(tmp, name, body)
    out = os.path.join(tmp, name + ".exr")
    rc, log = povray(pov, out, size, size, lib)
    if rc in (134, 139) or rc < 0:  # Python reports a signal as -N (the shell's 128 + N)
        fail(f"{name}: POV-Ray crashed (exit {rc})\n{log[-1500:]}")
    return rc, log, out


def main():
    soak, root, tmp, lib = setup_args(__doc__)
    bad = 0
    for i, (body, arg) in enumerate(BAD):
        rc, log, _ = render(tmp, lib, f"bad{i}", body)
        flat = " ".join(log.split())
        ok = rc == 1 and arg in flat
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} bad input -> exit {rc}, names '{arg}'")
        if not ok:
            print(log[-800:])
    for i, (body, text) in enumerate(WARN):
        rc, log, _ = render(tmp, lib, f"warn{i}", body)
        ok = rc == 0 and text in " ".join(log.split())
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} doubtful input -> exit {rc}, warns '{text}'")

    # Every preset x liquid at the wetness edges renders to finite, non-negative pixels.
    body = """#declare P = 0;
#while (P < Soak_N_Presets)
  #declare L = 0;
  #while (L < Soak_N_Liquids)
    #declare Ws = array[5] {0, 1e-9, Soak_Preset_Saturation[P], 1 - 1e-9, 1}
    #declare K = 0;
    #while (K < 5)
      box { <(P + K / 5) / Soak_N_Presets, L / Soak_N_Liquids, -1>, <(P + (K + 1) / 5) / Soak_N_Presets,
            (L + 1) / Soak_N_Liquids, 0> Soak_Wet_Material(Soak_Preset_Names[P], Soak_Liquid_Names[L], Ws[K]) }
      #declare K = K + 1;
    #end
    #declare L = L + 1;
  #end
  #declare P = P + 1;
#end
"""
    rc, log, out = render(tmp, lib, "all_presets", body, size=60)
    img = read_image(out) if rc == 0 else None
    ok = rc == 0 and np.all(np.isfinite(img)) and img.min() >= 0
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} all presets x liquids x wetness edges render (exit {rc})")

    # ... and as media sheets (every preset with a medium; the weights w = 0 and 1 included).
    rc, log, out = render(tmp, lib, "all_media", body.replace(
        "Soak_Wet_Material(Soak_Preset_Names[P], Soak_Liquid_Names[L], Ws[K]) }",
        "#if (Soak_Preset_Kind[P] != 2) hollow Soak_Sheet_Material(Soak_Preset_Names[P], Soak_Liquid_Names[L], Ws[K])"
        " scale <1, 1, 0.001> #end }"), size=30)
    img = read_image(out) if rc == 0 else None
    ok = rc == 0 and np.all(np.isfinite(img)) and img.min() >= 0
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} all presets with a medium x liquids x wetness edges render as media sheets (exit {rc})")

    # A soak_materials.inc of another layout (stale copy next to the scene) stops the parse.
    old = os.path.join(tmp, "old_layout")
    os.makedirs(old, exist_ok=True)
    with open(os.path.join(lib, "soak_materials.inc")) as f:
        data = f.read()
    current = int(re.search(r"#declare Soak_Data_Format_Version = (\d+);", data).group(1))
    data = data.replace(f"#declare Soak_Data_Format_Version = {current};",
                        f"#declare Soak_Data_Format_Version = {current - 1};")
    with open(os.path.join(old, "soak_materials.inc"), "w") as f:
        f.write(data)
    pov = write(old, "stale", 'box { 0, 1 Soak_Wet_Material("sand", "water", 0.5) }')
    rc, log = povray(pov, os.path.join(old, "stale.exr"), 4, 4, lib, cwd=old)
    ok = rc == 1 and "regenerate it" in " ".join(log.split())
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} soak_materials.inc of layout {current - 1} -> exit {rc}, asks to regenerate it")

    # Wetness functions outside [0, 1] are clamped, not wrapped (POV-Ray wraps pattern values >= 1).
    pairs = [("function { 5 }", "1"), ("function { 1 }", "1"), ("function { -3 }", "0"), ("function { 0.5 }", "0.5")]
    for i, (fn, w) in enumerate(pairs):
        a = render(tmp, lib, f"clampfn{i}", f'#declare W = {fn}\nbox {{ <0,0,-1>, <1,1,0> '
                   f'Soak_Wet_Material_Fn("brick", "water", W) }}')
        b = render(tmp, lib, f"clampc{i}", f'box {{ <0,0,-1>, <1,1,0> Soak_Wet_Material("brick", "water", {w}) }}')
        if a[0] != 0 or b[0] != 0:
            bad += 1
            print(f"FAIL clamp {fn}: exit {a[0]}, {b[0]}")
            continue
        pa, pb = read_image(a[2]).mean((0, 1)), read_image(b[2]).mean((0, 1))
        ok = np.allclose(pa, pb, rtol=2e-3, atol=2e-4)
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} wetness {fn} renders as the constant {w}: {pa} vs {pb}")

    # Subsurface: POV-Ray's crash paths, raw (they must crash, else the guards below prove nothing) ...
    for i, (what, body, want) in enumerate(SSS_RAW):
        pov = write_raw(tmp, f"sss_raw{i}",
                        "#version 3.7;\ncamera { location <0, -5, 3> look_at 0 }\nlight_source { <3, -2, 10> rgb 1 }\n" + body)
        rc, _ = povray(pov, os.path.join(tmp, f"sss_raw{i}.exr"), 16, 16, lib)
        ok = rc == want
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} raw POV-Ray, subsurface {what}: exit {rc} (expected {want}: the crash the macros guard)")
    # ... and through the macros: #error naming the cause (exit 1), never 134/139
    for i, (body, arg) in enumerate(SSS_BAD):
        pov = write_raw(tmp, f"sss_bad{i}", SSS_HEAD + body)
        rc, log = povray(pov, os.path.join(tmp, f"sss_bad{i}.exr"), 16, 16, lib)
        ok = rc == 1 and arg in " ".join(log.split())
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} subsurface bad input -> exit {rc}, names '{arg}'")
        if not ok:
            print(log[-800:])
    rc, log = povray(write_raw(tmp, "sss_warn", SSS_HEAD.replace("<10, 4>", "<5, 4>") + SSS_SET),
                     os.path.join(tmp, "sss_warn.exr"), 8, 8, lib)
    ok = rc == 0 and "a noisy BSSRDF" in " ".join(log.split())
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} subsurface, 5 diffuse samples -> exit {rc}, warns 'a noisy BSSRDF'")
    # zero, tiny and > 1 table values (written into the marble table's knots) are clamped: finite, no abort
    body = SSS_SET + """#declare T = Soak_Table("marble", "water");
#declare I = Soak_K_Start[T];
#while (I < Soak_K_Start[T] + Soak_K_Count[T])
  #declare Soak_K_Translucency[I] = <0, 1e-12, 0.3>;
  #declare Soak_K_Pigment[I] = <0, 1e-12, 1.5>;
  #declare I = I + 1;
#end
sphere { 0, 1 Soak_Wet_Subsurface_Material("marble", "water", 0.5) }
sphere { <1.5, 1, 0>, 0.6 Soak_Wet_User_Subsurface_Material("marble", "water", 1, pigment { rgb <0, 1, 2> }) }
"""
    rc, log = povray(write_raw(tmp, "sss_zero", SSS_HEAD + body), os.path.join(tmp, "sss_zero.exr"), 16, 16, lib)
    img = read_image(os.path.join(tmp, "sss_zero.exr")) if rc == 0 else None
    ok = rc == 0 and np.all(np.isfinite(img)) and img.max() > 0
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} subsurface with zero/tiny/>1 pigment and translucency channels renders finite (exit {rc})")
    # every preset with a medium x liquid at the wetness edges renders finite through the subsurface macro
    body = SSS_SET + """#declare P = 0;
#while (P < Soak_N_Presets)
  #if (Soak_Preset_Kind[P] != 2)
    #declare L = 0;
    #while (L < Soak_N_Liquids)
      #declare Ws = array[5] {0, 1e-9, Soak_Preset_Saturation[P], 1 - 1e-9, 1}
      #declare K = 0;
      #while (K < 5)
        sphere { <P - 5, L * 2, K * 2 - 4>, 0.8 Soak_Wet_Subsurface_Material(Soak_Preset_Names[P], Soak_Liquid_Names[L], Ws[K]) }
        #declare K = K + 1;
      #end
      #declare L = L + 1;
    #end
  #end
  #declare P = P + 1;
#end
"""
    rc, log = povray(write_raw(tmp, "sss_all", SSS_HEAD.replace("<0, -5, 3>", "<0, -30, 8>") + body),
                     os.path.join(tmp, "sss_all.exr"), 48, 48, lib)
    img = read_image(os.path.join(tmp, "sss_all.exr")) if rc == 0 else None
    ok = rc == 0 and np.all(np.isfinite(img)) and img.min() >= 0
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} subsurface: every preset with a medium x liquid x wetness edge renders finite (exit {rc})")
    # A user pigment's transmit is kept: over a background B, the pixel is (1 - T) x the opaque
    # pixel + T x B (POV-Ray's transmit), highlights off, a flat polygon (no interior).
    px = {}
    for t in (0.0, 0.5):
        body = (  # highlights off: the identity is about the diffuse and ambient terms
            "#declare Soak_Highlights = 0;\n"
            f'polygon {{ 5, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0>, <0,0,0> Soak_Wet_User_Texture("clay", "water", 0.6, '
            f'pigment {{ rgb <0.6, 0.4, 0.3> transmit {t} }}) }}')
        rc, log, out = render(tmp, lib, f"transmit{t}", body, size=8)
        if rc != 0:
            fail(f"transmit {t}: exit {rc}\n{log[-800:]}")
        px[t] = read_image(out)[4, 4]
    back = np.array([0.2, 0.2, 0.2])  # HEAD's sky_sphere
    want = 0.5 * px[0.0] + 0.5 * back
    ok = bool(np.all(np.abs(px[0.5] - want) <= 2e-3 + 1e-3 * want))
    bad += not ok
    print(f"{'ok  ' if ok else 'FAIL'} user pigment transmit 0.5: {np.round(px[0.5], 4)} vs 0.5 x opaque + 0.5 x sky "
          f"{np.round(want, 4)}")
    if bad:
        fail(f"{bad} guard checks failed")
    print("PASS")


if __name__ == "__main__":
    main()
