#!/bin/bash
# Usage: WORK=/shared/brdfnav-work DB=/shared/brdfnav-db [SHARDS=32] [PROFILE=paper] submit.sh
# Submits SHARDS array tasks, then the merge as a job that starts only when all of them succeed.
set -euo pipefail
: "${SHARDS:=32}"
: "${WORK:?}" "${DB:?}"
mkdir -p logs "$WORK"
here=$(dirname "$0")
array=$(sbatch --parsable --export=ALL --array=0-$((SHARDS - 1)) "$here/precompute_array.sbatch")
sbatch --export=ALL --dependency=afterok:"$array" "$here/merge.sbatch"
