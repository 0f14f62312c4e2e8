#!/bin/bash
# soak report: the checked-in values (docs/accuracy/report.json) are not
# stale -- the --quick subset regenerated here (fixed seeds) equals the
# checked-in cells within 1e-4 (values only: never timings, never plots);
# the statistics in the file follow from its own cells (an identity:
# "full" has zero error, each model's mean and worst error are recomputed
# here from the 6-decimal albedos, hence the 5e-4 tolerance); the
# full material's albedo agrees with an independent method (Lekner-Dorf
# film over Lambert by quadrature, as tests/cli/measure.sh) for marble;
# --help, argument errors (exit 2, option named), outputs all-or-nothing.
# ctest-label: slow
set -u
source "$(dirname "$0")/lib.bash"
root=${SOAK_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
checked="$root/docs/accuracy/report.json"

expect_exit 0 "--help" -- "$SOAK" report --help
grep -q "soak report" "$SOAK_TMP/last.out" && ok "--help prints usage" || bad "--help prints no usage"
expect_exit 2 "bad --samples" -- "$SOAK" report --samples 3
expect_stderr "--samples" "error names --samples"
expect_exit 2 "unknown option" -- "$SOAK" report --frobnicate
expect_stderr "--frobnicate" "error names the option"
expect_exit 2 "--cost-only without --model" -- "$SOAK" report --cost-only
expect_stderr "--model" "error names --model"
expect_exit 2 "--cost-only with an unknown model" -- "$SOAK" report --cost-only --model nosuch
expect_stderr "nosuch" "error names the model"
mkdir -p "$SOAK_TMP/keep"
echo previous > "$SOAK_TMP/keep/r.json"
expect_exit 2 "--markdown into a missing folder" -- "$SOAK" report --quick --no-cost --samples 16 \
  --json "$SOAK_TMP/keep/r.json" --markdown "$SOAK_TMP/nofolder/r.md"
[ "$(cat "$SOAK_TMP/keep/r.json")" = previous ] && ok "failed run left the previous json" || bad "failed run changed the json"

if [ ! -f "$checked" ]; then bad "no checked-in $checked"; finish; fi
expect_exit 0 "quick report" -- "$SOAK" report --quick --no-cost --json "$SOAK_TMP/q.json" --markdown "$SOAK_TMP/q.md"
python3 - "$checked" "$SOAK_TMP/q.json" <<'PY' && ok "quick cells equal the checked-in ones (values)" || bad "docs/accuracy/report.json is stale: run scripts/accuracy_report.sh"
import json, sys
old = json.load(open(sys.argv[1])); new = json.load(open(sys.argv[2]))
key = lambda c: (c["preset"], c["liquid"], round(c["wetness"], 6), c["angle_deg"], c["model"])
table = {key(c): c for c in old["cells"]}
if old["settings"]["samples"] != new["settings"]["samples"] or old["settings"]["seed"] != new["settings"]["seed"]:
    sys.exit(print("settings differ", old["settings"], new["settings"]) or 1)
bad = 0
for c in new["cells"]:
    o = table.get(key(c))
    if o is None:
        print("  missing in the checked-in file:", key(c)); bad += 1; continue
    d = max(abs(a - b) for a, b in zip(c["albedo"], o["albedo"]))
    if d > 1e-4:
        print("  stale:", key(c), o["albedo"], "->", c["albedo"]); bad += 1
print(f"  {len(new['cells'])} cells compared, {bad} differ")
sys.exit(1 if bad or not new["cells"] else 0)
PY
python3 - "$checked" <<'PY' && ok "checked-in statistics follow from the checked-in cells" || bad "checked-in statistics do not match the cells"
import json, sys
r = json.load(open(sys.argv[1]))
cells = {}
for c in r["cells"]:
    cells.setdefault((c["preset"], c["liquid"], c["wetness"], c["angle_deg"]), {})[c["model"]] = c["albedo"]
bad = 0
for m in r["models"]:
    errs = []
    for grid in cells.values():
        if "full" in grid and m["name"] in grid:
            f, v = grid["full"], grid[m["name"]]
            errs.append(max(abs(a - b) / max(b, 0.01) for a, b in zip(v, f)))
    mean = sum(errs) / len(errs) if errs else 0
    if len(errs) != m["cells"] or abs(mean - m["mean_rel_error"]) > 5e-4 or (errs and abs(max(errs) - m["worst_rel_error"]) > 5e-4):
        print("  ", m["name"], len(errs), m["cells"], mean, m["mean_rel_error"]); bad += 1
    if m["name"] == "full" and m["worst_rel_error"] != 0:
        print("  full has an error against itself"); bad += 1
sys.exit(1 if bad else 0)
PY
# Independent check of the reference: marble is a Lambert base of the chain's
# albedo under water over the interface area c; dry (w = 0) it is the base
# alone. Its R at normal incidence, wet, is (1 - c) A + c R_LD(A) with the
# Lekner-Dorf film albedo R_LD; A and c come from the dry cell and the chain,
# so here: the dry cell equals A (a Lambert base samples exactly), and the
# wet/dry ratio of the full material lies between R_LD(A)/A (c = 1) and 1.
python3 - "$SOAK_TMP/q.json" <<'PY' && ok "marble: full material between the film-free and Lekner-Dorf bounds" || bad "marble: full material outside the Lekner-Dorf bounds"
import json, math, sys
r = json.load(open(sys.argv[1]))
g = {(c["wetness"], c["angle_deg"]): c for c in r["cells"] if c["preset"] == "marble" and c["model"] == "full"}
def fresnel(n, mu):
    s2 = n * n * (1 - mu * mu)
    if s2 >= 1: return 1.0
    ct = math.sqrt(1 - s2)
    rs = (n * mu - ct) / (n * mu + ct); rp = (mu - n * ct) / (mu + n * ct)
    return 0.5 * (rs * rs + rp * rp)
n, N = 1.333, 20000
ri = sum(2 * fresnel(n, (k + 0.5) / N) * (k + 0.5) / N / N for k in range(N))
r0 = ((n - 1) / (n + 1)) ** 2
ok = True
for ch in range(3):
    A = g[(0, 0)]["albedo"][ch]
    wet = g[(1, 0)]["albedo"][ch]
    ld = r0 + (1 - r0) * A * (1 - ri) / (1 - A * ri)
    se = 4 * g[(1, 0)]["std_error"][ch] + 1e-6
    lo, hi = min(A, ld) - se, max(A, ld) + se
    print(f"  ch {ch}: A {A:.4f} wet {wet:.4f} Lekner-Dorf {ld:.4f}")
    ok &= lo <= wet <= hi and g[(0, 0)]["std_error"][ch] < 1e-9
sys.exit(0 if ok else 1)
PY
finish
