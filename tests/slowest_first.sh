#!/bin/sh
# The lines of stdin (test programs, model files) slowest first by the
# last run's times, so that a run side by side (xargs -P) ends about when
# its longest item does; items the times do not list come first of all
# (they may be slow). TIMES holds "SECONDS<TAB>ITEM" lines (it may be
# missing). Used by run_tests.sh and import_sweep.sh.
#
#   ... | tests/slowest_first.sh TIMES | xargs -P N ...
times=$1
[ -f "$times" ] || times=/dev/null
awk -F '\t' 'FILENAME == ARGV[1] { if (NF == 2) t[$2] = $1; next }
	{ print (($0 in t) ? t[$0] : 1e9) "\t" $0 }' "$times" - | sort -g -r -k1,1 | cut -f2-
