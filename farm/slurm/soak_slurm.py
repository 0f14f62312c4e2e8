#!/usr/bin/env python3
"""Writes (and optionally submits) a Slurm array job that bakes a soak image
sequence in chunks of frames, plus a job that checks it is complete.

  soak_slurm.py --frames 1-120 --chunk-size 10 --time 0 --frame-time 0.01 \\
      -o /shared/wet/dry.%04d.exr --job-dir /shared/jobs/dry [--soak PATH] \\
      [--cpus-per-task N] [--partition P] [--sbatch-arg ARG ...] [--submit] \\
      -- bake drying splash.png --t-fill 0.2 --noise 0.3 --seed 4

The sequence bakes: drying, turbulence, waves, drops and rain (a mesh wetting
in rain, its running film and drainage over time: `bake rain MESH ...`).

Everything after "--" is the soak command without the options this script
sets itself (--frames, --time, --frame-time, --frame-origin, -o, --threads). It writes
JOB_DIR/bake.sbatch (array task i bakes chunk i: its --frames come from a
table indexed by SLURM_ARRAY_TASK_ID) and JOB_DIR/check.sbatch (lists missing
frames, exit 1 if any; on success writes JOB_DIR/complete). With --submit it
runs sbatch for both, the check with --dependency=afterany on the array, and
prints the two job ids.

Chunks are identical to one soak run over the whole range: every chunk is
one soak run with the job's --time T and --frame-time DT and --frame-origin A
(the first frame of --frames), and soak bakes frame f at T + (f - A) * DT
whatever its own --frames range is. Outputs are staged by soak itself
(temporary file + rename per frame), so a frame on disk is complete.
"""
import argparse
import os
import re
import shlex
import subprocess
import sys

SEQUENCE_BAKES = ("drying", "turbulence", "waves", "drops", "rain")
OWNED = {"--frames", "--time", "--frame-time", "--frame-origin", "-o", "--output", "--threads"}


def fail(msg):
    print(f"soak_slurm: {msg}", file=sys.stderr)
    sys.exit(2)


def parse_frames(text):
    parts = text.split("-")
    try:
        a, b = (int(parts[0]), int(parts[1])) if len(parts) == 2 else (int(text), int(text))
    except ValueError:
        fail(f"--frames: expected A-B, got '{text}'")
    if not (0 <= a <= b <= 9999999):
        fail(f"--frames: expected 0 <= A <= B <= 9999999, got '{text}'")
    return a, b


def check_pattern(path):
    rest = path.replace("%%", "")
    convs = re.findall(r"%0?[0-9]?d", rest)
    if len(convs) != 1 or "%" in re.sub(r"%0?[0-9]?d", "", rest):
        fail(f"-o '{path}': needs one frame number pattern such as wet.%04d.exr")


def main(argv):
    if "--" not in argv:
        fail("give the soak command after '--', e.g. -- bake drying mask.png --noise 0.3")
    split = argv.index("--")
    soak_cmd = argv[split + 1:]
    p = argparse.ArgumentParser(prog="soak_slurm.py", description=__doc__.split("\n\n")[0])
    p.add_argument("--frames", required=True)
    p.add_argument("--chunk-size", type=int, default=10)
    p.add_argument("--time", type=float, required=True)
    p.add_argument("--frame-time", type=float, required=True)
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--job-dir", required=True)
    p.add_argument("--soak", default="soak")
    p.add_argument("--cpus-per-task", type=int, default=1)
    p.add_argument("--partition")
    p.add_argument("--job-name", default="soak-bake")
    p.add_argument("--sbatch-arg", action="append", default=[])
    p.add_argument("--submit", action="store_true")
    o = p.parse_args(argv[:split])

    if len(soak_cmd) < 2 or soak_cmd[0] != "bake" or soak_cmd[1] not in SEQUENCE_BAKES:
        fail("the soak command must be 'bake drying|turbulence|waves|drops|rain ...' (rain with its MESH: "
             "the rain over time as frames)")
    if soak_cmd[1] == "rain" and (len(soak_cmd) < 3 or soak_cmd[2].startswith("-")):
        fail("'bake rain' needs its MESH right after 'rain'")
    for a in soak_cmd:
        if a.split("=")[0] in OWNED:
            fail(f"'{a}' after '--' is set by this script; use its own option")
    first, last = parse_frames(o.frames)
    if not (1 <= o.chunk_size <= 100000):
        fail(f"--chunk-size: expected 1..100000, got {o.chunk_size}")
    if not (1 <= o.cpus_per_task <= 1024):
        fail(f"--cpus-per-task: expected 1..1024, got {o.cpus_per_task}")
    if not (-1e9 <= o.time <= 1e9) or not (0 <= o.frame_time <= 1e6):
        fail("--time must be in [-1e9, 1e9] and --frame-time in [0, 1e6]")
    check_pattern(o.output)
    out_dir = os.path.dirname(os.path.abspath(o.output))
    job_dir = os.path.abspath(o.job_dir)
    os.makedirs(os.path.join(job_dir, "logs"), exist_ok=True)

    chunks = [(a, min(a + o.chunk_size - 1, last)) for a in range(first, last + 1, o.chunk_size)]
    q = shlex.quote
    header = ["#!/bin/bash", f"#SBATCH --job-name={o.job_name}", f"#SBATCH --cpus-per-task={o.cpus_per_task}"]
    if o.partition:
        header.append(f"#SBATCH --partition={o.partition}")
    header += [f"#SBATCH {a}" for a in o.sbatch_arg]

    lines = header + [f"#SBATCH --array=0-{len(chunks) - 1}",
                      f"#SBATCH --output={job_dir}/logs/bake_%A_%a.log",
                      "# Written by farm/slurm/soak_slurm.py: chunk i of the frames is array task i.",
                      "set -euo pipefail",
                      f"mkdir -p {q(out_dir)}",
                      'case "${SLURM_ARRAY_TASK_ID:?not an array task}" in']
    for i, (a, b) in enumerate(chunks):
        args = [o.soak] + soak_cmd + ["--threads", str(o.cpus_per_task), "--frames", f"{a}-{b}",
                                      "--time", repr(o.time), "--frame-time", repr(o.frame_time),
                                      "--frame-origin", str(first), "-o", o.output]
        lines.append(f"  {i}) {' '.join(q(x) for x in args)} ;;")
    lines += ['  *) echo "soak_slurm: no chunk $SLURM_ARRAY_TASK_ID" >&2; exit 2 ;;', "esac", ""]
    bake = os.path.join(job_dir, "bake.sbatch")

    check = header + [f"#SBATCH --output={job_dir}/logs/check_%j.log",
                      "# Written by farm/slurm/soak_slurm.py: every frame of the bake exists.",
                      "set -uo pipefail",
                      f"pattern={q(o.output)}",
                      "missing=()",
                      f"for f in $(seq {first} {last}); do",
                      '  file=$(printf "$pattern" "$f")',
                      '  [ -s "$file" ] || missing+=("$f")',
                      "done",
                      'if [ ${#missing[@]} -gt 0 ]; then',
                      '  echo "soak_slurm: ${#missing[@]} frame(s) missing: ${missing[*]}" >&2',
                      "  exit 1",
                      "fi",
                      f"echo {first}-{last} > {q(os.path.join(job_dir, 'complete'))}.tmp",
                      f"mv {q(os.path.join(job_dir, 'complete'))}.tmp {q(os.path.join(job_dir, 'complete'))}",
                      f'echo "soak_slurm: frames {first}-{last} complete"', ""]
    check_path = os.path.join(job_dir, "check.sbatch")
    for path, text in ((bake, lines), (check_path, check)):
        tmp = path + ".tmp"
        with open(tmp, "w") as f:
            f.write("\n".join(text))
        os.chmod(tmp, 0o755)
        os.replace(tmp, path)
    print(f"soak_slurm: {len(chunks)} array tasks in {bake}, completeness check in {check_path}")
    if not o.submit:
        return 0
    r = subprocess.run(["sbatch", "--parsable", bake], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"sbatch {bake}: {r.stderr.strip()}")
    array_id = r.stdout.strip().split(";")[0]
    r = subprocess.run(["sbatch", "--parsable", f"--dependency=afterany:{array_id}", check_path],
                       capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"sbatch {check_path}: {r.stderr.strip()}")
    print(f"{array_id} {r.stdout.strip().split(';')[0]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
