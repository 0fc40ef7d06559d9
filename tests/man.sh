#!/bin/sh
# man.sh: the manual is clean for groff and mandoc, and its EXAMPLES run.
. "$top_srcdir/tests/setup.sh"

page=$top_srcdir/man/anvil.1
[ -f "$page" ] || skip_all "no $page"

# ---- lint ----
if command -v groff >/dev/null 2>&1; then
	check 'groff -man -ww -z exits 0' groff -man -ww -z "$page"
	assert 'groff -man -ww -z: no warnings' [ ! -s "$tmp/err" ]
	sed 's/^/#   /' "$tmp/err"
else
	skip 'groff -man -ww -z exits 0' 'no groff'
	skip 'groff -man -ww -z: no warnings' 'no groff'
fi
if command -v mandoc >/dev/null 2>&1; then
	check 'mandoc -Tlint -Wwarning is clean' mandoc -Tlint -Wwarning "$page"
	sed 's/^/#   /' "$tmp/out"
else
	skip 'mandoc -Tlint -Wwarning is clean' 'no mandoc'
fi

# ---- every command the manual documents ----
for c in run table materials accuracy plot tui sweep merge thickness fit dem; do
	assert "COMMANDS documents $c" grep -Eq "^\.(B|BI) $c( |\$)" "$page"
done

# ---- EXAMPLES ----
# A sentence that starts a line starts a paragraph: "...on a terminal:
# .B anvil tui" ran on into "A restitution table..." (qa5).
assert 'EXAMPLES: each capitalised text line opens a paragraph (.PP)' awk '
	/^\.SH /      { ex = ($0 == ".SH EXAMPLES"); prev = $0; next }
	!ex            { next }
	/^\.EX/        { in_ex = 1 }
	/^\.EE/        { in_ex = 0 }
	!in_ex && /^[A-Z]/ && prev !~ /^\.(PP|SH)/ { print "after " prev ": " $0; bad = 1 }
	{ prev = $0 }
	END { exit bad }' "$page"
# The "$ command" lines of the .EX blocks of EXAMPLES, with the roff
# escapes used there turned back into what a user types.
awk '/^\.SH /      { ex = ($0 == ".SH EXAMPLES"); next }
     ex && /^\.EX/ { in_ex = 1; next }
     ex && /^\.EE/ { in_ex = 0; next }
     ex && in_ex && /^\$ / { print substr($0, 3) }' "$page" |
	sed -e 's/\\-/-/g' -e "s/\\\\(aq/'/g" -e 's/\\&//g' -e 's/\\e/\\/g' >"$tmp/examples"
n=$(wc -l <"$tmp/examples" | tr -d ' ')
assert "EXAMPLES has commands ($n)" [ "$n" -ge 5 ]

# The examples call `anvil`: put the binary under test first on PATH and
# run them in a scratch directory beside the source tree's examples/.
mkdir "$tmp/bin" "$tmp/ex"
ln -s "$ANVIL" "$tmp/bin/anvil"
srcdir_abs=$(cd "$top_srcdir" && pwd)
ln -s "$srcdir_abs/examples" "$tmp/ex/examples"
gnuplot=${GNUPLOT:-gnuplot}
command -v "$gnuplot" >/dev/null 2>&1 && have_gnuplot=1 || have_gnuplot=0

while IFS= read -r cmd; do
	case $cmd in
	*'anvil plot'* | *--png*)
		if [ "$have_gnuplot" -eq 0 ]; then
			skip "example: $cmd" 'no gnuplot'
			continue
		fi ;;
	esac
	if (cd "$tmp/ex" && PATH="$tmp/bin:$PATH" sh -c "$cmd") </dev/null >"$tmp/out" 2>"$tmp/err"; then
		ok 0 "example: $cmd"
	elif grep -q 'is not available' "$tmp/err"; then
		# A model still being written; the example will run once it is in.
		skip "example: $cmd" "$(head -n 1 "$tmp/err")"
	else
		ok 1 "example: $cmd"
		sed 's/^/#   /' "$tmp/err"
	fi
done <"$tmp/examples"

done_testing
