#!/bin/sh
# verdict.sh: one verdict on the layer from `anvil plan`, `anvil run` and
# `anvil field` (engine/verdict.h), for the issue's ball on a block and a
# steel ball on glass (the tensile criterion); the geometry keys from the
# command line.
. "$top_srcdir/tests/setup.sh"

export ANVIL_NO_CACHE=1
ball='-s impactor.material=steel -s impactor.shape=ball -s impactor.radius=11.5mm
      -s impactor.mass=50g -s layer.thickness=100mm -s impact.velocity=3m/s'
# shellcheck disable=SC2086
check 'plan of a 50 g steel ball on a steel block' "$ANVIL" plan $ball
assert '  the verdict: the steel layer yields' grep -q '^  the steel layer yields: peak von Mises 3.41 GPa at 0.48 a' "$tmp/out"
assert '  and how the run will judge' grep -q '^  anvil run: quasi-static Hertz at the row.s computed P_max (the layer bends too little' "$tmp/out"
# shellcheck disable=SC2086
check 'run of the same' "$ANVIL" run -m layer $ball
# run's verdict is under its row's force (the physical contact's), and
# quasi-static (verdict.h's BLOCK rule: a block, 1.3 % radiated): 3.41 GPa,
# the searched field's 3.40; field's under the field's own, the paper
# contact's (3.37 GPa)
assert '  one line on stderr: the steel layer yields' grep -q '^anvil: the steel layer yields: peak von Mises 3.41 GPa at 0.48 a' "$tmp/err"
assert '  quasi-static, and why' grep -q "(quasi-static Hertz at the layer's computed P_max: the plate's bending changes the impact by 0.44 %, the waves would carry off 1.3 % of its energy)" "$tmp/err"
# shellcheck disable=SC2086
check 'field of the same' "$ANVIL" field -q $ball --at 0,0.4mm -o "$tmp/f.tsv"
assert '  the same verdict' grep -q '^anvil: the steel layer yields: peak von Mises 3.3. GPa at 0.5 a' "$tmp/err"
assert '  and the peak in the file is the true contact'"'"'s' grep -q '^# yield check: peak von Mises 33.. MPa' "$tmp/f.tsv"

check 'run of the default scene' "$ANVIL" run -m hertz
assert '  one line on the layer' sh -c "grep -c '^anvil: the steel layer yields' '$tmp/err' | grep -qx 1"
assert '  one on the copper impactor' grep -q '^anvil: the copper impactor yields under the same contact: peak von Mises .* Y = 57 MPa' "$tmp/err"
assert '  and no other yield text' sh -c "! grep -v '^anvil: the \(steel layer\|copper impactor\)' '$tmp/err' | grep -qi 'yield'"
check 'run with strong bodies' "$ANVIL" run -m hertz -s impactor.yield=100GPa -s layer.yield=100GPa
assert '  the layer stays elastic, the impactor not mentioned' \
	sh -c "grep -q '^anvil: the steel layer stays elastic' '$tmp/err' && ! grep -q impactor '$tmp/err'"

check 'run of a steel ball on glass' "$ANVIL" run -m layer "$top_srcdir/examples/ball-on-glass.scene"
assert '  names the tensile criterion' grep -q '^anvil: the glass layer cracks: edge tension (1-2nu) p0/3 .* tensile strength 45 MPa' "$tmp/err"
check 'run -q says nothing' "$ANVIL" run -q -m layer "$top_srcdir/examples/ball-on-glass.scene"
assert '  (quiet)' test ! -s "$tmp/err"

check 'a drop height from the command line' "$ANVIL" plan -s impactor.shape=ball -s impactor.diameter=10mm -s impact.drop_height=50mm
assert '  gives V0 = sqrt(2 g H) in the title' grep -q 'copper ball, D = 10 mm, at 0.99 m/s' "$tmp/out"
printf '[impact]\nvelocity = 3 m/s\ndrop_height = 1 m\n' >"$tmp/both.scene"
check_exit 2 'velocity and drop_height in one scene exit 2' "$ANVIL" plan "$tmp/both.scene"
assert '  naming file, line and key' grep -q 'both.scene:3: impact.drop_height: impact.velocity is set too (line 2)' "$tmp/err"
done_testing
