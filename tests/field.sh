#!/bin/sh
# field.sh: `anvil field` and `anvil map`: exit codes, TSV columns, the
# yield check in the output, atomic output files, the heat map's script
# (and its PNG where gnuplot is installed).  Draft accuracy: these tests
# are about the command line; tests/test_field checks the numbers.
# The awk programs are arguments of assert: their $ are awk's.
# shellcheck disable=SC2016
. "$top_srcdir/tests/setup.sh"

D="-s solver.accuracy=draft"
HEADER='r_mm	z_mm	t_us	P_kN	u_um	u_err_um	w_um	w_err_um	szz_MPa	szz_err_MPa	srr_MPa	srr_err_MPa	stt_MPa	stt_err_MPa	srz_MPa	srz_err_MPa	vm_MPa	vm_err_MPa'

columns() { grep -v '^#' "$1" | head -n 1; }
rows() { grep -v '^#' "$1" | tail -n +2 | wc -l | tr -d ' '; }
lines() { wc -l <"$1" | tr -d ' '; }
no_tmp() { [ -z "$(ls -A "$1")" ] || ! ls "$1" | grep -q tmp; }

# ---- help and dispatch ----
check '--help lists field' "$ANVIL" --help
assert '--help lists field and map' sh -c "grep -q '^  field ' '$tmp/out' && grep -q '^  map ' '$tmp/out'"
check 'field --help exits 0' "$ANVIL" field --help
check 'map --help exits 0' "$ANVIL" map --help

# ---- field: output ----
check 'field at two points' "$ANVIL" field $D -q --at 0,2mm --at 0.5r0,1r0
cp "$tmp/out" "$tmp/two.tsv"
assert 'field: the documented columns' [ "$(columns "$tmp/two.tsv")" = "$HEADER" ]
assert 'field: 201 samples per point' [ "$(rows "$tmp/two.tsv")" -eq 402 ]
assert 'field: every row has 18 fields' \
	awk -F '\t' '!/^#/ && NF != 18 { bad = 1 } END { exit bad }' "$tmp/two.tsv"
assert 'field: the points are r, z in mm' \
	awk -F '\t' '!/^#/ && $1 ~ /^[0-9.eE+-]+$/ && !(($1 == 0 && $2 == 2) || ($1 == 2 && $2 == 4)) { bad = 1 } END { exit bad }' "$tmp/two.tsv"
assert 'field: time from 0 to the contact time, P = 0 at both ends' \
	awk -F '\t' '!/^#/ && $1 == 0 && $3 == 0 { a = ($4 == 0) } END { exit !a }' "$tmp/two.tsv"
assert 'field: the yield check is reported' grep -q '^# yield check: peak von Mises .* MPa .* at r = .* t = .* us' "$tmp/two.tsv"
assert 'field: the impact is described' grep -q '^# layer, h = 4 mm, r0 = 4 mm: contact' "$tmp/two.tsv"

check 'field --quantity w,vm' "$ANVIL" field $D -q --at 0,1mm --quantity w,vm --no-yield
assert '--quantity selects the columns' \
	[ "$(columns "$tmp/out")" = "$(printf 'r_mm\tz_mm\tt_us\tP_kN\tw_um\tw_err_um\tvm_MPa\tvm_err_MPa')" ]
assert '--no-yield says so' grep -q '^# yield check: not done' "$tmp/out"
assert 'w grows into the layer: positive at the peak force' \
	awk -F '\t' '!/^#/ && $1 ~ /^[0-9.eE+-]+$/ && $5 > 0 { pos = 1 } END { exit !pos }' "$tmp/out"
grep -v '^#' "$tmp/out" >"$tmp/noyield.cols"
check 'the same field with the yield check' "$ANVIL" field $D -q --at 0,1mm --quantity w,vm
assert '...the same columns (the r0 patch of the paper either way: --no-yield skips the check only)' \
	sh -c "grep -v '^#' '$tmp/out' | cmp -s - '$tmp/noyield.cols'"

check 'field on a half-space' "$ANVIL" field $D -q -s layer.thickness=inf --at 0,10mm --quantity szz
assert 'half-space: h = inf in the description' grep -q '^# halfspace, h = inf, r0 = 4 mm' "$tmp/out"

# ---- field: bad input ----
check_exit 2 'no --at: exit 2' "$ANVIL" field $D
assert 'no --at: says so' grep -q 'no point given' "$tmp/err"
check_exit 2 '--at without a comma: exit 2' "$ANVIL" field $D --at 2mm
assert 'bad --at: names the option and shows the form' grep -q "\-\-at '2mm': expected R,Z" "$tmp/err"
assert 'bad --at: one line' [ "$(lines "$tmp/err")" -eq 1 ]
check_exit 2 '--at with a bad length: exit 2' "$ANVIL" field $D --at 0,two
check_exit 2 '--at below the bottom face: exit 2' "$ANVIL" field $D --at 0,5mm
assert 'below the bottom: says where the layer is' grep -q 'outside the layer, 0 to h = 4 mm' "$tmp/err"
check_exit 2 '--at with a bare depth (no unit): exit 2' "$ANVIL" field $D --at 0,0.002
assert 'a bare number: asks for units' grep -q "expected two lengths R,Z with units" "$tmp/err"
check 'a bare 0 needs no unit: --at 0,2mm' "$ANVIL" field $D --at 0,2mm --quantity w -q
check_exit 2 'map: --depth without a unit: exit 2' "$ANVIL" map $D --time 3us --depth 0.002
check_exit 2 '--at with a negative radius: exit 2' "$ANVIL" field $D --at -1mm,1mm
check_exit 2 'unknown quantity: exit 2' "$ANVIL" field $D --at 0,1mm --quantity sxx
check_exit 2 'a map option: exit 2' "$ANVIL" field $D --at 0,1mm --time 3us
assert 'a map option: names the command it belongs to' grep -q "time is an option of 'anvil map'" "$tmp/err"
check_exit 2 'bad scene key: exit 2' "$ANVIL" field $D --at 0,1mm -s layer.thicknes=2r0

# ---- atomic output ----
mkdir "$tmp/o"
check 'field -o FILE' "$ANVIL" field $D -q --at 0,1mm --quantity w -o "$tmp/o/f.tsv"
assert '-o: the file is there, complete' [ "$(rows "$tmp/o/f.tsv")" -eq 201 ]
assert '-o: nothing on standard output' [ ! -s "$tmp/out" ]
check_exit 2 'bad --at with -o: exit 2' "$ANVIL" field $D --at 0,9mm -o "$tmp/o/g.tsv"
assert 'bad --at with -o: no file, no temporary' sh -c "[ ! -e '$tmp/o/g.tsv' ] && ! ls '$tmp/o' | grep -q tmp"
check_exit 1 '-o into a missing directory: exit 1' "$ANVIL" field $D --at 0,1mm -o "$tmp/none/f.tsv"
assert 'missing directory: no temporary left' no_tmp "$tmp/o"

# ---- map ----
check 'map --grid 20x10' "$ANVIL" map $D -q --grid 20x10
cp "$tmp/out" "$tmp/map.tsv"
assert 'map: columns r_mm z_mm vm_MPa vm_err_MPa' \
	[ "$(columns "$tmp/map.tsv")" = "$(printf 'r_mm\tz_mm\tvm_MPa\tvm_err_MPa')" ]
assert 'map: 20 x 10 rows' [ "$(rows "$tmp/map.tsv")" -eq 200 ]
assert 'map: r from 0 to 3 r0, z from 0 to h' \
	awk -F '\t' '!/^#/ && $1 ~ /^[0-9.eE+-]+$/ { r = $1 > r ? $1 : r; z = $2 > z ? $2 : z } END { exit !(r == 12 && z == 4) }' "$tmp/map.tsv"
assert 'map: at the peak force by default' grep -q '^# anvil map: von Mises stress at t = 17.2' "$tmp/map.tsv"
assert 'map: it names its load, the paper'"'"'s patch, beside the verdict'"'"'s true contact' \
	grep -q "^# anvil map: .* over the paper's patch, r0 = 4 mm; the yield verdict takes the true contact radius" "$tmp/map.tsv"
assert 'map: the yield check' grep -q '^# yield check: peak von Mises' "$tmp/map.tsv"
assert 'map: von Mises >= 0 everywhere' awk -F '\t' '!/^#/ && $1 ~ /^[0-9.eE+-]+$/ && $3 < 0 { bad = 1 } END { exit bad }' "$tmp/map.tsv"

check 'map of sigma_zz at ts on a half-space' "$ANVIL" map $D -q -s layer.thickness=inf --time ts \
	--quantity szz --rmax 2r0 --depth 8mm --grid 5x5
assert 'half-space map: depth 8 mm, radius 8 mm' \
	awk -F '\t' '!/^#/ && $1 ~ /^[0-9.eE+-]+$/ { r = $1 > r ? $1 : r; z = $2 > z ? $2 : z } END { exit !(r == 8 && z == 8) }' "$tmp/out"

printf '[layer]\nyield = 150 MPa\n' >"$tmp/soft.scene"
check 'a soft layer' "$ANVIL" map $D -q --grid 4x4 "$tmp/soft.scene"
assert 'yield exceeded: the verdict in the output' grep -q '^# verdict: the steel layer yields: .* Y = 150 MPa' "$tmp/out"
assert 'yield exceeded: the verdict on stderr' grep -q '^anvil: the steel layer yields: peak von Mises .* Y = 150 MPa' "$tmp/err"

check_exit 2 'map: bad --time' "$ANVIL" map $D --time soon
check_exit 2 'map: --time past 4 contacts' "$ANVIL" map $D --time 1ms
assert '--time too late: says the range' grep -q 'must lie in 0 ..' "$tmp/err"
check_exit 2 'map: bad --grid' "$ANVIL" map $D --grid 1x100
check_exit 2 'map: --depth below the layer' "$ANVIL" map $D --depth 5mm
check_exit 2 'map: two quantities' "$ANVIL" map $D --quantity szz,vm
check_exit 2 'map: --at belongs to field' "$ANVIL" map $D --at 0,1mm

# ---- the heat map ----
check 'map --script' "$ANVIL" map $D -q --grid 30x20 --time 2us --quantity szz -s layer.thickness=2r0 \
	--script "$tmp/map.gp"
assert 'script: the map as an image' grep -q '^plot \$map using 1:2:3 with image' "$tmp/map.gp"
assert 'script: depth downwards' grep -q '^set yrange \[8:0\]' "$tmp/map.gp"
assert 'script: symmetric colours for a signed stress' grep -q '^set cbrange \[-' "$tmp/map.gp"
assert 'script: the S front and the P reflection are drawn' \
	sh -c "grep -q \"title 'S wave\" '$tmp/map.gp' && grep -q \"title 'P reflected from the bottom'\" '$tmp/map.gp'"
assert 'script: the Rayleigh front is drawn' grep -q "title 'Rayleigh wave" "$tmp/map.gp"
assert 'script: the note under the map names the load' grep -q "load: patch r0 = 4 mm (the verdict: true contact)" "$tmp/map.gp"
assert 'script: 20 rows of 30 points' [ "$(awk '/^\$map/ { on = 1; next } /^EOD/ { on = 0 } on && NF == 3' "$tmp/map.gp" | wc -l | tr -d ' ')" -eq 600 ]
assert '--script only: no TSV on standard output' [ ! -s "$tmp/out" ]

gnuplot=${GNUPLOT:-gnuplot}
if command -v "$gnuplot" >/dev/null 2>&1; then
	check 'map --png' "$ANVIL" map $D -q --grid 30x20 --png "$tmp/map.png"
	assert 'a PNG file' sh -c "head -c 8 '$tmp/map.png' | od -An -c | grep -q 'P   N   G'"
else
	skip 'map --png' 'no gnuplot'
	skip 'a PNG file' 'no gnuplot'
fi
check_exit 1 'map --png with a gnuplot that is not there: exit 1' env ANVIL_GNUPLOT=/nonexistent/gnuplot \
	"$ANVIL" map $D -q --grid 4x4 --png "$tmp/o/x.png"
assert 'no gnuplot: no PNG left' [ ! -e "$tmp/o/x.png" ]

# A contact 4e4 times 2h/c1 long: its field is refused at once, with the
# work it would take, not computed for over an hour.  (500 g was 71 ms
# here; its grazing end now answers at rest from 9 ms, impact_rest.c, a
# field of 40 s.)
check_exit 1 'the field of an 89 ms contact on a 2 mm plate: refused' "$ANVIL" field -q --no-yield \
	-s impactor.mass=5kg -s layer.thickness=2mm -s impact.velocity=1m/s -s solver.accuracy=draft \
	--at 0,2mm --quantity srr
assert '...saying how much work, and what judges it instead' \
	grep -q "^anvil: field: at least [0-9.]* min of work (.* Fourier terms on .* k panels: .*), over the budget of 10 min; anvil run judges such a contact by quasi-static Hertz" "$tmp/err"
assert '...and nothing on stdout' [ ! -s "$tmp/out" ]

# A thin plate where the paper's contact runs away (its r0 patch on an 80 um
# plate chatters: the plan refuses it, plan_paper.c) while `anvil run` answers: the
# impactor comes to rest on the plate (t_s = 14.7 s).  field takes run's
# row, says so, and refuses that load's window (5.5e8 times 2h/c1) in one
# line that names it, with run's own t_s: the same impact.
T="-s layer.thickness=0.02r0 -s impactor.mass=1kg"
check 'the thin plate: anvil run answers' "$ANVIL" run -q -m layer $T --format tsv
ts_run=$(awk -F '\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "ts_us") c = i; next } { print $c }' "$tmp/out")
check_exit 1 'the thin plate: field refuses the window, exit 1' "$ANVIL" field -q --at 0,0.05mm $T
assert "...saying the paper's contact failed and run's row (physical) loads the patch" \
	grep -q "^anvil: field: the paper's contact gives no force (layer: the paper's contact chatters on this plate .*); anvil run's row, the physical contact's, loads the r0 patch instead$" "$tmp/err"
assert '...then why not, in one line: the window against 2h/c1' \
	grep -q "^anvil: field: the load lasts [0-9.e+]* ms, [0-9.e+]* times 2h/c1: its window needs more Fourier terms than the bound of [0-9]*; anvil run judges such a contact by quasi-static Hertz$" "$tmp/err"
# (the load ends one of its 2000 history steps after t_s, printed to 4 digits)
assert "...whose load is run's contact (t_s $ts_run us)" \
	awk -v ts="$ts_run" '/the load lasts/ { for (i = 1; i <= NF; i++) if ($i == "lasts") ms = $(i + 1) }
		END { d = ms * 1e3 / ts - 1 - 1 / 2000; exit !(ts > 0 && d * d < 2.5e-7) }' "$tmp/err"
assert '...two lines on stderr, nothing on stdout' sh -c "[ \$(wc -l <'$tmp/err') -eq 2 ] && [ ! -s '$tmp/out' ]"

done_testing
