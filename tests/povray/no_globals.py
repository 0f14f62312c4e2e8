"""soak.inc leaves no global scratch identifiers behind: every identifier a macro
makes is #local, and the values one macro hands another are returned (arrays of
vectors), not #declare'd. Two checks:
  1. parse: every `#declare` in soak.inc is one of the settings (declared under
     #ifndef before the macros), a constant of the file's head, or the documented
     flag Soak_Subsurface_On; none is inside a macro other than
     Soak_Subsurface_Settings;
  2. run: a scene that calls the surface, user-pigment, puddle, media and colour
     macros, then stops with #error if any of the identifiers the macros used to
     leave global (Soak__Cur_*, Soak__BW_F) is defined.

usage: no_globals.py SOAK ROOT TMPDIR"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soakpov import fail, povray, setup_args  # noqa: E402

ALLOWED_TOP = {"Soak_Inc_Temp", "Soak_Eps"}
ALLOWED_IN_MACRO = {("Soak_Subsurface_Settings", "Soak_Subsurface_On")}
OLD_SCRATCH = ["Soak__Cur_Kind", "Soak__Cur_Pig", "Soak__Cur_FilmR", "Soak__Cur_Spec", "Soak__Cur_Rough",
               "Soak__Cur_Phong", "Soak__Cur_Back", "Soak__Cur_Metal", "Soak__BW_F", "Soak__Cur_Sigma_S",
               "Soak__Cur_Sigma_A", "Soak__Cur_G1", "Soak__Cur_G2", "Soak__Cur_Lobe_W", "Soak__Cur_Translucency"]


def parse_check(text):
    bad, macro, depth = [], None, 0
    settings = set(re.findall(r"#ifndef\((\w+)\)\s*#declare\s+(\w+)", text))
    settings = {a for a, b in settings if a == b}
    for n, line in enumerate(text.splitlines(), 1):
        code = line.split("//")[0]
        m = re.match(r"\s*#macro\s+(\w+)", code)
        if m:
            macro = m.group(1)
        for name in re.findall(r"#declare\s+(\w+)", code):
            if macro is None and (name in settings or name in ALLOWED_TOP):
                continue
            if (macro, name) in ALLOWED_IN_MACRO:
                continue
            bad.append(f"soak.inc line {n}: #declare {name}" + (f" in macro {macro}" if macro else ""))
        # a macro ends at an #end that closes it: track #if/#while/#switch/#macro nesting
        depth += len(re.findall(r"#(?:if|ifdef|ifndef|while|switch|macro|for)\b", code))
        depth -= len(re.findall(r"#end\b", code))
        if depth == 0:
            macro = None
    return bad, settings


def main():
    soak, root, tmp, lib = setup_args(__doc__)
    text = open(os.path.join(lib, "soak.inc")).read()
    bad, settings = parse_check(text)
    print(f"settings declared under #ifndef: {sorted(settings)}")
    if bad:
        fail("global #declare left in soak.inc:\n  " + "\n  ".join(bad))
    checks = "\n".join(f'#ifdef({n}) #error "soak.inc left the global {n} behind\\n" #end' for n in OLD_SCRATCH)
    pov = os.path.join(tmp, "no_globals.pov")
    with open(pov, "w") as f:
        f.write(f"""#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
#include "soak.inc"
#declare W = function {{ x }}
#declare M1 = Soak_Wet_Material("brick", "water", 0.5)
#declare M2 = Soak_Wet_Material_Fn("sand", "coffee", W)
#declare M3 = Soak_Wet_User_Material("clay", "water", 0.7, pigment {{ rgb <0.5, 0.3, 0.2> }})
#declare M4 = Soak_Wet_User_Texture_Fn("clay", "water", W, pigment {{ rgb 0.5 }})
#declare M5 = Soak_Puddle_Material("concrete", "water", W, 0.6, normal {{ bumps 0.2 }})
#declare M6 = Soak_Wet_Material("copper", "water", 1)
#declare C1 = Soak_Wet_Colour("sand", "water", 0.5, <0.5, 0.4, 0.3>);
#declare S1 = Soak_Sheet_Material("cotton", "water", 0.5)
{checks}
#debug "no scratch globals\\n"
camera {{ location <0, 0, -2> look_at 0 }}
sphere {{ 0, 1 material {{ M1 }} }}
""")
    rc, log = povray(pov, os.path.join(tmp, "no_globals.exr"), 8, 8, lib, cwd=tmp)
    if rc != 0 or "no scratch globals" not in log:
        fail(f"povray exit {rc}:\n{log[-1500:]}")
    print(f"soak.inc: no global #declare inside macros; {len(OLD_SCRATCH)} former scratch names undefined after the macros ran")
    print("PASS")


if __name__ == "__main__":
    main()
