"""Type mistakes stop the parse on a line of soak.inc that names the macro and the
argument. POV-Ray 3.7's language has no type test (no typeof; a string where a
number is expected, or the reverse, is a parse error wherever it is read), so an
include cannot turn them into its own #error message with the value; what it can
do is read every argument once, at the top of each public macro, on a line of its
own whose comment says what the argument must be (a "probe"). POV-Ray reports
"File '.../soak.inc' line N: Parse Error": line N is that probe. Each case below
renders a one-line scene with one mistake and asserts: exit 1, the reported line
belongs to soak.inc, and it names the macro and the argument. Before the probes
the same mistakes stopped inside helper macros (Soak_Preset_Index's strcmp,
Soak_Check_Unit, the texture_map's function) on lines naming neither.

usage: type_errors.py SOAK ROOT TMPDIR"""
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import fail, setup_args  # noqa: E402

CASES = [  # (what, object line, macro, argument)
    ("number for a preset name", 'Soak_Wet_Material(3, "water", 0.5)', "Soak_Wet_Material", "Preset"),
    ("number for a liquid name", 'Soak_Wet_Texture("sand", 2, 0.5)', "Soak_Wet_Texture", "Liquid"),
    ("string for the wetness", 'Soak_Wet_Material("sand", "water", "0.5")', "Soak_Wet_Material", "Wetness"),
    ("pigment for Wet_Fn", 'Soak_Wet_Material_Fn("sand", "water", pigment { rgb 1 })', "Soak_Wet_Material_Fn", "Wet_Fn"),
    ("number for Wet_Fn", 'Soak_Wet_Material_Bumped("sand", "water", 0.5, normal { bumps 0.1 })', "Soak_Wet_Material_Bumped", "Wet_Fn"),
    ("colour vector for User_Pigment", 'Soak_Wet_User_Material("clay", "water", 0.5, <0.5, 0.3, 0.2>)',
     "Soak_Wet_User_Material", "User_Pigment"),
    ("string for the puddle level", 'Soak_Puddle_Material("concrete", "water", function { x }, "0.8", normal { bumps 0.1 })',
     "Soak_Puddle_Material", "Level"),
    ("number for a map file", 'Soak_Wet_Material_Fn("sand", "water", Soak_Map_Fn(3))', "Soak_Map_Fn", "File"),
    ("string for an existing texture's dry colour", 'texture { pigment { rgb 0.5 } } Soak_Wet_Layer("oak", "water", 0.5, "brown")',
     "Soak_Wet_Layer", "Dry_Colour"),
    ("number for the existing texture's Wet_Fn",
     'Soak_Wet_Existing_Fn(texture { pigment { rgb 0.5 } }, "oak", "water", 0.5, <0.3, 0.2, 0.1>)',
     "Soak_Wet_Existing_Fn", "Wet_Fn"),
    ("pigment for the map to place", 'Soak_Wet_Existing_Fn(texture { pigment { rgb 0.5 } }, "oak", "water", '
     'Soak_Place_Fn(pigment { rgb 1 }, 10, transform { }), <0.3, 0.2, 0.1>)', "Soak_Place_Fn", "Fn"),
    ("a patterned texture (POV-Ray cannot layer over it)",
     'Soak_Wet_Existing_Fn(texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }, '
     '"oak", "water", function { x }, <0.3, 0.2, 0.1>)', "Soak_Wet_Existing_Fn", "Texture"),
    ("material { } around a material macro", 'material { Soak_Wet_Material("sand", "water", 0.5) }',
     "Soak_Wet_Material", "material { }"),
    ("pigment for the drops' map", 'Soak_Wet_Drops_Material("brick", "water", pigment { rgb 1 }, 0.1)',
     "Soak_Wet_Drops_Material", "Drops_Fn"),
    ("string for the drops' Spot", 'Soak_Wet_Drops_Material("brick", "water", function { x }, "0.1")',
     "Soak_Wet_Drops_Material", "Spot"),
]


def run(tmp, lib, obj, tag):
    pov = os.path.join(tmp, f"{tag}.pov")
    with open(pov, "w") as f:
        f.write('#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n#include "soak.inc"\n'
                f"plane {{ z, 0 {obj} }}\n")
    r = subprocess.run(["povray", f"+I{pov}", "-D", "+W8", "+H8", "-O/dev/null", f"+L{lib}"],
                       capture_output=True, text=True, cwd=tmp)
    return r.returncode, r.stdout + r.stderr


def main():
    soak, root, tmp, lib = setup_args(__doc__)
    inc = open(os.path.join(lib, "soak.inc")).read().split("\n")
    bad = 0
    rc, log = run(tmp, lib, 'Soak_Wet_Material("sand", "water", 0.5)', "control")
    if rc != 0:
        fail(f"the correct call does not parse (exit {rc}):\n{log[-800:]}")
    for i, (what, obj, macro, arg) in enumerate(CASES):
        rc, log = run(tmp, lib, obj, f"case{i}")
        m = re.search(r"File '([^']*)' line (\d+): Parse Error", log)
        line = inc[int(m.group(2)) - 1] if m and m.group(1).endswith("soak.inc") else ""
        ok = rc == 1 and macro + ":" in line.replace(" returns", ":") and arg in line
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {what}: exit {rc}, "
              f"{m.group(0) if m else 'no parse error reported'}\n       {line.strip()[:220]}")
    if bad:
        fail(f"{bad} type mistakes not reported on a line naming the macro and the argument")
    print("PASS")


if __name__ == "__main__":
    main()
