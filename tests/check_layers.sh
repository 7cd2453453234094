#!/bin/sh
# The layers of app/sources.mk, checked two ways:
#  1. every #include "..." in app/ and platform/ names a header of the
#     including module itself, of a module its DEPS_ list allows (never a
#     private folder of another module), of the board, or, in platform/,
#     of base, a port header or platform/ itself;
#  2. the compiler refuses an upward include: a file in app/math including
#     skin.h, compiled with math's include path, must fail to compile.
# Usage: check_layers.sh "CC CFLAGS" "mod=dep dep ... mod=..." \
#                        "PLATFORM DEPS" "PORT HEADERS" "PLATFORM DIRS"
cc=$1 spec=$2 plat_deps=$3 ports=$4 plat_dirs=$5
fail=0 files=0

deps_of() { # the DEPS_ list of module $1 from the spec
	echo "$spec" | tr ' ' '\n' | awk -v m="$1" '
		/=/ { split($0, kv, "="); cur = kv[1]; if (cur == m && kv[2] != "") print kv[2]; next }
		cur == m { print }'
}
headers_in() { # the headers directly in folder $1 (not its subfolders)
	find "$1" -maxdepth 1 -name '*.h' -printf '%f\n' 2>/dev/null
}

# Every #include "..." of the files given that is not in $allowed, said
# with the reason $1, counted in $files; fails if there is one. One awk for
# all the files.
includes_outside() {
	why=$1; shift
	files=$((files + $#))
	[ $# -gt 0 ] || return 0
	awk -v why="$why" '
		FNR == NR { ok[$0] = 1; next }
		/^#include "/ {
			h = $0; sub(/^#include "/, "", h); sub(/".*/, "", h)
			if (!(h in ok)) { print "check-layers: " FILENAME " includes " h ": " why; bad = 1 }
		}
		END { exit bad }' "$allowed" "$@"
}

allowed=$(mktemp) && trap 'rm -f "$allowed"' EXIT
for dir in app/*/; do
	m=$(basename "$dir")
	: > "$allowed"
	headers_in "app/$m" >> "$allowed"
	for p in "app/$m"/*/; do headers_in "$p" >> "$allowed"; done   # its private folders
	for d in $(deps_of "$m"); do
		if [ "$d" = platform ]; then
			for p in $plat_dirs; do headers_in "platform/$p" >> "$allowed"; done
		else
			headers_in "app/$d" >> "$allowed"
		fi
	done
	echo board_limits.h >> "$allowed"
	[ "$m" = cli ] && echo skp_version.h >> "$allowed"   # generated: --version
	# shellcheck disable=SC2046 # source paths have no spaces
	includes_outside "not in module $m or the modules it may use ($(deps_of "$m" | tr '\n' ' '))" \
		$(find "app/$m" -name '*.[ch]') || fail=1
done

: > "$allowed"
for d in $plat_deps; do [ "$d" = base ] && headers_in app/base >> "$allowed"; done
for p in $plat_dirs; do headers_in "platform/$p" >> "$allowed"; done
printf '%s\n' $ports board_limits.h >> "$allowed"
# shellcheck disable=SC2046
includes_outside "platform code may include base, platform and the port headers ($ports) only" \
	$(find platform -name '*.[ch]') || fail=1

# An upward include must not compile: app/math with math's include path.
probe=app/math/.check_layers_probe.c
inc=""
for d in math $(deps_of math); do inc="$inc -Iapp/$d"; done
printf '#include "skin.h"\nint check_layers_probe;\n' > "$probe"
# shellcheck disable=SC2086 # the compiler command and its flags
if $cc $inc -fsyntax-only "$probe" 2>/dev/null; then
	echo "check-layers: app/math compiled an include of skin.h (a module above it): the include paths do not enforce the layers"
	fail=1
fi
rm -f "$probe"

[ $fail -eq 0 ] && echo "check-layers: $files files include only their own layer and the layers below; an upward include does not compile"
exit $fail
