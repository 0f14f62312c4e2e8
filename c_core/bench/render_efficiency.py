"""Benchmark helper (not a test; run with a Python that has numpy, e.g. /usr/bin/python3):
time to a relative RMSE for one `soak render` build on one scene, without a reference
image or Blender, from the variance between renders of independent seeds and the CPU
time per sample. Used to compare two builds (old / new, interleaved by the caller) before
the Blender benchmark; c_core/bench/results/2026-11-28-render-vs-cycles.md used it.

  render_efficiency.py SOAK SCENE.json SPP SEED SEED [SEED ...] [--target 0.02]

Each seed renders SCENE at SPP with one thread. V = the per-pixel variance across the
seeds x SPP (the variance of one sample), averaged over pixels and RGB, relative to the
squared image mean; spp to target = V / target^2 (Monte Carlo error falls as 1/spp); CPU
per spp = (user CPU time of an SPP render - that of a 1-spp render, which carries
start-up, scene and mesh load) / (SPP - 1); time to target = the product. The estimate
of V needs several seeds (8 x 64 spp gave about 1 % between seed sets on
scenes/bench_wet_sphere.json once its fireflies were gone). For the benchmark's mesh
scene keep the script's renders (BENCH_KEEP=1 bench_render_vs_cycles.sh) and use its
scene_mesh.json beside uvsphere.obj.
"""
import os
import re
import resource
import subprocess
import sys
import tempfile

import numpy as np

PIXEL = re.compile(r"^\s*Pixel \((\d+), (\d+)\):\s*(.*)$")


def read_rgb(path):
    text = subprocess.run(["oiiotool", "--dumpdata", path], check=True, capture_output=True, text=True).stdout
    vals = [[float(v) for v in m.group(3).split()[:3]] for m in (PIXEL.match(l) for l in text.splitlines()) if m]
    if not vals:
        raise SystemExit("render_efficiency.py: no pixels read from " + path)
    return np.asarray(vals, dtype=np.float64)


def render(soak, scene, spp, seed, out):
    """Renders with one thread; returns the user CPU seconds of the soak process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    subprocess.run([soak, "render", scene, "-o", out, "--spp", str(spp), "--seed", str(seed), "--threads", "1", "-q"],
                   check=True)
    return resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before


def main():
    args = sys.argv[1:]
    target = 0.02
    if "--target" in args:
        i = args.index("--target")
        target = float(args[i + 1])
        del args[i:i + 2]
    if len(args) < 5:
        raise SystemExit(__doc__)
    soak, scene, spp, seeds = args[0], args[1], int(args[2]), [int(s) for s in args[3:]]
    if spp < 2:
        raise SystemExit("render_efficiency.py: SPP must be at least 2")
    with tempfile.TemporaryDirectory() as tmp:
        overhead = min(render(soak, scene, 1, 99, os.path.join(tmp, "one.exr")) for _ in range(2))
        images, cpu = [], []
        for s in seeds:
            out = os.path.join(tmp, "s%d.exr" % s)
            cpu.append(render(soak, scene, spp, s, out))
            images.append(read_rgb(out))
    images = np.array(images)
    mean = images.mean()
    v_rel = images.var(axis=0, ddof=1).mean() * spp / mean ** 2
    per_spp = (float(np.median(cpu)) - overhead) / (spp - 1)
    spp_needed = v_rel / target ** 2
    print("%s: %d seeds x %d spp, mean %.5f, relative variance per sample %.4f, spp to %.3g %% %.1f, "
          "CPU %.2f ms/spp, time to target %.3f s"
          % (soak, len(seeds), spp, mean, v_rel, 100 * target, spp_needed, 1e3 * per_spp, spp_needed * per_spp))


if __name__ == "__main__":
    main()
