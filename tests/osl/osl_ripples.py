#!/usr/bin/env python3
"""The ripple normal of osl/soak_wetmap.osl against the flipbook it reads.

`soak bake ripples` writes a small looping flipbook (32 x 32, 8 frames);
testshade runs soak_wetmap over a 32 x 32 grid whose points are the texel
centres (--center), on a flat surface (N = +Z, tangent +X), and writes
RippleNormal. The reference is read from the baked EXR by oiiotool (an
independent reader; --dumpdata): n = normalize(2 c - 1) of the texel, with
the file's top row at v = 1 (the flipbook's convention, v up). Checks:

 1. Frame 11 with LoopFrames 8 reads frame 3 (the loop), Frame -5 reads
    frame 3 too (negative frames wrap), every component within 2e-3 (half
    float EXR, filtered lookup at the texel centre);
 2. PuddleLevel above the wetness leaves N (no ripples where the surface is
    not flooded); an empty RippleFile leaves N;
 3. the tilt is not trivial (some normal leans by more than 1 degree).

OSL has no Debian package: without oslc/testshade/oiiotool on PATH this
exits 77 (SKIPPED), never a pass. usage: osl_ripples.py SOAK ROOT TMPDIR"""
import math
import os
import sys

from osl_tools import decode_normal, dump, prepare, run

G = 32
LOOP = 8
TOL = 2e-3


def shade(tmp, params, name):
    out = os.path.join(tmp, name + ".exr")
    cmd = ["testshade", "-t", "1", "-g", str(G), str(G), "--center"]
    for k, v in params:
        cmd += ["--param:type=" + ("int" if isinstance(v, int) else "float" if isinstance(v, float) else "string"),
                k, str(v)]
    cmd += ["soak_wetmap", "-o", "RippleNormal", out, "-d", "float"]
    run(cmd, tmp)
    return dump(out, tmp, G * G)


def main(soak, root, tmp):
    prepare(tmp, root, "soak_wetmap")
    run([soak, "bake", "ripples", "--rate", "50", "--tile", "0.1", "--width", str(G), "--loop-frames", str(LOOP),
         "--period", "0.4", "--seed", "3", "--frames", "0-%d" % (LOOP - 1), "-o", "rip.%04d.exr"], tmp)
    ref = dump(os.path.join(tmp, "rip.0003.exr"), tmp, G * G)
    fails, worst_tilt = [], 0.0
    for frame in (11, -5):
        params = [("RippleFile", "rip."), ("RippleExtension", ".exr"), ("Frame", frame), ("LoopFrames", LOOP)]
        got = shade(tmp, params, "f%d" % frame)
        worst = 0.0
        for (x, y), g in got.items():
            # testshade's row y is v = (y + 0.5) / G; the file's row G-1-y holds that v
            c = ref[(x, G - 1 - y)]
            n = decode_normal(c)
            worst_tilt = max(worst_tilt, math.degrees(math.acos(max(-1.0, min(1.0, n[2])))))
            worst = max(worst, max(abs(a - b) for a, b in zip(g, n)))
        ok = worst < TOL
        print("%s: Frame %d reads flipbook frame 3: max |RippleNormal - normalize(2c - 1)| %.2e (tol %g)"
              % ("ok" if ok else "FAIL", frame, worst, TOL))
        if not ok:
            fails.append("frame %d" % frame)
    ok = worst_tilt > 1.0
    print("%s: the flipbook's normals lean up to %.2f degrees" % ("ok" if ok else "FAIL", worst_tilt))
    if not ok:
        fails.append("flat flipbook")
    flipbook = [("RippleFile", "rip."), ("RippleExtension", ".exr"), ("LoopFrames", LOOP)]
    for name, params in (("dry", flipbook + [("Frame", 3), ("Amount", 0.5), ("PuddleLevel", 0.6)]),
                         ("nofile", [("Frame", 3)])):
        got = shade(tmp, params, name)
        worst = max(max(abs(a - b) for a, b in zip(g, (0.0, 0.0, 1.0))) for g in got.values())
        ok = worst < 1e-6
        print("%s: %s: RippleNormal = N (max |diff| %.2e)" % ("ok" if ok else "FAIL", name, worst))
        if not ok:
            fails.append(name)
    if fails:
        print("FAIL: " + ", ".join(fails))
        sys.exit(1)
    print("PASS")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        print(__doc__)
        sys.exit(2)
    main(*sys.argv[1:])
