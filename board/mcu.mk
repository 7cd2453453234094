# Rules for microcontroller boards (board.mk sets BOARD_KIND := mcu): the
# Makefile includes this file instead of its Linux rules. Builds
#   $(OUT)/libskp.a       the portable core for the board (CORE_MODULES
#                         of app/sources.mk less the GL renderer, the portable
#                         kernels only)
#   $(OUT)/emb_skin.elf   tests/embedded/emb_skin.c for the board (semihosted)
#   $(OUT)/host/emb_skin  the same test built for the host: the reference
# `make BOARD=... test` runs both and fails unless the fixed-kernel checksums
# are equal. The test's data is made on the host by tests/embedded/emb_gen.c
# (see there for why the tables are in fixed point).
HOSTCC   ?= cc
WARN     := -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wvla
OUT      := $(BUILD)

include app/sources.mk

# The portable core (app/sources.mk) less the renderer, which needs GLES2
# headers and a display; the board's SIMD is scalar (no x86 kernels).
MCU_MODULES := $(filter-out render,$(CORE_MODULES))
CORE_SRC    := $(foreach m,$(MCU_MODULES),$(SRC_$(m)))
MCU_INC     := $(foreach m,$(MCU_MODULES),-Iapp/$(m))

CPPFLAGS    := -Iboard/$(BOARD) -MMD -MP
CFLAGS_APP  := -std=c11 $(WARN) $(BOARD_CFLAGS) $(EXTRA_CFLAGS)
HOST_CFLAGS := -std=c11 $(WARN) -O2 -g $(EXTRA_CFLAGS)
EMB_DEFS    := $(if $(filter 1,$(MCU_FULL)),-DEMB_FULL)
EMB_INC     := -Itests/embedded -Itests/support -I$(OUT)/emb $(MCU_INC) -Iapp/skin/kernels

CORE_OBJ      := $(CORE_SRC:%.c=$(OUT)/%.o)
HOST_CORE_OBJ := $(CORE_SRC:%.c=$(OUT)/host/%.o)
CORE_LIB      := $(OUT)/libskp.a
HOST_CORE_LIB := $(OUT)/host/libskp.a
EMB_TABLES    := $(OUT)/emb/emb_tables.h
EMB_FLOAT     := $(OUT)/emb/emb_float_tables.h
EMB_ELF       := $(OUT)/emb_skin.elf
EMB_HOST      := $(OUT)/host/emb_skin
BENCH_ELF     := $(OUT)/emb_bench.elf
BENCH_HOST    := $(OUT)/host/emb_bench
EMB_GEN       := $(OUT)/host/emb_gen
EMB_CODEC_GEN := $(OUT)/host/emb_codec_gen
EMB_CODEC     := $(OUT)/emb/emb_codec.h
DEMO_AMC      := $(OUT)/assets/demo.amc

.PHONY: all test size bench clean help
all: $(CORE_LIB) $(EMB_ELF) $(EMB_HOST)

# Objects depend on the flags they were built with.
FLAGS_STAMP := $(OUT)/flags.stamp
FLAGS_NOW   := $(CC) $(CPPFLAGS) $(CFLAGS_APP) $(MCU_KERNEL_OPT) $(HOSTCC) $(HOST_CFLAGS) $(EMB_DEFS) $(EMB_FRAMES) $(EMB_STRIDE)
ifneq ($(strip $(shell cat $(FLAGS_STAMP) 2>/dev/null)),$(strip $(FLAGS_NOW)))
  $(shell mkdir -p $(OUT) && echo '$(FLAGS_NOW)' > $(FLAGS_STAMP))
endif

# each module with its own include path, as on Linux
$(foreach m,$(MCU_MODULES),$(eval $(SRC_$(m):%.c=$(OUT)/%.o) $(SRC_$(m):%.c=$(OUT)/host/%.o): MOD_INC = $(call mod_inc,$(m))))
# The skinning kernels and the maths under them (both DQBS kernels, fixed
# and float) at -O3 (board.mk's MCU_KERNEL_OPT): on a Cortex-M0 GCC 12's
# -O3 runs the fixed kernel in 6% fewer instructions than -O2, the float
# one (libgcc's soft-float) in 0.4% fewer.
$(foreach m,math skin,$(eval $(SRC_$(m):%.c=$(OUT)/%.o): OPT_KERNEL = $(MCU_KERNEL_OPT)))
$(OUT)/app/%.o: app/%.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(MOD_INC) $(CFLAGS_APP) $(OPT_KERNEL) -c $< -o $@
$(OUT)/host/app/%.o: app/%.c $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(HOSTCC) $(CPPFLAGS) $(MOD_INC) $(HOST_CFLAGS) -c $< -o $@

$(CORE_LIB): $(CORE_OBJ)
	rm -f $@ && $(AR) rcs $@ $^
$(HOST_CORE_LIB): $(HOST_CORE_OBJ)
	rm -f $@ && ar rcs $@ $^

# The test's data, made on the host with the board's limits.
$(OUT)/assets/demo_motion: assets/demo_motion.c
	@mkdir -p $(@D)
	$(HOSTCC) -std=c11 -D_DEFAULT_SOURCE $(WARN) -O2 $< -o $@ -lm
$(DEMO_AMC): $(OUT)/assets/demo_motion
	$< > $@.tmp && mv $@.tmp $@
$(EMB_GEN): tests/embedded/emb_gen.c $(HOST_CORE_LIB)
	$(HOSTCC) $(CPPFLAGS) $(MCU_INC) $(HOST_CFLAGS) $< $(HOST_CORE_LIB) -lm -o $@
$(EMB_TABLES): $(EMB_GEN) assets/demo.asf $(DEMO_AMC) $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(EMB_GEN) assets/demo.asf $(DEMO_AMC) $(EMB_FRAMES) $(EMB_STRIDE) $@ $(EMB_FLOAT)
$(EMB_FLOAT): $(EMB_TABLES)
	@test -f $@
# the compressed clip of tests/support/codec_synth.h, coded on the host by
# app/encode's segment coder (host only: it allocates)
$(OUT)/host/app/encode/encode_segment.o: MOD_INC = $(call mod_inc,encode)
$(EMB_CODEC_GEN): tests/embedded/emb_codec_gen.c $(OUT)/host/app/encode/encode_segment.o $(HOST_CORE_LIB)
	$(HOSTCC) $(CPPFLAGS) -Itests/support $(call mod_inc,encode) $(HOST_CFLAGS) $(filter %.c %.o %.a,$^) -lm -o $@
$(EMB_CODEC): $(EMB_CODEC_GEN)
	@mkdir -p $(@D)
	$(EMB_CODEC_GEN) $@

$(OUT)/emb/%.o: tests/embedded/%.c $(EMB_TABLES) $(EMB_FLOAT) $(EMB_CODEC) $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(EMB_INC) $(EMB_DEFS) $(CFLAGS_APP) -c $< -o $@
$(OUT)/host/emb/%.o: tests/embedded/%.c $(EMB_TABLES) $(EMB_FLOAT) $(EMB_CODEC) $(FLAGS_STAMP)
	@mkdir -p $(@D)
	$(HOSTCC) $(CPPFLAGS) $(EMB_INC) $(EMB_DEFS) $(HOST_CFLAGS) -c $< -o $@

# No crt0, no syscalls: newlib's libc and libm only resolve what the core
# names (memcpy, strcmp, sinf...). Anything that would need malloc or a
# system call fails to link; the nm check below makes it explicit.
$(EMB_ELF): $(OUT)/emb/emb_skin.o $(OUT)/emb/emb_hash.o $(OUT)/emb/emb_stress.o $(OUT)/emb/emb_cortex_m.o \
            $(CORE_LIB) tests/embedded/mps2.ld
	$(CC) $(MCU_CPU) -nostartfiles -T tests/embedded/mps2.ld -Wl,--gc-sections \
	  -Wl,-Map=$(OUT)/emb_skin.map -o $@ $(filter %.o %.a,$^) -lm -lc -lgcc
	@if $(NM) $@ | grep -qwE '_?(malloc|calloc|realloc|free|_sbrk|_write|printf)'; then \
	  echo "$@: links an allocator or stdio:"; $(NM) $@ | grep -wE '_?(malloc|calloc|realloc|free|_sbrk|_write|printf)'; \
	  rm -f $@; exit 1; fi
ifneq ($(MCU_FULL),1)
	@if $(NM) $@ | grep -qE '__aeabi_[fd]|__(add|sub|mul|div)[sd]f3'; then \
	  echo "$@: the fixed-point build links floating-point helpers:"; $(NM) $@ | grep -E '__aeabi_[fd]|__(add|sub|mul|div)[sd]f3'; \
	  rm -f $@; exit 1; fi
endif
$(EMB_HOST): $(OUT)/host/emb/emb_skin.o $(OUT)/host/emb/emb_hash.o $(OUT)/host/emb/emb_stress.o \
             $(OUT)/host/emb/emb_host.o $(HOST_CORE_LIB)
	$(HOSTCC) -o $@ $^ -lm

# The benchmark (tests/embedded/emb_bench.c): both DQBS kernels, floating
# point linked on every board (soft-float on the M0).
$(BENCH_ELF): $(OUT)/emb/emb_bench.o $(OUT)/emb/emb_cortex_m.o $(CORE_LIB) tests/embedded/mps2.ld
	$(CC) $(MCU_CPU) -nostartfiles -T tests/embedded/mps2.ld -Wl,--gc-sections \
	  -Wl,-Map=$(OUT)/emb_bench.map -o $@ $(filter %.o %.a,$^) -lm -lc -lgcc
$(BENCH_HOST): $(OUT)/host/emb/emb_bench.o $(OUT)/host/emb/emb_host.o $(HOST_CORE_LIB)
	$(HOSTCC) -o $@ $^ -lm

QEMU_RUN := timeout 300 $(QEMU_SYSTEM) -M $(QEMU_MACHINE) -nographic -semihosting -monitor none -serial null -kernel

test: deps
	@$(MAKE) --no-print-directory all
	@echo "== host reference: $(EMB_HOST)"; \
	$(EMB_HOST) > $(OUT)/emb_host.log 2>&1; hrc=$$?; cat $(OUT)/emb_host.log; \
	echo "== $(QEMU_SYSTEM) -M $(QEMU_MACHINE): $(EMB_ELF)"; \
	$(QEMU_RUN) $(EMB_ELF) > $(OUT)/emb_target.log 2>&1; trc=$$?; cat $(OUT)/emb_target.log; \
	h=$$(sed -n 's/^emb: fixed-kernel checksum //p' $(OUT)/emb_host.log); \
	t=$$(sed -n 's/^emb: fixed-kernel checksum //p' $(OUT)/emb_target.log); \
	fail=0; \
	if [ $$hrc -ne 0 ] || [ $$trc -ne 0 ]; then echo "emb: host exit $$hrc, target exit $$trc"; fail=1; fi; \
	if [ -z "$$h" ] || [ "$$h" != "$$t" ]; then echo "emb: FAILED: $(BOARD) fixed-kernel checksum '$$t' != host '$$h'"; fail=1; \
	else echo "emb: $(BOARD) fixed-kernel checksum $$t equals the host's"; fi; \
	hs=$$(sed -n 's/^emb: sampler checksum //p' $(OUT)/emb_host.log); \
	ts=$$(sed -n 's/^emb: sampler checksum //p' $(OUT)/emb_target.log); \
	if [ "$$hs" != "$$ts" ]; then echo "emb: FAILED: $(BOARD) sampler checksum '$$ts' != host '$$hs'"; fail=1; \
	elif [ -n "$$hs" ]; then echo "emb: $(BOARD) sampler checksum $$ts equals the host's (app/play: poses by time, and on a wall clock)"; fi; \
	hc=$$(sed -n 's/^emb: codec checksum //p' $(OUT)/emb_host.log); \
	tc=$$(sed -n 's/^emb: codec checksum //p' $(OUT)/emb_target.log); \
	if [ "$$hc" != "$$tc" ]; then echo "emb: FAILED: $(BOARD) codec checksum '$$tc' != host '$$hc'"; fail=1; \
	elif [ -n "$$hc" ]; then echo "emb: $(BOARD) codec checksum $$tc equals the host's (app/codec: decoded bits)"; fi; \
	h=$$(sed -n 's/^emb: stress checksum //p' $(OUT)/emb_host.log); \
	t=$$(sed -n 's/^emb: stress checksum //p' $(OUT)/emb_target.log); \
	if [ -z "$$h" ] || [ "$$h" != "$$t" ]; then echo "emb: FAILED: $(BOARD) stress checksum '$$t' != host '$$h'"; fail=1; \
	else echo "emb: $(BOARD) stress checksum $$t equals the host's"; fi; \
	if [ $$fail = 0 ]; then echo "emb: 1 passed, 0 failed"; else echo "emb: 0 passed, 1 failed"; exit 1; fi

# Both DQBS kernels on both cores, whichever board was named: instructions
# a vertex counted under qemu, cycles by a model, vertices at 30 fps
# (tests/embedded/mcu_bench.sh). Each board's objects in its own directory.
BENCH_DIR_cortex-m0 := $(if $(filter cortex-m0,$(BOARD)),$(OUT),build/cortex-m0)
BENCH_DIR_cortex-m4 := $(if $(filter cortex-m4,$(BOARD)),$(OUT),build/cortex-m4)
bench: deps
	@for b in cortex-m0 cortex-m4; do \
	  d=$$(case $$b in cortex-m0) echo $(BENCH_DIR_cortex-m0);; *) echo $(BENCH_DIR_cortex-m4);; esac); \
	  $(MAKE) --no-print-directory -s BOARD=$$b BUILD=$$d $$d/emb_bench.elf || exit 1; \
	done
	sh tests/embedded/mcu_bench.sh $(BENCH_DIR_cortex-m0)/emb_bench.elf $(BENCH_DIR_cortex-m4)/emb_bench.elf

# Flash = code + constants + the .data image; RAM = .data + .bss + stack.
size: $(EMB_ELF) $(CORE_LIB)
	@$(SIZE) -A $(EMB_ELF) | awk '{ s[$$1] = $$2 } END { printf "emb_skin.elf ($(BOARD)): flash %d bytes (code+constants %d, .data image %d), RAM %d bytes (.data %d + .bss %d + stack %d)\n", s[".text"] + s[".ARM.exidx"] + s[".data"], s[".text"] + s[".ARM.exidx"], s[".data"], s[".data"] + s[".bss"] + s[".stack"], s[".data"], s[".bss"], s[".stack"] }'
	@$(SIZE) -t $(CORE_LIB) | awk 'END { printf "libskp.a ($(BOARD), whole portable core): code %d bytes, .data %d, .bss %d\n", $$1, $$2, $$3 }'
	@cat $(CORE_OBJ:.o=.su) $(OUT)/emb/*.su 2>/dev/null | sort -t'	' -k2 -n -r | head -3 | \
	  awk -F'\t' '{ printf "  stack frame %s bytes: %s\n", $$2, $$1 }'

clean:
	rm -rf $(BUILD)

help:
	@echo "make BOARD=$(BOARD)        build $(CORE_LIB), $(EMB_ELF) and the host reference"
	@echo "make BOARD=$(BOARD) test   run the skinning test under $(QEMU_SYSTEM) -M $(QEMU_MACHINE) and compare checksums"
	@echo "make BOARD=$(BOARD) size   flash and RAM use"
	@echo "make BOARD=$(BOARD) bench  both DQBS kernels on the Cortex-M0 and M4: instructions a vertex (qemu), cycles (a model), vertices at 30 fps"
	@echo "make BOARD=$(BOARD) deps   check (and as root install) $(DEB_PKGS)"

-include $(CORE_OBJ:.o=.d) $(HOST_CORE_OBJ:.o=.d) $(wildcard $(OUT)/emb/*.d $(OUT)/host/emb/*.d)
