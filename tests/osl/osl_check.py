#!/usr/bin/env python3
"""Checks the shipped OSL shaders with OSL's own tools, where they are on PATH.

1. oslc compiles every shader in osl/ (plus the test driver).
2. Every closure a compiled shader calls is registered by the Cycles versions
   the shader says it serves (Blender's registries, read from its sources:
   see CYCLES_CLOSURES), with at least the registered number of arguments.
3. testshade runs soak_wetmap on .tx maps made by maketx (schedule and map
   orientation), and each wet shader over a grid (wetness along u, a base colour
   along v; every preset x liquid, with and without UseBaseColor) and
   osl_core_check compares every output with the core itself.

OSL has no Debian package: without oslc/testshade this exits 77 (SKIPPED),
never a pass. usage: osl_check.py ROOT CHECKER TMPDIR
"""
import os
import re
import shutil
import subprocess
import sys

# Closures registered by Cycles, with their number of formal arguments:
# 2.8x-3.1 intern/cycles/kernel/osl/osl_closures.cpp (register_closures),
# 3.2-3.4 intern/cycles/kernel/osl/closures.cpp (the generic "microfacet"
# is registered there), 3.5-4.x intern/cycles/kernel/osl/closures_template.h
# (microfacet_ggx is gone). Only the closures Soak could use are listed.
COMMON = {"diffuse": 1, "translucent": 1, "reflection": 1, "refraction": 2, "transparent": 0}
CYCLES_CLOSURES = {
    "2.80-3.1": dict(COMMON, microfacet_ggx=2),
    "3.4": dict(COMMON, microfacet_ggx=2, microfacet=7),
    "4.x": dict(COMMON, microfacet=7, dielectric_bsdf=8, conductor_bsdf=7),
}
SERVES = {
    "soak_wet_surface": ["3.4", "4.x"],
    "soak_wet_surface_legacy": ["2.80-3.1", "3.4"],
    "soak_wet_sheet": ["2.80-3.1", "3.4", "4.x"],
    "soak_wetmap": ["2.80-3.1", "3.4", "4.x"],
}
# (shader, presets it offers, outputs) run under testshade; the legacy
# surface calls microfacet_ggx, which testshade does not know: its code is
# the same generator's with one closure line changed (checked below).
RUNS = [("soak_wet_surface", None, ["WetColor", "Coverage", "Roughness"]),
        ("soak_wet_sheet", None, ["WetColor", "Coverage", "Roughness", "Transmittance"])]
GRID = (11, 3)


def skip(reason):
    print("SKIPPED: " + reason)
    sys.exit(77)


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def compile_all(root, tmp, failures):
    sources = sorted(f for f in os.listdir(os.path.join(root, "osl")) if f.endswith(".osl"))
    sources = [os.path.join(root, "osl", f) for f in sources]
    sources.append(os.path.join(root, "tests", "osl", "soak_test_grid.osl"))
    for src in sources:
        name = os.path.basename(src)[:-4]
        r = run(["oslc", "-o", os.path.join(tmp, name + ".oso"), src])
        ok = r.returncode == 0
        print(("ok  " if ok else "FAIL") + " oslc " + name + ("" if ok else ": " + r.stderr.strip()))
        if not ok:
            failures.append("oslc " + name)
    return [os.path.basename(s)[:-4] for s in sources]


def closure_calls(oso_path):
    """(name, number of arguments) of every closure op in a compiled shader."""
    consts, calls = {}, []
    for line in open(oso_path):
        m = re.match(r'const\s+string\s+(\$\w+)\s+"([^"]*)"', line)
        if m:
            consts[m.group(1)] = m.group(2)
        m = re.match(r'\s+closure\s+(.*?)\s*%', line)
        if m:
            args = m.group(1).split()
            # args: result, [weight,] name, formal args...
            idx = 1 if args[1] in consts else 2
            calls.append((consts.get(args[idx], "?"), len(args) - idx - 1))
    return calls


def check_closures(tmp, names, failures):
    for name, versions in SERVES.items():
        if name not in names:
            failures.append("shader missing: " + name)
            continue
        calls = closure_calls(os.path.join(tmp, name + ".oso"))
        for version in versions:
            reg = CYCLES_CLOSURES[version]
            for cl, nargs in sorted(set(calls)):
                if cl not in reg or nargs < reg[cl]:
                    failures.append("%s calls %s(%d args), not registered so in Cycles %s" % (name, cl, nargs, version))
        used = sorted({c for c, _ in calls})
        print("ok   %s: closures %s registered in Blender %s" % (name, ", ".join(used) or "none", ", ".join(versions)))
    # The claim that each surface variant is needed: the generic one is not
    # registered in 2.80-3.1, the legacy one not in 4.x.
    for name, version in (("soak_wet_surface", "2.80-3.1"), ("soak_wet_surface_legacy", "4.x")):
        calls = closure_calls(os.path.join(tmp, name + ".oso"))
        if all(c in CYCLES_CLOSURES[version] for c, _ in calls):
            failures.append("%s would also serve %s: the version split is stale" % (name, version))


def check_variants_agree(root, failures):
    """The legacy surface differs from the generic one only in its metal closure."""
    def body(name):
        text = open(os.path.join(root, "osl", name + ".osl")).read()
        text = text.split("shader " + name + "(", 1)[1].replace(name, "NAME")
        return [ln for ln in text.splitlines() if "microfacet" not in ln]
    a, b = body("soak_wet_surface"), body("soak_wet_surface_legacy")
    if a != b:
        failures.append("soak_wet_surface_legacy's code differs from soak_wet_surface beyond the metal closure")
    else:
        print("ok   soak_wet_surface_legacy = soak_wet_surface but for the metal closure")


def menu(root, shader, param):
    text = open(os.path.join(root, "osl", shader + ".osl")).read()
    m = re.search(r'string %s = "[^"]*" \[\[ string widget = "popup", string options = "([^"]*)"' % param, text)
    return m.group(1).split("|") if m else []


def parse_print(text, outputs):
    """testshade --print's values per pixel, in row-major order (x fastest)."""
    pixels, cur = {}, None
    for line in text.splitlines():
        m = re.match(r"Pixel \((\d+), (\d+)\):", line)
        if m:
            cur = {}
            pixels[(int(m.group(2)), int(m.group(1)))] = cur
        elif cur is not None and ":" in line:
            key, val = line.split(":", 1)
            if key.strip() in outputs:
                cur[key.strip()] = [float(x) for x in val.split()]
    return [pixels[k] for k in sorted(pixels)]


def testshade_rows(root, tmp, failures):
    """One testshade run per shader (one JIT, seconds): the driver's rows are
    blocks of GRID[1] rows, one per preset x liquid x UseBaseColor, the
    wetness along u and the base colours along v within each block."""
    nx, rows_per = GRID
    rows = []
    for shader, _, outputs in RUNS:
        presets, liquids = menu(root, shader, "Preset"), menu(root, shader, "Liquid")
        cases = [(p, q, b) for p in presets for q in liquids for b in (0, 1)]
        ny = rows_per * len(cases)
        drv = ["--param", "Presets", "|".join(presets), "--param", "Liquids", "|".join(liquids),
               "--param", "Rows", str(rows_per), "--param", "Height", str(ny)]
        grid = run(["testshade", "-t", "1", "-g", str(nx), str(ny), *drv, "soak_test_grid", "-o", "Wetness", "null",
                    "-o", "BaseColor", "null", "--print"], cwd=tmp)
        points = parse_print(grid.stdout, {"Wetness", "BaseColor"})
        if grid.returncode != 0 or len(points) != nx * ny:
            failures.append("testshade grid driver: " + grid.stderr.strip()[:300])
            continue
        cmd = ["testshade", "-t", "1", "-g", str(nx), str(ny), "--layer", "g", *drv, "--shader", "soak_test_grid", "g",
               "--layer", "s", "--shader", shader, "s"]
        for out in ("Wetness", "BaseColor", "Preset", "Liquid", "UseBaseColor"):
            cmd += ["--connect", "g", out, "s", out]
        cmd.append("--print")
        for o in outputs:
            cmd += ["-o", o, "null"]
        r = run(cmd, cwd=tmp)
        got = parse_print(r.stdout, set(outputs))
        if r.returncode != 0 or len(got) != nx * ny or "ERROR" in r.stderr or "unknown" in r.stderr:
            failures.append("testshade %s: %s" % (shader, r.stderr.strip()[:300]))
            continue
        for i, (pt, g) in enumerate(zip(points, got)):
            preset, liquid, use_base = cases[(i // nx) // rows_per]
            tr = g.get("Transmittance", [0, 0, 0])
            rows.append("%s,%s,%s,%d,%.7g,%.7g,%.7g,%.7g,%.7g,%.7g,%.7g,%.7g,%.7g,%.7g,%.7g,%.7g" % (
                shader, preset, liquid, use_base, *pt["BaseColor"], pt["Wetness"][0], *g["WetColor"],
                g["Coverage"][0], g["Roughness"][0], *tr))
    return rows


def check_wetmap(tmp, failures):
    """soak_wetmap.osl on .tx maps made by maketx: a constant start value 0.7
    (t0 = 0.3) and a map whose top half is 1 and bottom half 0 (the image's
    top row must be v = 1, as in Blender's UVs). Time is swept along u; the
    expected wetness is the schedule's definition (Hnat et al. 2006; osl/README.md):
    drying Amount * (1 - P), wetting Amount * P, P = clamp((Time - t0) / FillTime),
    0 where the map is 0."""
    maps = {"const": ["--pattern", "constant:color=0.7", "32x32", "1"],
            "split": ["--pattern", "constant:color=1", "32x16", "1", "--pattern", "constant:color=0", "32x16", "1",
                      "--mosaic", "1x2"]}
    for name, pattern in maps.items():
        exr, tx = os.path.join(tmp, name + ".exr"), os.path.join(tmp, name + ".tx")
        for cmd in (["oiiotool", *pattern, "-d", "float", "-o", exr], ["maketx", exr, "-o", tx]):
            r = run(cmd)
            if r.returncode != 0:
                failures.append(" ".join(cmd) + ": " + r.stderr.strip())
                return
    nx, ny, fill, amount = 21, 16, 0.2, 0.8
    worst, count = 0.0, 0
    for name, drying in (("const", 1), ("const", 0), ("split", 1)):
        r = run(["testshade", "-t", "1", "-g", str(nx), str(ny), "--center", "--layer", "g", "--shader", "soak_test_grid", "g",
                 "--layer", "w", "--param", "WetMap", name + ".tx", "--param", "Drying", str(drying),
                 "--param", "FillTime", str(fill), "--param", "Amount", str(amount), "--shader", "soak_wetmap", "w",
                 "--connect", "g", "Wetness", "w", "Time", "-o", "Wetness", "null", "--print"], cwd=tmp)
        got = parse_print(r.stdout, {"Wetness"})
        if r.returncode != 0 or len(got) != nx * ny:
            failures.append("testshade soak_wetmap %s: %s" % (name, r.stderr.strip()[:300]))
            return
        for i, g in enumerate(got):
            x, y = i % nx, i // nx
            u, v = (x + 0.5) / nx, (y + 0.5) / ny
            if name == "split" and abs(v - 0.5) < 0.15:
                continue  # texture filtering across the step
            start = 0.7 if name == "const" else (1.0 if v > 0.5 else 0.0)
            p = min(max((u - (1.0 - start)) / fill, 0.0), 1.0)
            want = 0.0 if start <= 0 else amount * ((1.0 - p) if drying else p)
            worst = max(worst, abs(g["Wetness"][0] - want))
            count += 1
    ok = worst <= 1e-4 and count > 0
    print(("ok  " if ok else "FAIL") + " soak_wetmap on maketx maps (constant, top/bottom split; drying and "
          "wetting): %d points, worst %.2g (<= 1e-4)" % (count, worst))
    if not ok:
        failures.append("soak_wetmap differs from the schedule")


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    root, checker, tmp = sys.argv[1:]
    missing = [t for t in ("oslc", "testshade", "maketx", "oiiotool") if not shutil.which(t)]
    if missing:
        skip("%s not on PATH (OSL has no Debian package); test_osl_math checks the shaders' math in C"
             % " and ".join(missing))
    os.makedirs(tmp, exist_ok=True)
    failures = []
    names = compile_all(root, tmp, failures)
    if not failures:
        check_closures(tmp, names, failures)
        check_variants_agree(root, failures)
        check_wetmap(tmp, failures)
        rows = testshade_rows(root, tmp, failures)
        csv = os.path.join(tmp, "testshade_rows.csv")
        with open(csv, "w") as f:
            f.write("# shader,preset,liquid,use_base,base r,g,b,wetness,WetColor r,g,b,Coverage,Roughness,T r,g,b\n")
            f.write("\n".join(rows) + "\n")
        r = run([checker, csv, str(GRID[0] * GRID[1] * 2 * (48 + 8))])
        print(r.stdout.strip())
        if r.returncode != 0:
            failures.append("testshade outputs differ from the core (osl_core_check)")
    for f in failures:
        print("FAIL " + f)
    print("%d failure(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
