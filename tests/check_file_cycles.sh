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
	: > "$tmp/def"
	for o in $objs; do
		$nm --defined-only "$o" | awk -v f="$(basename "$o" .o)" '$2 ~ /^[TDRB]$/ { print $3, f }' >> "$tmp/def"
	done
	: > "$tmp/edges"
	for o in $objs; do
		f=$(basename "$o" .o)
		$nm -u "$o" | awk '{ print $NF }' | sort -u | join - "$(sort -o "$tmp/def.s" "$tmp/def" && echo "$tmp/def.s")" |
			awk -v f="$f" '$2 != f { print f, $2 }' >> "$tmp/edges"
	done
	sort -u "$tmp/edges" -o "$tmp/edges"
	if ! tsort "$tmp/edges" > /dev/null 2> "$tmp/loop"; then
		echo "check-layers: app/$m: its files call each other in a circle:$(sed -n 's/^tsort: //p' "$tmp/loop" | grep -v loop | tr '\n' ' ')"
		fail=1
	fi
done
[ $fail -eq 0 ] && echo "check-layers: the files of $modules modules call downwards only (no circle inside a module)"
exit $fail
