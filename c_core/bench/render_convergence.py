"""Analysis helper of bench_render_vs_cycles.sh (run with a Python that has numpy,
e.g. /usr/bin/python3): RMSE of each render against its own renderer's converged
reference, the time each renderer needs to reach a common relative target RMSE, and
the ratio soak / Cycles. Prints a Markdown report and optionally writes it to a file.

  render_convergence.py RUNS.tsv TARGET_FRACTION [OUT.md] < extra markdown lines

RUNS.tsv lines: renderer  kind(ref|run)  spp  seconds  image  (tab separated); one
`ref` line per renderer. Images are read through `oiiotool --dumpdata` (RGB channels;
alpha ignored). The target is TARGET_FRACTION x the mean pixel value of each
renderer's reference (relative RMSE), so that both are held to the same relative
accuracy although their materials differ.

Time to target: the spp needed is interpolated linearly in log(spp)-log(RMSE) between
the two runs that bracket the target (past the last run: extrapolated with the slope
of the last two runs, and marked so); the time is then read from a least-squares
line seconds = a + b spp through all runs, so that one run slowed down by other jobs
on a shared machine does not decide the result. The time interpolated directly
between the two bracketing runs' measured times is printed as a check.

Reference noise: a reference of N spp has its own error, and the measured
MSE(n) = MSE_true(n) + MSE_ref. For Monte Carlo with independent seeds both scale as
V/n, so MSE_true(n) = MSE_measured(n) N / (N + n); the report shows the corrected
relative RMSE and uses it for the time to target (the raw-based times and ratio are
printed too). For Cycles' quasi-Monte Carlo sampler, whose error can fall faster
than 1/n, the correction overestimates the reference's error: it favours Cycles.
"""
import math
import os
import re
import subprocess
import sys

import numpy as np

PIXEL = re.compile(r"^\s*Pixel \((\d+), (\d+)\):\s*(.*)$")


def read_rgb(path):
    text = subprocess.run(["oiiotool", "--dumpdata", path], check=True, capture_output=True, text=True).stdout
    rows = [PIXEL.match(line) for line in text.splitlines()]
    vals = [[float(v) for v in m.group(3).split()[:3]] for m in rows if m]
    if not vals:
        raise SystemExit("render_convergence.py: no pixels read from " + path)
    return np.asarray(vals, dtype=np.float64)


def interp_to_target(runs, target):
    """runs: [(x, rmse)] sorted by spp; log-log interpolation of x at rmse = target.
    Returns (x, how)."""
    for (x0, e0), (x1, e1) in zip(runs, runs[1:]):
        if e0 >= target >= e1 and e0 > e1:
            s = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(x0) + s * (math.log(x1) - math.log(x0))), "interpolated"
    if runs[0][1] <= target:
        return runs[0][0], "reached by the first run (upper bound)"
    (x0, e0), (x1, e1) = runs[-2], runs[-1]
    slope = (math.log(e1) - math.log(e0)) / (math.log(x1) - math.log(x0))
    if not slope < 0:
        return float("nan"), "not reached"
    return math.exp(math.log(x1) + (math.log(target) - math.log(e1)) / slope), "extrapolated"


def main():
    runs_path, frac = sys.argv[1], float(sys.argv[2])
    out_path = sys.argv[3] if len(sys.argv) > 3 else None
    data = {}
    for line in open(runs_path):
        if not line.strip():
            continue
        name, kind, spp, secs, img = line.rstrip("\n").split("\t")
        data.setdefault(name, {"ref": None, "runs": []})
        if kind == "ref":
            data[name]["ref"] = (int(spp), float(secs), img)
        else:
            data[name]["runs"].append((int(spp), float(secs), img))
    names = list(data)
    res = {}
    for name in names:
        ref_spp, ref_secs, ref_img = data[name]["ref"]
        ref = read_rgb(ref_img)
        mean = float(ref.mean())
        rows = []
        for spp, secs, img in sorted(data[name]["runs"]):
            im = read_rgb(img)
            if im.shape != ref.shape:
                raise SystemExit("render_convergence.py: %s and %s differ in size" % (img, ref_img))
            mse = float(np.mean((im - ref) ** 2))
            rows.append((spp, secs, math.sqrt(mse), math.sqrt(mse * ref_spp / (ref_spp + spp))))
        target = frac * mean
        b, a = np.polyfit([r[0] for r in rows], [r[1] for r in rows], 1)
        r = dict(ref_spp=ref_spp, ref_secs=ref_secs, mean=mean, rows=rows, target=target, a=a, b=b)
        for key, col in (("", 3), ("_raw", 2)):
            spp_needed, how = interp_to_target([(x[0], x[col]) for x in rows], target)
            r["spp" + key], r["how" + key], r["t" + key] = spp_needed, how, a + b * spp_needed
        r["t_direct"], _ = interp_to_target([(x[1], x[3]) for x in rows], target)
        res[name] = r

    lines = []
    extra = sys.stdin.read().strip() if not sys.stdin.isatty() else ""
    if extra:
        lines += [extra, ""]
    hdr = "| spp | " + " | ".join("%s time (s) | %s RMSE | %s RMSE corr. / mean" % (n, n, n) for n in names) + " |"
    lines += [hdr, "|" + "---:|" * (1 + 3 * len(names))]
    spps = sorted({r[0] for n in names for r in res[n]["rows"]})
    for spp in spps:
        cells = []
        for n in names:
            row = [r for r in res[n]["rows"] if r[0] == spp]
            if row:
                _, secs, e, ec = row[0]
                cells.append("%.2f | %.5f | %.2f %%" % (secs, e, 100 * ec / res[n]["mean"]))
            else:
                cells.append(" | | ")
        lines.append("| %d | %s |" % (spp, " | ".join(cells)))
    lines.append("")
    for n in names:
        r = res[n]
        lines.append("- %s: reference %d spp in %.1f s, mean pixel value %.4f; time fit %.3f s + %.2f ms x spp; "
                     "target RMSE %.5f (%.1f %% of the mean) needs %.0f spp (%s) = **%.2f s** "
                     "(measured times interpolated directly: %.2f s; from the raw RMSE: %.0f spp, %.2f s)"
                     % (n, r["ref_spp"], r["ref_secs"], r["mean"], r["a"], 1e3 * r["b"], r["target"], 100 * frac,
                        r["spp"], r["how"], r["t"], r["t_direct"], r["spp_raw"], r["t_raw"]))
    if len(names) == 2:
        a, b = names
        ra, rb = res[a], res[b]
        lines.append("- **time-to-target ratio %s / %s: %.2f** = %.2f (spp needed) x %.2f (time per spp)"
                     % (a, b, ra["t"] / rb["t"], ra["spp"] / rb["spp"], (ra["t"] / ra["spp"]) / (rb["t"] / rb["spp"])))
        lines.append("- same ratio with the directly interpolated times: %.2f; with the raw RMSE: %.2f"
                     % (ra["t_direct"] / rb["t_direct"], ra["t_raw"] / rb["t_raw"]))
    report = "\n".join(lines) + "\n"
    sys.stdout.write(report)
    if out_path:
        with open(out_path + ".tmp", "w") as f:
            f.write(report)
        os.replace(out_path + ".tmp", out_path)


main()
