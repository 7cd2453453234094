#!/bin/sh
# The man pages, made by help2man from the programs' own --help, so the
# option reference never drifts from the code: skinplay(1), skintool(1) and
# one page per skintool command, skintool-COMMAND(1), from
# `skintool COMMAND --help` (the command list from `skintool --help`).
# --help's "Exit status:" list becomes the EXIT STATUS section;
# platform/debian/NAME.h2m adds what --help does not say (FILES, SEE ALSO).
# Usage: man_pages.sh OUT_DIR VERSION RUN_DIR
#   RUN_DIR holds skinplay and skintool as this machine runs them (for a
#   cross build: scripts that run them under qemu-user).
set -eu
out=$1 version=$2 run=$3
h2m=platform/debian
mkdir -p "$out"
tmp=$(mktemp -d) && trap 'rm -rf "$tmp"' EXIT

# $1 the program (a path), $2 the page's name, then help2man's options
page() {
	prog=$1 name=$2
	shift 2
	help2man --no-info --section=1 --version-string="$name $version" "$@" --output="$tmp/$name.1" "$prog"
	sed 's/^\.SS "Exit status:"$/.SH "EXIT STATUS"/' "$tmp/$name.1" > "$tmp/$name.1.tmp"
	grep -q '^\.SH "EXIT STATUS"' "$tmp/$name.1.tmp" || { echo "man_pages: $name: no Exit status list in --help"; exit 1; }
	mv "$tmp/$name.1.tmp" "$out/$name.1"
}

page "$run/skinplay" skinplay --include="$h2m/skinplay.h2m"

commands=$("$run/skintool" --help | sed -n 's/^  \([a-z][a-z-]*\)  *\([^ -].*\)$/\1/p')
[ -n "$commands" ] || { echo "man_pages: no commands in skintool --help"; exit 1; }
{
	echo '[SEE ALSO]'
	for c in $commands; do printf '.BR skintool\\-%s (1),\n' "$c"; done
	echo '.BR skinplay (1)'
} > "$tmp/skintool-see-also.h2m"
page "$run/skintool" skintool --include="$h2m/skintool.h2m" --include="$tmp/skintool-see-also.h2m"

printf '[SEE ALSO]\n.BR skintool (1),\n.BR skinplay (1)\n' > "$tmp/command.h2m"
for c in $commands; do
	what=$("$run/skintool" --help | sed -n "s/^  $c  *//p")
	printf '#!/bin/sh\nexec "%s" %s "$@"\n' "$run/skintool" "$c" > "$tmp/skintool-$c"
	chmod 755 "$tmp/skintool-$c"
	page "$tmp/skintool-$c" "skintool-$c" --name="$what" --include="$tmp/command.h2m"
done
