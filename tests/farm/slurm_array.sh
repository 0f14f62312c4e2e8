#!/bin/bash
# A one-node Slurm cluster on this machine (munged, slurmctld, slurmd started
# here as daemons by this script, as root, no systemd; NodeName=localhost,
# configuration, key, sockets, state and logs in a temporary folder, free
# ports), farm/slurm/soak_slurm.py's array job and completeness check
# submitted to it; the chunked frames must equal one soak run's pixel for
# pixel (oiiotool --dumpdata, compared as text: no tolerance), the check must
# pass, and fail naming the frame when one is deleted. Everything started is
# stopped on exit, failure included. Missing Slurm or munge is a failure:
# scripts/install-deps.sh installs them.
# Usage: slurm_array.sh SOAK_BINARY REPO_ROOT TMP_DIR
set -u
soak=$1 root=$2 tmp=$3
fail() { echo "FAIL: $*"; exit 1; }
[ "$(id -u)" = 0 ] || fail "needs root (daemons, as CI runs)"
for t in munged slurmctld slurmd sbatch squeue scontrol oiiotool /usr/bin/python3; do
  command -v "$t" >/dev/null || fail "$t not found (scripts/install-deps.sh installs slurm-wlm, munge)"
done
start=$(date +%s%N)
elapsed() { echo "$(( ($(date +%s%N) - start) / 1000000 )) ms"; }

rm -rf "$tmp" && mkdir -p "$tmp"/{munge,state,spool,log,job} || fail "cannot make $tmp"
tmp=$(cd "$tmp" && pwd)
pids=()
cleanup() {
  local p f
  for f in "$tmp/slurmd.pid" "$tmp/slurmctld.pid" "$tmp/munge/pid"; do
    [ -s "$f" ] && pids+=("$(cat "$f")")
  done
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  for p in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$p" 2>/dev/null
  done
  return 0
}
trap cleanup EXIT
trap 'exit 1' INT TERM

# munge: own key (mode 400), socket, log, pid and seed files.
chmod 755 "$tmp/munge"
head -c 1024 /dev/urandom > "$tmp/munge/munge.key" && chmod 400 "$tmp/munge/munge.key"
munged -f -S "$tmp/munge/sock" --key-file="$tmp/munge/munge.key" --log-file="$tmp/munge/log" \
  --pid-file="$tmp/munge/pid" --seed-file="$tmp/munge/seed" || fail "munged did not start: $(tail -3 "$tmp/munge/log")"

read -r ctl_port d_port < <(/usr/bin/python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')
mem=$(awk '/MemTotal/ {print int($2 / 1024 / 2)}' /proc/meminfo)
cat > "$tmp/slurm.conf" <<EOF
ClusterName=soakfarmtest
SlurmctldHost=localhost
SlurmctldPort=$ctl_port
SlurmdPort=$d_port
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge/sock
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
SchedulerParameters=sched_interval=1
MinJobAge=600
NodeName=localhost CPUs=2 RealMemory=$mem State=UNKNOWN
PartitionName=soaktest Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$tmp/slurm.conf
slurmctld -i -f "$SLURM_CONF" || fail "slurmctld did not start: $(tail -5 "$tmp/log/slurmctld.log")"
slurmd -f "$SLURM_CONF" -N localhost || fail "slurmd did not start: $(tail -5 "$tmp/log/slurmd.log")"
for _ in $(seq 100); do
  [ "$(sinfo -h -o %T 2>/dev/null)" = idle ] && break
  sleep 0.2
done
[ "$(sinfo -h -o %T 2>/dev/null)" = idle ] || fail "node not idle: $(sinfo 2>&1); $(tail -5 "$tmp/log/slurmctld.log")"
echo "cluster up ($(elapsed))"

# Frames 1-12 in chunks of 3 at time (f - 1) * 0.03 of a mask whose texel k
# (1..10) is k texels from the dry one: with --t-fill 1e-20 (a step) texel 3
# is wet at 0.3, frame 11's time, and dry one ulp later, where a chunk 10-12
# started at its own time 0.27 would put frame 11 (tests/cli/bake.sh). Every
# chunk is one soak run with the job's --time and --frame-origin 1.
mask=$tmp/step_mask.pgm
printf 'P2\n11 1\n1\n0 1 1 1 1 1 1 1 1 1 1\n' > "$mask"
bake=(bake drying "$mask" --seed 3 --t-fill 1e-20)
out=$tmp/chunked/wet.%04d.exr
ids=$(/usr/bin/python3 "$root/farm/slurm/soak_slurm.py" --frames 1-12 --chunk-size 3 --time 0 --frame-time 0.03 \
  -o "$out" --job-dir "$tmp/job" --soak "$soak" --submit -- "${bake[@]}" | tail -1) || fail "soak_slurm.py failed"
read -r array_id check_id <<<"$ids"
[ -n "${check_id:-}" ] || fail "no job ids from soak_slurm.py: $ids"
chunk3=$(grep "^  3) " "$tmp/job/bake.sbatch") || fail "bake.sbatch has no chunk 3"
[ "$(grep -c -- '--frames' <<<"$chunk3")" = 1 ] && grep -q -- "--frames 10-12 --time 0.0 --frame-time 0.03 --frame-origin 1 " <<<"$chunk3" ||
  fail "chunk 3 should be one soak run of frames 10-12 with the job's time and origin: $chunk3"

for _ in $(seq 600); do
  [ -z "$(squeue -h -j "$array_id,$check_id" 2>/dev/null)" ] && break
  sleep 0.2
done
state() { scontrol show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | sort -u | tr '\n' ' '; }
echo "array $array_id: $(state "$array_id"); check $check_id: $(state "$check_id")"
[ "$(state "$array_id")" = "JobState=COMPLETED " ] || fail "array job not completed: $(cat "$tmp"/job/logs/bake_* 2>/dev/null | tail -20)"
[ "$(state "$check_id")" = "JobState=COMPLETED " ] || fail "check job not completed: $(cat "$tmp"/job/logs/check_* 2>/dev/null)"
[ "$(cat "$tmp/job/complete")" = 1-12 ] || fail "check job did not mark the bake complete"
echo "jobs done ($(elapsed))"

single=$tmp/single/wet.%04d.exr
mkdir -p "$tmp/single"
"$soak" "${bake[@]}" --frames 1-12 --time 0 --frame-time 0.03 -o "$single" 2>/dev/null || fail "single soak run failed"
files=()
for f in $(seq 12); do files+=("$(printf "$out" $f)" "$(printf "$single" $f)"); done
oiiotool --dumpdata "${files[@]}" > "$tmp/dump.txt" || fail "oiiotool --dumpdata failed"
# One block per file: its pixel lines, compared between chunked and single.
awk -v n=24 '
  / : +[0-9]+ x +[0-9]+, / { k++; next }
  /^ +Pixel / { px[k] = px[k] $0 "\n"; count[k]++; if ($2 == "(3,") t3[k] = $NF }
  END {
    bad = 0
    for (i = 1; i <= n; i += 2) {
      if (count[i] != 11 || px[i] != px[i + 1]) { print "frame " (i + 1) / 2 " differs"; bad = 1 }
    }
    # single run (even blocks): texel 3 wet at frame 11, dry at frame 12
    if (t3[22] != 1 || t3[24] != 0) { print "texel 3: " t3[22] " at frame 11, " t3[24] " at 12 (want 1, 0)"; bad = 1 }
    exit bad
  }' "$tmp/dump.txt" || fail "chunked frames differ from the single run"
echo "12 chunked frames equal the single run's, pixel for pixel"

# The completeness check names a missing frame (run as the batch script, no queue).
rm "$(printf "$out" 5)"
msg=$(SLURM_JOB_ID=0 bash "$tmp/job/check.sbatch" 2>&1) && fail "check passed with frame 5 missing"
echo "$msg" | grep -q "missing: 5$" || fail "check did not name frame 5: $msg"
echo "check refuses an incomplete bake: $msg"
echo "PASS ($(elapsed))"
