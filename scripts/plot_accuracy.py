#!/usr/bin/python3
"""Pareto plots of `soak report`'s values: error against cost per model.

usage: plot_accuracy.py REPORT.json OUT_DIR
Writes OUT_DIR/pareto.png (relative error vs eval time) and
OUT_DIR/pareto_callgrind.png (vs instructions per eval, when the report has
callgrind counts). Needs Debian's python3-matplotlib (scripts/install-deps.sh).
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def pareto(points):
    """Names of the points no other point beats in both cost and error."""
    front = []
    for name, cost, err in points:
        if not any(c <= cost and e <= err and (c, e) != (cost, err) for _, c, e in points):
            front.append((cost, err))
    return sorted(front)


def plot(models, key, label, path):
    pts = [(m["name"], m[key], 100 * m["mean_rel_error"], 100 * m["worst_rel_error"]) for m in models if m[key] > 0]
    if not pts:
        return False
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=110)
    for name, cost, mean, worst in pts:
        ax.plot([cost, cost], [max(mean, 0.05), max(worst, 0.05)], color="0.75", lw=1, zorder=1)
        ax.scatter([cost], [max(mean, 0.05)], s=28, zorder=3, color="C3" if name == "full" else "C0")
        ax.annotate(name, (cost, max(mean, 0.05)), textcoords="offset points", xytext=(5, 4), fontsize=8)
    front = pareto([(n, c, max(m, 0.05)) for n, c, m, _ in pts])
    ax.plot([c for c, _ in front], [e for _, e in front], "--", color="C2", lw=1, label="Pareto front (mean)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(label)
    ax.set_ylabel("relative error of the directional albedo, % (dot: mean, bar: to worst)")
    ax.set_title("Soak models against the full material (soak report)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    tmp = path + ".tmp.png"
    fig.savefig(tmp)
    plt.close(fig)
    os.replace(tmp, path)
    return True


def main():
    if len(sys.argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    with open(sys.argv[1], encoding="utf-8") as f:
        report = json.load(f)
    out = sys.argv[2]
    models = report["models"]
    plot(models, "eval_ns", "cost: ns per RGB eval (soak_bsdf_eval_cost_ns, CPU time)", os.path.join(out, "pareto.png"))
    plot(models, "callgrind_ir_per_eval", "cost: instructions per eval (valgrind callgrind)",
         os.path.join(out, "pareto_callgrind.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
