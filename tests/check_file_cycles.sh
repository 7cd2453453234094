#!/bin/sh
# No two files of a module call each other, directly or round a longer
# circle: within each module the files' calls (from the symbols their
# objects define and leave undefined) must order them (tsort), so each file
# can be read knowing only the ones below it.
# Usage: check_file_cycles.sh NM "module=obj obj ..." ...
nm=$1; shift
export LC_ALL=C   # sort and join agree on the order
fail=0 modules=0
tmp=$(mktemp -d) && trap 'rm -rf "$tmp"' EXIT
for spec in "$@"; do
	m=${spec%%=*} objs=${spec#*=}
	[ -n "$objs" ] || continue
	modules=$((modules + 1))
	# two nm a module (-A: each line names its object); one a file took 43 s.
	# A file calls (or reads) another when it leaves undefined what the
	# other defines: the defined come first, then each use is an edge.
	# shellcheck disable=SC2086 # object paths have no spaces
	{ $nm -A --defined-only $objs | sed 's/^/D /'; $nm -A -u $objs | sed 's/^/U /'; } |
		awk 'function file(o) { sub(/:.*/, "", o); sub(/.*\//, "", o); sub(/\.o$/, "", o); return o }
		$1 == "D" && $3 ~ /^[TDRB]$/ { owner[$4] = file($2); next }
		$1 == "U" && ($NF in owner) && owner[$NF] != file($2) { print file($2), owner[$NF] }' > "$tmp/edges"
	sort -u "$tmp/edges" -o "$tmp/edges"
	if ! tsort "$tmp/edges" > /dev/null 2> "$tmp/loop"; then
		echo "check-layers: app/$m: its files call each other in a circle:$(sed -n 's/^tsort: //p' "$tmp/loop" | grep -v loop | tr '\n' ' ')"
		fail=1
	fi
done
[ $fail -eq 0 ] && echo "check-layers: the files of $modules modules call downwards only (no circle inside a module)"
exit $fail
