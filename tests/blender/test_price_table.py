"""The price the add-on's panel shows beside Quality (blender_addon/soak/
price.json) against the published benchmark file it names: the file rebuilt
from that table by c_core/bench/blender_price.py must equal the shipped one
(a number copied by hand, or a newer benchmark not carried over, fails), and
it must hold every Blender version, wiring and quality the panel reads
(price.py). Plain Python, under a second.

usage: python3 test_price_table.py REPO"""
import importlib.util
import json
import os
import sys

repo = sys.argv[1]
shipped_path = os.path.join(repo, "blender_addon", "soak", "price.json")
shipped = json.load(open(shipped_path, encoding="utf-8"))
spec = importlib.util.spec_from_file_location(
    "blender_price", os.path.join(repo, "c_core", "bench", "blender_price.py"))
bp = importlib.util.module_from_spec(spec)
spec.loader.exec_module(bp)
bench = os.path.join(repo, shipped["benchmark"])
rebuilt = bp.build(bench)
failures = []
if rebuilt != shipped:
    failures.append(f"{shipped_path} differs from {shipped['benchmark']}: regenerate with "
                    f"python3 c_core/bench/blender_price.py {shipped['benchmark']} blender_addon/soak/price.json")
for v in ("3.4", "4.3", "5.2"):
    for wired in ("constant", "varying"):
        for q in ("DRAFT", "BALANCED", "EXACT"):
            cell = shipped["cycles_overhead"].get(v, {}).get(wired, {}).get(q)
            if not (isinstance(cell, list) and len(cell) == 2 and all(0.5 < x < 10 for x in cell)):
                failures.append(f"overhead {v} {wired} {q}: {cell} (want min and median ratios in (0.5, 10))")
    for q in ("DRAFT", "BALANCED", "EXACT"):
        e = shipped["cycles_colour_error"].get(q, {}).get(v)
        if not (isinstance(e, float) and 0.0 <= e < 1.0):
            failures.append(f"colour error {q} {v}: {e}")
for k in ("linear", "exact"):
    if not isinstance(shipped["eevee_colour_error"].get(k), float):
        failures.append(f"EEVEE colour error '{k}' missing")
for f in failures:
    print("FAIL:", f)
if failures:
    sys.exit(1)
print(f"ok: price.json = {shipped['benchmark']} (18 overheads, 9 colour errors, 2 EEVEE errors)")
