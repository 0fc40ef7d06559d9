#!/bin/sh
# threads.sh: the layer response's frequencies run on all cores (OpenMP,
# green.c); each is independent and the sums run in a fixed order, so a
# run gives the same bits with one thread or several.  Every column but
# the solver's seconds is compared, over scenes that exercise a thin and a
# thick layer, a refinement and the twin.
. "${top_srcdir:-.}/tests/setup.sh"

run() {
	"$ANVIL" run -m layer,halfspace --format tsv "$@" | cut -f 1-16
}

for args in "-s layer.thickness=1r0 -s impact.velocity=10m/s" \
	"-s layer.thickness=0.5r0 -s impact.velocity=10m/s -s solver.accuracy=draft" \
	"-s layer.thickness=2r0 -s impact.velocity=100m/s -s solver.accuracy=fine"; do
	# shellcheck disable=SC2086
	OMP_NUM_THREADS=1 run $args >"$tmp/one"
	# shellcheck disable=SC2086
	OMP_NUM_THREADS=2 run $args >"$tmp/two"
	# shellcheck disable=SC2086
	OMP_NUM_THREADS=3 run $args >"$tmp/three"
	assert "1, 2 and 3 threads give the same bits: $args" \
		cmp -s "$tmp/one" "$tmp/two"
	assert "  (3 threads too)" cmp -s "$tmp/one" "$tmp/three"
	assert "  (and the run printed a layer row)" grep -q '^layer' "$tmp/one"
done
done_testing
