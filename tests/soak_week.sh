#!/bin/sh
# A week of a kiosk's show through rotating faults, in minutes: skinplay
# with --platform none (the show's clock, the image, the engine and every
# log line as on a screen, nothing drawn) on a short damaged clip, one
# virtual day per fault at a virtual display of SOAK_HZ frames a second.
# Where the fault is repairable the poses shown must be those of the
# undamaged image (--pose-digest); every day must exit 0, and its log stay
# within a bound that does not grow with the passes (a 10-frame clip loops
# over a million times a day).
# Usage: soak_week.sh BUILD_DIR [HZ] [DAYS]      (make soak)
#
# Days: 1 a byte flipped in the clip's frames block, 2 that block zeroed,
# 3 that block from another pack of the same show in the same second (same
# sequence), 4 bytes after the image and block 0 lost, 5 the storage
# ending before the copies, 6 a FIFO in the newer slot, 7 beyond repair:
# the frames block and its parity block lost (frames held) and the
# directory and its parity block lost (the directory from its copy).
set -u
out=$1; hz=${2:-7}; days=${3:-7}
tool=$out/skintool; play=$out/skinplay; amc=$out/assets/demo.amc
dir=$out/soak-week
rm -rf "$dir" && mkdir -p "$dir" || exit 1
frames=$((86400 * hz))
max_lines=40   # a day's log, status lines aside: start-up, the fault once, hourly summaries
start_all=$(date +%s)

# the demo's first 10 frames, packed twice in one second (same sequence)
awk '/^11$/ { exit } { print }' "$amc" >"$dir/short.amc"
for n in 1 2; do
	"$tool" pack assets/demo.asf "$dir/short.amc" --parity 4 --sequence 7 -o "$dir/week$n.skn" >/dev/null ||
		{ echo "soak-week: pack failed"; exit 1; }
done
info=$("$tool" info "$dir/week1.skn")
bs=$(echo "$info" | sed -n 's/^ *blocks *[0-9]* of \([0-9]*\) bytes.*/\1/p')
frames_block=$(echo "$info" | sed -n 's/^ *clip 0 .* blocks [0-9]*\.\.\([0-9]*\) .*/\1/p')
dir_block=$(echo "$info" | sed -n 's/^ *section *directory: blocks \([0-9]*\)\..*/\1/p')
groups=$(echo "$info" | sed -n 's/^ *parity .*: \([0-9]*\) groups .*/\1/p')
data=$(echo "$info" | sed -n 's/^ *parity *blocks \([0-9]*\)\..*/\1/p')
[ -n "$bs" ] && [ -n "$frames_block" ] && [ -n "$dir_block" ] && [ -n "$groups" ] && [ -n "$data" ] ||
	{ echo "soak-week: cannot read the image layout"; exit 1; }
parity_of() { echo $((data + $1 % groups)); }

zero_block() { dd if=/dev/zero of="$1" bs="$bs" seek="$2" count=1 conv=notrunc status=none; }
flip_byte() {
	off=$(($2 * bs + 200))
	byte=$(od -An -tu1 -j "$off" -N1 "$1" | tr -d ' ')
	printf "$(printf '\\%03o' $((byte ^ 0x5a)))" | dd of="$1" bs=1 seek="$off" conv=notrunc status=none
}

# run NAME SLOT...: a day of frames; sets digest, lines, rc
run() {
	name=$1; shift
	args=""
	for s in "$@"; do args="$args --image $s"; done
	t=$(date +%s)
	"$play" $args --platform none --display-rate "$hz" --frames "$frames" --pose-digest >"$dir/$name.log" 2>&1
	rc=$?
	secs=$(($(date +%s) - t))
	digest=$(sed -n 's/^poses: .* digest \([0-9a-f]*\)$/\1/p' "$dir/$name.log")
	lines=$(grep -vc '^frame [0-9]*: clip' "$dir/$name.log")
}

run undamaged "$dir/week1.skn"
ref=$digest
[ "$rc" = 0 ] && [ -n "$ref" ] || { echo "soak-week: the undamaged run failed (log $dir/undamaged.log)"; exit 1; }
echo "soak-week: undamaged: $frames frames (a day at $hz Hz), digest $ref, $lines log lines, $secs s"

# day N FAULT REPAIRABLE LOG_WANTED SLOTS...: its verdict in $dir/dayN.out
day() {
	n=$1 what=$2 same=$3 want=$4; shift 4
	run "day$n" "$@"
	verdict=ok
	[ "$rc" = 0 ] || verdict="exit $rc"
	[ "$same" = yes ] && [ "$digest" != "$ref" ] && verdict="poses differ from the undamaged run"
	[ "$same" = no ] && [ -z "$digest" ] && verdict="no poses"
	[ "$lines" -le "$max_lines" ] || verdict="$lines log lines (at most $max_lines)"
	grep -q "$want" "$dir/day$n.log" || verdict="no '$want' in the log"
	{
		echo "soak-week: day $n, $what: exit $rc, $([ "$same" = yes ] && echo "poses as undamaged" || echo "poses held over the loss"), $lines log lines, $secs s: $verdict"
		[ "$verdict" = ok ] || echo "soak-week: FAILED: day $n (log $dir/day$n.log)"
	} >"$dir/day$n.out"
}

# one_day N: day N's fault on a copy of its own, played
one_day() {
	n=$1 f="$dir/fault$1.skn"
	cp "$dir/week1.skn" "$f"
	case $(( (n - 1) % 7 + 1 )) in
	1) flip_byte "$f" "$frames_block"
	   day "$n" "a byte flipped in the frames block" yes "block $frames_block rebuilt from parity" "$f" ;;
	2) zero_block "$f" "$frames_block"
	   day "$n" "the frames block zeroed" yes "block $frames_block rebuilt from parity" "$f" ;;
	3) dd if="$dir/week2.skn" of="$f" bs="$bs" skip="$frames_block" seek="$frames_block" count=1 conv=notrunc status=none
	   day "$n" "the frames block another pack's (same sequence)" yes "block $frames_block rebuilt from parity" "$f" ;;
	4) head -c 1000 /dev/urandom >>"$f"; zero_block "$f" 0
	   day "$n" "1000 bytes after the image, block 0 lost" yes "header read from its copy" "$f" ;;
	5) truncate -s "-$((2 * bs))" "$f"
	   day "$n" "the storage ending before the copies" yes "the storage ends 2 blocks before the image" "$f" ;;
	6) rm -f "$dir/fifo$n.skn" && mkfifo "$dir/fifo$n.skn"
	   day "$n" "a FIFO in the newer slot" yes "refused: a FIFO" "$dir/fifo$n.skn" "$f" ;;
	7) zero_block "$f" "$frames_block"; zero_block "$f" "$(parity_of "$frames_block")"
	   zero_block "$f" "$dir_block"; zero_block "$f" "$(parity_of "$dir_block")"
	   day "$n" "frames and directory blocks beyond parity" no "held over bad blocks" "$f" ;;
	esac
}

# the days side by side, one a processor (each is one skinplay, nothing
# drawn), their verdicts in order
jobs=${SKP_SOAK_JOBS:-$(nproc 2>/dev/null || echo 1)}
running=0
for n in $(seq 1 "$days"); do
	one_day "$n" &
	running=$((running + 1))
	[ "$running" -lt "$jobs" ] || { wait; running=0; }
done
wait
fail=0
for n in $(seq 1 "$days"); do
	if [ -s "$dir/day$n.out" ]; then
		cat "$dir/day$n.out"
		! grep -q "FAILED" "$dir/day$n.out" || fail=1
	else
		echo "soak-week: FAILED: day $n gave no verdict"
		fail=1
	fi
done
all=$(($(date +%s) - start_all))
echo "soak-week: $days days at $hz Hz ($((days * frames)) frames of a 10-frame clip), $jobs at a time, $all s"
[ $fail = 0 ] && echo "soak-week: passed" || echo "soak-week: FAILED"
exit $fail
