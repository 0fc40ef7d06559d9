# setup.sh: sourced by every shell test (tests/*.sh), after jq's tests/setup.
#
# Gives: set -eu, LC_ALL=C, $ANVIL (the binary), $top_srcdir, $SHARED (may
# not exist, as in distcheck's build tree), a scratch directory $tmp removed
# on exit, and TAP helpers:
#   ok STATUS DESC           status 0 passes
#   assert DESC CMD...       passes if CMD (a test, grep, awk...) succeeds;
#                            a plain failing command would stop the script
#                            under set -e, so conditions go through here
#   check DESC CMD...        passes if CMD exits 0
#   check_exit N DESC CMD... passes if CMD exits with status N
#   skip DESC REASON         a skipped test
#   skip_all REASON          "1..0 # SKIP": the whole script is skipped
#   diag TEXT                a comment line
#   done_testing             prints the plan; the script's exit status
# A command's stdout and stderr are kept in $tmp/out and $tmp/err.
set -eu
LC_ALL=C
export LC_ALL

: "${top_srcdir:=.}"
: "${ANVIL:=$PWD/anvil}"
: "${SHARED:=$top_srcdir/../shared}"
export ANVIL top_srcdir SHARED

tmp=$(mktemp -d "${TMPDIR:-/tmp}/anvil-test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
trap 'exit 1' HUP INT TERM

tap_n=0
tap_failed=0

diag() {
	printf '# %s\n' "$*"
}

ok() {
	tap_n=$((tap_n + 1))
	if [ "$1" -eq 0 ]; then
		printf 'ok %d - %s\n' "$tap_n" "$2"
	else
		printf 'not ok %d - %s\n' "$tap_n" "$2"
		tap_failed=$((tap_failed + 1))
	fi
}

assert() {
	desc=$1
	shift
	if "$@"; then ok 0 "$desc"; else ok 1 "$desc"; fi
}

# Run a command with its output in $tmp/out and $tmp/err; sets $rc.
run() {
	if "$@" >"$tmp/out" 2>"$tmp/err"; then rc=0; else rc=$?; fi
}

check() {
	desc=$1
	shift
	run "$@"
	ok "$rc" "$desc"
	[ "$rc" -eq 0 ] || { diag "exit $rc: $*"; sed 's/^/#   /' "$tmp/err"; }
}

check_exit() {
	want=$1 desc=$2
	shift 2
	run "$@"
	[ "$rc" -eq "$want" ] && s=0 || s=1
	ok "$s" "$desc"
	[ "$s" -eq 0 ] || { diag "exit $rc, want $want: $*"; sed 's/^/#   /' "$tmp/err"; }
}

skip() {
	tap_n=$((tap_n + 1))
	printf 'ok %d - %s # SKIP %s\n' "$tap_n" "$1" "$2"
}

skip_all() {
	printf '1..0 # SKIP %s\n' "$1"
	exit 0
}

done_testing() {
	printf '1..%d\n' "$tap_n"
	[ "$tap_failed" -eq 0 ]
}

[ -x "$ANVIL" ] || skip_all "no anvil binary at $ANVIL"
