#!/bin/bash
# Benchmark (not a test): the radiance convention's effect on noise inside glass.
# Two `soak` binaries -- OLD (beta multiplied by 1/eta^2 on refraction and Russian
# roulette played on beta alone, before commit "render: one radiance convention")
# and NEW (roulette on beta * eta_scale, pbrt's etaScale) -- render
# c_core/bench/glass_eta_scene.json (a glass sphere, n = 1.5, on a Lambert floor next
# to a wet scattering sphere) with the same spp and seeds 1..N, runs interleaved
# (old, new, old, new, ...), one thread each, CPU time of each process
# (/usr/bin/time %U+%S). Reported: mean per-pixel variance across the N seeds (all
# pixels, and the pixels whose paths meet the glass: where the two differ), the
# difference of the two mean images in standard errors (the expectation must not
# change), CPU seconds (start-up of about 0.24 s included), and the efficiency 1 / (variance x time).
#
# usage: bench_glass_eta.sh OLD_SOAK NEW_SOAK [SPP] [SEEDS]    (defaults 128, 12)
# Build OLD from the commit before the change, e.g.
#   git archive <commit>^ | tar -x -C /tmp/old && cmake -S /tmp/old -B /tmp/old/build \
#     -DCMAKE_BUILD_TYPE=Release && cmake --build /tmp/old/build --target soak_cli
set -eu
HERE="$(cd "$(dirname "$0")" && pwd)"
OLD="${1:?OLD soak binary}"
NEW="${2:?NEW soak binary}"
SPP="${3:-128}"
SEEDS="${4:-12}"
SCENE="$HERE/glass_eta_scene.json"
PY=/usr/bin/python3
command -v oiiotool >/dev/null || { echo "oiiotool not on PATH"; exit 1; }
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
: >"$W/times.tsv"
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
for s in $(seq "$SEEDS"); do
    for v in old new; do
        bin=$OLD
        [ "$v" = new ] && bin=$NEW
        /usr/bin/time -f "%U %S" -o "$W/t" "$bin" render "$SCENE" -o "$W/${v}_$s.exr" --spp "$SPP" --seed "$s" \
            --threads 1 -q
        printf '%s\t%s\n' "$v" "$(awk '{ print $1 + $2 }' "$W/t")" >>"$W/times.tsv"
    done
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
"$PY" - "$W" "$SEEDS" "$SPP" "$load_before" "$load_after" <<'EOF'
import subprocess, sys
import numpy as np
w, n, spp = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])

def read(path):
    out = subprocess.run(["oiiotool", "--dumpdata", path], check=True, capture_output=True, text=True).stdout
    vals = [[float(x) for x in line.split(":", 1)[1].split()[:3]] for line in out.splitlines()
            if line.strip().startswith("Pixel")]
    if not vals:
        raise SystemExit("no pixels read from " + path)
    return np.array(vals)

imgs = {v: np.stack([read(f"{w}/{v}_{s}.exr") for s in range(1, n + 1)]) for v in ("old", "new")}
times = {"old": [], "new": []}
for line in open(f"{w}/times.tsv"):
    v, t = line.split()
    times[v].append(float(t))
var = {v: imgs[v].var(axis=0, ddof=1) for v in imgs}       # per pixel and channel
mean = {v: imgs[v].mean(axis=0) for v in imgs}
# same seeds: a pixel none of whose paths meets the glass is identical in both
glass = (imgs["old"] != imgs["new"]).any(axis=(0, 2))
se = np.sqrt((var["old"] + var["new"]) / n)
z = (mean["old"] - mean["new"]) / np.where(se > 0, se, np.inf)
print(f"# Radiance convention: glass scene noise, old vs new\n")
print(f"`c_core/bench/glass_eta_scene.json`, 64x48, {spp} spp, seeds 1..{n}, 1 thread, runs interleaved; "
      f"load average before / after: {sys.argv[4]} / {sys.argv[5]} (shared machine).\n")
print("| | old (roulette on beta) | new (beta x eta_scale) | new / old |")
print("|---|---|---|---|")
def row(name, a, b, fmt="%.4g"):
    print(f"| {name} | {fmt % a} | {fmt % b} | {b / a:.3f} |")
row("mean pixel variance, all pixels", var["old"].mean(), var["new"].mean())
row(f"mean pixel variance, the {glass.sum()} of {glass.size} pixels whose images differ (paths meet the glass)",
    var["old"][glass].mean(), var["new"][glass].mean())
row("CPU seconds per render (mean)", np.mean(times["old"]), np.mean(times["new"]), "%.3f")
eff_o = 1 / (var["old"].mean() * np.mean(times["old"]))
eff_n = 1 / (var["new"].mean() * np.mean(times["new"]))
row("efficiency 1 / (variance x CPU time), all pixels", eff_o, eff_n)
zg = np.abs(z[glass])
print(f"\nsame expectation? over the differing pixels, |mean old - mean new| / standard error: mean {zg.mean():.3f}, "
      f"share above 3: {(zg > 3).mean():.4f} (for independent estimates of one expectation about 0.8 and 0.003)")
EOF
