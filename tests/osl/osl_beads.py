#!/usr/bin/env python3
"""osl/soak_beads.osl against the `soak bake beads` map it reads.

`soak bake beads` writes a 32 x 32 map (90 deg, 25 mm/h for 60 s, 1 mm
texels, 32-bit EXR); testshade runs soak_beads over a 32 x 32 grid whose
points are the texel centres (--center) on a flat surface (N = +Z, tangent
+X). The reference is the EXR read by oiiotool (an independent reader): the
normal normalize(2 c - 1) and the height alpha x HeightRange of the texel,
the file's top row at v = 1. Checks: every component within 1e-5; the map
is not flat (some normal leans by more than 5 degrees, some height above
10 % of the range); no BeadFile leaves N and height 0.

OSL has no Debian package: without oslc/testshade/oiiotool on PATH this
exits 77 (SKIPPED), never a pass. usage: osl_beads.py SOAK ROOT TMPDIR"""
import math
import os
import sys

from osl_tools import decode_normal, dump, prepare, run

G = 32
TOL = 1e-5
HR = 0.006


def shade(tmp, params, name, output):
    out = os.path.join(tmp, name + "_" + output + ".exr")
    cmd = ["testshade", "-t", "1", "-g", str(G), str(G), "--center"]
    for k, v in params:
        cmd += ["--param:type=" + ("float" if isinstance(v, float) else "string"), k, str(v)]
    cmd += ["soak_beads", "-o", output, out, "-d", "float"]
    run(cmd, tmp)
    return dump(out, tmp, G * G)


def main(soak, root, tmp):
    prepare(tmp, root, "soak_beads")
    run([soak, "bake", "beads", "--contact-angle", "90", "--rate", "25", "--duration", "60", "--texel", "0.001",
         "--width", str(G), "--height", str(G), "--height-range", str(HR), "--float", "-o", "b.exr"], tmp)
    ref = dump(os.path.join(tmp, "b.exr"), tmp, G * G)
    params = [("BeadFile", "b.exr"), ("HeightRange", HR)]
    nrm, hgt = shade(tmp, params, "b", "BeadNormal"), shade(tmp, params, "b", "Height")
    fails, worst_n, worst_h, tilt, top = [], 0.0, 0.0, 0.0, 0.0
    for (x, y), g in nrm.items():
        c = ref[(x, G - 1 - y)]   # testshade's row y is v = (y + 0.5) / G; the file's row G-1-y holds it
        n = decode_normal(c)
        tilt = max(tilt, math.degrees(math.acos(max(-1.0, min(1.0, n[2])))))
        worst_n = max(worst_n, max(abs(a - b) for a, b in zip(g, n)))
        worst_h = max(worst_h, abs(hgt[(x, y)][0] - c[3] * HR))
        top = max(top, c[3])
    for ok, msg in ((worst_n < TOL, "max |BeadNormal - normalize(2c - 1)| %.2e (tol %g)" % (worst_n, TOL)),
                    (worst_h < TOL * HR, "max |Height - alpha x HeightRange| %.2e m (tol %g)" % (worst_h, TOL * HR)),
                    (tilt > 5.0 and top > 0.1, "the map holds beads: normals lean up to %.1f deg, height up to "
                     "%.2f of the range" % (tilt, top))):
        print("%s: %s" % ("ok" if ok else "FAIL", msg))
        if not ok:
            fails.append(msg)
    got = shade(tmp, [], "nofile", "BeadNormal")
    worst = max(max(abs(a - b) for a, b in zip(g, (0.0, 0.0, 1.0))) for g in got.values())
    ok = worst < 1e-6
    print("%s: no BeadFile: BeadNormal = N (max |diff| %.2e)" % ("ok" if ok else "FAIL", worst))
    if not ok:
        fails.append("nofile")
    if fails:
        print("FAIL: " + "; ".join(fails))
        sys.exit(1)
    print("PASS")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        print(__doc__)
        sys.exit(2)
    main(*sys.argv[1:])
