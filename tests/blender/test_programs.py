"""The node programs of soak_data.json (column_program, row_program,
schedule_program), run here with Blender's Math-node semantics (safe SQRT
and DIVIDE, clamp to [0, 1]), against the table layout the export states:
column j at dry albedo a = 1 - (1 - j/(columns-1))^2 must give t = j/(columns-1);
row r at L = saturation (r/rows_below)^2 (r <= rows_below), else
saturation + (1 - saturation)(r - rows_below)/rows_above, must give
t = r/(rows-1); halfway between knots the program must stay between the
neighbours' t (monotone). The schedule against soak_fill_fraction's
definition (soak/porous.h): 0 before the start, (t - t0)/T during the fill,
1 from t0 + T on; T = 0 a step at t0. Plain Python, no Blender.
usage: python3 test_programs.py SOAK_DATA_JSON"""
import json
import math
import sys


def run(ops, env):
    res = []
    for op in ops:
        name, args, clamp = op[0], op[1:-1], op[-1]
        v = [a if isinstance(a, (int, float)) and not isinstance(a, bool)
             else (res[int(a[1:])] if a.startswith("#") else env[a]) for a in args]
        r = {"ADD": lambda: v[0] + v[1], "SUBTRACT": lambda: v[0] - v[1], "MULTIPLY": lambda: v[0] * v[1],
             "DIVIDE": lambda: v[0] / v[1] if v[1] != 0 else 0.0, "MULTIPLY_ADD": lambda: v[0] * v[1] + v[2],
             "SQRT": lambda: math.sqrt(v[0]) if v[0] > 0 else 0.0, "MAXIMUM": lambda: max(v[0], v[1]),
             "MINIMUM": lambda: min(v[0], v[1])}[name]()
        res.append(min(max(r, 0.0), 1.0) if clamp else r)
    return res[-1]


def main(path):
    d = json.load(open(path))
    worst, n = 0.0, 0
    for m in d["materials"]:
        for liquid, t in m["liquids"].items():
            na, n1, n2, ws = t["columns"], t["rows_below"], t["rows_above"], t["saturation"]
            for j in range(na):
                s = j / (na - 1)
                e = abs(run(t["column_program"], {"x": 1 - (1 - s) ** 2}) - s)
                worst, n = max(worst, e), n + 1
            rows = n1 + n2 + 1

            def L(r):
                return ws * (r / n1) ** 2 if n1 > 0 and r <= n1 else ws + (1 - ws) * (r - n1) / n2
            for r in range(rows):
                e = abs(run(t["row_program"], {"x": L(r)}) - r / (rows - 1))
                worst, n = max(worst, e), n + 1
                if r + 1 < rows:
                    mid = run(t["row_program"], {"x": 0.5 * (L(r) + L(r + 1))}) * (rows - 1)
                    if not r <= mid <= r + 1:
                        sys.exit(f"FAIL: {m['name']}/{liquid}: row program not monotone at row {r}: {mid}")
    if worst > 1e-7:
        sys.exit(f"FAIL: a program misses its knots by {worst:.2e} ({n} knots)")
    sched = d["schedule_program"]
    cases = [((5.0, 2.0, 4.0), 0.75), ((1.0, 2.0, 4.0), 0.0), ((6.0, 2.0, 4.0), 1.0), ((9.0, 2.0, 4.0), 1.0),
             ((2.0, 2.0, 0.0), 1.0), ((1.999, 2.0, 0.0), 0.0), ((2.0, 2.0, 4.0), 0.0)]
    for (t, t0, T), want in cases:
        got = run(sched, {"time": t, "start_time": t0, "fill_time": T})
        if abs(got - want) > 1e-9:
            sys.exit(f"FAIL: schedule at t={t}, t0={t0}, T={T}: {got}, soak_fill_fraction gives {want}")
    print(f"PASS: {n} knots within {worst:.1e}, {len(cases)} schedule points")
    folding(d)


def load_wet_bounds():
    """The add-on's wet_bounds (its folding and interval arithmetic) with a
    stand-in for Blender's bpy module, which its helpers import."""
    import importlib
    import os
    import types
    addon = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "blender_addon")
    sys.modules.setdefault("bpy", types.ModuleType("bpy"))
    pkg = types.ModuleType("soak")
    pkg.__path__ = [os.path.join(addon, "soak")]
    sys.modules["soak"] = pkg
    return importlib.import_module("soak.wet_bounds")


def folding(d):
    """wet_bounds (issue 33, a varying wetness): a program folded to what
    its inputs can be equals the exported one there (run by this file's own
    interpreter), and the intervals hold every sampled value. The film-free
    row program of each table against the full one on [0, saturation]; the
    liquid program with some inputs fixed against the full one."""
    import random
    wb = load_wet_bounds()
    rng = random.Random(33)
    worst, dropped = 0.0, 0
    for m in d["materials"]:
        for liquid, t in m["liquids"].items():
            folded = wb.row_program(t, False)
            dropped += len(t["row_program"]) - len(folded)
            for k in range(101):
                x = t["saturation"] * k / 100
                worst = max(worst, abs(run(folded, {"x": x}) - run(t["row_program"], {"x": x})))
    full = wb.liquid_program()
    names = list(wb.NAMES.values())
    for trial in range(300):
        box = {}
        for name in names:
            a, b = sorted(rng.uniform(-0.5, 3.0) for _ in range(2))
            box[name] = (a, a) if rng.random() < 0.5 else (a, b)
        folded = wb.fold_program(full, box)
        iv = wb.intervals(full, box)[-1]
        for _ in range(20):
            env = {k: rng.uniform(*v) for k, v in box.items()}
            got, want = run(folded, env), run(full, env)
            worst = max(worst, abs(got - want))
            if not iv[0] - 1e-12 <= want <= iv[1] + 1e-12:
                sys.exit(f"FAIL: liquid {want} outside its interval {iv} for {box}")
    if worst > 1e-6:
        sys.exit(f"FAIL: a folded program differs from the exported one by {worst:.2e}")
    porous = sum(1 for m in d["materials"] if m["porosity"] > 0) * 4
    if dropped < 2 * porous:
        sys.exit(f"FAIL: the film-free row programs dropped {dropped} operations, expected 2 per porous table")
    print(f"PASS: folded programs within {worst:.1e} of the exported ones; {dropped} film operations dropped")


main(sys.argv[1])
