#!/bin/sh
# The DQBS kernels on the Cortex-M cores that run them (make BOARD=cortex-m0
# bench): the fixed-point kernel and the float one (soft-float on the M0,
# the FPU's single precision on the M4F), each built for its board
# (tests/embedded/emb_bench.c), skinning the test body for one frame.
#   - instructions a vertex: counted under qemu-system-arm
#     (tests/embedded/mcu_count.sh), exact for the code the compiler made;
#   - cycles a vertex, a model, not a measurement: for the M4, llvm-mca's
#     Cortex-M4 scheduling model over the first 60,000 instructions each
#     kernel executed, plus a taken branch's pipeline refill (1 cycle after
#     an immediate branch, 2 after one to a register, as the M4's manual
#     says), scaled to the whole count; for the M0, which LLVM has no model
#     of, the cycle table of its Technical Reference Manual over every
#     instruction executed (mcu_count.sh); both with memory at zero wait
#     states (a real part's flash may add some);
#   - what that gives at 30 frames a second: vertices a 48 MHz M0 and a
#     168 MHz M4 could skin, all of the core's time spent skinning.
# Usage: sh tests/embedded/mcu_bench.sh M0_BENCH.elf M4_BENCH.elf
set -eu
m0=${1:?M0 benchmark ELF}; m4=${2:?M4 benchmark ELF}
here=$(dirname "$0")
mca=${LLVM_MCA:-llvm-mca}
dir=$(mktemp -d) && trap 'rm -rf "$dir"' EXIT

# board ELF MACHINE MHZ -> lines "board kernel vertices insns m0cycles m4cycles|-"
measure() {
	board=$1 elf=$2 machine=$3
	mkdir -p "$dir/$board"
	STREAM=$dir/$board sh "$here/mcu_count.sh" "$elf" "$machine" > "$dir/$board.out"
	grep '^emb-bench: .* runs ' "$dir/$board.out" | awk '{ print $2, $4, $6 }' > "$dir/$board.kernels"
	grep -v '^emb-bench' "$dir/$board.out" > "$dir/$board.runs"
	first=1
	while read -r kernel runs verts; do
		last=$((first + runs - 1))
		m4cyc=-
		if [ "$board" = cortex-m4 ] && command -v "$mca" >/dev/null 2>&1; then
			set -- $(awk -v r="$first" '$1 == r { print $4, $5 }' "$dir/$board.runs")
			m4cyc=$("$mca" -mtriple=thumbv7em-none-eabi -mcpu=cortex-m4 -iterations=1 "$dir/$board/run$first.s" 2>/dev/null |
				awk -v imm="$1" -v reg="$2" '/^Instructions:/ { n = $2 } /^Total Cycles:/ { c = $3 } END { if (n) print (c + imm + 2 * reg) / n }')
			[ -n "$m4cyc" ] || { echo "mcu_bench: llvm-mca gave no figure for $kernel" >&2; exit 1; }
		fi
		awk -v f="$first" -v l="$last" -v k="$kernel" -v b="$board" -v v="$verts" -v cpi="$m4cyc" '
			$1 >= f && $1 <= l { ins += $2; cyc += $3 }
			END { printf "%s %s %d %.1f %.1f %s\n", b, k, v, ins / v, cyc / v, cpi == "-" ? "-" : sprintf("%.1f", cpi * ins / v) }' "$dir/$board.runs"
		first=$((last + 1))
	done < "$dir/$board.kernels"
}

# the two cores side by side (each is one emulator and its trace's reader)
measure cortex-m0 "$m0" mps2-an385 > "$dir/rows.m0" &
m0_pid=$!
measure cortex-m4 "$m4" mps2-an386 > "$dir/rows.m4"
wait "$m0_pid" || { echo "mcu_bench: the Cortex-M0 count failed" >&2; exit 1; }
cat "$dir/rows.m0" "$dir/rows.m4" > "$dir/rows"
command -v "$mca" >/dev/null 2>&1 || echo "mcu_bench: llvm-mca not installed (Debian: llvm): no Cortex-M4 model figures"
awk '
function at30(cyc, mhz) { return cyc > 0 ? sprintf("%d", mhz * 1e6 / cyc / 30) : "-" }
{ b[NR] = $1; k[NR] = $2; ins[NR] = $4; m0[NR] = $5; m4[NR] = $6; key[$1 " " $2] = NR }
END {
	printf "%-10s %-11s %12s %22s %16s %22s\n", "core", "kernel", "insns/vertex", "ratio", "cycles/vertex", "vertices at 30 fps"
	for (i = 1; i <= NR; i++) {
		m0core = b[i] == "cortex-m0"
		cyc = m0core ? m0[i] : m4[i]
		model = m0core ? "TRM table" : "llvm-mca"
		f = key[b[i] " dqbs"]; r = ""
		if (k[i] == "dqbs-fixed" && f)
			r = m0core ? sprintf("%.2fx fewer than float", ins[f] / ins[i]) : sprintf("%.2fx float speed", (m4[i] == "-" ? 0 : m4[f] / m4[i]))
		printf "%-10s %-11s %12.1f %22s %10s (%s) %9s at %d MHz\n", b[i], k[i], ins[i], r, cyc, model, at30(cyc, m0core ? 48 : 168), m0core ? 48 : 168
	}
	print "cycles: a model (M4: llvm-mca -mcpu=cortex-m4 with taken-branch refills; M0: the TRM cycle table), every access at zero wait states"
}' "$dir/rows"
