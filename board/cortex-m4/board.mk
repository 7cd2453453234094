# board/cortex-m4: Cortex-M4F (ARMv7E-M, single-precision FPU), run under
# QEMU's mps2-an386. Builds the portable core (no display, no GL) with
# Debian's bare-metal GCC and newlib (only memcpy/memset/strcmp and libm),
# and the semihosted skinning test tests/embedded/ (rules in
# board/mcu.mk): `make BOARD=cortex-m4 [test|size]`.
BOARD_DESC    := Cortex-M4F, mps2-an386 under qemu-system-arm
BOARD_KIND    := mcu
CC            := arm-none-eabi-gcc
SIZE          := arm-none-eabi-size
NM            := arm-none-eabi-nm
AR            := arm-none-eabi-ar
MCU_CPU       := -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
# -ffreestanding: no hosted libc assumed (newlib links only what the core
# calls by name); -fstack-usage feeds `make size`.
BOARD_CFLAGS  := $(MCU_CPU) -O2 -g -ffreestanding -ffunction-sections -fdata-sections -fstack-usage
# app/math and app/skin (the skinning kernels): board/mcu.mk
MCU_KERNEL_OPT := -O3
SIMD          := scalar
# 1: the test also runs the float pipeline (parse, FK, bind) on the target.
MCU_FULL      := 1
QEMU_SYSTEM   := qemu-system-arm
QEMU_MACHINE  := mps2-an386
# The embedded test's data: frames of the demo motion, every STRIDE-th.
EMB_FRAMES    := 8
EMB_STRIDE    := 140
# Debian packages `make deps BOARD=cortex-m4` installs (board/deps.mk).
DEB_PKGS      := gcc libc6-dev make gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm

# Its own build directory unless BUILD= is given, so that switching between
# boards rebuilds nothing that another board built.
ifeq ($(origin BUILD),file)
BUILD := build/$(BOARD)
endif
