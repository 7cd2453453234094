#!/bin/sh
# Proves a SIMD fixed-point object does no floating-point arithmetic: its
# disassembly may move and shuffle vector registers (bit moves), but must not
# contain any floating-point arithmetic, comparison or conversion. x86-64
# (SSE/AVX mnemonics) and AArch64 (f-prefixed ones but fmov, a bit move;
# scvtf/ucvtf). OBJDUMP names the target's objdump (default objdump).
# Usage: [OBJDUMP=aarch64-linux-gnu-objdump] check_simd_integer.sh OBJECT...
bad=0
objdump=${OBJDUMP:-objdump}
for o in "$@"; do
	found=$($objdump -d --no-show-raw-insn "$o" | awk '/^ *[0-9a-f]+:/ {print $2}' |
		grep -E '^v?(add|sub|mul|div|sqrt|rsqrt|rcp|min|max|cmp|round|dp|hadd|hsub|fn?m(add|sub)[0-9]*)(p|s)(s|d)$|^v?cvt|^v?u?comis|^f[a-z0-9]+$|^[su]cvtf$' |
		grep -vx 'fmov' | sort -u | tr '\n' ' ')
	if [ -n "$found" ]; then
		echo "check-simd: $o uses floating-point instructions: $found"
		bad=1
	else
		echo "check-simd: $o uses integer arithmetic only"
	fi
done
exit $bad
