#!/bin/sh
# physical.sh: [effects] contact from the command line (issue 10): the
# default scene shows the paper's and the physical rows side by side, each
# saying which it is, in every format; other scenes the physical ones; the
# key refused when wrong.
# shellcheck disable=SC2016
. "$top_srcdir/tests/setup.sh"

export ANVIL_NO_CACHE=1
M='-mlayer,halfspace'

check 'run: the default scene' "$ANVIL" run -q $M
assert '  the paper'"'"'s layer row, named' grep -q '^layer (paper)  *1 ' "$tmp/out"
assert '  the physical layer row' grep -q '^layer  *1 ' "$tmp/out"
assert '  the paper'"'"'s half-space row, named' grep -q '^halfspace (paper)  *inf ' "$tmp/out"
assert '  the notes name the rows' grep -q '^layer: physical contact' "$tmp/out"

check 'run -f tsv' "$ANVIL" run -q $M -f tsv
assert '  the contact column' awk -F '\t' 'NR == 1 { exit $NF != "contact" }' "$tmp/out"
assert '  paper, physical, paper, physical' \
	[ "$(awk -F '\t' 'NR > 1 { printf "%s:%s ", $1, $NF }' "$tmp/out")" = 'layer:paper layer:physical halfspace:paper halfspace:physical ' ]
assert '  the physical half-space loses less than Hertz, more than the paper'"'"'s patch' \
	awk -F '\t' '$1 == "halfspace" { r[$NF] = $8 } END { exit !(r["physical"] < r["paper"] && r["physical"] < 1) }' "$tmp/out"

check 'run -f json' "$ANVIL" run -q $M -f json
if command -v python3 >/dev/null 2>&1; then
	assert '  each result has its contact' python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
c = [(r["model"], r["contact"]) for r in d["results"]]
sys.exit(c != [("layer", "paper"), ("layer", "physical"), ("halfspace", "paper"), ("halfspace", "physical")])' "$tmp/out"
else
	skip '  each result has its contact' 'no python3'
fi

check 'run -f csv -m hertz' "$ANVIL" run -q -m hertz -f csv
assert '  hertz has no contact model of its own: -' awk -F , 'NR == 2 { exit $NF != "-" }' "$tmp/out"

check 'another scene: the physical rows only' "$ANVIL" run -q $M -s layer.thickness=2r0 -f tsv
assert '  no paper row' [ "$(awk -F '\t' 'NR > 1 { printf "%s ", $NF }' "$tmp/out")" = 'physical physical ' ]
check 'contact = paper: the paper'"'"'s rows only' "$ANVIL" run -q $M -s effects.contact=paper -f tsv
assert '  no physical row' [ "$(awk -F '\t' 'NR > 1 { printf "%s ", $NF }' "$tmp/out")" = 'paper paper ' ]

check 'plan prints the contact' "$ANVIL" plan
assert '  the setting' grep -q '^  contact: both (effects.contact)$' "$tmp/out"
assert '  the paper'"'"'s row' grep -q '^  layer (paper)  *layer ' "$tmp/out"
check 'plan -f tsv' "$ANVIL" plan -f tsv
assert '  the rows'"'"' contact' \
	[ "$(awk -F '\t' '$1 == "row" { printf "%s:%s ", $2, $NF }' "$tmp/out")" = 'hertz:- zener:- layer:paper layer:physical halfspace:paper halfspace:physical ' ]

check_exit 2 'a bad contact exits 2' "$ANVIL" run -s effects.contact=sometimes
assert '  naming the key and the choices' grep -q 'effects.contact: expected auto, physical, paper or both' "$tmp/err"
printf '[effects]\ncontact = fancy\n' >"$tmp/bad.scene"
check_exit 2 'in a scene file' "$ANVIL" run "$tmp/bad.scene"
assert '  naming file, line and key' grep -q 'bad.scene:2: effects.contact' "$tmp/err"

# Repeated contacts in the physical pass are tested in test_physical.c (h =
# r0/4, fast convolution against the direct sum) and test_thin.c (merged
# sub-resolution separations, the contact budget, thin-layer refusals).

# A contact end pending across long mode's freeze of a full segment: the
# end's node lies in the frozen segment (impact.c, contact_end).  This
# scene crashed (its index wrapped round) once the plate's tail was the
# point load's own (plate.c).
check 'h = 0.05 r0, 100 kg at 0.1 m/s: long mode, an end pending across a freeze' \
	"$ANVIL" run -q -m layer -s layer.thickness=0.05r0 -s impactor.mass=100kg \
	-s impact.velocity=0.1m/s -f tsv
assert '  the layer row answers, R_f in [0, 1]' \
	awk -F '\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next } $1 == "layer" { r = $c["Rf"]; n++ } END { exit !(n == 1 && r >= 0 && r <= 1) }' "$tmp/out"

# ---- anvil plot models (the script: no gnuplot needed) ----
check 'plot models --script' "$ANVIL" plot models --script "$tmp/m.gp"
assert '  two panels side by side' grep -q '^# panel 2: R_f against h/r0$' "$tmp/m.gp"
assert '  four force histories and two R_f curves' [ "$(grep -c '^\$d[0-9]* << EOD$' "$tmp/m.gp")" -eq 6 ]
assert '  the physical solid, the paper'"'"'s dashed, in the key' \
	sh -c "grep -q \"title 'physical contact'\" '$tmp/m.gp' && grep -q \"title 'paper''s contact'\" '$tmp/m.gp'"
assert '  R_f of both at the six thicknesses' \
	awk '/^\$d5 << EOD$/ { b = 1; next } /^\$d6 << EOD$/ { b = 2; next } /^EOD$/ { b = 0 } b { n[b]++ } END { exit !(n[1] == 6 && n[2] == 6) }' "$tmp/m.gp"

done_testing
