#!/bin/sh
# answer.sh: the direct answers (issue 12) with the contact models
# ([effects] contact): anvil thickness compares like with like and says
# which contact it used; anvil fit and dem name theirs; a failing row says
# why and the others go on.
. "$top_srcdir/tests/setup.sh"

# Not the paper's case (V0 = 3 m/s): auto is the physical contact.
D='-s solver.accuracy=draft -s impact.velocity=3m/s'
cd "$tmp"

# The largest relative deviation of the layer's t_s, R_f, P_max from the
# half-space's, by a direct anvil run at h = $1 r0 with contact $2 (the
# rows picked by their model and contact columns).
dev() {
	$ANVIL run $D -m layer,halfspace -s "layer.thickness=${1}r0" -s "effects.contact=$2" -f tsv \
		2>/dev/null | awk -F'\t' -v want="$2" '
		NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
		$c["contact"] != want { next }
		{ m = $c["model"]; ts[m] = $c["ts_us"]; rf[m] = $c["Rf"]; p[m] = $c["Pmax_kN"]; n++ }
		function rel(a, b) { x = (a - b) / b; return x < 0 ? -x : x }
		END { if (n != 2) { print "nan"; exit }
		      d = rel(ts["layer"], ts["halfspace"])
		      if (rel(rf["layer"], rf["halfspace"]) > d) d = rel(rf["layer"], rf["halfspace"])
		      if (rel(p["layer"], p["halfspace"]) > d) d = rel(p["layer"], p["halfspace"])
		      print d }'
}
cell() { # cell FILE ROW COLUMN-NAME
	awk -F'\t' -v r="$2" -v k="$3" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i } NR == r { print $c[k] }' "$1"
}
# The answer h of contact $1 in th-$1.tsv passes a direct run of that
# contact, and the miss below it on the bisection's grid fails.
against_runs() {
	h=$(cell "th-$1.tsv" 2 h_r0)
	hb=$(cell "th-$1.tsv" 2 h_below_r0)
	assert "$1: the bisection closed to 2% ($hb .. $h r0)" \
		awk -v h="$h" -v b="$hb" 'BEGIN { exit !(h > b && h / b <= 1.02) }'
	assert "$1: at h = $h r0 a direct run with the $1 contact is within 2%" \
		awk -v d="$(dev "$h" "$1")" 'BEGIN { exit !(d <= 0.02) }'
	assert "$1: at h = $hb r0, just below, it is not" \
		awk -v d="$(dev "$hb" "$1")" 'BEGIN { exit !(d > 0.02 && d < 1) }'
}

# ---- thickness, per contact model ----
check "thickness, auto contact (this scene: physical)" \
	$ANVIL thickness $D --within 2% --rtol 2% -o th-auto.txt
assert "...says it used the physical contact" grep -q '^physical contact: h = ' th-auto.txt
for c in physical paper; do
	check "thickness -s effects.contact=$c" \
		$ANVIL thickness $D -s effects.contact=$c --within 2% --rtol 2% -f tsv -o "th-$c.tsv"
	assert "...one row, contact $c" \
		sh -c "[ \$(wc -l <th-$c.tsv) -eq 2 ] && [ \"\$(awk -F'\t' 'NR == 2 { print \$NF }' th-$c.tsv)\" = $c ]"
	against_runs $c
done
assert "the two contacts give different thicknesses" \
	[ "$(cell th-physical.tsv 2 h_r0)" != "$(cell th-paper.tsv 2 h_r0)" ]
check "thickness -s effects.contact=both" \
	$ANVIL thickness $D -s effects.contact=both --within 2% --rtol 2% -f tsv -o th-both.tsv --curve curve.tsv
assert "...a row per contact, each the answer of that contact alone" \
	sh -c '[ "$(sed -n 2p th-both.tsv)" = "$(sed -n 2p th-paper.tsv)" ] &&
	       [ "$(sed -n 3p th-both.tsv)" = "$(sed -n 2p th-physical.tsv)" ]'
assert "...the curve names each thickness's contact, sorted within each" \
	awk -F'\t' 'NR == 1 { ok = $NF == "contact"; next }
		    $NF != c { c = $NF; n[c]++; p = 0 } $1 <= p { ok = 0 } { p = $1 }
		    END { exit !(ok && n["paper"] == 1 && n["physical"] == 1) }' curve.tsv
check_exit 1 "thickness: solver.scheme = paper with the physical contact is refused" \
	$ANVIL thickness $D -s solver.scheme=paper -s effects.contact=physical -o none.tsv
assert "...saying why, and no file written" \
	sh -c 'grep -q "has the paper contact, not the physical" "$0" && [ ! -e none.tsv ]' "$tmp/err"
check_exit 1 "thickness: a range where nothing is within" \
	$ANVIL thickness $D --range 0.5..1 -s effects.contact=paper -o none.tsv
assert "...names the contact and writes nothing" \
	sh -c 'grep -q "paper contact: even h = 1 r0 is not within" "$0" && [ ! -e none.tsv ]' "$tmp/err"

done_testing
