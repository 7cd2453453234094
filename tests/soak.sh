#!/bin/sh
# Soak: skinplay headless for many frames on a damaged flash image with a
# random button script; checks that it exits cleanly, that its resident
# memory stays flat after warm-up, and that every injected fault was logged.
# Usage: soak.sh BUILD_DIR FRAMES [SAMPLE_SECONDS]      (make soak)
#
# Faults, each a corrupted byte (a CRC mismatch, persistent like a worn
# flash page) in a block of the clip: three blocks alone in their parity
# groups, which skinplay must rebuild from parity ("block N rebuilt from
# parity"), and two blocks of one group, beyond repair, which it must log
# ("image: block N bad") and hold the last good frame over on every loop.
# Buttons: 500 random presses of ALGO/PLAY/NEXT/VIEW (short and long) from a
# fixed seed, spread over the expected run time, from 20 s on: the first loop
# of the clip plays through every damaged block.
set -u
out=$1; frames=$2; every=${3:-1}
tool=$out/skintool; play=$out/skinplay; amc=$out/assets/demo.amc
dir=$out/soak
mkdir -p "$dir" || exit 1
for f in "$tool" "$play" "$amc"; do
	[ -e "$f" ] || { echo "soak: $f missing (make all first)"; exit 1; }
done

# small blocks and large parity groups, the clip's frames raw (3 frames a
# block): 770 frames blocks against 8 groups, room for five faults in
# distinct groups with a lost pair inside the clip. Compressed, the tour's
# held poses cost almost nothing and its walk most of its 11 blocks: both
# blocks of a lost pair can fall in the walk's segment, the second never
# read (tests/integration/test_kiosk_survives.c loses compressed blocks)
"$tool" pack assets/demo.asf "$amc" --raw --block-size=512 --parity=256 -o "$dir/show.skn" >"$dir/pack.log" 2>&1 ||
	{ cat "$dir/pack.log"; exit 1; }
bs=$("$tool" info "$dir/show.skn" | sed -n 's/^ *blocks *[0-9]* of \([0-9]*\) bytes.*/\1/p')
# the clip's frames blocks (after its quantisation or codec header)
range=$("$tool" info "$dir/show.skn" | sed -n 's/^ *clip 0 .* blocks [0-9]*\.\.\([0-9]*\) (frames from \([0-9]*\)).*/\2 \1/p')
set -- $range
[ -n "$bs" ] && [ $# = 2 ] || { echo "soak: cannot read the image layout"; exit 1; }
first=$1; last=$2
groups=$("$tool" info "$dir/show.skn" | sed -n 's/^ *parity .*: \([0-9]*\) groups .*/\1/p')
segs=$("$tool" info "$dir/show.skn" | sed -n 's/^ *clip 0 .* in \([0-9]*\) segments.*/\1/p')
[ -n "$groups" ] || { echo "soak: the image has no parity"; exit 1; }
# block b is in group b mod groups: the lost pair (b and b + groups, one
# group) and the three rebuilt ones each in a group of its own, all inside
# the clip: the pair first, then the rebuilt ones spread from both ends
# and the middle to the nearest block of an unused group. A compressed
# clip loses the segments a lost block touches, and their other blocks
# are not read: the rebuilt ones keep a segment and more (span) away.
placed=$(awk -v first="$first" -v last="$last" -v g="$groups" -v segs="${segs:-0}" 'BEGIN {
	span = segs > 0 ? int((last - first + 1) / segs) + 2 : 0
	for (b = first + 1; b + g <= last; b++) { lost = b; break }
	if (!lost) exit 1
	used[lost % g] = 1
	want[1] = first + 1; want[2] = int((first + last) / 2); want[3] = last - 1
	for (i = 1; i <= 3; i++) {
		got = 0
		for (d = 0; d <= last - first && !got; d++)
			for (s = -1; s <= 1 && !got; s += 2) {
				b = want[i] + s * d
				far = (b - lost > span || lost - b > span) && (b - lost - g > span || lost + g - b > span)
				if (b > first && b < last && !((b % g) in used) && far) got = b
			}
		if (!got) exit 1
		used[got % g] = 1; rebuilt = rebuilt " " got
	}
	print substr(rebuilt, 2) "|" lost " " lost + g
}') || { echo "soak: cannot place the faults in clip blocks $first..$last with $groups parity groups"; exit 1; }
rebuilt=${placed%|*}; lost=${placed#*|}
faults="$rebuilt $lost"
cp "$dir/show.skn" "$dir/damaged.skn"
for b in $faults; do
	off=$((b * bs + 100))
	byte=$(od -An -tu1 -j "$off" -N1 "$dir/damaged.skn" | tr -d ' ')
	printf "$(printf '\\%03o' $((byte ^ 0x5a)))" | dd of="$dir/damaged.skn" bs=1 seek="$off" conv=notrunc status=none
done

# Headless, script time is display time: frame n is at n * 1000 / 60 ms (the
# default --display-rate). Presses from 20 s (frame 1200) to the end of the run.
span_ms=$((frames * 1000 / 60 - 20000))
[ "$span_ms" -lt 1000 ] && span_ms=1000
awk -v n=500 -v span="$span_ms" 'BEGIN {
	srand(20261121); split("ALGO PLAY NEXT VIEW", name, " ");
	print "# soak: random presses (tests/soak.sh)";
	for (i = 0; i < n; i++) {
		step = span / n; t = 20000 + int(step * (i + rand() * 0.3)); b = name[1 + int(rand() * 4)];
		hold = rand() < 0.2 && step > 2000 ? 900 : int(step / 3 < 80 ? step / 3 : 80) + 1;
		print t, b, "press"; print t + hold, b, "release";
	}
}' >"$dir/buttons.txt"

echo "soak: $frames frames, image $dir/damaged.skn (bad blocks: $rebuilt rebuilt from parity, $lost beyond repair), buttons $dir/buttons.txt"
start=$(date +%s)
"$play" --image "$dir/damaged.skn" --platform surfaceless --size 160x90 --frames "$frames" \
	--hud-fps off --input "script:$dir/buttons.txt" >"$dir/skinplay.log" 2>&1 &
pid=$!
: >"$dir/rss.txt"
while kill -0 "$pid" 2>/dev/null; do
	rss=$(sed -n 's/^VmRSS:[[:space:]]*\([0-9]*\) kB/\1/p' "/proc/$pid/status" 2>/dev/null)
	[ -n "$rss" ] && echo "$(($(date +%s) - start)) $rss" >>"$dir/rss.txt"
	sleep "$every"
done
wait "$pid"; rc=$?
secs=$(($(date +%s) - start))

fail=0
grep '^played' "$dir/skinplay.log"
[ "$rc" = 0 ] || { echo "soak: FAILED: skinplay exited with status $rc (log $dir/skinplay.log)"; fail=1; }
grep -q "^played $frames frames" "$dir/skinplay.log" || { echo "soak: FAILED: did not play $frames frames"; fail=1; }
for b in $rebuilt; do
	grep -q "^image: .*: block $b rebuilt from parity" "$dir/skinplay.log" ||
		{ echo "soak: FAILED: block $b (alone in its parity group) was not rebuilt"; fail=1; }
done
for b in $lost; do
	grep -q "^image: block $b bad" "$dir/skinplay.log" ||
		{ echo "soak: FAILED: block $b (beyond repair) was not logged"; fail=1; }
done
grep -Eq "clip .*: [1-9][0-9]* frames? held over bad blocks" "$dir/skinplay.log" ||
	{ echo "soak: FAILED: no frame was held over the blocks beyond repair"; fail=1; }
echo "soak: faults: $(grep -c ' rebuilt from parity' "$dir/skinplay.log") rebuilt from parity," \
	"$(grep -c '^image: block [0-9]* bad' "$dir/skinplay.log") logged beyond repair, playback survived"
echo "soak: input events handled: $(grep -c '^input:' "$dir/skinplay.log")"
# Flat: views and skinning modes come and go with the buttons, so RSS
# swings by about 5 MiB (llvmpipe's buffers) and its peaks fall anywhere;
# a leak is a level that keeps rising, which lifts the floor too. Compare
# the floor (the lowest sample) of the last quarter of the run with the
# floor of the quarter after warm-up (the first 10%): at most 2 MiB or 2%
# higher. (Peaks against peaks failed a flat run: a 112.7 MB spike in the
# middle, 110.1 early, 112.5 late.)
awk -v secs="$secs" '
	function floor_of(a, b,   i, m) { m = r[a]; for (i = a; i <= b; i++) if (r[i] < m) m = r[i]; return m }
	function peak_of(a, b,   i, m) { m = 0; for (i = a; i <= b; i++) if (r[i] > m) m = r[i]; return m }
	{ t[NR] = $1; r[NR] = $2 }
	END {
		if (NR < 8) { print "soak: too few RSS samples (run longer)"; exit 1 }
		w = 1; while (w < NR && t[w] < secs * 0.1) w++;
		e = w; while (e < NR && t[e] < secs * 0.35) e++;
		l = NR; while (l > e && t[l] > secs * 0.75) l--;
		early = floor_of(w, e); late = floor_of(l, NR);
		printf "soak: VmRSS kB: first %d, after warm-up (%d s) %d, last %d, max %d; %d s-%d s between %d and %d, the last quarter between %d and %d; %d samples over %d s\n",
			r[1], t[w], r[w], r[NR], peak_of(w, NR), t[w], t[e], early, peak_of(w, e), late, peak_of(l, NR), NR, secs;
		lim = early / 50; if (lim < 2048) lim = 2048;
		if (late - early > lim) { printf "soak: FAILED: resident memory rose by %d kB (floor of the last quarter over the early one; limit %d)\n", late - early, lim; exit 1 }
		printf "soak: resident memory flat after warm-up (late floor - early floor = %d kB, limit %d)\n", late - early, lim;
	}' "$dir/rss.txt" || fail=1
[ $fail = 0 ] && echo "soak: passed" || echo "soak: FAILED"
exit $fail
