#!/bin/sh
# completion.sh: completion/anvil.bash completes commands, options, formats
# and the scene keys anvil itself accepts.
. "$top_srcdir/tests/setup.sh"

script=$top_srcdir/completion/anvil.bash
command -v bash >/dev/null 2>&1 || skip_all 'no bash'
[ -f "$script" ] || skip_all "no $script"

check 'anvil --complete-keys exits 0' "$ANVIL" --complete-keys
assert 'the keys include layer.thickness and impactor.E' \
	grep -qx 'layer.thickness' "$tmp/out" && grep -qx 'impactor.E' "$tmp/out"
# every key listed is one the parser accepts (a key's own default value
# is not needed: a bad value is exit 2 too, so ask for an unknown-key error)
run "$ANVIL" plan -s layer.bogus=@
assert 'the check below can fail: a bogus key is an unknown key' grep -q 'unknown key' "$tmp/err"
bad=0
while IFS= read -r k; do
	"$ANVIL" plan -s "$k=@" >/dev/null 2>"$tmp/kerr" || :
	grep -q 'unknown key' "$tmp/kerr" && { diag "not a key: $k"; bad=1; }
done <"$tmp/out"
assert 'every listed key is known to the parser' [ "$bad" -eq 0 ]

# Complete "anvil WORDS..." with the cursor on the last word.
complete_words() {
	bash -c '. "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1));
		_anvil; printf "%s\n" "${COMPREPLY[@]}"' sh "$script" "$@"
}
assert 'commands: "ru" gives run' [ "$(complete_words "$ANVIL" ru)" = run ]
assert 'options of run: "--hist" gives --history' [ "$(complete_words "$ANVIL" run --hist)" = --history ]
assert 'formats: -f j gives json' [ "$(complete_words "$ANVIL" run -f j)" = json ]
assert 'keys: -s layer.th gives layer.thickness=' \
	[ "$(complete_words "$ANVIL" run -s layer.th)" = layer.thickness= ]
assert 'plot kinds: restitution-' [ "$(complete_words "$ANVIL" plot restitution- | wc -l)" -eq 4 ]
assert 'commands: "swe" gives sweep' [ "$(complete_words "$ANVIL" swe)" = sweep ]
assert 'options of sweep: "--sha" gives --shard' [ "$(complete_words "$ANVIL" sweep --sha)" = --shard ]

done_testing
