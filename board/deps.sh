#!/bin/sh
# Prints which of the Debian packages given are not installed, on one line.
# NAME means the native architecture (or an Architecture: all package),
# NAME:ARCH another one (a cross build's libraries). Prints nothing where
# there is no dpkg: there the build's own errors have to speak.
command -v dpkg-query >/dev/null 2>&1 || exit 0
native=$(dpkg --print-architecture)
names=$(for p in "$@"; do printf '%s\n' "${p%%:*}"; done | sort -u)
# shellcheck disable=SC2086 # one argument per package name
dpkg-query -W -f='${Package}:${Architecture} ${db:Status-Status}\n' $names 2>/dev/null |
awk -v native="$native" -v want="$*" '
$2 == "installed" { ok[$1] = 1 }
END {
	n = split(want, w, " ")
	for (i = 1; i <= n; i++) {
		p = w[i]
		if (index(p, ":") == 0)
			p = p ":" native
		split(p, name, ":")
		if (!ok[p] && !ok[name[1] ":all"])
			miss = miss (miss == "" ? "" : " ") w[i]
	}
	if (miss != "")
		print miss
}'
