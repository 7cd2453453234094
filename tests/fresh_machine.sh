#!/bin/sh
# The README's commands on a fresh machine: a Debian minbase root with only
# git and make (debootstrap), a clone of this repository's HEAD, then
# `make test` and `make run` exactly as the README has them, each timed;
# `make run` must show the default show's character (its vertex count in
# the log, its skin over 2% of the contact sheet: tests/fresh_pixels.c).
# With --deb it also builds the packages there (`make deb`, lintian) and, in
# a second, pristine root, installs skinplay alone (`apt install
# ./skinplay_*.deb`: neither skintool nor Assimp may come with it), plays the
# installed demo image headless to the end of its clip, installs
# skinplay-tools and runs `skintool info` on the image, purges both and
# checks that nothing is left.
#
#   tests/fresh_machine.sh [--suite=trixie|bookworm] [--deb | --debs=DIR]
#                          [--test=all|unit] [--cross=rpi4] [--keep]
#                          [--cache=DIR] [--mirror=URL] [--quiet]
#
# --test=unit runs `make test-unit` where the README says `make test`: for
# a release whose every tier this machine already ran (CI on Debian 12).
# --debs=DIR installs the packages `make deb` made on this machine (DIR,
# usually build/) in the pristine root instead of building them in the
# fresh one: this machine's release only.
#
# --cross=BOARD then cross-builds that board in the same root, as its README
# (board/rpi4/README.md) says: `make deps BOARD=rpi4`, `make BOARD=rpi4
# test-unit` (the unit tier under qemu-user, built with the package's
# hardening flags, as every build is), `make BOARD=rpi4 deb` (that build
# packaged, lintian): on trixie, the system Raspberry Pi OS trixie is built from.
#
# Needs root (debootstrap, chroot, mounts), util-linux's unshare, overlayfs
# and the network to the mirror. The minbase root is made once per suite and
# kept in the cache (default /var/cache/skinplay-fresh; --refresh makes it
# again); each run works on an overlay of it, so a second run starts from
# the same untouched system in seconds. Downloaded .debs are cached too.
# Everything is mounted in a private mount and pid namespace: when the run
# ends, however it ends, its mounts and processes are gone. The shared test
# data (../shared) is mounted read-only beside the clone when present.
# Exit status: 0 when every step passed, 1 when one failed (its log's tail
# is printed), 2 for bad usage or a machine that cannot run the check.
set -eu

suite=trixie deb=0 keep=0 quiet=0 refresh=0 cross= tier=all debs=
cache=/var/cache/skinplay-fresh mirror=http://deb.debian.org/debian
repo=$(cd "$(dirname "$0")/.." && pwd)
for a in "$@"; do
	case $a in
	--suite=*) suite=${a#*=} ;;
	--deb) deb=1 ;;
	--debs=*) deb=1 debs=${a#*=} ;;
	--test=*) tier=${a#*=} ;;
	--cross=*) cross=${a#*=} ;;
	--keep) keep=1 ;;
	--quiet) quiet=1 ;;
	--refresh) refresh=1 ;;
	--cache=*) cache=${a#*=} ;;
	--mirror=*) mirror=${a#*=} ;;
	--inside=*) inside=${a#*=} ;;
	--help) sed -n '2,/^set -eu/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
	*) echo "fresh_machine: unknown argument '$a' (--help lists them)" >&2; exit 2 ;;
	esac
done

say() { [ "$quiet" = 1 ] || echo "fresh-machine $suite: $*"; }
die() { echo "fresh-machine $suite: $*" >&2; exit 2; }
now() { date +%s; }

# ---- inside the namespaces: mount, chroot, run one step ----------------
# $inside is "build" or "package": which root, which steps.
if [ -n "${inside:-}" ]; then
	work=$FRESH_WORK
	root=$work/$inside
	# an overlay of the cached base; where overlayfs is missing, a copy
	if ! mount -t overlay overlay -o "lowerdir=$cache/$suite,upperdir=$work/$inside-upper,workdir=$work/$inside-ovl" \
		"$root" 2>/dev/null && [ ! -e "$root/.skinplay-base" ]; then
		cp -a "$cache/$suite/." "$root/"
	fi
	mount -t proc proc "$root/proc"
	# a cross board's tests run its programs through the host's qemu entry
	if [ -e /proc/sys/fs/binfmt_misc/register ]; then
		mount -t binfmt_misc binfmt_misc "$root/proc/sys/fs/binfmt_misc" 2>/dev/null || true
	fi
	mount --rbind /dev "$root/dev"
	mount -t tmpfs -o mode=1777 tmpfs "$root/dev/shm"
	mount --rbind /sys "$root/sys"
	mkdir -p "$cache/$suite-archives" "$root/var/cache/apt/archives"
	mount --bind "$cache/$suite-archives" "$root/var/cache/apt/archives"
	cp /etc/resolv.conf "$root/etc/resolv.conf"
	mkdir -p "$root/src/repo"
	mount --bind -o ro "$repo" "$root/src/repo"
	if [ -d "$repo/../shared" ] && [ "$inside" = build ]; then
		mkdir -p "$root/root/work/shared"
		mount --bind -o ro "$repo/../shared" "$root/root/work/shared"
	fi
	exec chroot "$root" /usr/bin/env -i HOME=/root TERM=dumb LANG=C.UTF-8 \
		PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
		/bin/sh -c "$FRESH_SCRIPT"
fi

# ---- outside: the base root, the work area, the steps -------------------
[ "$(id -u)" = 0 ] || die "needs root (debootstrap, chroot, mounts)"
for c in debootstrap unshare chroot; do
	command -v $c >/dev/null 2>&1 || die "needs $c (apt-get install debootstrap util-linux)"
done
case $suite in bookworm|trixie) ;; *) die "--suite is bookworm or trixie, got '$suite'" ;; esac
case $tier in all|unit) ;; *) die "--test is all or unit, got '$tier'" ;; esac
if [ -n "$debs" ]; then
	debs=$(cd "$debs" 2>/dev/null && pwd) || die "--debs: no directory '$debs'"
	ls "$debs"/skinplay_*.deb "$debs"/skinplay-tools_*.deb >/dev/null 2>&1 ||
		die "--debs: no skinplay_*.deb and skinplay-tools_*.deb in $debs (make deb)"
fi
[ -z "$cross" ] || [ -f "$repo/board/$cross/board.mk" ] || die "--cross: no board/$cross/board.mk"
git -C "$repo" rev-parse HEAD >/dev/null 2>&1 || die "$repo is not a git clone"

mkdir -p "$cache"
if [ "$refresh" = 1 ] || [ ! -e "$cache/$suite/.skinplay-base" ]; then
	t=$(now)
	say "debootstrap --variant=minbase --include=git,make $suite (once; kept in $cache/$suite)"
	rm -rf "$cache/$suite"
	if ! debootstrap --variant=minbase --include=git,make "$suite" "$cache/$suite" "$mirror" \
		> "$cache/$suite.debootstrap.log" 2>&1; then
		tail -n 20 "$cache/$suite.debootstrap.log" >&2
		die "debootstrap failed (log: $cache/$suite.debootstrap.log)"
	fi
	date -u > "$cache/$suite/.skinplay-base"
	say "base system in $(($(now) - t)) s"
fi

work=$(mktemp -d "${TMPDIR:-/var/tmp}/skinplay-fresh.XXXXXX")
cleanup() {
	if [ "$keep" = 1 ]; then say "kept $work"; else rm -rf "$work"; fi
}
trap cleanup EXIT
for r in build package; do mkdir -p "$work/$r" "$work/$r-upper" "$work/$r-ovl"; done
logs=$work/logs
mkdir -p "$logs"

# Runs script (sh) in root $1 (build or package), logging to $logs/$2.log;
# prints the step's time; on failure prints the log's tail and stops.
fail=0
# On a terminal a running step shows its time and, from the last run's
# time of the same step (kept in the cache), about how long is left.
times=$cache/$suite.times
progress() {
	pid=$1 name=$2 t=$3
	last=$(awk -v n="$name" '$1 == n { s = $2 } END { print s + 0 }' "$times" 2>/dev/null) || last=0
	while kill -0 "$pid" 2>/dev/null; do
		if [ -t 2 ]; then
			el=$(($(now) - t))
			if [ "$last" -gt "$el" ]; then left=", about $((last - el)) s left"; else left=""; fi
			printf '\rfresh-machine %s: %s: %d s%s   ' "$suite" "$name" "$el" "$left" >&2
		fi
		sleep 1
	done
	[ -t 2 ] && printf '\r%78s\r' '' >&2
	wait "$pid"
}
step() {
	r=$1 name=$2 script=$3 t=$(now)
	FRESH_WORK=$work FRESH_SCRIPT="$script" unshare --mount --pid --fork --propagation private \
		"$0" --suite="$suite" --cache="$cache" --inside="$r" > "$logs/$name.log" 2>&1 &
	if progress $! "$name" "$t"; then
		summary=$(grep -E '^(tests:|run:|deb:|package:)' "$logs/$name.log" | tail -n 3 | tr '\n' ' ')
		echo "$name $(($(now) - t))" >> "$times"
		say "$name: passed in $(($(now) - t)) s ${summary:+($summary)}"
	else
		say "$name: FAILED after $(($(now) - t)) s; the end of its log:"
		tail -n 40 "$logs/$name.log"
		[ "$keep" = 1 ] && say "whole log: $logs/$name.log"
		fail=1
		exit 1
	fi
}

rev=$(git -C "$repo" rev-parse --short HEAD)
say "clone of $rev, then the README's commands"
step build clone "git clone -q /src/repo /root/work/main && git -C /root/work/main log --oneline -1"
# exactly as the README says, from the clone
if [ "$tier" = all ]; then
	step build "make-test" "cd /root/work/main && make test"
else
	step build "make-test-unit" "cd /root/work/main && make test-unit"
fi
# the default show's character: the MakeHuman body (13,380 vertices) named
# in the log, and its skin on the contact sheet (tests/fresh_pixels.c)
step build "make-run" "cd /root/work/main && { make run >/root/run.log 2>&1; rc=\$?; cat /root/run.log; [ \$rc = 0 ]; } &&
	ls out/contact_sheet.png >/dev/null &&
	grep -q 'a body of 13380 vertices' /root/run.log &&
	cc -O2 tests/fresh_pixels.c -o /root/fresh_pixels \$(pkg-config --cflags --libs libpng) &&
	/root/fresh_pixels out/contact_sheet.png 2 &&
	echo \"run: \$(ls out/frame_*.png | wc -l) frames and out/contact_sheet.png, the MakeHuman body in them\""

if [ "$deb" = 1 ]; then
	mkdir -p "$work/package-upper/root" "$work/package/root"
	if [ -n "$debs" ]; then
		say "the packages make deb made on this machine ($debs)"
		for f in "$debs"/skinplay*_*.deb; do
			cp "$f" "$work/package-upper/root/" && cp "$f" "$work/package/root/"
		done
	else
		step build "make-deb" "cd /root/work/main && make deb"
		# what the build root wrote is in its overlay's upper layer (or the copy)
		for d in build-upper build; do
			for f in "$work/$d/root/work/main/build/"skinplay*_*.deb; do
				[ -f "$f" ] && cp "$f" "$work/package-upper/root/" && cp "$f" "$work/package/root/"
			done
		done
	fi
	pkg=$(basename "$work/package-upper/root/"skinplay_*.deb)
	tools=$(basename "$work/package-upper/root/"skinplay-tools_*.deb)
	say "$pkg: $(du -k "$work/package-upper/root/$pkg" | cut -f1) KiB, $tools: $(du -k "$work/package-upper/root/$tools" | cut -f1) KiB"
	# the file list of the untouched system, to compare after the purge (/run
	# is a tmpfs on a booted system)
	list='find / -xdev \( -path /proc -o -path /sys -o -path /dev -o -path /root -o -path /tmp -o -path /run -o -path /var/cache \
		-o -path /var/lib/apt -o -path /var/lib/dpkg -o -path /var/log -o -path /src \) -prune -o -print | sort'
	step package "package-install" "apt-get update -qq && $list > /root/before.txt &&
		DEBIAN_FRONTEND=noninteractive apt-get install -y -qq ./root/$pkg >/dev/null &&
		! command -v skintool >/dev/null && ! dpkg -l 'libassimp*' 2>/dev/null | grep -q '^ii' &&
		echo \"package: \$(dpkg-query -W -f='\${Package} \${Version} \${Architecture}' skinplay) installed, without skintool or Assimp\""
	# (a program's status decides, not that of the head or tail it is piped
	# to, which would pass a program that failed)
	step package "package-play" "v=\$(skinplay --version) && echo \"\$v\" | head -n 1 &&
		skinplay --image /usr/share/skinplay/demo.skn --platform surfaceless --size 320x180 &&
		test -f /usr/share/man/man1/skinplay.1.gz && echo 'package: played the demo to its end'"
	step package "package-tools" "DEBIAN_FRONTEND=noninteractive apt-get install -y -qq ./root/$tools >/dev/null &&
		info=\$(skintool info /usr/share/skinplay/demo.skn) && echo \"\$info\" | tail -n 1 &&
		test -f /usr/share/man/man1/skintool.1.gz && test -f /usr/share/man/man1/skintool-pack.1.gz &&
		echo \"package: \$(dpkg-query -W -f='\${Package} \${Version}' skinplay-tools) installed; info: all good\""
	# left behind: a path the purge did not take back that no installed package
	# owns (what apt pulled in, adduser say, stays installed and owns its
	# files), but for the shadow files' backups: the skinplay user and the
	# gpio group stay, as Debian does with system users
	step package "package-purge" "dpkg -L skinplay skinplay-tools > /root/files.txt &&
		DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq skinplay skinplay-tools >/dev/null &&
		DEBIAN_FRONTEND=noninteractive apt-get autoremove --purge -y -qq >/dev/null &&
		$list > /root/after.txt && comm -13 /root/before.txt /root/after.txt > /root/new.txt &&
		cat /var/lib/dpkg/info/*.list | sort -u > /root/owned.txt &&
		comm -23 /root/new.txt /root/owned.txt | grep -vx -e /etc/passwd- -e /etc/group- -e /etc/shadow- \
			-e /etc/gshadow- > /root/orphans.txt;
		if [ -s /root/orphans.txt ]; then echo 'left behind:'; cat /root/orphans.txt; exit 1; fi;
		! dpkg-query -W skinplay >/dev/null 2>&1 && ! dpkg-query -W skinplay-tools >/dev/null 2>&1 &&
		echo \"package: purged, nothing left behind (\$(wc -l < /root/files.txt) paths were the packages')\""
fi
if [ -n "$cross" ]; then
	step build "cross-$cross-deps" "cd /root/work/main && make deps BOARD=$cross"
	# the unit tier under qemu-user: the board's code as this release's
	# compiler builds it (gcc 14 on trixie); the host's CI runs every tier
	# (built with the package's flags, as every build is: the package below
	# is the build tested here, not compiled again)
	step build "cross-$cross-test" "cd /root/work/main && make BOARD=$cross test-unit"
	# its demo image packed by this root's own skintool (the image format is
	# one on every architecture; under qemu-user the pack takes minutes)
	step build "cross-$cross-deb" "cd /root/work/main && make BOARD=$cross DEMO_PACKER=build/skintool deb"
fi
say "all steps passed"
