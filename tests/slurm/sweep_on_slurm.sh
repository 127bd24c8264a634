#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `sinew sweep` on Slurm, on this machine: starts a one-node cluster of its
# own (munged with a key made here, slurmctld and slurmd from Debian's
# slurm-wlm, a minimal slurm.conf, every state, spool and log folder in a
# temporary folder), runs a sweep through `sbatch --array`, gathers it, and
# checks that every file is the same as the local sweep's, byte for byte,
# but for the timing: the "timing" member of each run's summary and the
# last two columns of summary.csv (wall_time_s, real_time_factor). The
# daemons are stopped whatever happens (trap).
#
# Before that, and whatever the daemons do, the emitted script is checked
# with `bash -n` and each of its array tasks is run by hand with
# SLURM_ARRAY_TASK_ID set, which must give the same files too.
#
#   tests/slurm/sweep_on_slurm.sh SINEW_PROGRAM
#
# Exit status 0 passed, 1 failed, 77 skipped (ctest's SKIP_RETURN_CODE):
# only when Slurm's programs are missing or its daemons cannot start here,
# with the reason on stdout.
set -euo pipefail

sinew=${1:?usage: sweep_on_slurm.sh SINEW_PROGRAM}
work=$(mktemp -d /tmp/sinew-slurm-XXXXXX)
pids=()
cleanup()
{
    for pid in "${pids[@]}"; do
        kill "$pid" 2>/dev/null || true
    done
    for pid in "${pids[@]}"; do
        wait "$pid" 2>/dev/null || true
    done
    rm -rf "$work"
}
trap cleanup EXIT

fail()
{
    echo "FAIL: $*" >&2
    exit 1
}

# Whether the folders $1 and $2 hold the same files with the same bytes,
# but for the timing; files only $2 has are named in $3 (a pattern).
same_results()
{
    local a=$1 b=$2 extra=$3
    diff <(ls "$a") <(ls "$b" | grep -Ev "$extra") || fail "$a and $b hold different files"
    local name
    for name in $(ls "$a"); do
        case "$name" in
        summary.csv)
            cmp -s <(sed -E 's/,[^,]*,[^,]*$//' "$a/$name") <(sed -E 's/,[^,]*,[^,]*$//' "$b/$name") ||
                fail "$a/$name and $b/$name differ before the timing columns"
            ;;
        *.summary.json)
            cmp -s <(sed '/"timing"/,$d' "$a/$name") <(sed '/"timing"/,$d' "$b/$name") ||
                fail "$a/$name and $b/$name differ before their timing"
            ;;
        *)
            cmp -s "$a/$name" "$b/$name" || fail "$a/$name and $b/$name differ"
            ;;
        esac
    done
}

cd "$work"
cat > arm_sweep.json <<'JSON'
{
  "model": "arm",
  "set": {"duration": 0.5},
  "grid": {"weight": [0, 5], "activation.Biceps Long": [0, 0.5, 1]}
}
JSON
"$sinew" sweep arm_sweep.json --out local > local.log || fail "the local sweep failed: $(cat local.log)"
[ "$(ls local/*.summary.json | wc -l)" = 6 ] || fail "the local sweep did not write 6 summaries"

# The emitted script: 6 runs, 4 a task, so 2 tasks, the second with 2 runs.
# The folder Slurm runs in has a space in its name, which the script's
# #SBATCH lines must quote for sbatch.
for out in by_hand "by slurm"; do
    "$sinew" sweep arm_sweep.json --out "$out" --emit slurm --chunk 4 > "$out.log" ||
        fail "--emit slurm failed: $(cat "$out.log")"
    bash -n "$out/sweep.sbatch" || fail "$out/sweep.sbatch is not valid bash"
    grep -q '^#SBATCH --array=0-1$' "$out/sweep.sbatch" || fail "$out/sweep.sbatch is not an array of 2 tasks"
done
for task in 0 1; do
    SLURM_ARRAY_TASK_ID=$task bash by_hand/sweep.sbatch || fail "array task $task, run by hand, failed"
done
"$sinew" sweep arm_sweep.json --out by_hand --gather > gather.log || fail "gathering failed: $(cat gather.log)"
same_results local by_hand '^(jobs.txt|sweep.sbatch)$'
echo "the array tasks run by hand wrote the local sweep's files"

# ---- The cluster: one node, this machine. ----------------------------------
for program in munged slurmctld slurmd sbatch sinfo timeout; do
    if ! command -v "$program" > /dev/null; then
        echo "SKIP: $program is not installed (tools/setup.sh installs munge and slurm-wlm)"
        exit 77
    fi
done
mkdir -p munge state spool log
# munged wants its socket's folders open to everyone (they are to be
# reached by every user's jobs) and its key readable by its owner alone.
chmod 755 "$work" munge
head -c 1024 /dev/urandom > munge/munge.key
chmod 400 munge/munge.key
# Each daemon under `timeout`, so that none outlives the test even when
# ctest kills it (no trap runs then); `timeout` passes on the trap's TERM.
life=240
timeout "$life" munged --foreground --key-file="$work/munge/munge.key" --socket="$work/munge/socket" \
    --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" --seed-file="$work/munge/seed" \
    > munge/stdout.log 2>&1 &
pids+=($!)
for _ in $(seq 1 20); do
    [ -S munge/socket ] && break
    sleep 0.25
done
if ! [ -S munge/socket ]; then
    echo "SKIP: munged did not start here:"
    tail -n 5 munge/stdout.log munge/munged.log 2> /dev/null || true
    exit 77
fi
# Two ports of this run's own, so that runs side by side do not meet.
port=$((20000 + ($$ % 5000) * 2))
cat > slurm.conf <<CONF
ClusterName=sinewtest
SlurmctldHost=localhost
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge/socket
SlurmctldPort=$port
SlurmdPort=$((port + 1))
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/state/slurmctld.pid
SlurmdPidFile=$work/spool/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=localhost CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
sleep 0.5
timeout "$life" slurmctld -D -f "$SLURM_CONF" > log/slurmctld.stdout 2>&1 &
pids+=($!)
timeout "$life" slurmd -D -f "$SLURM_CONF" > log/slurmd.stdout 2>&1 &
pids+=($!)
ready=no
for _ in $(seq 1 40); do
    if timeout 3 sinfo --noheader --format=%t 2> /dev/null | grep -Eq '^idle'; then
        ready=yes
        break
    fi
    sleep 0.5
done
if [ "$ready" != yes ]; then
    echo "SKIP: the Slurm daemons did not start here; their last words:"
    tail -n 5 munge/munged.log log/*.log log/*.stdout 2> /dev/null || true
    exit 77
fi
echo "slurm: $(sinfo --noheader --format='%P %t %N %c CPUs')"

# Polled every 0.2 s: `sbatch --wait` polls ever more slowly (10 s for
# this job that takes well under one).
job=$(sbatch --parsable "by slurm/sweep.sbatch") || fail "sbatch refused the script"
for _ in $(seq 1 1000); do
    states=$(scontrol show job "$job" 2> /dev/null | grep -o 'JobState=[A-Z_]*' | sort -u | tr '\n' ' ')
    [ -n "$states" ] && ! grep -Eq 'PENDING|RUNNING|CONFIGURING|COMPLETING' <<< "$states" && break
    sleep 0.2
done
[ "$states" = "JobState=COMPLETED " ] || fail "the array job ended $states: $(cat "by slurm"/slurm-*.out 2> /dev/null)"
"$sinew" sweep arm_sweep.json --out "by slurm" --gather > gather.log || fail "gathering failed: $(cat gather.log)"
same_results local "by slurm" '^(jobs.txt|sweep.sbatch|slurm-.*\.out)$'
echo "the sweep run by Slurm (2 array tasks) wrote the local sweep's files"
