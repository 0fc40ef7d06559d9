#!/bin/sh
# input.sh: issue 13 from the command line: each reported reproducer, the
# unit rule, plausibility warnings and --strict, generated titles in JSON.
# Only anvil plan (nothing computed) and the fast hertz/zener models run.
# shellcheck disable=SC2016
. "$top_srcdir/tests/setup.sh"

M=-mhertz,zener

# A 1-byte stack under-read in set_path (an ASan build stops on it).
check "plan -s 'output.histories=#x'" "$ANVIL" plan -s 'output.histories=#x'
printf '[output]\nhistories=#\n' >"$tmp/hash.scene"
check "[output] histories=# (a file called '#')" "$ANVIL" plan "$tmp/hash.scene"

# CR-only line ends: the file's own scene runs, not the default.
printf '[impact]\rvelocity = 3 m/s\r[solver]\rmodels = hertz\r' >"$tmp/cr.scene"
check 'a CR-only scene runs' "$ANVIL" run "$tmp/cr.scene" -f tsv
assert '  with its own velocity (3 m/s)' awk -F'\t' 'NR == 2 && $1 == "hertz" && $3 == 3 { f = 1 } END { exit !f }' "$tmp/out"

# A UTF-8 BOM is skipped.
printf '\357\273\277[impact]\nvelocity = 4 m/s\n' >"$tmp/bom.scene"
check 'a scene with a UTF-8 BOM runs' "$ANVIL" run "$tmp/bom.scene" $M -f tsv
assert '  with its own velocity (4 m/s)' awk -F'\t' 'NR == 2 && $3 == 4 { f = 1 } END { exit !f }' "$tmp/out"

# An empty scene file is refused, not silently the paper's case.
: >"$tmp/empty.scene"
check_exit 2 'an empty scene exits 2' "$ANVIL" run "$tmp/empty.scene" $M
assert '  naming the file' grep -q "empty.scene: no KEY = VALUE in the scene" "$tmp/err"
assert '  and nothing on stdout' test ! -s "$tmp/out"

# No size limit: /dev/zero grew memory until OOM.
if [ -r /dev/zero ]; then
	check_exit 2 '/dev/zero as the scene exits 2' "$ANVIL" plan /dev/zero
	assert '  "larger than 1048576 bytes", naming it' grep -q "^anvil: /dev/zero: larger than 1048576 bytes" "$tmp/err"
fi

# Implausible or non-finite values: refused with the key and the range.
check_exit 2 '-s impactor.radius=1e308 exits 2' "$ANVIL" plan -s impactor.radius=1e308
assert '  a bare number needs a unit' grep -q "impactor.radius: '1e308' needs a unit, e.g. 1e308 mm" "$tmp/err"
check_exit 2 '-s impactor.radius=1e308m exits 2' "$ANVIL" plan -s impactor.radius=1e308m
assert '  outside the range' grep -q "impactor.radius: must be within 1e-09 .. 1000 m" "$tmp/err"
for kv in layer.nu=-0.9999999999999999 impact.velocity=1e-300m/s impactor.mass=1e300kg layer.E=1e300Pa; do
	check_exit 2 "-s $kv exits 2" "$ANVIL" plan -s "$kv"
	assert "  names the key and the range" grep -q "${kv%%=*}: must be within" "$tmp/err"
done

# The unit rule on -s.
check_exit 2 '-s impact.velocity=10 exits 2' "$ANVIL" plan -s impact.velocity=10
assert "  '10' needs a unit, e.g. 10 m/s" grep -q "impact.velocity: '10' needs a unit, e.g. 10 m/s" "$tmp/err"
check '-s impact.velocity=10m/s is fine' "$ANVIL" plan -s impact.velocity=10m/s

# title=#x round-trips; a non-UTF-8 title is refused (JSON stays valid).
check_exit 2 'a non-UTF-8 title exits 2' "$ANVIL" run $M -s "$(printf 'scene.title=caf\351')"
assert '  "is not valid UTF-8 text"' grep -q "scene.title: is not valid UTF-8 text" "$tmp/err"
check 'a title of valid UTF-8 runs' "$ANVIL" run $M -f json -s "$(printf 'scene.title=caf\303\251 #1')"
assert '  and is in the JSON' grep -q "\"title\": \"caf.* #1\"" "$tmp/out"

# The title describes the scene unless set.
check 'material and mass changed' "$ANVIL" run $M -f json -s impactor.material=steel -s impactor.mass=50g
assert '  the title is made from the scene' grep -q '"title": "50 g steel impactor, r0 = 4 mm, at 10 m/s on a 4 mm steel layer"' "$tmp/out"
check 'the default scene' "$ANVIL" run $M -f json -s solver.accuracy=draft
assert "  keeps the paper's title" grep -q "\"title\": \"Copper rod on a steel layer (Pyr'yev et al. 2024)\"" "$tmp/out"

# Plausibility warnings and --strict.
printf '[impactor]\nmass = 2000 kg\n' >"$tmp/heavy.scene"
check 'a 2 t impactor runs' "$ANVIL" plan "$tmp/heavy.scene"
assert '  with one warning line: FILE:LINE: KEY: ...' grep -q "^anvil: warning: $tmp/heavy.scene:2: impactor.mass: 2e+03 kg is above 1e+03 kg" "$tmp/err"
check_exit 2 '  --strict makes it an error (exit 2)' "$ANVIL" --strict plan "$tmp/heavy.scene"
check_exit 2 '  --strict after the command too' "$ANVIL" plan "$tmp/heavy.scene" --strict
check_exit 2 '-s impact.velocity=6km/s --strict' "$ANVIL" run $M -s impact.velocity=6km/s --strict
assert '  "command line: impact.velocity"' grep -q "command line: impact.velocity: 6 km/s is above 5 km/s" "$tmp/err"
assert '  nothing on stdout' test ! -s "$tmp/out"
printf '[impactor]\nshape = ball\ndiameter = 10 mm\nmass = 1 kg\n' >"$tmp/dense.scene"
check 'a 1 kg ball of 10 mm runs' "$ANVIL" plan "$tmp/dense.scene"
assert '  warned: heavier than a solid ball (FILE:LINE of the mass)' \
	grep -q "^anvil: warning: $tmp/dense.scene:4: impactor.mass: 1 kg is above 4.7[0-9] g (a solid ball of this diameter and material" "$tmp/err"
check 'a 4 g ball of 10 mm, or its own mass, is silent' "$ANVIL" plan -s impactor.shape=ball \
	-s impactor.diameter=10mm -s impactor.mass=4g
assert '  no warning: only the note that the 1 r0 layer followed the diameter' \
	sh -c '[ "$(wc -l <"$1")" -eq 1 ] && grep -q "^anvil: note: layer.thickness = 1 r0 follows the radius" "$1"' sh "$tmp/err"
check '--strict on a plausible scene is silent' "$ANVIL" --strict plan
assert '  no warning' test ! -s "$tmp/err"

# A number beyond a double is out of range, not "not a velocity".
check_exit 2 '-s impact.velocity=1e999m/s exits 2' "$ANVIL" plan -s impact.velocity=1e999m/s
assert '  "out of range"' grep -q "impact.velocity: expected a velocity such as '10 m/s', got '1e999m/s' (out of range)" "$tmp/err"

# "brass" is not a typo of "glass".
check_exit 2 '-s layer.material=brass exits 2' "$ANVIL" plan -s layer.material=brass
assert '  no glass suggested; how to define it' grep -q "'brass' is not a built-in material: define it with \[material brass\]" "$tmp/err"

done_testing
