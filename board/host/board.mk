# board/host: x86-64 Debian 12 (desktop, headless, CI).
BOARD_DESC    := x86-64 Debian 12 host (desktop, headless, CI)
CC            ?= cc
BOARD_CFLAGS  := -O2 -g
# Skinning kernels: avx2 (AVX2+FMA, any x86-64 since 2013) or scalar.
SIMD          ?= avx2
# Debian packages `make deps` installs and the pkg-config modules that prove them.
DEB_PKGS      := pkg-config libcmocka-dev libegl-dev libgles-dev libosmesa6-dev \
                 libgbm-dev libdrm-dev libgpiod-dev libpng-dev libx11-dev xvfb chromium
PC_MODULES    := cmocka egl glesv2 osmesa gbm libdrm libgpiod libpng x11
# programs the tests use (Xvfb: the X11 display test; chromium: the report page)
DEB_TOOLS     := Xvfb chromium
