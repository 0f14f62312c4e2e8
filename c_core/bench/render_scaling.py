"""Benchmark helper (not a test; run with a Python that has numpy, e.g. /usr/bin/python3):
scaling of `soak render` on one scene, in CPU time (the machine may be shared: wall time
is not used for anything reported as a ratio).

  render_scaling.py SOAK SCENE.json [SPP]

Prints, for the scene at its own size and at twice its width and height (4x the pixels),
at SPP samples (default 8): user+system CPU seconds of the render less that of a 1-spp
render of the same size (start-up, scene and mesh load), the ratio 4x / 1x (the goal of
issue 38: <= 4.2), and paths per CPU second with 1 and with 2 threads (with 2 threads the
CPU time of both is counted, so equal numbers mean perfect scaling), plus soak's own
wall-clock paths/s for reference.
"""
import json
import os
import re
import resource
import subprocess
import sys
import tempfile

PATHS = re.compile(r"^paths: (\d+) \((\d+) paths/s\)", re.M)


def cpu_render(soak, scene, spp, threads, width, height, out):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run([soak, "render", scene, "-o", out, "--spp", str(spp), "--threads", str(threads),
                        "--width", str(width), "--height", str(height), "--seed", "3"],
                       check=True, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    m = PATHS.search(r.stdout)
    return cpu, (int(m.group(1)), int(m.group(2))) if m else (0, 0)


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    soak, scene = sys.argv[1], sys.argv[2]
    spp = int(sys.argv[3]) if len(sys.argv) > 3 else 8
    sc = json.load(open(scene))
    w, h = int(sc["render"]["width"]), int(sc["render"]["height"])
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "o.exr")
        cost = {}
        for f in (1, 2):
            base = min(cpu_render(soak, scene, 1, 1, w * f, h * f, out)[0] for _ in range(2))
            full = min(cpu_render(soak, scene, spp, 1, w * f, h * f, out)[0] for _ in range(2))
            cost[f] = full - base
        rate = {}
        for threads in (1, 2):
            cpu, (paths, wall_rate) = cpu_render(soak, scene, spp, threads, w, h, out)
            rate[threads] = (paths / cpu, wall_rate)  # start-up included in both
    print("%s: %dx%d vs %dx%d at %d spp: CPU %.2f s vs %.2f s, ratio %.3f (goal <= 4.2); "
          "paths per CPU second 1 thread %.0f, 2 threads %.0f (soak's wall paths/s %d, %d)"
          % (os.path.basename(scene), w, h, 2 * w, 2 * h, spp, cost[1], cost[2], cost[2] / cost[1],
             rate[1][0], rate[2][0], rate[1][1], rate[2][1]))


if __name__ == "__main__":
    main()
