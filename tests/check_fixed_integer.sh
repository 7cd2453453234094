#!/bin/sh
# Proves app/math/fixed.c is integer-only: compiles it with the FPU/SIMD registers
# disabled (GCC then rejects any float or double use on x86-64 and AArch64)
# and checks the object for libm or soft-float helper calls.
# Usage: check_fixed_integer.sh CC [flags...] [file.c]   (default app/math/fixed.c)
if [ $# -lt 1 ]; then
	echo "usage: $0 CC [flags...] [file.c]" >&2
	exit 2
fi
cc=$1; shift
src=app/math/fixed.c
flags=""
for a in "$@"; do
	case $a in
	*.c) src=$a ;;
	*) flags="$flags $a" ;;
	esac
done

case $($cc -dumpmachine 2>/dev/null) in
x86_64*|amd64*|aarch64*) regs=-mgeneral-regs-only ;;
*) regs=""; echo "check-fixed: note: no register check for this target, symbols only" ;;
esac

tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
obj=$tmp/fixed.o

# shellcheck disable=SC2086  # flags are deliberately split
if ! $cc -std=c11 -O2 $flags $regs -c "$src" -o "$obj" 2>"$tmp/err"; then
	echo "check-fixed: $src does not build with $regs (floating point used?):"
	cat "$tmp/err"
	exit 1
fi

# libm, libgcc soft-float (__addsf3, __floatsidf, __fixdfsi ...) and the
# ARM EABI soft-float helpers (__aeabi_fadd, __aeabi_d2iz, __aeabi_i2f ...).
bad=$(nm -u "$obj" | awk '{print $NF}' | sed 's/@.*//' |
	grep -E 'sqrt|sin|cos|__.*sf|__.*df|__float|__fix|__aeabi_[df]|__aeabi_u?[il]2[df]' |
	tr '\n' ' ')
if [ -n "$bad" ]; then
	echo "check-fixed: $src calls floating-point helpers: $bad"
	exit 1
fi
echo "check-fixed: $src uses integer arithmetic only"
