#!/bin/bash
# slurm_array_test.sh BRDFNAV SCRIPTS PROFILE REFERENCE_DB
#
# The Slurm scripts users run (SCRIPTS = hosts/slurm: submit.sh, precompute_array.sbatch,
# merge.sbatch), unchanged, against a real single-node Slurm that this test starts: munged,
# slurmctld and slurmd from Debian's munge and slurm-wlm, configured for one node on 127.0.0.1
# in a temporary directory, stopped by their process ids whatever happens (docs/SLURM.md).
#
#   1. 3 shards of PROFILE and the dependent merge: the database is byte-identical to
#      REFERENCE_DB, the single-machine build of the same settings (CTest's test_database).
#   2. Again, from run 1's finished shard 0 (copied: submit.sh keeps it and submits shards 1
#      and 2), with array task 1 killed in the middle of its work (scancel --signal=KILL) and
#      requeued (scontrol requeue) while task 2 runs: the task resumes from its finished images,
#      which it keeps as they were, and the database is still identical.
#   3. Again from shards 0 and 2, with task 1 killed and not requeued: the merge fails, naming
#      shard 1; submit.sh run again submits shard 1 alone, which resumes, and the database is
#      still identical.
#
# Exit 77 (CTest's SKIP_RETURN_CODE) with the reason when it cannot run here: not root, Slurm or
# munge not installed, or the daemons do not start. BRDFNAV_REQUIRE_SLURM=1 makes that a
# failure. A failed run keeps its directory (/tmp/brdfnav-slurm.*: logs, shards) and says so;
# BRDFNAV_SLURM_TEST_KEEP=1 keeps it always.
set -euo pipefail
export PATH=$PATH:/usr/sbin:/sbin
BRDFNAV=$(realpath "$1") SCRIPTS=$(realpath "$2") PROFILE=$3 REFERENCE=$(realpath "$4")

note() { printf '[slurm test %3d s] %s\n' "$SECONDS" "$*"; }
fail() {
  printf 'FAILED: %s\n' "$*"
  exit 1
}
skip() {
  printf 'SKIPPED: %s\n' "$*"
  if [[ ${BRDFNAV_REQUIRE_SLURM:-0} == 1 ]]; then fail "BRDFNAV_REQUIRE_SLURM=1 and: $*"; fi
  exit 77
}

((EUID == 0)) || skip "needs root, to start slurmd (which runs jobs as their user) and slurmctld"
for c in mungekey munged munge unmunge slurmctld slurmd sbatch squeue scontrol scancel sinfo; do
  command -v "$c" >/dev/null ||
    skip "$c not found: the test needs Debian's slurm-wlm and munge (./run deps installs them)"
done
[[ -f $REFERENCE/manifest.yaml ]] || fail "$REFERENCE: no database to compare with"
# A test run inside a Slurm job must not hand that job's settings to this cluster's commands.
while read -r var; do
  case $var in SLURM_* | SBATCH_* | SQUEUE_* | SCONTROL_* | SINFO_* | SALLOC_* | SRUN_*) unset "$var" ;; esac
done < <(compgen -e)

T=$(mktemp -d "${TMPDIR:-/tmp}/brdfnav-slurm.XXXXXX")
chmod 755 "$T"  # munged requires every directory above its socket to be searchable by all
mkdir -m 700 "$T/munge"
mkdir "$T/run" "$T/state" "$T/spool" "$T/log"
export SLURM_CONF=$T/slurm.conf
# Every process of this cluster (the daemons, slurmstepd, the jobs and their brdfnav) carries
# this variable, the test itself does not: how the cleanup finds any that outlives its daemons.
MARK=BRDFNAV_SLURM_TEST=$T

instance_pids() {
  local p environ
  for p in /proc/[0-9]*; do
    environ=()
    mapfile -d '' -t environ 2>/dev/null <"$p/environ" || continue
    [[ " ${environ[*]} " == *" $MARK "* ]] && printf '%s\n' "${p#/proc/}"
  done
  return 0
}

daemons=()  # "name pid", in the order they were started
watchdog=
stop_pid() {  # NAME PID: SIGTERM, then SIGKILL after 10 s
  local name=$1 pid=$2 k
  kill -0 "$pid" 2>/dev/null || return 0
  kill -TERM "$pid" 2>/dev/null || true
  for ((k = 0; k < 100; k++)); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$pid" 2>/dev/null; then
    note "$name (pid $pid) ignored SIGTERM for 10 s: SIGKILL"
    kill -KILL "$pid" 2>/dev/null || true
  fi
  wait "$pid" 2>/dev/null || true
}
cleanup() {
  local status=$? k left i jobs name pid args
  trap - EXIT
  set +e
  if ((${#daemons[@]} > 0)); then
    # The jobs first, while slurmctld and slurmd run: slurmd's slurmstepd processes outlive it.
    if squeue -h -o %i 2>/dev/null | grep -q .; then
      note "cleanup: cancelling the jobs still queued"
      mapfile -t jobs < <(squeue -h -o %A 2>/dev/null)
      scancel --quiet "${jobs[@]}" 2>/dev/null
      for ((k = 0; k < 150; k++)); do
        squeue -h -o %i 2>/dev/null | grep -q . || break
        sleep 0.1
      done
    fi
    for ((i = ${#daemons[@]} - 1; i >= 0; i--)); do
      read -r name pid <<<"${daemons[i]}"
      stop_pid "$name" "$pid"
    done
  fi
  # Anything of this cluster still alive (a slurmstepd, a job, a brdfnav) is a leak: kill it by
  # its pid and fail the test.
  for ((k = 0; k < 50; k++)); do
    left=$(instance_pids)
    [[ -n $left ]] || break
    sleep 0.1
  done
  if [[ -n $left ]]; then
    note "cleanup: processes of this cluster still running after its daemons stopped:"
    for i in $left; do
      mapfile -d '' -t args 2>/dev/null <"/proc/$i/cmdline"
      printf '    %s %s\n' "$i" "${args[*]}"
    done
    for i in $left; do kill -KILL "$i" 2>/dev/null; done
    sleep 0.5
    left=$(instance_pids)
    ((status != 0)) || status=1
  fi
  [[ -z $left ]] || note "cleanup: could not kill: $left"
  [[ -z $watchdog ]] || { kill "$watchdog" 2>/dev/null; wait "$watchdog" 2>/dev/null; }
  wait  # the removals of the runs checked (discard_run)
  if ((status == 0 || status == 77)) && [[ -z ${BRDFNAV_SLURM_TEST_KEEP:-} ]]; then
    rm -rf "$T"
  else
    note "kept for inspection: $T (logs in $T/log and $T/*/work/logs)"
  fi
  exit "$status"
}
trap cleanup EXIT
trap 'exit 143' TERM INT HUP
# The EXIT trap cannot run if CTest kills this script with SIGKILL (its timeout): a watchdog in a
# session of its own then kills whatever of this cluster remains.
# shellcheck disable=SC2016  # the watchdog's script, expanded by the watchdog
setsid bash -c '
  while kill -0 "$1" 2>/dev/null; do sleep 1; done
  for p in /proc/[0-9]*; do
    mapfile -d "" -t e 2>/dev/null <"$p/environ" || continue
    [[ " ${e[*]} " == *" $2 "* ]] && kill -KILL "${p#/proc/}"
  done' watchdog $$ "$MARK" </dev/null >/dev/null 2>&1 &
watchdog=$!

start_daemon() {  # NAME COMMAND...: in the background, its output in log/NAME.out
  local name=$1
  shift
  env "$MARK" "$@" >"$T/log/$name.out" 2>&1 &
  daemons+=("$name $!")
}
# When a daemon has died: skip while the cluster starts (Slurm cannot run here), fail once it
# is up; either way naming the daemon and the end of its log.
up=0
check_daemons() {
  local d name pid st why
  for d in "${daemons[@]}"; do
    read -r name pid <<<"$d"
    kill -0 "$pid" 2>/dev/null && continue
    wait "$pid" && st=0 || st=$?
    why="$name exited (status $st); the end of its log:
$(tail -n 15 "$T/log/$name.out")"
    ((up)) && fail "$why"
    skip "Slurm cannot start here: $why"
  done
}

# Two free TCP ports on 127.0.0.1 for slurmctld and slurmd, below Linux's ephemeral range.
listening_ports() {
  local f local_address state
  for f in /proc/net/tcp /proc/net/tcp6; do
    [[ -r $f ]] || continue
    while read -r _ local_address _ state _; do
      [[ $state == 0A ]] && printf ' %d' "$((16#${local_address##*:}))"
    done < <(tail -n +2 "$f")
  done
  printf ' '
}
used=$(listening_ports)
for ((port = 20000 + RANDOM % 10000; ; port += 2)); do
  [[ $used == *" $port "* || $used == *" $((port + 1)) "* ]] || break
done

node=${HOSTNAME%%.*}  # slurmctld must run on the host SlurmctldHost names
cpus=$(nproc)
memory=$(($(sed -n 's/^MemTotal: *\([0-9]*\) kB/\1/p' /proc/meminfo) / 2048))
cat >"$SLURM_CONF" <<EOF
# A one-node cluster on 127.0.0.1 for brdfnav's tests/slurm (generated by slurm_array_test.sh).
ClusterName=brdfnavtest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$T/run/munge.socket
CredType=cred/munge
StateSaveLocation=$T/state
SlurmdSpoolDir=$T/spool
SlurmctldPidFile=$T/run/slurmctld.pid
SlurmdPidFile=$T/run/slurmd.pid
SlurmctldLogFile=$T/log/slurmctld.log
SlurmdLogFile=$T/log/slurmd.log
# No cgroups in a container: processes tracked by their parents, no task affinity.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
# Dependent jobs start as soon as the array ends, not up to 3 s later (the default).
SchedulerParameters=batch_sched_delay=0
ReturnToService=2
JobRequeue=1
KillWait=2
MinJobAge=600
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=30 State=UP
EOF

note "starting munged, slurmctld and slurmd in $T (ports $port and $((port + 1)))"
mungekey --create --keyfile="$T/munge/munge.key" >/dev/null
start_daemon munged munged --foreground --socket="$T/run/munge.socket" \
  --key-file="$T/munge/munge.key" --pid-file="$T/run/munged.pid" --seed-file="$T/munge/seed" \
  --log-file="$T/log/munged.log"
for ((k = 0; ; k++)); do
  munge -n -S "$T/run/munge.socket" 2>/dev/null | unmunge -S "$T/run/munge.socket" >/dev/null 2>&1 &&
    break
  check_daemons
  ((k < 100)) || skip "munged did not answer on $T/run/munge.socket in 10 s"
  sleep 0.1
done
start_daemon slurmctld slurmctld -D -f "$SLURM_CONF"
start_daemon slurmd slurmd -D -f "$SLURM_CONF" -N "$node"
for ((k = 0; ; k++)); do
  [[ $(sinfo -h -n "$node" -o %t 2>/dev/null) == idle ]] && break
  check_daemons
  ((k < 300)) || skip "the node did not become idle in 30 s: $(sinfo 2>&1 | tail -n 1);" \
    "slurmctld's log ends: $(tail -n 5 "$T/log/slurmctld.log")"
  sleep 0.1
done
up=1
note "Slurm $(sinfo -V | cut -d' ' -f2) is up: node $node, $cpus CPUs"

# submit.sh as a user runs it: the parameters in the environment, the resources scaled down.
submit() {  # RUN OUT: work and database in T/RUN, submit.sh's output in OUT
  (cd "$T" && env "$MARK" WORK="$T/$1/work" DB="$T/$1/db" PROFILE="$PROFILE" SHARDS=3 \
    BRDFNAV="$BRDFNAV" SHARD_CPUS=1 SHARD_MEM=256M SHARD_TIME=10 MERGE_CPUS="$cpus" \
    MERGE_MEM=1G MERGE_TIME=10 "$SCRIPTS/submit.sh") >"$2" 2>&1 || fail "submit.sh: $(cat "$2")"
}
job_of() { sed -n "s/^submit.sh: $1 job \([0-9]*\).*/\1/p" "$2"; }
shard_1_alone() {  # OUT: submit.sh submitted the array of shard 1 alone
  grep -q "^submit.sh: array job $(job_of array "$1"): shards 1 of 0-2$" "$1" ||
    fail "submit.sh did not submit shard 1 alone: $(cat "$1")"
}
state() { scontrol show job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p'; }
wait_idle() {  # until no job is queued or running (at most 600 s: CI runs other tests beside)
  local k
  for ((k = 0; k < 6000; k++)); do
    squeue -h -o %i | grep -q . || return 0
    check_daemons
    sleep 0.1
  done
  squeue
  fail "jobs still queued or running after 600 s"
}
same_as_reference() {  # DB
  [[ -f $1/manifest.yaml ]] || fail "$1: no database was written"
  local diffs
  diffs=$(diff -r --brief "$REFERENCE" "$1") || fail "$1 differs from $REFERENCE:
$diffs"
  note "$1: $(find "$1" -type f | wc -l) files, byte-identical to the single-machine build"
}
# A run whose checks passed is removed while the next one runs: some 3,000 files, whose removal
# takes seconds on a disk mounted with discard.
discard_run() { [[ -n ${BRDFNAV_SLURM_TEST_KEEP:-} ]] || rm -rf "${T:?}/${1:?}" & }
# Run 1's finished SHARDS copied into RUN's work directory: runs 2 and 3 test shard 1's kill and
# resumption, and rendering the others again would only add to the test's time. Run 2 keeps
# shard 2 to render: a task requeued once its array has ended is too late, the merge has run.
seed_run() {  # RUN SHARD...
  local run=$1 i
  shift
  mkdir -p "$T/$run/work"
  for i in "$@"; do cp -a "$T/run1/work/shard-$i" "$T/$run/work/"; done
}
# The files of a shard: its node images and its cell midpoints (precompute's blend check).
images_in() { { find "$1" -name '*.exr' ! -name '.*' -type f 2>/dev/null || true; } | wc -l; }

# Kills array task I of job A in the middle of its work: once it has finished at least one
# image, SIGKILL through the scheduler. Checks the shard was left unfinished.
kill_mid_work() {  # A I WORK TOTAL
  local a=$1 i=$2 work=$3 total=$4 k n
  for ((k = 0; ; k++)); do
    (($(images_in "$work/shard-$i.partial") > 0)) && break
    [[ ! -e $work/shard-$i ]] || fail "shard $i finished before it could be killed"
    ((k < 1200)) || fail "task ${a}_$i wrote no image in 60 s"
    sleep 0.05
  done
  scancel --signal=KILL "${a}_$i"
  for ((k = 0; k < 300; k++)); do
    case $(state "${a}_$i") in PENDING | RUNNING | COMPLETING | CONFIGURING) sleep 0.1 ;; *) break ;; esac
  done
  n=$(images_in "$work/shard-$i.partial")
  note "task ${a}_$i: $(state "${a}_$i") by scancel --signal=KILL with $n of its $total files written"
  [[ ! -e $work/shard-$i ]] || fail "shard $i finished before the kill took effect"
  ((n >= 1 && n < total)) || fail "shard $i had $n of $total images at the kill"
}
# Each finished image: its inode and modification time, which a rendering again would change.
image_stamps() {
  [[ -d $1 ]] || fail "$1: no such directory"
  (cd "$1" && find . -name '*.exr' ! -name '.*' -type f -printf '%P %i %T@\n' | sort)
}
rendered() {  # LOG: the files rendered, by the last "render: N images, M reused ..." line and
  # the last "cells: N cell midpoints, M reused ..." line
  printf '%s + %s' \
    "$(sed -n 's/^brdfnav: render: \([0-9]*\) images, \([0-9]*\) reused.*/\1 - \2/p' "$1" | tail -n 1)" \
    "$(sed -n 's/^brdfnav: cells: \([0-9]*\) cell midpoints, \([0-9]*\) reused.*/\1 - \2/p' "$1" | tail -n 1)"
}

# 1. Three shards and the merge.
note "run 1: 3 shards of the $PROFILE profile and the merge"
out1=$T/run1.submit.out
submit run1 "$out1"
a1=$(job_of array "$out1") m1=$(job_of merge "$out1")
[[ -n $a1 && -n $m1 ]] || fail "submit.sh did not name its jobs: $(cat "$out1")"
wait_idle
logs1=$T/run1/work/logs
for i in 0 1 2; do
  [[ $(state "${a1}_$i") == COMPLETED ]] || fail "task ${a1}_$i: $(state "${a1}_$i"):
$(cat "$logs1/shard-${a1}_$i.log")"
  for line in "\] start on" "^render: 100%" "^cells: 100%" "^brdfnav: shard written" "\] finished in"; do
    grep -q "$line" "$logs1/shard-${a1}_$i.log" ||
      fail "task $i's log has no line matching '$line': $(cat "$logs1/shard-${a1}_$i.log")"
  done
  total[i]=$(grep -c '\.exr: ' "$T/run1/work/shard-$i/shard.yaml")
done
[[ $(state "$m1") == COMPLETED ]] || fail "merge job $m1: $(state "$m1"): $(cat "$logs1/merge-$m1.log")"
grep -q "^brdfnav: blend check: [0-9]* cells, 0 midpoints rendered here" "$logs1/merge-$m1.log" ||
  fail "the merge rendered cell midpoints the shards should have: $(cat "$logs1/merge-$m1.log")"
same_as_reference "$T/run1/db"
note "run 1: shards of ${total[*]} files (node images and cell midpoints); task 1's log:"
sed 's/^/    /' "$logs1/shard-${a1}_1.log" | grep -v '^    [a-z ]*: [1-9]0%$'
seed_run run2 0
seed_run run3 0 2
discard_run run1

# 2. Task 1 killed in the middle of its work, requeued: it resumes.
note "run 2: shard 0 of run 1; task 1 killed in the middle of its work, then requeued"
out2=$T/run2.submit.out
submit run2 "$out2"
grep -q "^submit.sh: array job $(job_of array "$out2"): shards 1-2 of 0-2$" "$out2" ||
  fail "submit.sh did not keep shard 0: $(cat "$out2")"
a2=$(job_of array "$out2") m2=$(job_of merge "$out2")
work2=$T/run2/work
kill_mid_work "$a2" 1 "$work2" "${total[1]}"
before=$(image_stamps "$work2/shard-1.partial")
# The kill revoked the task's credential on the node, and slurmd refuses any credential of the
# job issued in the same whole second ("Killing non-startable batch job: Job credential revoked",
# and the task FAILED). The requeued task can be allocated at once on the CPU the kill freed: it
# must not be in that second.
sleep 2
scontrol requeue "${a2}_1"
# A requeued job waits 2 minutes before it is eligible again (slurmctld's fixed delay): now.
scontrol update JobId="${a2}_1" StartTime=now
wait_idle
log2=$work2/logs/shard-${a2}_1.log
[[ $(state "${a2}_1") == COMPLETED ]] || fail "requeued task ${a2}_1: $(state "${a2}_1"): $(cat "$log2")"
[[ $(state "$m2") == COMPLETED ]] || fail "merge $m2: $(state "$m2"): $(cat "$work2/logs/merge-$m2.log")"
if ! grep -q "attempt 2, .*resuming its images" "$log2" || ! grep -q "^brdfnav: resuming in" "$log2"
then
  fail "the requeued task's log does not say it resumed: $(cat "$log2")"
fi
after=$(image_stamps "$work2/shard-1")
kept=$(comm -12 <(echo "$before") <(echo "$after") | wc -l)
((kept == $(echo "$before" | wc -l))) ||
  fail "images finished before the kill were written again: $(comm -23 <(echo "$before") <(echo "$after") | head)"
again=$(($(rendered "$log2")))
((again + kept == total[1])) ||
  fail "the requeued task rendered $again files and kept $kept: not the shard's ${total[1]}"
note "run 2: the requeued task kept the $kept files finished before the kill (same inode and" \
  "time) and rendered the other $again of its ${total[1]}"
same_as_reference "$T/run2/db"
discard_run run2

# 3. Task 1 killed, not requeued: the merge fails naming it; submitting again redoes it alone.
note "run 3: shards 0 and 2 of run 1; task 1 killed and not requeued, then submit.sh again"
out3=$T/run3.submit.out
submit run3 "$out3"
shard_1_alone "$out3"
a3=$(job_of array "$out3") m3=$(job_of merge "$out3")
work3=$T/run3/work
kill_mid_work "$a3" 1 "$work3" "${total[1]}"
wait_idle
[[ $(state "$m3") == FAILED ]] || fail "merge $m3 with shard 1 unfinished: $(state "$m3")"
grep -q "ERROR: shards started but not finished .*: 1$" "$work3/logs/merge-$m3.log" ||
  fail "the failed merge does not name shard 1: $(cat "$work3/logs/merge-$m3.log")"
note "run 3: merge $m3 failed as it should:"
sed 's/^/    /' "$work3/logs/merge-$m3.log"
out3b=$T/run3.submit-again.out
submit run3 "$out3b"
shard_1_alone "$out3b"
a3b=$(job_of array "$out3b") m3b=$(job_of merge "$out3b")
wait_idle
[[ $(state "$m3b") == COMPLETED ]] || fail "merge $m3b: $(cat "$work3/logs/merge-$m3b.log")"
grep -q "attempt 1, .*resuming its images" "$work3/logs/shard-${a3b}_1.log" ||
  fail "shard 1 submitted again did not resume: $(cat "$work3/logs/shard-${a3b}_1.log")"
same_as_reference "$T/run3/db"

# The merge's message for shards never started (merge.sbatch outside Slurm: it fails before
# brdfnav runs).
message=$(WORK=$work3 DB=$T/run3/db-5 SHARDS=5 BRDFNAV=false bash "$SCRIPTS/merge.sbatch" 2>&1) &&
  fail "merge.sbatch with shards 3 and 4 missing succeeded"
grep -q "ERROR: shards missing (never started): 3 4$" <<<"$message" ||
  fail "merge.sbatch does not name the missing shards 3 and 4: $message"
note "passed"
