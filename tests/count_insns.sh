#!/bin/sh
# Instructions a vertex of each SIMD kernel of an aarch64 build, counted
# under qemu-user: `skintool bench` runs one instruction per translation
# block (-singlestep) with every block executed inside the kernels' objects
# logged, and each logged instruction counts for the kernel entered last.
# A count, not a timing: the Cortex-A72 retires up to three a cycle, and
# loads and divisions cost more than one. Usage:
#   sh tests/count_insns.sh [BUILD_DIR] [VERTICES]   (default build/rpi4, 4096)
set -eu
build=${1:-build/rpi4}
verts=${2:-4096}
nm=${NM:-aarch64-linux-gnu-nm}
size=${SIZE:-aarch64-linux-gnu-size}
qemu=${QEMU:-qemu-aarch64-static}
export QEMU_LD_PREFIX=${QEMU_LD_PREFIX:-/usr/aarch64-linux-gnu}
tool=$build/skintool
. "$(dirname "$0")/neon_kernels.sh"
# qemu-user loads an aarch64 PIE program at this address
base=${QEMU_PIE_BASE:-0x5500000000}
for need in "$nm" "$size" "$qemu"; do
	command -v "$need" >/dev/null || { echo "count_insns: $need not found" >&2; exit 1; }
done
[ -x "$tool" ] || { echo "count_insns: $tool not built (make BOARD=rpi4)" >&2; exit 1; }
log=$(mktemp) && trap 'rm -f "$log" "$log.rows" "$log.extra"' EXIT

# An object's code is contiguous in the program: its start is where one of
# its symbols landed, less that symbol's offset in the object.
range() { # object symbol
	at_obj=$("$nm" "$build/$1" | awk -v s="$2" '$3 == s { print $1 }')
	at_bin=$("$nm" "$tool" | awk -v s="$2" '$3 == s { print $1 }')
	len=$("$size" -A "$build/$1" | awk '$1 == ".text" { print $2 }')
	lo=$((base + 0x$at_bin - 0x$at_obj))
	printf '0x%x..0x%x' "$lo" $((lo + len - 1))
}
k=app/skin/kernels
ranges="$(range $k/skin_neon.o skin_lbs_neon),$(range $k/skin_fixed_neon.o skin_dqbs_fixed_neon)"
ranges="$ranges,$(range $k/skin_fixed.o skin_dqbs_fixed),$(range app/math/fixed.o fx_blend_scale)"
entry_list() { # symbols: "address=symbol ..."
	for s in "$@"; do
		printf ' %x=%s' $((base + 0x$("$nm" "$tool" | awk -v s="$s" '$3 == s { print $1 }'))) "$s"
	done
}

# -singlestep was renamed -one-insn-per-tb in qemu 8.1
step=-singlestep
"$qemu" -h | grep -q -- -one-insn-per-tb && step=-one-insn-per-tb
# count RANGES ENTRIES: each entry's calls and instructions a vertex
count() {
	"$qemu" $step -d exec,nochain -dfilter "$1" -D "$log" "$tool" bench --verts="$verts" --rounds=1 -q >/dev/null
	awk -v entries="$2" -v verts="$verts" '
	BEGIN { n = split(entries, e, " "); for (i = 1; i <= n; i++) { split(e[i], kv, "="); name[kv[1]] = kv[2]; order[i] = kv[2] } }
	/^Trace/ {
		split($0, f, "/"); pc = f[2]; sub(/^0+/, "", pc)
		if (pc in name) { cur = name[pc]; calls[cur]++ }
		if (cur != "") insns[cur]++
	}
	END {
		for (i = 1; i <= n; i++) {
			k = order[i]
			if (!calls[k]) { print "count_insns: " k " was not called" > "/dev/stderr"; exit 1 }
			print k, calls[k], insns[k] / (calls[k] * verts)
		}
	}' "$log"
}
count "$ranges" "$(entry_list $NEON_KERNELS)" > "$log.rows" || exit 1
neon_table "$(printf '%-24s %6s %20s  %s' "kernel (aarch64)" "calls" "instructions/vertex" "ratio")" "%-24s %6d %20.1f" < "$log.rows"

# What the compare view's close-up and the difference view add a frame
# (skintool bench's close-up part: skin_diff_between runs twice, without
# and with the per-vertex distances), against the frame's two kernels on
# the board's compact streams.
ranges="$(range app/skin/skin_diff.o skin_diff_between),$(range app/render/render_diff.o render_diff_colours)"
count "$ranges" "$(entry_list skin_diff_between skin_diff_focus render_diff_colours)" > "$log.extra" || exit 1
cat "$log.rows" "$log.extra" | awk '
{ v[$1] = $3 }
END {
	frame = v["skin_lbs_compact_neon"] + v["skin_dqbs_compact_neon"]
	closeup = v["skin_diff_between"] + v["skin_diff_focus"]
	diffview = v["skin_diff_between"] + v["render_diff_colours"]
	printf "close-up (where LBS and DQBS part, where on the joint): %.1f instructions/vertex, %.2fx the compare frame'"'"'s two compact kernels (%.1f)\n", closeup, closeup / frame, frame
	printf "difference view (distances, colours): %.1f instructions/vertex, %.2fx those kernels\n", diffview, diffview / frame
}'

# What version 7's per-block digests cost a block read on the Pi: the
# instructions of one block's leaf (SHA-256 of its 4096 bytes: 65 rounds
# of the compression) and of one check against its digest block, counted
# while `skintool info` reads a small image (tests/data/tiny.*), every block
# checked.
img=$(mktemp --suffix=.skn) && trap 'rm -f "$log" "$log.rows" "$log.extra" "$img"' EXIT
"$qemu" "$tool" pack tests/data/tiny.asf tests/data/tiny.amc -q --sequence=1 -o "$img" >/dev/null
# every instruction of sha256.o; each leaf is one sha256_init (the root
# over the leaves one more: counted in, it is small)
"$qemu" $step -d exec,nochain -dfilter "$(range app/base/sha256.o sha256_update)" -D "$log" "$tool" info "$img" >/dev/null || true
sha=$(grep -c '^Trace' "$log")
init_at=$(printf '%x' $((base + 0x$("$nm" "$tool" | awk '$3 == "sha256_init" { print $1 }'))))
leaves=$(grep -c "^Trace[^[]*\[[0-9a-f]*/0*$init_at/" "$log" || true)
[ "$leaves" -gt 0 ] || { echo "count_insns: sha256_init was not called" >&2; exit 1; }
awk -v sha="$sha" -v n="$leaves" 'BEGIN {
	printf "block digests (aarch64): a block'"'"'s leaf (SHA-256 of its 4096 bytes) %.0f instructions, %.2f a byte (%d hashes by skintool info)\n", sha / n, sha / n / 4096, n }'
