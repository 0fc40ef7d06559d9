#!/bin/sh
# plot.sh: `anvil plot` and `anvil run --png` end to end: every chart kind
# gives a real PNG of the asked size that is not blank; hostile titles stay
# text; a missing or failing gnuplot is one clear error and leaves no file.
# The PNG tests are skipped when gnuplot is not installed.
. "${top_srcdir:-.}/tests/setup.sh"

GNUPLOT=${GNUPLOT:-gnuplot}
have_gnuplot=0
command -v "$GNUPLOT" >/dev/null 2>&1 && have_gnuplot=1
have_python=0
command -v python3 >/dev/null 2>&1 && have_python=1
# Layer models run at the cheapest level: these tests are about charts.
draft="-s solver.accuracy=draft"

# "WIDTH HEIGHT COLOURS" of a PNG, from its IHDR chunk and its decoded
# pixels (zlib, PNG filters undone), COLOURS counted up to 2 (not blank);
# "bad" when it is no PNG.
cat >"$tmp/pnginfo.py" <<'EOF'
import struct, sys, zlib
def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)
def main(path):
    d = open(path, 'rb').read()
    if d[:8] != b'\x89PNG\r\n\x1a\n' or d[12:16] != b'IHDR':
        return 'bad'
    w, h, depth, ctype = struct.unpack('>IIBB', d[16:26])
    idat, pos = b'', 8
    while pos < len(d):
        n, = struct.unpack('>I', d[pos:pos + 4])
        if d[pos + 4:pos + 8] == b'IDAT':
            idat += d[pos + 8:pos + 8 + n]
        pos += 12 + n
    raw = zlib.decompress(idat)
    bpp = max(1, {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype] * depth // 8)
    stride = (w * {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype] * depth + 7) // 8
    prev, colours = bytearray(stride), set()
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            line[i] = (line[i] + [0, a, b, (a + b) // 2, paeth(a, b, c)][f]) & 255
        for i in range(0, stride, bpp):
            colours.add(bytes(line[i:i + bpp]))
        prev = line
        if len(colours) > 1:
            break  # not blank: that is all we need to know
    return '%d %d %d' % (w, h, len(colours))
print(main(sys.argv[1]))
EOF

# Checks that $1 is a PNG of $2 x $3 pixels with more than one colour.
is_png() {
	if [ "$have_python" = 1 ]; then
		info=$(python3 "$tmp/pnginfo.py" "$1" 2>&1 || echo bad)
		set -- "$1" "$2" "$3" $info
		[ "$#" -eq 6 ] && [ "$4" = "$2" ] && [ "$5" = "$3" ] && [ "$6" -gt 1 ] && return 0
		diag "$1: got '$info', want $2 $3 and more than one colour"
		return 1
	fi
	# No python3: signature and size from `file`, not blank by a size
	# heuristic (a blank 8-bit PNG of this size compresses to < 2 kB).
	file "$1" | grep -q "PNG image data, $2 x $3" && [ "$(wc -c <"$1")" -gt 2000 ]
}
[ "$have_python" = 1 ] || diag "no python3: PNG pixels not decoded; 'file' and a size heuristic instead"

# A directory holds exactly the files named (no temporary left behind).
only_files() {
	dir=$1
	shift
	[ "$(cd "$dir" && ls -A)" = "$(printf '%s\n' "$@" | sed '/^$/d')" ]
}

# --- usage errors: no gnuplot needed -----------------------------------
check_exit 2 "unknown chart is a usage error" "$ANVIL" plot forse -o "$tmp/x.png"
assert "unknown chart suggests a name" grep -q "did you mean 'force'" "$tmp/err"
check_exit 2 "missing -o is a usage error" "$ANVIL" plot force
assert "missing -o is said" grep -q -- "-o" "$tmp/err"
check_exit 2 "-o - refused for a PNG" "$ANVIL" plot force -o -
check_exit 2 "bad --size refused" "$ANVIL" plot force -o "$tmp/x.png" --size 12
check "--help" "$ANVIL" plot --help
assert "--help lists every kind" grep -q "restitution-lambda" "$tmp/out"

# --- missing gnuplot: one line naming gnuplot, no file --------------------
mkdir "$tmp/none"
check_exit 1 "missing gnuplot: exit 1" env ANVIL_GNUPLOT=/nonexistent \
	"$ANVIL" plot force -s solver.models=hertz -o "$tmp/none/f.png"
assert "missing gnuplot: one line naming gnuplot" \
	test "$(grep -c gnuplot "$tmp/err")" -eq 1 -a "$(wc -l <"$tmp/err")" -eq 1
assert "missing gnuplot: no file left" only_files "$tmp/none"

# `anvil run --png` without gnuplot still writes the history.
check_exit 1 "run --png without gnuplot: exit 1" env ANVIL_GNUPLOT=/nonexistent \
	"$ANVIL" run -s solver.models=hertz,zener --png "$tmp/runpng" --history "$tmp/hist.tsv"
assert "run --png without gnuplot: the history is written" test -s "$tmp/hist.tsv"
assert "run --png without gnuplot: gnuplot named" grep -q gnuplot "$tmp/err"

# --- the script alone: no gnuplot needed ---------------------------------
check "--script without -o writes only the script" \
	"$ANVIL" plot restitution-lambda $draft --script "$tmp/rl.gp"
assert "the script has its data inline" grep -q '^\$d1 << EOD$' "$tmp/rl.gp"

hostile='it'"'"'s "q"
system("touch '"$tmp"'/pwned1") `touch '"$tmp"'/pwned2` @x ^_{}\'
check "hostile --title: script written" \
	"$ANVIL" plot force -s solver.models=hertz,zener --title "$hostile" --script -
assert "hostile --title: quoted on one line" grep -q \
	"^set label 1001 'it''s \"q\" system(\"touch .*pwned1\") \`touch .*pwned2\` @x ^_{}\\\\' at screen .* noenhanced\$" "$tmp/out"
check "a title with leading and doubled quotes: script written" \
	"$ANVIL" plot force -s solver.models=hertz --title "''x''y'" --script -
assert "leading quotes in their own piece" grep -q \
	"^set label 1001 \"''\".'x'.\"''\".'y''' at screen" "$tmp/out"
check "a short contact's time axis in us" \
	"$ANVIL" plot force -s solver.models=hertz,zener --script -
assert "t in us" grep -q "^set xlabel 't (µs)'" "$tmp/out"
check "a drop weight's time axis in ms (0.54 s contact: not 540000 us)" \
	"$ANVIL" plot force -s solver.models=hertz,zener -s layer.thickness=0.25r0 -s impactor.mass=2kg --script -
assert "t in ms, on a log axis (Hertz's contact is 1e-3 of Zener's)" grep -q "^set xlabel 't (ms), log scale'" "$tmp/out"
assert "the curve's last time in ms" awk '/^\$d/ { d = 1; next } /^EOD/ { d = 0 } d && $1 > m { m = $1 } END { exit !(m > 500 && m < 600) }' "$tmp/out"
assert "the log axis from a hundredth of the shortest contact" awk '/^set logscale x/ { l = 1 } /^set xrange \[/ && l { split($3, a, /[\[\]:]/); lo = a[2] } END { exit !(l && lo > 0 && lo < 0.01) }' "$tmp/out"
check "one long contact whose force peaks early: a log axis too" \
	"$ANVIL" plot force -s solver.models=zener -s layer.thickness=0.1r0 --script -
assert "...log scale (Zener's plate: P peaks at 4 us of 16 ms)" grep -q "^set xlabel 't (µs), log scale'" "$tmp/out"
assert "...its force in N (it peaks at 0.16 kN)" grep -q "^set ylabel 'contact force P (N)'" "$tmp/out"
check "a drop weight's deflection in mm (Zener's plate: 204 mm under 2 kg on r0/4)" \
	"$ANVIL" plot deflection -s solver.models=zener -s layer.thickness=0.25r0 -s impactor.mass=2kg --script -
assert "...w in mm" grep -q "^set ylabel 'deflection w (mm), + into the layer'" "$tmp/out"
assert "...its values in mm: over 1, under 1000" awk '/^\$d/ { d = 1; next } /^EOD/ { d = 0 } d && $2 > m { m = $2 } END { exit !(m > 1 && m < 1000) }' "$tmp/out"
check "a short contact's deflection stays in um" "$ANVIL" plot deflection -s solver.models=zener --script -
# Zener's 105 um at h = r0 beside 1.5 um at 10 r0, none below 0: log w, not |w|
assert "...w in um, on a log axis (peaks 70 times apart)" \
	grep -q "^set ylabel 'deflection w (µm), log scale'" "$tmp/out"
check "the brief's drop weight: the plate's 640 mm beside the half-space's +-0.47 um" \
	"$ANVIL" plot deflection -s solver.models=zener,halfspace -s layer.thickness=0.1r0 \
	-s impactor.mass=2kg -s impact.velocity=5m/s --script -
assert "...|w| on a log axis in mm (the physical half-space's w changes sign)" \
	grep -q "^set ylabel 'deflection |w| (mm), log scale'" "$tmp/out"
assert "...no value drawn below 0" awk '/^\$d/ { d = 1; next } /^EOD/ { d = 0 } d && $2 < 0 { exit 1 }' "$tmp/out"
check "a short contact's axis stays linear" \
	"$ANVIL" plot history -s solver.models=hertz,halfspace --script -
assert "no log axis" sh -c "! grep -q '^set logscale x' '$tmp/out'"
assert "the paper's cases with the paper's contact, said" grep -q "with the paper''s contact (effects.contact)" "$tmp/out"
# Without a SCENE: the paper's figures (its bodies at 10 or 100 m/s, at its
# thicknesses) with its contact; -s keys off them give the run's (physical).
check "the paper's Fig. 3 (-s impact.velocity=100m/s)" \
	"$ANVIL" plot force -s solver.models=hertz,halfspace -s impact.velocity=100m/s --script -
assert "...the paper's contact" grep -q "with the paper''s contact (effects.contact)" "$tmp/out"
check "...at a paper's thickness in mm (8 mm = 2 r0)" \
	"$ANVIL" plot force -s solver.models=hertz,halfspace -s layer.thickness=8mm --script -
assert "...the paper's contact" grep -q "with the paper''s contact (effects.contact)" "$tmp/out"
for off in impactor.mass=2kg impact.velocity=5m/s layer.thickness=0.1r0 layer.material=glass; do
	check "-s $off, no SCENE: not the paper's figure" \
		"$ANVIL" plot force -s solver.models=hertz,halfspace -s "$off" --script -
	assert "...the physical contact, as anvil run -s $off" \
		grep -q "with the physical contact (effects.contact)" "$tmp/out"
done
printf '[layer]\nthickness = 2 mm\n[solver]\naccuracy = draft\nmodels = layer\n' > "$tmp/user.scene"
check "a user's scene: its histories with its run's contact" \
	"$ANVIL" plot force "$tmp/user.scene" --script -
assert "the physical contact, said" grep -q "with the physical contact (effects.contact)" "$tmp/out"
check "...the same scene's table row" "$ANVIL" run "$tmp/user.scene" -f tsv
pmax=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "Pmax_kN") c = i } $1 == "layer" { print $c }' "$tmp/out")
"$ANVIL" plot force "$tmp/user.scene" --script - > "$tmp/userplot" 2>/dev/null
assert "...whose peak force ($pmax kN) the chart reaches" awk -v p="$pmax" \
	'/^\$d/ { d = 1; next } /^EOD/ { d = 0 } d && $2 > m { m = $2 } END { exit !(p > 0 && m > 0.97 * p && m <= 1.001 * p) }' "$tmp/userplot"
check "the examples' title names both materials: not said twice" \
	"$ANVIL" plot force -s solver.models=hertz --script -
assert "subtitle: title, then the numbers" grep -q "(Pyr'*yev et al. 2024): m = 12.2 g, r₀ = 4 mm" "$tmp/out"
check "a drop's history chart" "$ANVIL" plot history -s impact.drop_height=0.5m -s solver.models=hertz,zener --script -
assert "...its title gives V0 in three digits" grep -q "^set label 1001 'Contact force, impactor velocity and deflection, V_0 = 3.13 m/s'" "$tmp/out"
assert "...its subtitle names r0 once and leaves V0 to the title" \
	awk '/^set label 1002 / { n = gsub(/r₀ = /, ""); v = /V₀/ } END { exit !(n == 1 && !v) }' "$tmp/out"
check_exit 2 "an unknown image type is a usage error" "$ANVIL" plot force -o "$tmp/x.jpg"
assert "the image types are named" grep -q "png, .svg or .pdf" "$tmp/err"
check "restitution-thickness respects -s layer.thickness" \
	"$ANVIL" plot restitution-thickness $draft -s layer.thickness=5mm -s impact.velocity=10m/s --script -
assert "the scene's thickness is marked" grep -q "this scene: h = 1.25 r_0" "$tmp/out"
assert "h also in mm" grep -q "x2label 'h (mm), with r_0 = 4 mm'" "$tmp/out"
check "restitution-lambda without the paper's table" env ANVIL_PAPER_TABLES=/nonexistent \
	"$ANVIL" plot restitution-lambda $draft --script -
assert "paper values not found: said" grep -q "paper values not found" "$tmp/err"
assert "paper values not found: the rest drawn" grep -q "Zener''s ODE" "$tmp/out"

# --- restitution-velocity: a curve per material pair (issue 12) --------------
rvm="$ANVIL plot restitution-velocity $draft --velocities 1m/s,3m/s,10m/s"
check "restitution-velocity --materials: script written" \
	$rvm --materials copper/steel,steel/steel,glass --script "$tmp/rvm.gp"
assert "...a key entry per pair, in the palette's first colours" sh -c '
	grep -q "#0072b2'"'"' title '"'"'copper on steel'"'"'" "$1" &&
	grep -q "#d55e00'"'"' title '"'"'steel on steel'"'"'" "$1" &&
	grep -q "#009e73'"'"' title '"'"'copper on glass'"'"'" "$1"' sh "$tmp/rvm.gp"
assert "...per pair a layer line, its markers, Zener dashed and a tinted half-space band" sh -c '
	for c in 0072b2 d55e00 009e73; do
		[ $(grep -c "^.*\$d[0-9]* using 1:2 with lines lw 2 dt 1 lc rgb .#$c. notitle" "$1") -eq 1 ] &&
		[ $(grep -c "^.*\$d[0-9]* using 1:2 with points ps 1.6 lc rgb .#$c. pt 13 notitle" "$1") -eq 1 ] &&
		[ $(grep -c "^.*\$d[0-9]* using 1:2 with lines lw 2 dt (9,5) lc rgb .#$c. notitle" "$1") -eq 1 ] || exit 1
	done
	[ $(grep -c "with lines lw 6 dt 1 lc rgb .#[0-9a-f]*. notitle" "$1") -eq 3 ]' sh "$tmp/rvm.gp"
assert "...the bands drawn first (under the curves)" sh -c '
	awk "/^plot / { p = 1 } p && /notitle/ { n++; if (/lw 6/ && n > 3) exit 1; if (!/lw 6/ && n <= 3) exit 1 }" "$1"' sh "$tmp/rvm.gp"
assert "...the three velocities of each curve, the axis over them" sh -c '
	grep -q "^set xrange \[1:10\]$" "$1" && grep -q "^set xtics (1, 2, 5, 10)$" "$1" &&
	[ $(awk "/^\\\$d4 << EOD/ { p = 1; next } /^EOD/ { p = 0 } p" "$1" | wc -l) -eq 3 ]' sh "$tmp/rvm.gp"
assert "...a subtitle without the scene's own materials, the contact in the footnote" sh -c '
	grep -q "^set label 1002 .12.2 g impactor, r₀ = 4 mm, on a layer, h = 4 mm = 1 r₀; materials (impactor on layer) in the key." "$1" &&
	! grep "^set label 1002" "$1" | grep -q "Copper rod" &&
	grep -q "^set label 1003 .layer and half-space with the physical contact (effects.contact)." "$1"' sh "$tmp/rvm.gp"
check "restitution-velocity --materials with the paper's contact" \
	$rvm --materials steel -s effects.contact=paper --script "$tmp/rvp.gp"
assert "...LAYER alone keeps the scene's impactor; the footnote says paper" sh -c '
	grep -q "title .copper on steel." "$1" && grep -q "with the paper contact" "$1"' sh "$tmp/rvp.gp"
for bad in 'copper/' '/steel' 'unobtainium' 'copper/steel/glass' 'steel,' \
	'steel,steel,steel,steel,steel,steel,steel'; do
	check_exit 2 "restitution-velocity --materials '$bad' is refused" $rvm --materials "$bad" --script "$tmp/no.gp"
	assert "...naming the list or item, no script" sh -c 'grep -q -- "--materials" "$1" && [ ! -e "$2" ]' \
		sh "$tmp/err" "$tmp/no.gp"
done
check "restitution-velocity --materials with a ball (its mass follows its material)" \
	$rvm -s impactor.shape=ball -s impactor.diameter=10mm --materials copper/steel,steel/steel --script "$tmp/rvb.gp"
assert "...the masses in the key, not one mass in the subtitle" sh -c '
	grep -q "title .copper on steel, 4.69 g." "$1" && grep -q "title .steel on steel, 4.1 g." "$1" &&
	grep -q "^set label 1002 .impactor, r₀ = 5 mm, .* and masses in the key" "$1"' sh "$tmp/rvb.gp"
check_exit 2 "--materials on another chart is refused" "$ANVIL" plot force --materials steel --script -
check_exit 2 "--velocities with a bad range is refused" $rvm --velocities 1..10m/s:0 --script "$tmp/no.gp"
check "restitution-velocity per thickness: the contact in the footnote" \
	$rvm -s layer.thickness=2r0 --script "$tmp/rvh.gp"
assert "...physical (auto is not the paper's contact here)" grep -q "with the physical contact" "$tmp/rvh.gp"

if [ "$have_gnuplot" = 0 ]; then
	for k in force velocity deflection history restitution-thickness restitution-lambda \
		accuracy formats injection failing-gnuplot killed run-png expected-scripts \
		restitution-velocity-materials; do
		skip "$k PNG" "gnuplot ($GNUPLOT) not installed"
	done
	done_testing
	exit
fi

# --- every chart kind ----------------------------------------------------
for k in force velocity deflection history restitution-thickness restitution-lambda accuracy; do
	mkdir "$tmp/$k"
	check "$k: exit 0" "$ANVIL" plot "$k" $draft -o "$tmp/$k/$k.png" --size 640x480
	assert "$k: a 640x480 PNG, not blank" is_png "$tmp/$k/$k.png" 640 480
	assert "$k: no temporary file left" only_files "$tmp/$k" "$k.png"
done
check "history: taller by default" "$ANVIL" plot history -s solver.models=hertz,zener \
	-o "$tmp/hist.png"
assert "history: an 800x1000 PNG" is_png "$tmp/hist.png" 800 1000

# --- restitution-velocity per material pair, as a PNG ------------------------
mkdir "$tmp/rvmat"
check "restitution-velocity --materials: exit 0" $rvm --materials copper/steel,steel/steel,glass \
	-o "$tmp/rvmat/rv.png"
assert "restitution-velocity --materials: an 800x600 PNG, not blank" is_png "$tmp/rvmat/rv.png" 800 600

# --- SVG and PDF by the extension ----------------------------------------
check "SVG by extension" "$ANVIL" plot force -s solver.models=hertz,zener -o "$tmp/f.svg"
assert "an SVG" grep -q "<svg" "$tmp/f.svg"
check "PDF by extension" "$ANVIL" plot velocity -s solver.models=hertz,zener -o "$tmp/f.pdf"
assert "a PDF" test "$(head -c 4 "$tmp/f.pdf")" = "%PDF"
check "a leading quote in the title renders" "$ANVIL" plot force -s solver.models=hertz \
	--title "'x" -o "$tmp/q.png"
assert "a leading quote: a PNG" is_png "$tmp/q.png" 800 600
check "--font and --title" "$ANVIL" plot force -s solver.models=hertz,zener \
	-o "$tmp/font.png" --size 300x200 --font "DejaVu Sans,8" --title "small"
assert "--font: a 300x200 PNG" is_png "$tmp/font.png" 300 200

# --- injection: nothing runs, the chart still renders ---------------------
check "hostile --title: rendered" "$ANVIL" plot force -s solver.models=hertz,zener \
	-o "$tmp/inj.png" --title "$hostile"
assert "hostile --title: a PNG" is_png "$tmp/inj.png" 800 600
printf '[scene]\ntitle = x'"'"'); system("touch %s/pwned3"); print(`touch %s/pwned4`\n[solver]\nmodels = hertz, zener\n' \
	"$tmp" "$tmp" >"$tmp/evil.scene"
check "hostile scene title: rendered" "$ANVIL" plot velocity "$tmp/evil.scene" -o "$tmp/inj2.png"
assert "hostile scene title: a PNG" is_png "$tmp/inj2.png" 800 600
check "hostile font name: rendered" "$ANVIL" plot force -s solver.models=hertz \
	-o "$tmp/inj3.png" --font "Sans,9'; system('touch $tmp/pwned5'); '"
assert "nothing was executed" test ! -e "$tmp/pwned1" -a ! -e "$tmp/pwned2" \
	-a ! -e "$tmp/pwned3" -a ! -e "$tmp/pwned4" -a ! -e "$tmp/pwned5"

# --- a failing gnuplot: anvil's line, gnuplot's words, no file -------------
mkdir "$tmp/fail"
printf '#!/bin/sh\ncat >/dev/null\necho "line 7: undefined function: frobnicate" >&2\nexit 1\n' \
	>"$tmp/fake-gnuplot"
chmod +x "$tmp/fake-gnuplot"
check_exit 1 "failing gnuplot: exit 1" env ANVIL_GNUPLOT="$tmp/fake-gnuplot" \
	"$ANVIL" plot force -s solver.models=hertz -o "$tmp/fail/f.png"
assert "failing gnuplot: named, with its own message" \
	grep -q "gnuplot.*exit status 1" "$tmp/err"
assert "failing gnuplot: its error text shown" grep -q "frobnicate" "$tmp/err"
assert "failing gnuplot: no file left" only_files "$tmp/fail"

# --- a killed plot: no temporary file, no gnuplot left -------------------
mkdir "$tmp/kill"
printf '#!/bin/sh\ncat >/dev/null\necho $$ >"%s/gp.pid"\nexec sleep 60\n' "$tmp" >"$tmp/slow-gnuplot"
chmod +x "$tmp/slow-gnuplot"
ANVIL_GNUPLOT="$tmp/slow-gnuplot" "$ANVIL" plot force -s solver.models=hertz \
	-o "$tmp/kill/f.png" 2>"$tmp/kill.err" &
anvil_pid=$!
i=0
while [ ! -s "$tmp/gp.pid" ] && [ $i -lt 200 ]; do sleep 0.05; i=$((i + 1)); done
kill -TERM "$anvil_pid"
rc=0
wait "$anvil_pid" || rc=$?
assert "killed plot: ended by SIGTERM" test "$rc" -eq 143
assert "killed plot: no temporary file" only_files "$tmp/kill"
gp=$(cat "$tmp/gp.pid" 2>/dev/null || echo 0)
assert "killed plot: its gnuplot is gone" sh -c '! kill -0 "$1" 2>/dev/null' sh "$gp"
[ "$gp" = 0 ] || kill -KILL "$gp" 2>/dev/null || true

# --- anvil run --png DIR ---------------------------------------------------
check "run --png: exit 0" "$ANVIL" run -s solver.models=hertz,zener \
	--png "$tmp/runpng2" --history "$tmp/hist2.tsv"
for k in force velocity deflection; do
	assert "run --png: $k.png" is_png "$tmp/runpng2/$k.png" 800 600
done
assert "run --png: the history too" test -s "$tmp/hist2.tsv"

# --- the expected scripts of test_plot are valid gnuplot -------------------
for f in "$top_srcdir"/tests/plot-expected/*.gp; do
	b=$(basename "$f" .gp)
	check "expected script $b renders" sh -c '"$1" "$2" >"$3"' sh "$GNUPLOT" "$f" "$tmp/exp-$b.png"
	assert "expected script $b: a PNG" is_png "$tmp/exp-$b.png" \
		"$(sed -n 's/.*size \([0-9]*\),.*/\1/p' "$f" | head -1)" \
		"$(sed -n 's/.*size [0-9]*,\([0-9]*\).*/\1/p' "$f" | head -1)"
done

done_testing
