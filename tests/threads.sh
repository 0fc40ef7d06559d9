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
# The physical row warm (its responses from the disk cache): the row's
# impact and its error estimate's four run side by side on the threads
# (solver_phys.c phys_rounds); cold, the error runs only after the row's own,
# and warm too where the row will likely come to rest (the thin plate's
# third case, at rest: its error runs stop at its rest time).
# Every column but time_s, against a cold run, with 1 and 2 threads.
physical() {
	"$ANVIL" run -q -m layer -s effects.contact=physical --format tsv "$@" |
		awk -F '\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "time_s") c = i }
			{ for (i = 1; i <= NF; i++) if (i != c) printf "%s\t", $i; print "" }'
}
export XDG_CACHE_HOME="$tmp/xdg"
for args in "-s layer.thickness=1r0 -s impact.velocity=9.5m/s" \
	"-s layer.thickness=0.25r0 -s impactor.mass=100g -s impact.velocity=10m/s" \
	"-s layer.thickness=0.05r0 -s impactor.mass=10kg -s impact.velocity=0.01m/s"; do
	# shellcheck disable=SC2086
	ANVIL_NO_CACHE=1 physical $args >"$tmp/cold"
	# shellcheck disable=SC2086
	OMP_NUM_THREADS=1 physical $args >"$tmp/fill"
	# shellcheck disable=SC2086
	OMP_NUM_THREADS=2 physical $args >"$tmp/two"
	# shellcheck disable=SC2086
	OMP_NUM_THREADS=1 physical $args >"$tmp/one"
	assert "physical, warm on 2 threads = cold: $args" cmp -s "$tmp/cold" "$tmp/two"
	assert "  (warm on 1 thread, and the run that filled the cache)" \
		sh -c 'cmp -s "$1/cold" "$1/one" && cmp -s "$1/cold" "$1/fill"' sh "$tmp"
	assert "  (and the run printed a layer row with an error estimate)" \
		awk -F '\t' '$1 == "layer" && $12 + 0 > 0 { f = 1 } END { exit !f }' "$tmp/cold"
done
done_testing
