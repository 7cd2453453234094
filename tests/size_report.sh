#!/bin/sh
# `make size`: skinplay's code and static RAM, the RAM per module (from the
# link map: each object's .data and .bss) and the largest buffers (from the
# symbols, with the source line that declares them).
# Usage: size_report.sh BINARY BOARD SIZE NM "obj.o=module ..."
bin=$1 board=$2 size=$3 nm=$4 modules=$5
[ -f "$bin.map" ] || { echo "size: $bin.map missing (relink: rm $bin; make)"; exit 1; }

$size "$bin" | awk -v b="$board" 'NR == 2 {
	printf "skinplay (%s): code %d bytes (text), static RAM %d bytes = %.1f MB (.data %d + .bss %d)\n",
	       b, $1, $2 + $3, ($2 + $3) / 1048576, $2, $3 }'

echo "static RAM per module (.data + .bss):"
# map lines: " .bss  0xADDR  0xSIZE  path/to/obj.o" or "... libx.a(obj.o)"; a long
# section name puts address, size and object on the next line
awk -v modules="$modules" '
function hex(s,   v, i, c) {
	v = 0; s = tolower(s); sub(/^0x/, "", s)
	for (i = 1; i <= length(s); i++) { c = index("0123456789abcdef", substr(s, i, 1)); v = v * 16 + c - 1 }
	return v
}
BEGIN { n = split(modules, m, " "); for (i = 1; i <= n; i++) { split(m[i], kv, "="); mod[kv[1]] = kv[2] } }
function account(size, obj,   base, name) {
	base = obj; sub(/.*\(/, "", base); sub(/\)$/, "", base); sub(/.*\//, "", base)
	name = (base in mod) ? mod[base] : (obj ~ /\.so|libc|crt|libgcc|\/usr\//) ? "(C library, startup)" : "(other: " base ")"
	ram[name] += size
}
/^ \.(bss|data|tbss|tdata)[. ]/ || /^ COMMON / {
	if (NF >= 4) account(hex($3), $4); else pending = 1; next
}
pending && /^ +0x/ { account(hex($2), $3); pending = 0; next }
{ pending = 0 }
END { for (k in ram) if (ram[k] > 0) printf "%12d  %s\n", ram[k], k }' "$bin.map" | sort -rn

echo "largest buffers:"
$nm -S --size-sort -l "$bin" 2>/dev/null | awk '$3 ~ /^[bBdD]$/' | tail -n 8 | sort -k2 -r |
	awk 'function hex(s,   v, i) { v = 0; s = tolower(s)
	       for (i = 1; i <= length(s); i++) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
	       return v }
	     { src = $5; sub(/.*\/(app|platform)\//, "", src); sub(/.*\//, "", src)
	       printf "%12d  %s (%s)\n", hex($2), $4, src }'
