#!/bin/sh
# errors.sh: a hurried user's mistakes (qa7's break-it pass): each is
# refused or said in one line naming what is wrong, exits non-zero, and
# leaves nothing half-written; devices, links and FIFOs given as outputs
# stay what they are.
. "${top_srcdir:-.}/tests/setup.sh"

M=-mhertz,zener
K=$tmp/k
mkdir "$K"
no_tmp() { [ -z "$(find "$K" -name '*.tmp*' -o -name '.*.??????')" ]; }

# ---- write failures are said, with the file and the reason ----
# (qa7: a history larger than the stream's buffer failed inside the
# writer, and run exited 1 without a word)
if [ -c /dev/full ]; then
	check_exit 1 'run --history /dev/full: exit 1' "$ANVIL" run $M --history /dev/full -o "$K/r.tsv"
	assert '...saying which file and why' grep -q '^anvil: /dev/full: write failed: No space left' "$tmp/err"
	assert '...and the results file is not left behind' [ ! -e "$K/r.tsv" ]
	check_exit 1 'run --history /dev/full, the table on standard output: exit 1' \
		"$ANVIL" run -q $M --history /dev/full
	assert '...one line, the history file (standard output was not written to)' \
		sh -c '[ "$(wc -l <"$0")" -eq 1 ] && grep -q "^anvil: /dev/full: write failed" "$0"' "$tmp/err"
	check_exit 1 'run -f json > /dev/full: exit 1' sh -c "\"\$ANVIL\" run $M -f json >/dev/full"
	assert '...saying so' grep -q '^anvil: standard output: write failed: No space left' "$tmp/err"
	# (qa7: "table: input/output error", "field: ...", "sweep: write failed")
	for c in "table -f json" "field --at 0,1mm --no-yield -q" "map --grid 30x30 --no-yield -q" \
		"sweep impact.velocity=1..10m/s:40 -m hertz" "plot force --script -"; do
		check_exit 1 "$c > /dev/full: exit 1" sh -c "\"\$ANVIL\" $c >/dev/full"
		assert "...saying what and why" grep -q '^anvil: standard output: write failed: No space left' "$tmp/err"
	done
	check_exit 1 'sweep -o /dev/full: exit 1' "$ANVIL" sweep impact.velocity=1..10m/s:40 -m hertz -o /dev/full
	assert '...naming the file' grep -q '^anvil: /dev/full: write failed: No space left' "$tmp/err"
else
	for t in $(seq 17); do skip "write failures ($t)" 'no /dev/full'; done
fi

# ---- plot's outputs: links followed, devices written into ----
# (qa7: the script and the image were renamed onto the path given: a
# link was replaced by a file, and as root --script /dev/full replaced
# the device with a regular file)
ln -s target.gp "$K/link.gp"
check 'plot --script onto a link' "$ANVIL" plot force --script "$K/link.gp"
assert '...the link is still a link' [ -L "$K/link.gp" ]
assert '...and the file it names has the script' grep -q '^# anvil chart' "$K/target.gp"
mkdir "$K/dir"
check_exit 1 'plot --script a directory: exit 1' "$ANVIL" plot force --script "$K/dir"
assert '...saying it is a directory' grep -q 'dir: is a directory' "$tmp/err"
if [ "$(id -u)" = 0 ] && mknod "$K/full" c 1 7 2>/dev/null; then
	check_exit 1 'plot --script into a full device: exit 1' "$ANVIL" plot force --script "$K/full"
	assert '...saying why' grep -q 'full: write failed: No space left' "$tmp/err"
	assert '...and the device is still a device' [ -c "$K/full" ]
	check_exit 1 'map --script into it: exit 1' "$ANVIL" map --grid 4x4 --no-yield -q --script "$K/full" -o "$K/m.tsv"
	assert '...the device is still a device' [ -c "$K/full" ]
else
	for t in 1 2 3 4 5; do skip "plot into a device ($t)" 'not root (mknod)'; done
fi

# ---- a closed pipe ----
# (qa7: SIGPIPE's default killed anvil with the results' temporary file
# beside r.tsv; now the handler removes it, and the status is still 141)
# (hertz, zener and the half-space: a history of 130 kB, beyond a pipe's 64 kB)
sh -c "\"\$ANVIL\" run -q -m hertz,zener,halfspace --history - -o \"$K/r.tsv\"; echo \$? >\"$K/rc\"" |
	head -c 1 >/dev/null
assert 'run --history - | head: 141, as SIGPIPE' [ "$(cat "$K/rc")" = 141 ]
assert '...and neither the results nor their temporary file are left' \
	sh -c "[ ! -e '$K/r.tsv' ] && [ -z \"\$(find '$K' -name 'r.tsv.tmp*')\" ]"

# ---- an empty file name ----
# (qa7: "anvil: : write failed: No such file or directory")
for c in "run $M -o" "run $M --history" "plot force --script" "sweep impact.velocity=1m/s -m hertz -o"; do
	check_exit 1 "$c '': exit 1" $ANVIL $c ''
	assert '...saying the name is empty' grep -q '^anvil: an empty output file name' "$tmp/err"
done

# ---- a range typed as elsewhere ----
check_exit 2 'sweep impact.velocity=1:1e6:1: exit 2' $ANVIL sweep impact.velocity=1:1e6:1
assert '...saying what a range is' grep -q 'a range is A\.\.B\[UNIT\]:COUNT' "$tmp/err"

# ---- fit: a measurement no run gives is refused before the search ----
# (qa7: ts=-62us and Rf=1.5 searched the whole range to say no thickness
# gives them; ts=62us+- said "ts=: expected a time ..., got ''")
for m in ts=-62us ts=0us Pmax=0kN Rf=1.5 Rf=-0.1; do
	check_exit 2 "fit $m: exit 2" $ANVIL fit "$m"
	assert '...saying why, naming it' grep -q "'$m': \(must be > 0\|a restitution lies in 0 .. 1\)" "$tmp/err"
done
check_exit 2 'fit ts=62us+-: exit 2' $ANVIL fit 'ts=62us+-'
assert '...nothing after +-' grep -q 'nothing after +-' "$tmp/err"
assert 'no temporary file is left' no_tmp

done_testing
