#!/bin/sh
# Static analysis of app/ and platform/: cppcheck, then clang-tidy (the
# clang static analyzer and the bugprone checks that are not style).
# Fails on any finding not listed, with its reason, in tests/lint/*.supp.
# Usage: lint.sh BOARD "EXTRA CFLAGS (pkg-config, backend defines)" \
#                "-I FLAGS OF EVERY MODULE (app/sources.mk)" "SOURCES" "HOST MODULES"
board=${1:-host}; extra=$2; inc=$3; sources=$4
hosts=$5   # app/sources.mk's HOST_MODULES: GNU C (they talk to Linux), the core C11
fail=0

if command -v cppcheck >/dev/null 2>&1; then
	out=$(cppcheck -q -j "$(nproc 2>/dev/null || echo 1)" --enable=warning,portability,performance --std=c11 --inline-suppr \
		--suppressions-list=tests/lint/cppcheck.supp $inc -Iboard/"$board" \
		-DSKP_SIMD_AVX2 $(printf '%s\n' $extra | grep '^-D' | tr '\n' ' ') --error-exitcode=1 \
		--template='{file}:{line}: {severity} [{id}] {message}' $sources 2>&1)
	rc=$?
	if [ $rc -ne 0 ] || [ -n "$out" ]; then
		echo "$out"
		echo "lint: cppcheck: findings above (fix them, or justify in tests/lint/cppcheck.supp)"
		fail=1
	else
		echo "lint: cppcheck: app/ platform/: no findings ($(grep -c '^[a-zA-Z]' tests/lint/cppcheck.supp) justified suppressions)"
	fi
else
	echo "lint: cppcheck not installed (apt-get install cppcheck)"; fail=1
fi

if command -v clang-tidy >/dev/null 2>&1; then
	checks='-*,clang-analyzer-*,-clang-analyzer-security.insecureAPI.*,-clang-analyzer-security.FloatLoopCounter'
	# bugprone, less the style-only ones: "!strcmp()" is this code's idiom,
	# _GNU_SOURCE is how platform/ asks for Linux APIs, binary magic is
	# copied without a NUL, and the rest are opinions about signatures.
	checks="$checks,bugprone-*,-bugprone-easily-swappable-parameters,-bugprone-narrowing-conversions"
	checks="$checks,-bugprone-implicit-widening-of-multiplication-result,-bugprone-reserved-identifier"
	checks="$checks,-bugprone-suspicious-string-compare,-bugprone-not-null-terminated-result,-bugprone-branch-clone"
	# The analyzer's paths explored per function (LINT_NODES, clang's
	# max-nodes): 75,000, its shallow mode's figure, with the deep mode's
	# inlining across the file kept. Clang's default, 225,000, costs 3.2
	# times the processor time on the ten heaviest files (72.8 s against
	# 22.8 s) and finds one more of the justified findings (rig_skel_parts.c);
	# `make lint LINT_NODES=225000` runs at that depth.
	nodes="--extra-arg=-Xclang --extra-arg=-analyzer-config --extra-arg=-Xclang --extra-arg=max-nodes=${LINT_NODES:-75000}"
	logs=$(mktemp -d); trap 'rm -rf "$logs"' EXIT
	# one clang-tidy a processor, each file's findings in a file of its own
	export checks inc board extra logs hosts nodes
	printf '%s\n' $sources | xargs -P "$(nproc 2>/dev/null || echo 1)" -n 1 sh -c '
		f=$1
		m=${f#app/}; m=${m%%/*}
		case " $hosts " in *" $m "*) std=gnu11 ;; *) std=c11 ;; esac
		case $f in platform/*) std=gnu11 ;; esac
		simd=""
		case $f in *_avx2.c) simd="-mavx2 -mfma" ;; esac
		# shellcheck disable=SC2086
		out=$(clang-tidy -quiet --checks="$checks" $nodes "$f" -- -std=$std $inc -Iboard/"$board" \
			-DSKP_SIMD_AVX2 $simd $extra 2>/dev/null | grep -E "^[^ ]+:[0-9]+:[0-9]+: (warning|error):")
		[ -z "$out" ] || printf "%s\n" "$out" > "$logs/$(echo "$f" | tr / _)"' sh
	new=$(cat "$logs"/* 2>/dev/null | sort -u | while IFS= read -r line; do
		file=$(echo "$line" | cut -d: -f1 | sed "s|^$(pwd)/||")
		check=$(echo "$line" | sed -n 's/.*\[\([^]]*\)\]$/\1/p')
		grep -qx "$file:$check" tests/lint/clang-tidy.supp || echo "$line"
	done)
	if [ -n "$new" ]; then
		echo "$new"
		echo "lint: clang-tidy: findings above (fix them, or justify in tests/lint/clang-tidy.supp)"
		fail=1
	else
		echo "lint: clang-tidy: app/ platform/: no findings beyond $(grep -c '^[a-z]' tests/lint/clang-tidy.supp) justified in tests/lint/clang-tidy.supp"
	fi
else
	echo "lint: clang-tidy not installed (apt-get install clang-tidy)"; fail=1
fi
exit $fail
