#!/bin/sh
# Runs every cmocka test program given, shows its output, and ends with one
# summary in cmocka's own format plus a plain "N passed, N failed" line.
out=$1; shift
export SKP_BUILD="$out"
export SKP_SHARED="${SKP_SHARED:-../shared}"
# Mesa's OSMesa keeps its framebuffer for ever: suppress that leak only
export LSAN_OPTIONS="suppressions=$(pwd)/tests/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
[ -d "$SKP_SHARED/data" ] || echo "note: $SKP_SHARED/data not found: tests that need the shared data report themselves skipped"
run=0; passed=0; failed=0; skipped=0; failed_progs=""
log=$(mktemp); trap 'rm -f "$log"' EXIT
for t in "$@"; do
	# cross boards (tests/cross_run.sh): skipped programs, and the emulator
	case " $SKP_TEST_SKIP " in *" $(basename "$t") "*)
		echo "[ SKIPPED  ] $(basename "$t"): $SKP_TEST_SKIP_WHY"
		skipped=$((skipped + 1)); continue ;;
	esac
	$SKP_TEST_RUNNER "$t" >"$log" 2>&1; rc=$?
	cat "$log"
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
		failed_progs="$failed_progs $(basename "$t")"
	fi
done
echo
echo "[==========] $run test(s) run from $# program(s)."
echo "[  PASSED  ] $passed test(s)."
[ "$skipped" -gt 0 ] && echo "[  SKIPPED ] $skipped test(s)."
if [ -n "$failed_progs" ]; then
	echo "[  FAILED  ] $failed test(s), in:$failed_progs"
	echo "tests: $passed passed, $failed failed, $skipped skipped"
	exit 1
fi
echo "tests: $passed passed, 0 failed, $skipped skipped"
