#!/bin/sh
# layers.sh: the core's include graph points one way (issue 15).
#
# Layers, lowest first: base < input < physics, transform < field < engine.
# A file under src/core/LAYER may include (#include "...") only headers of
# its own layer or lower ones; physics and transform, side by side, include
# neither each other (each builds on input and base alone).  "config.h"
# (autoconf's) is allowed everywhere.  The core never includes curses, nor
# a header of src/ui, nor scene.h below the input layer (the engine sees
# problems and plans, not scenes).
. "${top_srcdir:-.}/tests/setup.sh"

rank() {
	case $1 in
	base) echo 0 ;; input) echo 1 ;; physics | transform) echo 2 ;;
	field) echo 3 ;; engine) echo 4 ;; *) echo 99 ;;
	esac
}

# scan CORE: counts the bad includes under CORE/*/ into $bad, files into $nfiles
scan() {
	core=$1
	# where each core header lives: NAME LAYER
	for d in "$core"/*/; do
		l=$(basename "$d")
		for h in "$d"*.h; do
			[ -e "$h" ] && echo "$(basename "$h") $l"
		done
	done >"$tmp/headers"
	ui_headers=$(find "$top_srcdir/src/ui" -name '*.h' -exec basename {} \; | sort -u)

	bad=0
	nfiles=0
	for f in "$core"/*/*.[ch]; do
		nfiles=$((nfiles + 1))
		l=$(basename "$(dirname "$f")")
		r=$(rank "$l")
		for inc in $(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f"); do
			[ "$inc" = config.h ] && continue
			hl=$(awk -v h="$inc" '$1 == h { print $2 }' "$tmp/headers")
			if [ -z "$hl" ]; then
				for u in $ui_headers; do
					[ "$u" = "$inc" ] && { diag "$f: includes ui header $inc"; bad=$((bad + 1)); }
				done
				continue
			fi
			hr=$(rank "$hl")
			if [ "$hr" -gt "$r" ] || { [ "$hr" -eq "$r" ] && [ "$hl" != "$l" ]; }; then
				diag "$f ($l) includes $inc ($hl)"
				bad=$((bad + 1))
			fi
			if [ "$inc" = scene.h ] && [ "$r" -gt 1 ]; then
				diag "$f ($l) includes scene.h"
				bad=$((bad + 1))
			fi
		done
	done
}

scan "$top_srcdir/src/core"
assert "every core include points to its own or a lower layer ($nfiles files, $bad bad)" \
	[ "$bad" -eq 0 ]
assert "the core includes no curses" \
	sh -c "! grep -En '#[[:space:]]*include[[:space:]]*[<\"](n?curses|ncursesw)' '$top_srcdir/src/core'/*/*.[ch]"
assert "the layer table covers every core folder" \
	sh -c "for d in '$top_srcdir/src/core'/*/; do case \$(basename \$d) in base|input|physics|transform|field|engine) ;; *) exit 1;; esac; done"
# the checker itself: an engine header included from input is caught
mkdir -p "$tmp/fake/input" "$tmp/fake/engine"
: >"$tmp/fake/engine/solver.h"
printf '#include "solver.h"\n' >"$tmp/fake/input/x.c"
scan "$tmp/fake"
assert "a planted upward include (input -> engine) is found" [ "$bad" -eq 1 ]
done_testing
