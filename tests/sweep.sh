#!/bin/sh
# sweep.sh: anvil sweep, merge, thickness, fit and dem (issue 12).
. "$top_srcdir/tests/setup.sh"

D='-s solver.accuracy=draft'
src=$(cd "$top_srcdir" && pwd)
cd "$tmp"

# ---- rows ----
check "a 2 x 2 sweep runs" $ANVIL sweep $D -m hertz,zener 'layer.thickness=1r0,2r0' \
	'impact.velocity=1m/s,3m/s' -o s.tsv -q
assert "one header and 8 rows (2 scenes x 2 x 2 models)" [ "$(wc -l <s.tsv)" -eq 9 ]
assert "axes in the user's units, scene columns for joining" \
	grep -q '^row	rows	layer.thickness_r0	impact.velocity_m_s	impactor	layer	mass_kg	r0_m	h_m	h_r0	V0_m_s	model	contact	status	message	ts_us	ts_err_us' s.tsv
assert "last axis varies fastest" \
	[ "$(awk -F'\t' 'NR > 1 { printf "%s/%s/%s ", $3, $4, $12 }' s.tsv)" = \
	  "1/1/hertz 1/1/zener 1/3/hertz 1/3/zener 2/1/hertz 2/1/zener 2/3/hertz 2/3/zener " ]
# the row's values are those of anvil run on the same scene
$ANVIL run $D -m zener -s layer.thickness=2r0 -s impact.velocity=3m/s -f tsv >run.tsv 2>/dev/null
assert "a row equals anvil run on its scene (R_f, t_s)" \
	[ "$(awk -F'\t' '$3 == 2 && $4 == 3 && $12 == "zener" { print $16, $24 }' s.tsv)" = \
	  "$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i } NR == 2 { print $c["ts_us"], $c["Rf"] }' run.tsv)" ]
check "a log range, CSV by extension" $ANVIL sweep $D -m hertz 'impact.velocity=0.1..10m/s:3:log' -o r.csv -q
assert "log range: 0.1, 1, 10 m/s" \
	[ "$(awk -F, 'NR > 1 { printf "%s ", $3 }' r.csv)" = "0.1 1 10 " ]
check "materials and --zip" $ANVIL sweep $D -m hertz --zip 'layer.material=steel,glass' \
	'impact.velocity=1m/s,2m/s' -o z.tsv -q
assert "--zip pairs the lists: 2 rows" \
	[ "$(awk -F'\t' 'NR > 1 { printf "%s/%s ", $3, $4 }' z.tsv)" = "steel/1 glass/2 " ]
if command -v python3 >/dev/null 2>&1; then
	check "JSON output" $ANVIL sweep $D -m hertz 'impact.velocity=1m/s,2m/s' -f json -o j.json -q
	check "the JSON parses, 2 objects" python3 -c 'import json,sys; d=json.load(open("j.json")); sys.exit(len(d) != 2 or d[1]["V0_m_s"] != 2)'
else
	skip "JSON output" "no python3"
	skip "the JSON parses" "no python3"
fi

# ---- the contact model: a column, one model per table, both on request ----
check "a sweep of the layer and hertz" $ANVIL sweep $D -m hertz,layer 'impact.velocity=5m/s,10m/s' -o c.tsv -q
assert "a contact column: physical for the layer, - for hertz; one layer row at 10 m/s (auto is physical in a table, the paper's own case too)" \
	[ "$(awk -F'\t' 'NR > 1 { printf "%s/%s/%s ", $3, $11, $12 }' c.tsv)" = "5/hertz/- 5/layer/physical 10/hertz/- 10/layer/physical " ]
check "contact = both" $ANVIL sweep $D -m layer -s effects.contact=both 'impact.velocity=5m/s,10m/s' -o both.tsv -q
assert "...two layer rows a scene, the paper's first (as anvil run)" \
	[ "$(awk -F'\t' 'NR > 1 { printf "%s/%s ", $3, $12 }' both.tsv)" = "5/paper 5/physical 10/paper 10/physical " ]
$ANVIL run $D -m layer -s effects.contact=both -s impact.velocity=5m/s -f tsv 2>/dev/null |
	awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i } NR > 1 { print $c["Rf"], $c["Rf_err"] }' >both.run
check "a both sweep of one scene" $ANVIL sweep $D -m layer -s effects.contact=both 'impact.velocity=5m/s' -o both1.tsv -q
assert "...its rows are anvil run's, to the bit (R_f)" \
	[ "$(awk -F'\t' 'NR > 1 { printf "%s ", $23 }' both1.tsv)" = "$(awk '{ printf "%s ", $1 }' both.run)" ]
assert "...in a longer sweep (a shared, wider response) within the summed error estimates" \
	awk -F'\t' 'NR == FNR { r[FNR] = $1; e[FNR] = $2; next }
		FNR > 1 && $3 == 5 { k++; d = $23 - r[k]; if (d < 0) d = -d; if (d > $24 + e[k]) bad = 1 }
		END { exit bad || k != 2 }' both.run both.tsv
head -n 3 both.tsv >bothcut.tsv # killed between a scene's two rows
check "--resume of a both sweep cut between a scene's rows" $ANVIL sweep $D -m layer -s effects.contact=both \
	'impact.velocity=5m/s,10m/s' -o bothcut.tsv --resume -q
assert "...= uninterrupted" cmp -s bothcut.tsv both.tsv
check "a list's unit written once, on its last value" $ANVIL sweep $D -m hertz,layer 'impact.velocity=5,10m/s' -o c1.tsv -q
assert "...the same table as with every unit written" cmp -s c1.tsv c.tsv

# a row that fails says why, and the others print
# (a layer 1e-4 r0 thin: the planner refuses it before any work)
check_exit 1 "a refused row: exit 1" $ANVIL sweep $D -m layer 'layer.thickness=0.0001r0,2r0' -o f.tsv -q
assert "the refused row has status < 0 and a message, the other its values" \
	[ "$(awk -F'\t' 'NR > 1 { printf "%s:%s:%s ", ($13 < 0), ($14 != ""), ($23 != "nan") }' f.tsv)" = "1:1:0 0:0:1 " ]

# ---- bad specs: one line naming the argument, exit 2 ----
for spec in 'impact.velocity=0.1..10m/s:0' 'layer.thickness=1mm,' 'foo.bar=1,2' \
	'layer.thickness=1mm,2m' 'impact.velocity=1mm,2mm' 'impact.velocity=1..10:3:cubic'; do
	check_exit 2 "refused: $spec" $ANVIL sweep $D "$spec" -q
	assert "one line naming it: $spec" [ "$(wc -l <"$tmp/err")" -eq 1 ]
	assert "...that names the argument: $spec" grep -qF "$spec" "$tmp/err"
done
check_exit 2 "--zip with lists of different lengths" $ANVIL sweep --zip 'impact.velocity=1m/s,2m/s' 'layer.thickness=1r0'
check_exit 2 "--shard 0/4: shards count from 1" $ANVIL sweep 'impact.velocity=1m/s' --shard 0/4
assert "...says how to use Slurm's 0-based ids" grep -q 'SLURM_ARRAY_TASK_ID + 1' "$tmp/err"

# ---- the same bytes for any -j ----
SW="$D -m layer,halfspace layer.thickness=1r0,2r0,3r0 impact.velocity=2m/s,5m/s"
check "-j 1" $ANVIL sweep $SW -j 1 -o j1.tsv -q
check "-j 2" $ANVIL sweep $SW -j 2 -o j2.tsv -q
check "-j 5" $ANVIL sweep $SW -j 5 -o j5.tsv -q
assert "-j 1, 2 and 5 write the same bytes" sh -c 'cmp -s j1.tsv j2.tsv && cmp -s j1.tsv j5.tsv'

# ---- shards and merge ----
for k in 1 2 3 4; do
	$ANVIL sweep $SW --shard $k/4 -o sh$k.tsv -q -j 1
done
check "merge 4 shards" $ANVIL merge sh3.tsv sh1.tsv sh4.tsv sh2.tsv -o merged.tsv
assert "merged = unsharded, byte for byte" cmp -s merged.tsv j1.tsv
check_exit 2 "merge refuses a missing shard" $ANVIL merge sh1.tsv sh2.tsv sh4.tsv -o m2.tsv
assert "...naming the rows missing" grep -q 'rows .* missing' "$tmp/err"
assert "...and writes nothing" [ ! -e m2.tsv ]
check_exit 2 "merge refuses a shard given twice" $ANVIL merge sh1.tsv sh2.tsv sh2.tsv sh3.tsv sh4.tsv
check_exit 2 "merge refuses shards of another sweep" $ANVIL merge sh1.tsv s.tsv

# GNU parallel: examples/sweep-parallel.sh itself, on a small draft sweep
if command -v parallel >/dev/null 2>&1; then
	mkdir bin par
	ln -s "$ANVIL" bin/anvil
	ex=$src/examples/sweep-parallel.sh
	check "examples/sweep-parallel.sh: 3 shards by GNU parallel, merged" \
		sh -c "cd par && PATH=\"$tmp/bin:\$PATH\" AXES='layer.thickness=1r0,2r0,3r0 impact.velocity=2m/s,5m/s' \
			SWEEP_ARGS='$D -m layer,halfspace' sh '$ex' 3"
	$ANVIL sweep $SW -o j1.csv -q
	assert "GNU parallel + merge = unsharded, byte for byte" cmp -s par/rf.csv j1.csv
else
	skip "examples/sweep-parallel.sh" "no GNU parallel (Debian package 'parallel')"
	skip "GNU parallel + merge = unsharded" "no GNU parallel"
fi

# ---- interrupted, then resumed ----
LONG="$D -m layer layer.thickness=1..4r0:32 -s impact.velocity=2m/s -j 1"
check "the whole sweep" $ANVIL sweep $LONG -o long.tsv -q
$ANVIL sweep $LONG -o part.tsv -q 2>int.err &
pid=$!
# wait for the first two rows in the temporary file, then SIGTERM (what
# Slurm sends at the time limit; Ctrl-C's SIGINT takes the same path, but
# a background job of a script starts with SIGINT ignored)
n=0
while [ $n -lt 600 ]; do
	f=$(ls part.tsv.tmp* 2>/dev/null | head -1)
	[ -n "$f" ] && [ "$(wc -l <"$f" 2>/dev/null || echo 0)" -ge 3 ] && break
	kill -0 $pid 2>/dev/null || break
	sleep 0.05
	n=$((n + 1))
done
kill -TERM $pid 2>/dev/null || true
rc=0
wait $pid || rc=$?
if [ "$rc" -eq 143 ]; then
	ok 0 "SIGTERM: exit 143"
	assert "...says how far it got" grep -q 'interrupted: [0-9]* of 32 rows in part.tsv; continue with --resume' int.err
	assert "...leaves a valid partial file: a prefix of the whole" \
		sh -c 'n=$(wc -l <part.tsv); [ "$n" -ge 1 ] && [ "$n" -lt 33 ] && head -n "$n" long.tsv | cmp -s - part.tsv'
	assert "...and no temporary file" [ -z "$(ls part.tsv.tmp* 2>/dev/null)" ]
else
	skip "SIGTERM: exit 143" "the sweep ended (exit $rc) before the signal"
fi
check "--resume runs the rest" $ANVIL sweep $LONG -o part.tsv --resume -q
assert "resumed = uninterrupted, byte for byte" cmp -s part.tsv long.tsv
head -n 4 long.tsv >cut.tsv
printf '4\t32\t1.2' >>cut.tsv # a row cut short by a kill -9
check "--resume after a kill mid-row" $ANVIL sweep $LONG -o cut.tsv --resume -q
assert "...drops the cut row and completes the file" cmp -s cut.tsv long.tsv
# Wait (at most 30 s) until the sweep PID has opened OUT's temporary file,
# or ended.
wait_started() {
	local out=$1 pid=$2 n=0
	while [ $n -lt 600 ] && [ -z "$(ls "$out".tmp* 2>/dev/null)" ] && kill -0 "$pid" 2>/dev/null; do
		sleep 0.05
		n=$((n + 1))
	done
}
# A signal during a scene's layer row, with a model after it that still
# finishes (the half-space): the scene is no result, not a row "failed:
# cancelled" that --resume would then keep (qa5).
SLOW="-m layer,halfspace -s impactor.mass=1kg layer.thickness=0.02r0 solver.accuracy=reference -j 1"
$ANVIL sweep $SLOW -o slow.tsv -q 2>slow.err &
pid=$!
wait_started slow.tsv $pid
sleep 0.5 # into the layer row (about 2.3 s at reference; fine now ends in 0.8 s, near the signal)
sent=0
kill -TERM $pid 2>/dev/null && sent=1
rc=0
wait $pid || rc=$?
if [ "$sent" -eq 1 ] && [ "$rc" -ne 0 ]; then
	assert "SIGTERM in a scene's layer row, halfspace after it: exit 143" [ "$rc" -eq 143 ]

	assert "...no row of that scene (none 'cancelled')" \
		sh -c '[ "$(wc -l <slow.tsv)" -eq 1 ] && ! grep -q cancelled slow.tsv'
	assert "...says interrupted, not failed" grep -q 'interrupted: 0 of 2 rows' slow.err
else
	skip "SIGTERM in a scene's layer row, halfspace after it: exit 143" "the sweep ended (exit $rc) before the signal"
fi
# Two such scenes side by side, the signal 1.2 s in, while both still run
# (about 2.2 s each at reference; at fine they now end in 0.3-0.8 s, before
# the signal): the sweep ends at once, not when the runs under way do (qa7:
# 1.4-1.6 s later; now 10-20 ms)
SLOW2="-m layer -s impactor.mass=1kg -s solver.accuracy=reference layer.thickness=0.02r0,0.021r0 -j 2"
$ANVIL sweep $SLOW2 -o slow2.tsv -q 2>slow2.err &
pid=$!
wait_started slow2.tsv $pid
sleep 1.2
t0=$(date +%s%N)
sent=0
kill -TERM $pid 2>/dev/null && sent=1
rc=0
wait $pid || rc=$?
ms=$((($(date +%s%N) - t0) / 1000000))
if [ "$sent" -eq 1 ] && [ "$rc" -eq 143 ]; then
	assert "SIGTERM with two slow runs under way: ends at once ($ms ms, not their end)" [ "$ms" -lt 700 ]
	assert "...says interrupted, rows for --resume" grep -q 'interrupted: 0 of 2 rows in slow2.tsv' slow2.err
else
	skip "SIGTERM with two slow runs under way: ends at once" "the sweep ended (exit $rc) before the signal"
	skip "...says interrupted" "the sweep ended before the signal"
fi
cp long.tsv long.bak
check_exit 2 "--resume refuses another sweep's file" $ANVIL sweep $D -m hertz 'impact.velocity=1m/s' -o long.tsv --resume
assert "...and leaves it alone" cmp -s long.tsv long.bak

# ---- a velocity sweep shares one response per thickness (plan.h) ----
VS="$D -m layer impact.velocity=0.1..10m/s:25:log -j 1"
check "a 25-point velocity sweep, the paper's contact" $ANVIL sweep $VS -s effects.contact=paper -o vp.tsv -v
assert "...computes one layer response" grep -q '; 1 layer responses computed' "$tmp/err"
check "the same, the physical contact" $ANVIL sweep $VS -o vf.tsv -v
assert "...computes its 4 corrections once (point load and patch, the patch below, half the band)" \
	grep -q '; 4 layer responses computed' "$tmp/err"
for k in 1 2 3; do
	$ANVIL sweep $VS --shard $k/3 -o vf$k.tsv -q
done
check "its 3 shards merged" $ANVIL merge vf1.tsv vf2.tsv vf3.tsv -o vfm.tsv
assert "...= unsharded, byte for byte (every shard takes the same envelope)" cmp -s vfm.tsv vf.tsv
# a row against anvil run of its scene (no envelope): both within their
# error of the truth, so within the sum of each other's (man page, sweep)
$ANVIL run $D -m layer -s impact.velocity=1m/s -f tsv >v1.tsv 2>/dev/null
assert "a row = anvil run of its scene within the sum of their errors (t_s, P_max, R_f)" \
	awk -F'\t' 'NR == FNR && FNR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
		NR == FNR && $c["V0_m_s"] == 1 { t = $c["ts_us"]; te = $c["ts_err_us"]; p = $c["Pmax_kN"]
			pe = $c["Pmax_err_kN"]; r = $c["Rf"]; re = $c["Rf_err"]; n++; next }
		NR != FNR && FNR == 1 { for (i = 1; i <= NF; i++) d[$i] = i; next }
		NR != FNR { m++; ok = (t - $d["ts_us"])^2 <= (te + $d["ts_err_us"])^2 &&
			(p - $d["Pmax_kN"])^2 <= (pe + $d["Pmax_err_kN"])^2 &&
			(r - $d["Rf"])^2 <= (re + $d["Rf_err"])^2 }
		END { exit !(n == 1 && m == 1 && ok) }' vf.tsv v1.tsv

# ---- the response cache shared by concurrent processes ----
cache="$tmp/cache"
# The physical contact (the default): its corrections go through the
# shared cache as the paper's responses do.
CW="$D -m layer layer.thickness=1.5r0,2.5r0,3.5r0 impact.velocity=2m/s,4m/s -j 1"
for i in 1 2 3 4; do
	env -u ANVIL_NO_CACHE XDG_CACHE_HOME="$cache" $ANVIL sweep $CW -o c$i.tsv -q 2>c$i.err &
	eval "p$i=\$!"
done
bad=0
for i in 1 2 3 4; do eval "wait \$p$i" || bad=1; done
ok $bad "4 concurrent writers on one cache: all succeed"
$ANVIL sweep $CW -o c0.tsv -q
assert "...their rows equal a run without a cache" \
	sh -c 'for i in 1 2 3 4; do cmp -s c0.tsv c$i.tsv || exit 1; done'
assert "...no warning (no corrupt file seen)" sh -c '! cat c1.err c2.err c3.err c4.err | grep -q .'
assert "...no temporary file left in the cache" [ -z "$(find "$cache" -name '*tmp*' 2>/dev/null)" ]
env -u ANVIL_NO_CACHE XDG_CACHE_HOME="$cache" $ANVIL sweep $CW -o cw.tsv -v 2>cw.err
assert "a warm run computes no response" grep -q ' 0 layer responses computed' cw.err
assert "...and writes the same bytes" cmp -s cw.tsv c0.tsv
assert "...the cache holds 4 corrections per thickness (12 phys- files)" \
	[ "$(find "$cache" -name 'phys-draft-*.bin' | wc -l)" -eq 12 ]
CP="$D -m layer -s effects.contact=paper layer.thickness=1.5r0,2.5r0 impact.velocity=2m/s,4m/s -j 1"
env -u ANVIL_NO_CACHE XDG_CACHE_HOME="$cache" $ANVIL sweep $CP -o cp1.tsv -q
env -u ANVIL_NO_CACHE XDG_CACHE_HOME="$cache" $ANVIL sweep $CP -o cp2.tsv -v 2>cp.err
assert "the paper's contact beside them: warm, no response computed, the same bytes" \
	sh -c "grep -q ' 0 layer responses computed' cp.err && cmp -s cp1.tsv cp2.tsv"

# ---- thickness: against direct runs ----
check "thickness --within 2%" $ANVIL thickness $D --within 2% --rtol 2% -f tsv -o th.tsv --curve curve.tsv
h=$(awk -F'\t' 'NR == 2 { print $1 }' th.tsv)
hb=$(awk -F'\t' 'NR == 2 { print $3 }' th.tsv)
assert "the bisection closed to 2%" awk -v h="$h" -v b="$hb" 'BEGIN { exit !(h > b && h / b <= 1.02) }'
# deviation of the layer from the half-space at h, by anvil run
dev() {
	$ANVIL run $D -m layer,halfspace -s "layer.thickness=${1}r0" -f tsv 2>/dev/null | awk -F'\t' '
		NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
		{ ts[NR] = $c["ts_us"]; rf[NR] = $c["Rf"]; p[NR] = $c["Pmax_kN"] }
		END { d = 0; split("ts rf p", q, " ")
		      x = (ts[2] - ts[3]) / ts[3]; if (x < 0) x = -x; if (x > d) d = x
		      x = (rf[2] - rf[3]) / rf[3]; if (x < 0) x = -x; if (x > d) d = x
		      x = (p[2] - p[3]) / p[3]; if (x < 0) x = -x; if (x > d) d = x
		      print d }'
}
assert "at h, a direct run is within 2%" awk -v d="$(dev "$h")" 'BEGIN { exit !(d <= 0.02) }'
assert "just below, a direct run is not" awk -v d="$(dev "$hb")" 'BEGIN { exit !(d > 0.02) }'
assert "the curve lists every thickness tried, sorted" \
	sh -c 'awk -F"\t" "NR > 2 && \$1 <= p { exit 1 } { p = \$1 }" curve.tsv && [ $(wc -l <curve.tsv) -ge 5 ]'

# ---- fit: against direct runs ----
check "fit ts=60us+-1us for the thickness" $ANVIL fit $D ts=60us+-1us -f tsv -o fit.tsv
x=$(awk -F'\t' 'NR == 2 { print $3 }' fit.tsv)
lo=$(awk -F'\t' 'NR == 2 { print $4 }' fit.tsv)
hi=$(awk -F'\t' 'NR == 2 { print $5 }' fit.tsv)
ts_at() {
	$ANVIL run $D -m layer -s "layer.thickness=${1}r0" -f tsv 2>/dev/null |
		awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i } NR == 2 { print $c["ts_us"] }'
}
assert "a direct run at the answer gives 60 us (to 0.01 us)" \
	awk -v t="$(ts_at "$x")" 'BEGIN { d = t - 60; exit !(d < 0.01 && d > -0.01) }'
assert "the interval's ends give 60 -+ 1 us" \
	awk -v a="$(ts_at "$lo")" -v b="$(ts_at "$hi")" 'BEGIN { 
		d1 = a - 61; d2 = b - 59; if (a < b) { d1 = a - 59; d2 = b - 61 }
		exit !(d1 < 0.01 && d1 > -0.01 && d2 < 0.01 && d2 > -0.01) }'
check "fit Rf for the velocity" $ANVIL fit $D Rf=0.5 --for impact.velocity -m zener -f tsv -o fv.tsv
v=$(awk -F'\t' 'NR == 2 { print $3 }' fv.tsv)
assert "a direct run at that velocity gives R_f = 0.5 (to 1e-5)" awk -v r="$($ANVIL run $D -m zener \
	-s "impact.velocity=${v}m/s" -f tsv 2>/dev/null | awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i } NR == 2 { print $c["Rf"] }')" \
	'BEGIN { d = r - 0.5; exit !(d < 1e-5 && d > -1e-5) }'
check_exit 1 "fit: no solution in the range" $ANVIL fit $D ts=1ms -m hertz --for impact.velocity
assert "...says so with the values seen" grep -q 'no impact.velocity in .* gives ts = 1000 us .*: ts is' "$tmp/err"
check_exit 2 "fit: a time without a unit" $ANVIL fit ts=62
check_exit 2 "fit: an unknown unknown" $ANVIL fit ts=62us --for layer.rho

# ---- dem ----
check "dem table" $ANVIL dem $D -m zener --velocities 0.5..4m/s:4:log -o dem.csv
assert "header and 4 rows, SI" sh -c '[ "$(head -1 dem.csv)" = "velocity_m_s,restitution,contact_time_s,restitution_err,contact_time_err_s,status,contact,message" ] && [ $(wc -l <dem.csv) -eq 5 ]'
assert "its R_f and t_s are anvil run's" [ "$(awk -F, 'NR == 3 { printf "%.9g %.9g", $2, $3 * 1e6 }' dem.csv)" = \
	"$($ANVIL run $D -m zener -s impact.velocity=1m/s -f tsv 2>/dev/null | awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i } NR == 2 { printf "%.9g %.9g", $c["Rf"], $c["ts_us"] }')" ]
check_exit 2 "dem: bad velocities" $ANVIL dem --velocities 1..2m/s:0

# ---- charts from sweeps ----
check "plot restitution-velocity (script)" $ANVIL plot restitution-velocity $D -s layer.thickness=2r0 --script rv.gp
assert "...R_f against a log V0 axis, the half-space band and Zener dashed" \
	sh -c 'grep -q "set logscale x" rv.gp && grep -q "half-space" rv.gp && grep -q "Zener" rv.gp'
check "a V0 x h sweep for the map" $ANVIL sweep $D -m layer impact.velocity=1..10m/s:3:log layer.thickness=1r0,2r0,4r0 -o map.tsv -q
check "plot restitution-map FILE (script)" $ANVIL plot restitution-map map.tsv --script rm.gp
assert "...a heat map with contours over the 3 x 3 grid" \
	sh -c 'grep -q "set contour base" rm.gp && grep -q "with pm3d" rm.gp && [ $(grep -c "^[0-9.e+-]* [0-9.e+-]* [0-9.e+-]*$" rm.gp) -eq 9 ]'
check "a V0 x h sweep with both contacts" $ANVIL sweep $D -m layer -s effects.contact=both impact.velocity=1..10m/s:3:log layer.thickness=1r0,2r0 -o mapb.tsv -q
check "...its map" $ANVIL plot restitution-map mapb.tsv --script rmb.gp
assert "...its axes labelled at the swept values (a log axis under a decade has no labelled tic of gnuplot's own)" \
	sh -c 'grep -q "^set ytics (\"1\" 1, \"2\" 2)" rmb.gp && grep -q "^set xtics (\"1\" 1, " rmb.gp'
assert "...is the physical contact's, named in the title, 3 x 2 cells" \
	sh -c 'grep -q "physical contact" rmb.gp && [ $(grep -c "^[0-9.e+-]* [0-9.e+-]* [0-9.e+-]*$" rmb.gp) -eq 6 ]'
check_exit 2 "restitution-map: a file that is not a sweep's" $ANVIL plot restitution-map dem.csv --script x.gp
if [ -n "${GNUPLOT:-}" ] && command -v "$GNUPLOT" >/dev/null 2>&1; then
	check "restitution-map as PNG" $ANVIL plot restitution-map map.tsv -o rm.png
	assert "...a PNG" sh -c 'head -c 4 rm.png | grep -q PNG'
else
	skip "restitution-map as PNG" "no gnuplot"
	skip "...a PNG" "no gnuplot"
fi

done_testing
