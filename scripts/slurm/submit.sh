#!/usr/bin/env bash
# Submits `tierlift test` as N array tasks and the dependent merge; prints both job ids.
#   scripts/slurm/submit.sh N OUT PATH...      (then: cat OUT/merged/summary.md)
set -euo pipefail
n=${1:?usage: submit.sh N OUT PATH...}
out=${2:?usage: submit.sh N OUT PATH...}
shift 2
here=$(dirname "$0")
mkdir -p "$out"
array=$(sbatch --parsable --array=0-$((n - 1)) "$here/tierlift-test.sbatch" "$out" "$@")
merge=$(sbatch --parsable --dependency=afterany:"${array%%;*}" "$here/tierlift-test.sbatch" merge "$out")
echo "array job $array, merge job $merge"
