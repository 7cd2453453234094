# board/cortex-m0: Cortex-M0 (ARMv6-M, no FPU): the portable core compiles
# (float code through libgcc's soft-float), but the test runs only the
# fixed-point kernel, which needs no floating point at all. QEMU has no
# Cortex-M0 machine with enough RAM, so `make BOARD=cortex-m0 test` runs
# the ARMv6-M binary on mps2-an385 (a Cortex-M3, which executes the
# ARMv6-M instruction set): it checks the code and the checksum, not M0
# timing or memory. `make size BOARD=cortex-m0` gives flash and RAM.
BOARD_DESC    := Cortex-M0 (ARMv6-M, no FPU), run on mps2-an385
BOARD_KIND    := mcu
CC            := arm-none-eabi-gcc
SIZE          := arm-none-eabi-size
NM            := arm-none-eabi-nm
AR            := arm-none-eabi-ar
MCU_CPU       := -mcpu=cortex-m0 -mthumb -mfloat-abi=soft
BOARD_CFLAGS  := $(MCU_CPU) -O2 -g -ffreestanding -ffunction-sections -fdata-sections -fstack-usage
# app/math and app/skin (the skinning kernels): board/mcu.mk
MCU_KERNEL_OPT := -O3
SIMD          := scalar
MCU_FULL      := 0
QEMU_SYSTEM   := qemu-system-arm
QEMU_MACHINE  := mps2-an385
EMB_FRAMES    := 8
EMB_STRIDE    := 140
DEB_PKGS      := gcc libc6-dev make gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm

# Its own build directory unless BUILD= is given, so that switching between
# boards rebuilds nothing that another board built.
ifeq ($(origin BUILD),file)
BUILD := build/$(BOARD)
endif
