"""Helper of bench_render_vs_cycles.sh (run with /usr/bin/python3): from every timed
render of the benchmark (OUTDIR/times.tsv: renderer, kind ref|run, spp, wall s, CPU s,
image; tab separated; several rounds per spp) writes one runs file per statistic for
render_convergence.py: OUTDIR/runs_{cpu,wall}_{min,median}.tsv, each with the
renderer's one reference and, per spp, the minimum or the median over the rounds.

  render_times.py OUTDIR "SPP SPP ..."
"""
import statistics
import sys


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    outdir, spps = sys.argv[1], [int(x) for x in sys.argv[2].split()]
    rows = [line.rstrip("\n").split("\t") for line in open(outdir + "/times.tsv") if line.strip()]
    for col, clock in ((4, "cpu"), (3, "wall")):
        for stat, fn in (("min", min), ("median", statistics.median)):
            lines = []
            for name in ("soak", "Cycles"):
                ref = [r for r in rows if r[0] == name and r[1] == "ref"]
                if len(ref) != 1:
                    raise SystemExit("render_times.py: %s has %d reference renders" % (name, len(ref)))
                lines.append("%s\tref\t%s\t%s\t%s\n" % (name, ref[0][2], ref[0][col], ref[0][5]))
                for spp in spps:
                    runs = [r for r in rows if r[0] == name and r[1] == "run" and int(r[2]) == spp]
                    if not runs or any(not r[col] for r in runs):
                        raise SystemExit("render_times.py: %s has no %s time for %d spp" % (name, clock, spp))
                    lines.append("%s\trun\t%d\t%.4f\t%s\n" % (name, spp, fn([float(r[col]) for r in runs]), runs[0][5]))
            with open("%s/runs_%s_%s.tsv" % (outdir, clock, stat), "w") as f:
                f.writelines(lines)


if __name__ == "__main__":
    main()
