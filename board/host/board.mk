# board/host: x86-64 Debian 12 or 13 (desktop, headless, CI).
BOARD_DESC    := x86-64 Debian 12 or 13 (desktop, headless, CI)
CC            ?= cc
BOARD_CFLAGS  := -O2 -g
DEB_ARCH      := amd64
# Backends (app/sources.mk): every display for development and CI.
DISPLAYS      := surfaceless osmesa kms x11
INPUTS        := gpio keyboard script
# Skinning kernels: avx2 (AVX2+FMA, any x86-64 since 2013) or scalar.
SIMD          ?= avx2
# Debian packages `make deps` installs (board/deps.mk): compiler, libraries,
# the tools the tests run (Xvfb and xdotool: the X11 display and its keys; faketime: a wrong
# clock; chromium: the report
# page) and the packaging tools (`make deb`).
DEB_PKGS      := gcc libc6-dev make pkg-config libcmocka-dev libegl-dev libgles-dev libosmesa6-dev \
                 libgbm-dev libdrm-dev libgpiod-dev libpng-dev libx11-dev libassimp-dev libjson-c-dev xvfb xdotool faketime chromium assimp-testmodels \
                 dpkg-dev help2man lintian
