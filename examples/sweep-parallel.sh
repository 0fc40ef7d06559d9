#!/bin/sh
# sweep-parallel.sh: a restitution sweep in N shards run by GNU parallel
# (one process per core here; with --sshlogin, on several machines sharing
# a file system), then merged into the table one unsharded run writes.
#   examples/sweep-parallel.sh [N]        (default 8)
# AXES and SWEEP_ARGS replace the axes and add options (tests/sweep.sh runs
# this script with a small draft sweep and compares it byte for byte with
# an unsharded run).
set -eu
n=${1:-8}
axes=${AXES:-"impact.velocity=0.1..10m/s:25:log layer.thickness=1mm,2mm,5mm,10mm,20mm"}
# shellcheck disable=SC2086  # the axes and options are words
seq 1 "$n" | parallel --will-cite --halt now,fail=1 \
	anvil sweep $axes ${SWEEP_ARGS:-} -j 1 --shard {}/"$n" --resume -q -o rf-{}.csv
files=$(seq 1 "$n" | sed 's/.*/rf-&.csv/')
# shellcheck disable=SC2086
anvil merge $files -o rf.csv
echo "rf.csv: $(($(wc -l <rf.csv) - 1)) rows"
