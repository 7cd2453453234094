#!/bin/sh
# Cycles a vertex of each NEON kernel on a Cortex-A72 by llvm-mca's model
# (LLVM's scheduling model for the core: pipelines, latencies, one load a
# cycle), from the main loop of each kernel in an aarch64 build: one step
# of 4 vertices (8 for the fixed kernel). A model, not a measurement:
# every load hits L1 and branches cost nothing. The loops hold whole steps
# only (the last vertices of a call are handled after the loop), so no
# rarely taken code is counted as if it ran each step. The fixed kernel's
# loop is a function of its own (fixed_neon_run). Usage:
#   sh tests/model_cycles.sh [BUILD_DIR]   (default build/rpi4; needs llvm-mca)
set -eu
build=${1:-build/rpi4}
objdump=${OBJDUMP:-aarch64-linux-gnu-objdump}
mca=${LLVM_MCA:-llvm-mca}
for need in "$objdump" "$mca"; do
	command -v "$need" >/dev/null || { echo "model_cycles: $need not found (Debian: llvm, binutils-aarch64-linux-gnu)" >&2; exit 1; }
done
loop=$(mktemp) && trap 'rm -f "$loop" "$loop.rows"' EXIT
k=$build/app/skin/kernels
. "$(dirname "$0")/neon_kernels.sh"

# The function's instructions from the target of its longest backward
# conditional branch (a rotated loop's back edge; an unconditional one may
# be a jump back from code after the loop, as GCC 14 places a kernel's
# last partial step) to that branch; calls and branches become nops (mca
# models no control flow).
main_loop() { # object function
	"$objdump" -d --no-show-raw-insn "$1" | awk -v f="<$2>:" '
	function hex(s,  i, n) { n = 0; s = tolower(s); for (i = 1; i <= length(s); i++) n = n * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1; return n }
	$2 == f { on = 1; next }
	on && NF == 0 { exit }
	on && $1 ~ /^[0-9a-f]+:$/ {
		n++; at[n] = hex(substr($1, 1, length($1) - 1)); line = $0
		sub(/^[^:]*:[ \t]*/, "", line); sub(/[ \t]*\/\/.*$/, "", line); sub(/[ \t]*<.*$/, "", line)
		op = line; sub(/[ \t].*$/, "", op)
		if (op ~ /^(b|bl|b\.[a-z]+|cbz|cbnz|tbz|tbnz)$/) {
			t = line; sub(/^.*[ \t,]/, "", t); t = hex(t)
			if (op != "bl" && op != "b" && t < at[n] && at[n] - t > best) { best = at[n] - t; from = t; to = at[n] }
			line = "nop"
		}
		ins[n] = line
	}
	END { for (i = 1; i <= n; i++) if (at[i] >= from && at[i] <= to) print ins[i] }'
}

for f in $NEON_KERNELS; do
	obj=$k/skin_neon.o fn=$f verts=4
	[ "$f" = skin_dqbs_fixed_neon ] && obj=$k/skin_fixed_neon.o fn=fixed_neon_run verts=8
	main_loop "$obj" "$fn" > "$loop"
	"$mca" -mtriple=aarch64 -mcpu=cortex-a72 -iterations=300 "$loop" 2>/dev/null |
		awk -v f="$f" -v n="$(wc -l < "$loop")" -v verts=$verts '/^Iterations:/ { it = $2 } /^Total Cycles:/ { c = $3 }
			END { if (!it) exit 1; print f, n, c / it / verts }' >> "$loop.rows" ||
		{ echo "model_cycles: llvm-mca gave no figure for $f" >&2; exit 1; }
done
neon_table "$(printf '%-24s %10s %13s  %s' "kernel" "loop insns" "cycles/vertex" "ratio (time)")" "%-24s %10d %13.1f" < "$loop.rows"
