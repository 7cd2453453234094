# board/rpi4: Raspberry Pi 4 kiosk (Cortex-A72, aarch64, Debian 12 arm64 or
# Raspberry Pi OS bookworm; KMS on vc4/v3d, buttons on the GPIO header).
# Cross build from x86-64: `make BOARD=rpi4` (CROSS_COMPILE= builds natively
# on the Pi). Runtime settings are in board.ini, wiring in README.md.
BOARD_DESC    := Raspberry Pi 4 (aarch64) kiosk
CROSS_COMPILE ?= aarch64-linux-gnu-
CC            := $(CROSS_COMPILE)gcc
AR            := $(CROSS_COMPILE)ar
NM            := $(CROSS_COMPILE)nm
SIZE          := $(CROSS_COMPILE)size
STRIP         := $(CROSS_COMPILE)strip
DEB_ARCH      := arm64
BOARD_CFLAGS  := -O2 -g -mcpu=cortex-a72
# Backends (app/sources.mk): the kiosk's screen (kms) and headless runs;
# no X11 and no OSMesa, so neither library is needed on the Pi.
DISPLAYS      := kms surfaceless
INPUTS        := gpio keyboard script
# No AVX2 on ARM: NEON float kernels (app/skin/kernels/skin_neon.c), or SIMD=scalar.
SIMD          ?= neon
# Debian packages `make deps` installs (board/deps.mk), building on the Pi.
LIB_PKGS      := libcmocka-dev libegl-dev libgles-dev libgbm-dev libdrm-dev libgpiod-dev libpng-dev libjpeg-dev libassimp-dev libjson-c-dev
DEB_PKGS      := gcc libc6-dev make pkg-config $(LIB_PKGS) dpkg-dev help2man lintian

# Cross build from another architecture (Debian 12 x86-64): the compiler,
# the arm64 multiarch -dev packages (dpkg --add-architecture arm64), a
# pkg-config that looks only at them, and qemu-user to run the tests
# (`make BOARD=rpi4 test`, through tests/cross_run.sh: the rendering tests
# are skipped there, see that script for why).
ifneq ($(CROSS_COMPILE),)
ifneq ($(shell uname -m),aarch64)
DEB_PKGS      := gcc libc6-dev make pkg-config gcc-aarch64-linux-gnu qemu-user-static binfmt-support \
                 $(addsuffix :arm64,$(LIB_PKGS)) dpkg-dev help2man lintian
DEPS_PREPARE  := dpkg --add-architecture arm64 &&
PKG_CONFIG    := PKG_CONFIG_LIBDIR=/usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig pkg-config
export QEMU_LD_PREFIX := /usr/aarch64-linux-gnu
# the demo image and the man pages are made by the arm64 programs
TARGET_RUN    := qemu-aarch64-static
RPI4_QEMU_SKIP := test_render test_display test_kiosk test_image_cli test_compare_report test_compare_pictures test_compare_parts test_image_repair \
                  test_convert_cli test_user_mesh_play test_rig_import test_readme test_image_meaning test_playback_window test_kiosk_wait \
                  test_compare_seen test_background test_kiosk_options test_image_cli_damage test_sync test_skintool_view \
                  test_video
TEST_WRAP     := sh tests/cross_run.sh aarch64 "$(RPI4_QEMU_SKIP)" --
endif
endif

# Its own build directory unless BUILD= is given, so that switching between
# boards rebuilds nothing that another board built.
ifeq ($(origin BUILD),file)
BUILD := build/$(BOARD)
endif
