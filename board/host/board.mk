# board/host: x86-64 Debian 12 or 13 (desktop, headless, CI).
BOARD_DESC    := x86-64 Debian 12 or 13 (desktop, headless, CI)
CC            ?= cc
BOARD_CFLAGS  := -O2 -g
DEB_ARCH      := amd64
# Backends (app/sources.mk): every display for development and CI.
DISPLAYS      := surfaceless osmesa kms x11
INPUTS        := gpio keyboard script
# Video output (skinplay -o F.mp4 / F.webm, platform/sys/video_writer.c):
# auto builds it when pkg-config finds libavcodec, libavformat, libavutil
# and libswscale (app/sources.mk: PC_video); `make VIDEO=no` leaves it out
# (and its packages), `VIDEO=yes` stops the build without them.
VIDEO         ?= auto
# Skinning kernels: avx2 (AVX2+FMA, any x86-64 since 2013) or scalar.
SIMD          ?= avx2
# Debian packages `make deps` installs (board/deps.mk): compiler, libraries,
# the tools the tests run (Xvfb and xdotool: the X11 display and its keys; faketime: a wrong
# clock; chromium: the report
# page; ffmpeg: ffprobe reads the videos back) and the packaging tools (`make deb`).
DEB_PKGS      := gcc libc6-dev make pkg-config libcmocka-dev libegl-dev libgles-dev libosmesa6-dev \
                 libgbm-dev libdrm-dev libgpiod-dev libpng-dev libjpeg-dev libx11-dev libassimp-dev libjson-c-dev xvfb xdotool faketime chromium assimp-testmodels \
                 dpkg-dev help2man lintian \
                 $(if $(filter no,$(VIDEO)),,libavcodec-dev libavformat-dev libavutil-dev libswscale-dev ffmpeg)
