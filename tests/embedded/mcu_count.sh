#!/bin/sh
# Instructions a vertex of the kernels of a Cortex-M benchmark program
# (tests/embedded/emb_bench.c), counted under qemu-system-arm: the program
# runs one instruction per translation block with every executed block
# logged, and each instruction executed between a call of emb_count_begin
# and the next call of emb_count_end counts for the kernel being timed (the
# kernel's own code and all it calls: libgcc's soft-float and 64-bit
# helpers, libm). The program says on its output which kernel it ran, how
# often and on how many vertices in all. Also, from the same trace:
#   - the Cortex-M0's cycles by its Technical Reference Manual's table
#     (ARM DDI 0432C, table 3-1: 1 cycle an ALU instruction and a multiply
#     on the fast multiplier, 2 a load or store, 1+N a multiple transfer,
#     3 a taken branch, 4 a BL, 4+N a POP into the PC): a model, with every
#     memory access at zero wait states;
#   - with STREAM=DIR, each kernel's first 60,000 executed instructions as
#     assembly (DIR/KERNEL.s), for llvm-mca's Cortex-M4 model
#     (tests/embedded/mcu_bench.sh), branches as nops and IT blocks dropped
#     (llvm-mca models no control flow), and DIR/KERNEL.branches: the taken
#     branches among them, immediate and register ones.
# Prints one line per kernel: name, runs, vertices, instructions a vertex,
# M0 model cycles a vertex. Usage:
#   sh tests/embedded/mcu_count.sh ELF MACHINE   (MACHINE: mps2-an385 or mps2-an386)
set -eu
elf=${1:?ELF}; machine=${2:?QEMU machine}
qemu=${QEMU_SYSTEM:-qemu-system-arm}
objdump=${OBJDUMP:-arm-none-eabi-objdump}
nm=${NM:-arm-none-eabi-nm}
for need in "$qemu" "$objdump" "$nm"; do
	command -v "$need" >/dev/null || { echo "mcu_count: $need not found (make deps BOARD=cortex-m0)" >&2; exit 1; }
done
dir=$(mktemp -d) && trap 'rm -rf "$dir"' EXIT
mkfifo "$dir/trace"

# pc|size|mnemonic|operands, from the disassembly (sizes from the raw bytes)
"$objdump" -d "$elf" | awk -F'\t' '
/^ *[0-9a-f]+:\t/ && NF >= 3 {
	pc = $1; sub(/^ */, "", pc); sub(/:$/, "", pc); sub(/^0+/, "", pc)
	raw = $2; gsub(/ /, "", raw)
	ops = ""; for (i = 4; i <= NF; i++) ops = ops (i > 4 ? " " : "") $i
	# a float immediate is shown encoded, its value in the comment
	if ($3 ~ /^vmov/ && ops ~ /#[0-9]+[ \t]*@/) { n = split(ops, w, " "); sub(/#[0-9]+.*$/, "#" w[n], ops) }
	sub(/[ \t]*[@;].*$/, "", ops); sub(/[ \t]*<.*$/, "", ops)
	print pc "|" length(raw) / 2 "|" $3 "|" ops
}' > "$dir/listing"
addr() { "$nm" "$elf" | awk -v s="$1" '$3 == s { a = $1; sub(/^0+/, "", a); print a }'; }
begin=$(addr emb_count_begin); end=$(addr emb_count_end)
[ -n "$begin" ] && [ -n "$end" ] || { echo "mcu_count: $elf has no emb_count_begin/end" >&2; exit 1; }

# -singlestep became -accel tcg,one-insn-per-tb=on in qemu 8.1
step=-singlestep
"$qemu" -accel tcg,help 2>&1 | grep -q one-insn-per-tb && step="-accel tcg,one-insn-per-tb=on"
# shellcheck disable=SC2086 # $step is one or two words
timeout 1800 "$qemu" -M "$machine" $step -nographic -semihosting -monitor none -serial null \
	-d exec,nochain -D "$dir/trace" -kernel "$elf" > "$dir/out" 2>&1 &
qpid=$!
awk -F'|' -v begin="$begin" -v end="$end" -v stream="${STREAM:-}" -v limit=60000 '
function hex(s,  i, n) { n = 0; s = tolower(s); for (i = 1; i <= length(s); i++) n = n * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1; return n }
function base(m) { sub(/\.[nw]$/, "", m); return m }
function is_cond_branch(m) { return m ~ /^b(eq|ne|cs|cc|hs|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le)$/ }
function writes_pc(m, ops) {
	return ((m == "pop" || m ~ /^ldm/) && ops ~ /pc/) || (m ~ /^(ldr|mov|add)/ && ops ~ /^pc,/)
}
function is_branch(m, ops) { return m ~ /^(b|bl|bx|blx|cbz|cbnz|tbb|tbh)$/ || is_cond_branch(m) || writes_pc(m, ops) }
# Cortex-M0 TRM table 3-1 (a taken conditional branch 3, else 1)
function cost(m, ops, taken,  n, r) {
	if (m ~ /^(ldr|str)(b|h|sb|sh)?$/) return (m == "ldr" && ops ~ /^pc,/) ? 5 : 2
	if (m ~ /^(ldm|stm)/ || m == "push" || m == "pop") { n = split(ops, r, ","); return 1 + n + (ops ~ /pc/ ? 3 : 0) }
	if (m == "bl") return 4
	if (m == "bx" || m == "blx") return 3
	if (m == "b") return 3
	if (is_cond_branch(m)) return taken ? 3 : 1
	if ((m == "mov" || m == "add") && ops ~ /^pc,/) return 3
	return 1
}
# The instruction as llvm-mc reads it alone: no width suffix, and inside
# an IT block (dropped) no condition either.
function plain(m,  dot, rest) {
	sub(/\.[nw]$/, "", m)
	if (itleft > 0) {
		itleft--
		dot = index(m, "."); rest = dot ? substr(m, dot) : ""; m = dot ? substr(m, 1, dot - 1) : m
		sub(/(eq|ne|cs|cc|hs|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le|al)$/, "", m)
		m = m rest
	}
	return m
}
# The instruction at pc, once the next one shows whether it branched.
function retire(pc, taken,  m, o, k) {
	m = base(mn[pc]); o = op[pc]; k = runs
	ins[k]++; cyc[k] += cost(m, o, taken)
	if (stream == "" || dumped[k] >= limit) return
	dumped[k]++
	if (m ~ /^it[te]*$/) { itleft = length(m) - 1; return }
	if (is_branch(m, o)) {
		if (itleft > 0) itleft--
		print "nop" > (stream "/run" k ".s")
		if (taken && (m ~ /^(bx|blx)$/ || writes_pc(m, o))) reg[k]++
		else if (taken) imm[k]++
	} else {
		print plain(mn[pc]) "\t" o > (stream "/run" k ".s")
	}
}
FNR == NR { size[$1] = $2; mn[$1] = $3; op[$1] = $4; next }
{ split($0, f, "/"); pc = f[2]; sub(/^0+/, "", pc) }
pc == begin { on = 1; runs++; prev = ""; next }
on && prev != "" { retire(prev, hex(pc) != hex(prev) + size[prev]) }
pc == end { on = 0; prev = ""; next }
on { prev = pc }
END { for (k = 1; k <= runs; k++) print k, ins[k], cyc[k], imm[k] + 0, reg[k] + 0 }' "$dir/listing" "$dir/trace" > "$dir/runs"
wait "$qpid" || { echo "mcu_count: $elf failed under $qemu -M $machine:" >&2; cat "$dir/out" >&2; exit 1; }
cat "$dir/out"
cat "$dir/runs"
