# bash completion for anvil: commands, options, scene keys and values.
# Installed by `make install` into $(datadir)/bash-completion/completions;
# without installing: `. completion/anvil.bash`.
# Scene keys come from the anvil being completed (`anvil --complete-keys`),
# so they are always those it accepts.

_anvil_opts() {
	case $1 in
	run) echo "-s --set -f --format -o --output --history --png -m --models -v --verbose -q --quiet -h --help" ;;
	table) echo "--v0 -f --format -o --output -s --set -h --help" ;;
	materials) echo "-f --format -o --output -h --help" ;;
	accuracy) echo "-s --set -f --format -o --output -m --model -h --help" ;;
	plan) echo "-s --set -m --models -f --format -o --output -h --help" ;;
	field) echo "-s --set --at --quantity -o --output -f --format --no-yield -q --quiet -h --help" ;;
	map) echo "-s --set --time --quantity --rmax --depth --grid -o --output -f --format --png --script --size --no-yield -q --quiet -h --help" ;;
	plot) echo "-s --set -o --output --size --font --title --script -h --help" ;;
	tui) echo "-s -h --help" ;;
	sweep) echo "-s --set -o --output -f --format --zip -j --jobs --shard --resume -m --models -q --quiet -v --verbose -h --help" ;;
	merge) echo "-o --output -f --format -h --help" ;;
	thickness) echo "-s --set --within --rtol --range --curve -f --format -o --output -h --help" ;;
	fit) echo "-s --set --for --range -m --model -f --format -o --output -h --help" ;;
	dem) echo "-s --set --velocities -m --model -o --output -f --format -j --jobs -h --help" ;;
	esac
}

_anvil() {
	local cur prev cmd i
	COMPREPLY=()
	cur=${COMP_WORDS[COMP_CWORD]}
	prev=${COMP_WORDS[COMP_CWORD - 1]}
	local commands="run table materials accuracy plot tui plan field map sweep merge thickness fit dem"
	if [ "$COMP_CWORD" -eq 1 ]; then
		mapfile -t COMPREPLY < <(compgen -W "$commands --help --version" -- "$cur")
		return
	fi
	cmd=${COMP_WORDS[1]}
	case $prev in
	-s | --set)
		local keys
		keys=$("${COMP_WORDS[0]}" --complete-keys 2>/dev/null)
		compopt -o nospace 2>/dev/null
		mapfile -t COMPREPLY < <(compgen -W "$keys" -S = -- "$cur")
		return ;;
	-f | --format)
		mapfile -t COMPREPLY < <(compgen -W "table tsv csv json" -- "$cur")
		return ;;
	-m | --models | --model)
		mapfile -t COMPREPLY < <(compgen -W "hertz zener layer halfspace all" -- "$cur")
		return ;;
	--quantity)
		mapfile -t COMPREPLY < <(compgen -W "u w szz srr stt srz vm" -- "$cur")
		return ;;
	--time)
		mapfile -t COMPREPLY < <(compgen -W "tmax ts" -- "$cur")
		return ;;
	--png)
		[ "$cmd" = run ] && mapfile -t COMPREPLY < <(compgen -d -- "$cur") ||
			mapfile -t COMPREPLY < <(compgen -f -- "$cur")
		return ;;
	--for)
		mapfile -t COMPREPLY < <(compgen -W "layer.thickness layer.E impact.velocity" -- "$cur")
		return ;;
	-o | --output | --history | --script | --curve)
		mapfile -t COMPREPLY < <(compgen -f -- "$cur")
		return ;;
	--v0 | --at | --rmax | --depth | --grid | --size | --font | --title | -j | --jobs | --shard | \
		--within | --rtol | --range | --velocities)
		return ;;
	esac
	if [ "$cmd" = plot ] && [ "$COMP_CWORD" -eq 2 ]; then
		mapfile -t COMPREPLY < <(compgen -W "force velocity deflection restitution-thickness restitution-lambda accuracy restitution-velocity restitution-map" -- "$cur")
		return
	fi
	case $cur in
	-*) mapfile -t COMPREPLY < <(compgen -W "$(_anvil_opts "$cmd")" -- "$cur") ;;
	*) # a scene file
		mapfile -t COMPREPLY < <(compgen -f -X '!*.scene' -- "$cur"; compgen -d -- "$cur") ;;
	esac
}
complete -F _anvil anvil
