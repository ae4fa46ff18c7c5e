#!/bin/bash
# Submits a sharded brdfnav precompute to Slurm (docs/SLURM.md): one array task per shard
# (precompute_array.sbatch), then the merge (merge.sbatch), which starts once every task has
# ended and fails, naming them, if some shards are missing or unfinished.
#
#   WORK=/shared/brdfnav-work DB=/shared/brdfnav-paper hosts/slurm/submit.sh [sbatch options]
#
# Parameters (environment variables; defaults after the '='):
#   WORK         the shards' directory, on a file system every node shares (required)
#   DB           the database directory the merge creates (required; must not exist)
#   PROFILE=paper          grid density: smoke, test, default or paper
#   ENV_MAP=     the environment map, which every node reads (empty: brdfnav's default, as
#                `$BRDFNAV precompute --help` gives it)
#   RES=         image width and height in pixels (empty: the profile's)
#   SHARDS=32    number of shards, so of array tasks (at least 2)
#   BRDFNAV=brdfnav        the brdfnav executable as the nodes see it
#   LOGS=$WORK/logs        one log per task (shard-<array job>_<i>.log) and one for the merge
#   SHARD_CPUS=16 SHARD_MEM=8G SHARD_TIME=12:00:00    each array task's resources
#   MERGE_CPUS=16 MERGE_MEM=32G MERGE_TIME=04:00:00   the merge's resources
# Arguments are passed to both sbatch calls (e.g. --partition=... --account=...); so are
# sbatch's own SBATCH_* variables.
#
# Submitting again after a failure (same parameters) submits only the shards that are not
# complete: a shard with its shard.yaml is kept, an interrupted one resumes from its finished
# images (brdfnav precompute --resume).
set -euo pipefail

: "${WORK:?set WORK to a directory on a shared file system (docs/SLURM.md)}"
: "${DB:?set DB to the database directory to create}"
: "${PROFILE:=paper}"
: "${ENV_MAP:=}"
: "${RES:=}"
: "${SHARDS:=32}"
: "${BRDFNAV:=brdfnav}"
: "${SHARD_CPUS:=16}" "${SHARD_MEM:=8G}" "${SHARD_TIME:=12:00:00}"
: "${MERGE_CPUS:=16}" "${MERGE_MEM:=32G}" "${MERGE_TIME:=04:00:00}"

say() { printf 'submit.sh: %s\n' "$*"; }
die() { printf 'submit.sh: error: %s\n' "$*" >&2; exit 1; }

if [[ ! $SHARDS =~ ^[0-9]+$ ]] || ((10#$SHARDS < 2)); then
  die "SHARDS=$SHARDS: expected a whole number of at least 2 (one machine: brdfnav precompute)"
fi
SHARDS=$((10#$SHARDS))
[[ -z $RES || $RES =~ ^[0-9]+$ ]] || die "RES=$RES: expected a number of pixels"
# brdfnav's default map, from the one place it is defined: the tasks are then given it by name,
# so the logs and the check of kept shards below name the map every shard is made with.
if [[ -z $ENV_MAP ]]; then
  ENV_MAP=$("$BRDFNAV" precompute --help 2>/dev/null | sed -n 's/^ *--env TEXT=\([^ ]*\).*/\1/p') ||
    true
  [[ -n $ENV_MAP ]] ||
    die "cannot ask $BRDFNAV for its default environment map here: set ENV_MAP to the map"
fi
# Absolute paths: the jobs may start in another directory, and the logs should name them whole.
WORK=$(realpath -m -- "$WORK")
DB=$(realpath -m -- "$DB")
: "${LOGS:=$WORK/logs}"
LOGS=$(realpath -m -- "$LOGS")
[[ ! -e $DB ]] || die "$DB already exists; remove it (or choose another DB) to build it again"
here=$(cd "$(dirname "$0")" && pwd)

# Jobs of an earlier submission for the same WORK still queued or running would write the same
# shards: wait for them (or scancel them) first.
tag="brdfnav:$WORK"
active=$(squeue --me --noheader --format='%i|%k' | awk -F'|' -v t="$tag" '$2 == t {printf " %s", $1}')
[[ -z $active ]] ||
  die "jobs of an earlier submission for $WORK are still queued or running:$active" \
    "(wait for them to end, or scancel them, then submit again)"

# A complete shard is kept if it is of this build; anything else there is an error, not a guess.
field() { sed -n "s/^$1: *//p" "$2" | head -n 1; }
todo=()
for ((i = 0; i < SHARDS; i++)); do
  yaml=$WORK/shard-$i/shard.yaml
  if [[ ! -f $yaml ]]; then
    [[ ! -e $WORK/shard-$i ]] ||
      die "$WORK/shard-$i exists without shard.yaml (not a shard brdfnav finished): remove it"
    todo+=("$i")
    continue
  fi
  [[ $(field shard "$yaml") == "$i/$SHARDS" ]] ||
    die "$yaml is shard $(field shard "$yaml"), not $i/$SHARDS: WORK holds another build's" \
      "shards; use another WORK or the SHARDS they were made with"
  [[ $(field profile "$yaml") == "$PROFILE" ]] ||
    die "$yaml was made with profile $(field profile "$yaml"), not $PROFILE"
  [[ -z $RES || $(field resolution "$yaml") == "$RES" ]] ||
    die "$yaml was made at resolution $(field resolution "$yaml"), not $RES"
  [[ $(sed -n 's/^  path: *//p' "$yaml" | head -n 1) == "$ENV_MAP" ]] ||
    die "$yaml was made with another environment map than $ENV_MAP"
done

# 0 1 2 5 7 8 -> 0-2,5,7-8 (sbatch --array)
ranges() {
  local out="" first=$1 last=$1 i
  shift
  for i in "$@" ""; do
    if [[ -n $i ]] && ((i == last + 1)); then last=$i; continue; fi
    out+=${out:+,}$first$([[ $last != "$first" ]] && printf -- '-%s' "$last")
    first=$i last=$i
  done
  printf '%s' "$out"
}

mkdir -p -- "$WORK" "$LOGS"
export WORK DB PROFILE ENV_MAP RES SHARDS BRDFNAV LOGS
common=(--parsable --export=ALL --comment="$tag" "$@")
say "profile $PROFILE, environment $ENV_MAP, resolution ${RES:-of the profile}, $SHARDS shards"
say "shards in $WORK, database $DB, logs in $LOGS"
dependency=()
if ((${#todo[@]} > 0)); then
  ((${#todo[@]} == SHARDS)) || say "$((SHARDS - ${#todo[@]})) shards are complete and kept"
  array=$(sbatch "${common[@]}" --array="$(ranges "${todo[@]}")" \
    --cpus-per-task="$SHARD_CPUS" --mem="$SHARD_MEM" --time="$SHARD_TIME" \
    --open-mode=append --output="$LOGS/shard-%A_%a.log" "$here/precompute_array.sbatch")
  array=${array%%;*}
  say "array job $array: shards $(ranges "${todo[@]}") of 0-$((SHARDS - 1))"
  # afterany, not afterok: the merge runs whatever the tasks' fate and names the shards that are
  # missing. (afterok on an array never recovers: a task that failed once keeps the merge waiting
  # forever, even after `scontrol requeue` finishes it.)
  dependency=(--dependency=afterany:"$array")
else
  say "all $SHARDS shards are complete"
fi
merge=$(sbatch "${common[@]}" "${dependency[@]}" \
  --cpus-per-task="$MERGE_CPUS" --mem="$MERGE_MEM" --time="$MERGE_TIME" \
  --output="$LOGS/merge-%j.log" "$here/merge.sbatch")
merge=${merge%%;*}
say "merge job $merge${dependency:+, after the array}: writes $DB"
