#!/bin/sh
# tui.sh: `anvil tui` in a detached tmux: results appear, keys change them,
# a small terminal gets its message, export and save work (or say why not),
# and the terminal is restored on q, Ctrl-C and SIGTERM.
# Only the hertz and zener models run: fast and always available.
# The awk programs are arguments: their $ are awk's.
# shellcheck disable=SC2016
. "$top_srcdir/tests/setup.sh"

# ---- without a terminal ----
check 'tui --help exits 0' "$ANVIL" tui --help
assert 'tui --help shows the usage' grep -q '^usage: anvil tui' "$tmp/out"
check_exit 1 'tui without a terminal fails' "$ANVIL" tui </dev/null
assert 'and says it needs one' grep -q 'needs a terminal' "$tmp/err"
check_exit 2 'tui: unknown option exits 2' "$ANVIL" tui --bogus
check_exit 2 'tui: a bad -s exits 2' "$ANVIL" tui -s impactor.mas=3g
assert 'tui: a bad -s names the key' grep -q 'mas' "$tmp/err"
check_exit 2 'tui: -s without a value exits 2' "$ANVIL" tui -s

if ! command -v tmux >/dev/null 2>&1; then
	skip 'the TUI in a terminal' 'tmux is not installed'
	done_testing
	exit
fi

# A private server, its socket in the scratch directory (removed with it).
T() { tmux -S "$tmp/tmux" -f /dev/null "$@"; }
trap 'T kill-server >/dev/null 2>&1 || :; rm -rf "$tmp"' EXIT
ESC=$(printf '\033')

screen() { T capture-pane -p -t "$1"; }
flag() { T display-message -p -t "$1" "#{$2}"; }

# Poll (every 0.1 s, at most 10 s) until the pane of session $1 shows
# the extended regular expression $2.
wait_for() {
	n=100
	while [ "$n" -gt 0 ]; do
		screen "$1" | grep -Eq -- "$2" && return 0
		sleep 0.1
		n=$((n - 1))
	done
	diag "timed out waiting for '$2'; the screen:"
	screen "$1" | sed 's/^/#   /'
	return 1
}

# Start "anvil tui ARGS" in session $1 (100x30) from an interactive sh.
# $ENVS is put before the command.
start() {
	s=$1
	shift
	T new-session -d -s "$s" -x 100 -y 30 -c "$tmp" sh
	T send-keys -t "$s" -l "$ENVS \"$ANVIL\" tui $*"
	T send-keys -t "$s" Enter
}

# Once the TUI of session $1 has ended (the shell's prompt is the last
# line), ask the shell for its exit status: "anvil-exit=N" on the screen.
# Asked afterwards, not with "; echo": a shell drops the rest of a command
# line whose command died of SIGINT.
ask_status() {
	n=100
	until screen "$1" | awk 'NF { last = $0 } END { exit last !~ /^[$#] ?$/ }'; do
		n=$((n - 1))
		[ "$n" -gt 0 ] || break
		sleep 0.1
	done
	T send-keys -t "$1" -l 'echo anvil-exit=$?'
	T send-keys -t "$1" Enter
}

# The Zener and Hertz columns of the t_s row.
ts_zener() { screen "$1" | awk '/t_s  /{ print $(NF - 1); exit }'; }

wait_changed() { # session, old value
	n=100
	while [ "$n" -gt 0 ]; do
		v=$(ts_zener "$1")
		[ -n "$v" ] && [ "$v" != "$2" ] && [ "$v" != "..." ] && return 0
		sleep 0.1
		n=$((n - 1))
	done
	return 1
}

# tmux must be able to run a session here at all.
if ! T new-session -d -s probe -x 80 -y 24 sh 2>"$tmp/err"; then
	skip 'the TUI in a terminal' "tmux cannot start: $(cat "$tmp/err")"
	done_testing
	exit
fi
# The probe session stays until the end: with no session left the server
# exits, and a new-session racing its exit fails ("server exited
# unexpectedly", seen under load).

# ---- results, keys, resize, quit ----
ENVS="ANVIL_GNUPLOT=/nonexistent/gnuplot"
start main -s solver.models=hertz,zener
assert 'the results appear' wait_for main 'last run'
assert 'the alternate screen is in use' [ "$(flag main alternate_on)" = 1 ]
assert 'the verdict mark: the layer yields, quasi-static Hertz' \
	wait_for main 'layer yields \(quasi-static Hertz\): [0-9.]+ [GM]Pa von Mises, Y = '
assert 'the shape row' wait_for main 'shape +rod'
before=$(ts_zener main)
assert "Zener's t_s is a number ($before us)" awk -v v="$before" 'BEGIN { exit !(v + 0 > 0) }'
assert 'the thickness shows in mm' wait_for main 'thickness +4 mm'
assert 'and in r0' wait_for main 'thickness +1 r0'

T send-keys -t main L
assert 'a coarse step of the thickness shows 5 mm' wait_for main 'thickness +5 mm'
assert "Zener's t_s changes" wait_changed main "$before"
after=$(ts_zener main)
diag "Zener t_s: $before us at 4 mm, $after us at 5 mm"

assert 'P(t) of the paper'"'"'s scene on a linear axis' wait_for main 'P\(t\) \[kN\] vs t'
T send-keys -t main v
assert 'v switches the plot to v(t)' wait_for main 'v\(t\) \[m/s\]'
T send-keys -t main '?'
assert '? shows the help' wait_for main 'this help'
T send-keys -t main x
assert 'a key leaves the help' wait_for main 'Results'

T send-keys -t main P
assert 'P shows the plan the rows ran from' wait_for main 'the plan \(any key returns\)'
assert 'the plan names the zener row and its method' wait_for main 'zener'
T send-keys -t main x
assert 'a key leaves the plan' wait_for main 'Results'

T send-keys -t main p
assert 'a missing gnuplot is a status-line message' wait_for main 'export failed: .*gnuplot'
assert 'and the TUI is still running' wait_for main 'Results'

T send-keys -t main Enter C-u
T send-keys -t main -l 'oops'
T send-keys -t main Enter
assert 'a bad value typed: the error in the status line' wait_for main 'expected a length'
T send-keys -t main Escape

T send-keys -t main s
assert 's saves the scene' wait_for main 'saved to anvil-scene.scene'
assert 'the saved file exists' [ -f "$tmp/anvil-scene.scene" ]
check 'anvil run reads the saved scene' "$ANVIL" run "$tmp/anvil-scene.scene" -f tsv
run_ts=$(awk -F '\t' '$1 == "zener" { printf "%.4g", $4 }' "$tmp/out")
assert "anvil run gives the t_s the TUI showed ($run_ts = $after)" [ "$run_ts" = "$after" ]

T resize-window -t main -x 80 -y 24
assert 'at 80x24 the verdict still says quasi-static Hertz, and its stress' \
	wait_for main 'layer yields \(quasi-static Hertz\): [0-9.]+ [GM]Pa'
assert '  and the impactor line its stress' wait_for main 'impactor yields too: [0-9.]+ [GM]Pa von Mises'
assert '  the header'"'"'s title, cut, ends in an ellipsis' \
	wait_for main '^ anvil tui  anvil-scene\.scene  .*(…|\.\.\.) +(last run|from cache)'
T resize-window -t main -x 60 -y 20
assert 'a 60x20 terminal gets the size message' \
	wait_for main 'anvil needs at least 80x24; this terminal is 60x20'
T resize-window -t main -x 20 -y 8
assert 'a 20x8 terminal still learns the size it needs (the message wraps)' \
	wait_for main '^ *80x24; this terminal *$'
T resize-window -t main -x 100 -y 30
assert 'back at 100x30 the screen returns' wait_for main 'Results'

T send-keys -t main q
ask_status main
assert 'q quits with status 0' wait_for main '^anvil-exit=0$'
assert 'the alternate screen is left' [ "$(flag main alternate_on)" = 0 ]
assert 'the cursor is visible again' [ "$(flag main cursor_flag)" = 1 ]
assert 'the keypad is back in normal mode' [ "$(flag main keypad_cursor_flag)" = 0 ]

# ---- a drop weight on a thin plate: Hertz's 105 kN beside Zener's 0.08 kN ----
start thin -s solver.models=hertz,zener,halfspace -s layer.thickness=0.1r0 -s impactor.mass=2kg \
	-s impact.velocity=5m/s
assert 'thin plate: peaks 1300 times apart put P on a log axis' wait_for thin 'P\(t\) \[kN, log\] vs t'
assert '...its ticks the decades down to a hundredth of the smaller peak' \
	wait_for thin '^ +0\.001 .*$'
assert 'thin plate: the 2 kg mass shown in kg, not 2000 g' wait_for thin 'mass +2 kg'
T send-keys -t thin v v
# Zener's 640 mm beside the half-space's +-0.47 um (the physical contact's
# radiation lag changes sign): |w| on a log axis, in mm
assert "thin plate: w(t) as |w| on a log axis in mm" wait_for thin '\|w\|\(t\) \[mm, log\] vs t'
assert "...its legend: Hertz's w = 0, which a log axis cannot draw" wait_for thin 'Hertz \(w = 0\)'
T send-keys -t thin Q
ask_status thin
assert 'thin plate: Q quits with status 0' wait_for thin '^anvil-exit=0$'

# ---- q while the worker computes; q with unsaved changes ----
ENVS="ANVIL_NO_CACHE=1"
start busy -s solver.models=layer -s solver.accuracy=reference -s layer.thickness=0.5r0
assert 'a long computation is under way' wait_for busy 'computing'
T send-keys -t busy q
# at once: the shell's prompt is back within 2 s (the layer takes several)
n=20
until screen busy | awk 'NF { last = $0 } END { exit last !~ /^[$#] ?$/ }'; do
	n=$((n - 1))
	[ "$n" -gt 0 ] || break
	sleep 0.1
done
assert 'q quits at once while the worker computes' [ "$n" -gt 0 ]
ask_status busy
assert 'and exits 0' wait_for busy '^anvil-exit=0$'
assert 'busy q: the alternate screen is left' [ "$(flag busy alternate_on)" = 0 ]

ENVS=""
start ask -s solver.models=hertz
assert 'third session: results' wait_for ask 'last run'
T send-keys -t ask l
T send-keys -t ask q
assert 'q with unsaved changes asks first' wait_for ask 'unsaved changes: quit anyway'
T send-keys -t ask n
assert 'n: still running' wait_for ask 'Results'
T send-keys -t ask Q
ask_status ask
assert 'Q quits without asking, status 0' wait_for ask '^anvil-exit=0$'

# ---- Ctrl-C ----
ENVS=""
start int -s solver.models=hertz,zener
assert 'second session: results' wait_for int 'last run'
T send-keys -t int C-c
ask_status int
assert 'Ctrl-C ends it as SIGINT (status 130)' wait_for int '^anvil-exit=130$'
assert 'Ctrl-C: the alternate screen is left' [ "$(flag int alternate_on)" = 0 ]
assert 'Ctrl-C: the cursor is visible' [ "$(flag int cursor_flag)" = 1 ]

# ---- NO_COLOR, SIGTERM ----
ENVS="NO_COLOR=1"
start mono -s solver.models=hertz,zener
assert 'NO_COLOR session: results' wait_for mono 'last run'
T capture-pane -e -p -t mono >"$tmp/mono"
# SGR parameters 30-48 and 90-107 set colours; 39 and 49 (the default
# colours) tmux writes itself, bold and reverse are no colour
assert 'NO_COLOR: not one colour attribute' \
	awk -v esc="$ESC" 'index($0, esc) {
		s = $0
		while (match(s, esc "\\[[0-9;]*m")) {
			n = split(substr(s, RSTART + 2, RLENGTH - 3), p, ";")
			for (i = 1; i <= n; i++)
				if ((p[i] >= 30 && p[i] <= 48 && p[i] != 39) ||
				    (p[i] >= 90 && p[i] <= 107)) bad = 1
			s = substr(s, RSTART + RLENGTH)
		}
	} END { exit bad }' "$tmp/mono"
pane=$(flag mono pane_pid)
pid=$(ps -A -o pid= -o ppid= | awk -v p="$pane" '$2 == p { print $1; exit }')
if [ -n "$pid" ]; then
	kill -TERM "$pid"
	ask_status mono
	assert 'SIGTERM: dies of the signal (status 143)' wait_for mono '^anvil-exit=143$'
	assert 'SIGTERM: the alternate screen is left' [ "$(flag mono alternate_on)" = 0 ]
	assert 'SIGTERM: the cursor is visible' [ "$(flag mono cursor_flag)" = 1 ]
else
	skip 'SIGTERM restores the terminal' 'cannot find the process with ps'
fi

done_testing
