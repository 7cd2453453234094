#!/bin/sh
# Runs the cmocka test programs given, several at once, and ends with one
# summary in cmocka's own format plus a plain "N passed, N failed" line.
#
#   run_tests.sh BUILD_DIR PROGRAM...
#
# SKP_TEST_JOBS programs run at a time (default: the machine's processors).
# The slowest programs start first, by the times of the last run (kept in
# BUILD_DIR/tests/.times; slowest_first.sh), so that the run ends when its
# longest program does. Each program's output is shown whole when it ends, followed by its
# time; the five slowest are listed at the end.
# SKP_TEST_ONLY="test_a test_b" runs only those of the programs given;
# SKP_TEST_SKIP="..." reports those skipped, with SKP_TEST_SKIP_WHY.
# (run_tests.sh --one PROGRAM: one program, for the parallel runs below)
if [ "$1" != --one ]; then
out=$1; shift
if [ -n "${SKP_TEST_ONLY:-}" ]; then
	only=
	for t in "$@"; do
		case " $SKP_TEST_ONLY " in *" $(basename "$t") "*) only="$only $t" ;; esac
	done
	if [ -z "$only" ]; then
		echo "run_tests.sh: none of SKP_TEST_ONLY ($SKP_TEST_ONLY) is among the programs given" >&2
		exit 2
	fi
	# shellcheck disable=SC2086 # test paths have no spaces (build/tests/NAME)
	set -- $only
fi
export SKP_BUILD="$out"
export SKP_SHARED="${SKP_SHARED:-../shared}"
# Mesa's OSMesa keeps its framebuffer for ever: suppress that leak only
export LSAN_OPTIONS="suppressions=$(pwd)/tests/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
[ -d "$SKP_SHARED/data" ] || echo "note: $SKP_SHARED/data not found: tests that need the shared data report themselves skipped"
jobs=${SKP_TEST_JOBS:-$(nproc 2>/dev/null || echo 1)}
times=$out/tests/.times
logs=$(mktemp -d); trap 'rm -rf "$logs"' EXIT
start=$(date +%s)
fi

# one program: its log, exit status and wall time in $logs/NAME.*
run_one() {
	t=$1 name=$(basename "$1")
	case " $SKP_TEST_SKIP " in *" $name "*)
		echo "[ SKIPPED  ] $name: $SKP_TEST_SKIP_WHY" > "$logs/$name.log"
		echo skip > "$logs/$name.rc"
		flock "$logs/lock" cat "$logs/$name.log"
		return ;;
	esac
	s=$(date +%s.%N)
	$SKP_TEST_RUNNER "$t" > "$logs/$name.log" 2>&1
	echo $? > "$logs/$name.rc"
	awk -v s="$s" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f\n", e - s }' > "$logs/$name.time"
	flock "$logs/lock" sh -c 'cat "$1"; echo "[ TIME     ] $2: $3 s"' sh "$logs/$name.log" "$name" "$(cat "$logs/$name.time")"
}

if [ "$1" = --one ]; then
	run_one "$2"
	exit 0
fi

if [ "$jobs" -le 1 ]; then
	for t in "$@"; do run_one "$t"; done
else
	export logs SKP_TEST_RUNNER SKP_TEST_SKIP SKP_TEST_SKIP_WHY
	printf '%s\n' "$@" | sh "$(dirname "$0")/slowest_first.sh" "$times" | xargs -P "$jobs" -n 1 sh "$0" --one
fi

run=0; passed=0; failed=0; skipped=0; failed_progs=""
mkdir -p "$out/tests"; : > "$times.new"
for t in "$@"; do
	name=$(basename "$t") log=$logs/$name.log
	rc=$(cat "$logs/$name.rc" 2>/dev/null || echo 1)
	if [ "$rc" = skip ]; then skipped=$((skipped + 1)); continue; fi
	printf '%s\t%s\n' "$(cat "$logs/$name.time" 2>/dev/null || echo 0)" "$t" >> "$times.new"
	# cmocka 1.1.7 (Debian 13) puts the group's name before the count:
	# "[==========] tests: 4 test(s) run."; 1.1.5 (Debian 12) does not
	g='\([^ ]*: \)\{0,1\}'
	r=$(sed -n "s/^\[==========\] $g\([0-9]*\) test(s) run\./\2/p" "$log" | tail -n 1)
	p=$(sed -n "s/^\[  PASSED  \] $g\([0-9]*\) test(s)\./\2/p" "$log" | tail -n 1)
	f=$(sed -n "s/^\[  FAILED  \] $g\([0-9]*\) test(s), listed below:/\2/p" "$log" | tail -n 1)
	s=$(sed -n "s/^\[  SKIPPED \] $g\([0-9]*\) test(s), listed below:/\2/p" "$log" | tail -n 1)
	run=$((run + ${r:-0})); passed=$((passed + ${p:-0}))
	failed=$((failed + ${f:-0})); skipped=$((skipped + ${s:-0}))
	if [ "$rc" -ne 0 ] || [ -z "$r" ]; then
		[ -z "$f" ] && failed=$((failed + 1))
		failed_progs="$failed_progs $name"
	fi
done
slowest=$(sort -g -r -k1,1 "$times.new" | head -n 5 |
	awk -F '\t' '{ n = split($2, p, "/"); printf "%s%s %s s", (NR > 1 ? ", " : ""), p[n], $1 }')
# the times of programs not run this time are kept
awk -F '\t' 'NR == FNR { run[$2] = 1; print; next } NF == 2 && !($2 in run)' "$times.new" "$times" 2>/dev/null > "$times.all" &&
	mv "$times.all" "$times" || mv "$times.new" "$times"
rm -f "$times.new"
echo
echo "[==========] $run test(s) run from $# program(s), $jobs at a time, in $(($(date +%s) - start)) s."
echo "slowest: $slowest"
echo "[  PASSED  ] $passed test(s)."
[ "$skipped" -gt 0 ] && echo "[  SKIPPED ] $skipped test(s)."
if [ -n "$failed_progs" ]; then
	echo "[  FAILED  ] $failed test(s), in:$failed_progs"
	for name in $failed_progs; do
		echo "== $name (failed): the end of its output"
		tail -n 15 "$logs/$name.log"
	done
	echo "tests: $passed passed, $failed failed, $skipped skipped"
	exit 1
fi
echo "tests: $passed passed, 0 failed, $skipped skipped"
