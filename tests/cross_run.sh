#!/bin/sh
# Runs the test runner for a cross-built board under qemu-user.
# Usage: cross_run.sh ARCH "TESTS TO SKIP" -- COMMAND...
#
# With binfmt_misc handling ARCH (qemu-user-static + binfmt-support; as
# root this script enables it when it can), the test programs and the tools
# they spawn run as if native. Without it, the test programs run through
# qemu-ARCH-static (SKP_TEST_RUNNER) and the integration tests, which spawn
# the built tools, are skipped as well. The rendering tests are always
# skipped: under qemu-user there is no GPU and no aarch64 Mesa driver, and a
# software rasteriser emulated instruction by instruction would take hours.
# SKP_TEST_EMULATED names the emulator, for tests to probe what it may not
# run and skip it: threads (pthread_create in a dynamically linked aarch64
# program never returns under qemu-user 7.2 or 10.0 on some hosts; a static
# one's does).
arch=$1; skip=$2; shift 2
[ "$1" = "--" ] && shift
qemu=qemu-$arch-static
command -v "$qemu" >/dev/null 2>&1 || { echo "cross_run: $qemu not found (make deps BOARD=...)"; exit 1; }
export QEMU_LD_PREFIX="${QEMU_LD_PREFIX:-/usr/$arch-linux-gnu}" SKP_TEST_EMULATED="$qemu"

binfmt=/proc/sys/fs/binfmt_misc
if [ ! -e "$binfmt/qemu-$arch" ] && [ "$(id -u)" = 0 ] && command -v update-binfmts >/dev/null 2>&1; then
	[ -e "$binfmt/register" ] || mount -t binfmt_misc binfmt_misc "$binfmt" 2>/dev/null
	update-binfmts --enable "qemu-$arch" >/dev/null 2>&1
fi
echo "cross_run: skipped: $skip (no GPU or display under qemu-user; rendering is tested natively)"
if grep -q '^enabled' "$binfmt/qemu-$arch" 2>/dev/null; then
	echo "cross_run: $arch programs run through binfmt_misc ($qemu)"
	export SKP_TEST_RUNNER=""
else
	export SKP_TEST_RUNNER="$qemu"
	spawn=$(grep -l test_tool_path tests/unit/test_*.c tests/integration/test_*.c | xargs -n1 basename | sed 's/\.c$//' | tr '\n' ' ')
	echo "cross_run: no binfmt_misc entry for $arch: tests run through $qemu; also skipped: $spawn(they spawn the built tools)"
	skip="$skip $spawn"
fi
why="skipped under qemu-user (reason above)"
export SKP_TEST_SKIP="$skip" SKP_TEST_SKIP_WHY="$why"
exec "$@"
