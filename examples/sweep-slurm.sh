#!/bin/bash
# sweep-slurm.sh: a restitution sweep as a Slurm job array of 8 shards,
# then merged.  Submit with:
#   sbatch examples/sweep-slurm.sh
#   sbatch --dependency=afterok:JOBID --wrap 'anvil merge rf-*.csv -o rf.csv'
# Shards count from 1, as --array=1-8 numbers them (with --array=0-7 give
# --shard $((SLURM_ARRAY_TASK_ID + 1))/8).  Slurm's SIGTERM at the time
# limit leaves the rows done in the shard's file: resubmit the same array
# and --resume carries on.  All tasks share one response cache directory
# (atomic writes: safe on one file system).
#SBATCH --job-name=anvil-sweep
#SBATCH --array=1-8
#SBATCH --cpus-per-task=4
#SBATCH --time=01:00:00
#SBATCH --signal=TERM@60
set -euo pipefail
: "${SLURM_ARRAY_TASK_ID:?run under sbatch (or set SLURM_ARRAY_TASK_ID=1..8)}"
export XDG_CACHE_HOME=${XDG_CACHE_HOME:-$HOME/.cache}
exec anvil sweep \
	impact.velocity=0.1..10m/s:25:log \
	layer.thickness=1mm,2mm,5mm,10mm,20mm \
	-j "${SLURM_CPUS_PER_TASK:-1}" \
	--shard "$SLURM_ARRAY_TASK_ID/8" --resume -o "rf-$SLURM_ARRAY_TASK_ID.csv"
