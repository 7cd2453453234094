# skinplay build. `make help` lists the targets.
BOARD    ?= host
BUILD    ?= build
PREFIX   ?= /usr/local
DESTDIR  ?=

.DEFAULT_GOAL := all
VERSION  := 0.16.0
GIT_REV  := $(or $(shell git describe --always --dirty --abbrev=12 2>/dev/null),unknown)

include board/$(BOARD)/board.mk
include board/deps.mk

# Microcontroller boards (cortex-m4, cortex-m0) build the portable core and
# a semihosted test instead of the Linux programs: board/mcu.mk.
ifeq ($(BOARD_KIND),mcu)
include board/mcu.mk
else

include app/sources.mk

ifeq ($(SANITIZE),1)
  # Line tables only (-g1, after the board's -g): the file and line a
  # report names, without the variables' debug information, which cost
  # a fifth of the compile time (six of the heaviest files: 5.7 processor
  # seconds against 6.9). -O1, ASan's own advice, halves the compile time
  # but slows the sanitized tests by about as much (547 processor seconds
  # against 494).
  SAN_FLAGS := -g1 -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
  OUT       := $(BUILD)/san
else
  SAN_FLAGS :=
  OUT       := $(BUILD)
endif

# SIMD kernels chosen at build time (board.mk sets SIMD; `make SIMD=scalar`
# builds the portable path only). NEON is part of AArch64: no flags.
SIMD_DEFS_avx2  := -DSKP_SIMD_AVX2
SIMD_FLAGS_avx2 := -mavx2 -mfma
SIMD_DEFS_neon  := -DSKP_SIMD_NEON
SIMD_DEFS  := $(SIMD_DEFS_$(SIMD))
SIMD_FLAGS := $(SIMD_FLAGS_$(SIMD))

# pkg-config for the board's architecture (board.mk may set a cross one).
PKG_CONFIG ?= pkg-config
WARN     := -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wvla
# The board's backends (board.mk: DISPLAYS, INPUTS) and their libraries. No
# GL library is linked (app/render/gl_api.h): EGL hands out the entry
# points and OSMesa is dlopen()ed.
PLAT_PC     := $(sort $(foreach d,$(DISPLAYS),$(PC_display_$(d))) $(foreach i,$(INPUTS),$(PC_input_$(i))) $(PC_platform))
PLAT_CFLAGS := $(shell $(PKG_CONFIG) --cflags $(PLAT_PC) 2>/dev/null)
PLAT_LIBS   := $(shell $(PKG_CONFIG) --libs $(PLAT_PC) 2>/dev/null) $(if $(filter osmesa,$(DISPLAYS)),-ldl)
# libgpiod's API changed at 2.0: one seam file per API, by the library's
# pkg-config version (1.6 on Debian 12 / Pi OS bookworm, 2.x on trixie).
GPIOD_API := $(if $(filter 0 1,$(firstword $(subst ., ,$(shell $(PKG_CONFIG) --modversion libgpiod 2>/dev/null)))),1,2)
# Video output (skinplay -o F.mp4, F.webm): where board.mk asks for it
# (VIDEO: auto, yes; unset or no: none) and pkg-config finds libavcodec,
# libavformat, libavutil and libswscale. Only skinplay, the tests and the
# layer check link them; elsewhere skinplay refuses a video name.
VIDEO_ON     := $(if $(filter auto yes,$(VIDEO)),$(shell $(PKG_CONFIG) --exists $(PC_video) 2>/dev/null && echo 1))
ifeq ($(VIDEO)$(VIDEO_ON),yes)
$(error VIDEO=yes: pkg-config finds no $(PC_video) (Debian: libavcodec-dev libavformat-dev libavutil-dev libswscale-dev))
endif
VIDEO_CFLAGS := $(if $(VIDEO_ON),$(shell $(PKG_CONFIG) --cflags $(PC_video) 2>/dev/null))
VIDEO_LIBS   := $(if $(VIDEO_ON),$(shell $(PKG_CONFIG) --libs $(PC_video) 2>/dev/null))
BACKEND_DEFS := $(foreach d,$(DISPLAYS),-DSKP_DISPLAY_$(d)) $(foreach i,$(INPUTS),-DSKP_INPUT_$(i)) \
                -DSKP_GPIOD_API=$(GPIOD_API) $(if $(VIDEO_ON),-DSKP_VIDEO)
# Debian's hardening flags, as the packages are built (HARDEN=1, the
# default where dpkg-buildflags is: platform/debian/harden.mk), so that
# `make deb` packages this build without compiling everything again.
include platform/debian/harden.mk
CPPFLAGS    := -Iboard/$(BOARD) $(SIMD_DEFS) -MMD -MP
CFLAGS_CORE := -std=c11 $(WARN) $(BOARD_CFLAGS) $(SAN_FLAGS) $(EXTRA_CFLAGS)
# Host code (platform, programs) talks to Linux and POSIX, so it may use
# GNU extensions.
CFLAGS_HOST := -std=gnu11 $(WARN) $(BOARD_CFLAGS) $(SAN_FLAGS) $(PLAT_CFLAGS) $(BACKEND_DEFS) $(EXTRA_CFLAGS)
LDFLAGS  := $(SAN_FLAGS) $(EXTRA_LDFLAGS)
LDLIBS   := -lm -pthread $(PLAT_LIBS)

$(foreach m,$(APP_MODULES),$(eval OBJ_$(m) := $(SRC_$(m):%.c=$$(OUT)/%.o)))
$(foreach m,$(CORE_MODULES),$(eval $(OBJ_$(m)): MOD_FLAGS = $(call mod_inc,$(m)) $$(CFLAGS_CORE)))
$(foreach m,$(HOST_MODULES),$(eval $(OBJ_$(m)): MOD_FLAGS = $(call mod_inc,$(m)) $$(CFLAGS_HOST)))
# libassimp, json-c and libjpeg: only the importer compiles against them and only skintool (and
# the tests) link them.
IMPORT_CFLAGS := $(shell $(PKG_CONFIG) --cflags $(PC_import) 2>/dev/null)
IMPORT_LIBS   := $(shell $(PKG_CONFIG) --libs $(PC_import) 2>/dev/null)
$(OBJ_import): MOD_FLAGS += $(IMPORT_CFLAGS)

PLAT_SRC := platform/display/display.c platform/display/display_common.c \
            $(if $(filter-out osmesa,$(DISPLAYS)),platform/display/display_egl.c) \
            $(DISPLAYS:%=platform/display/display_%.c) \
            platform/input/input.c platform/input/input_common.c $(INPUTS:%=platform/input/input_%.c) \
            $(if $(filter gpio,$(INPUTS)),platform/input/input_gpiod$(GPIOD_API).c) \
            $(filter-out $(if $(VIDEO_ON),,platform/sys/video_writer.c),$(wildcard platform/storage/*.c platform/sys/*.c))
PLAT_OBJ := $(PLAT_SRC:%.c=$(OUT)/%.o)
$(PLAT_OBJ): MOD_FLAGS = $(foreach m,$(DEPS_platform),-Iapp/$(m)) $(PLAT_INC) $(CFLAGS_HOST)
$(OUT)/platform/sys/video_writer.o: MOD_FLAGS += $(VIDEO_CFLAGS)

CORE_OBJ := $(foreach m,$(CORE_MODULES),$(OBJ_$(m)))
# The frame's path and binding at start-up (app/runtime, app/setup): Linux
# code, but held to the core's rule too: files through platform/storage,
# messages through app/cli (cli_say.h), no allocation.
PATH_OBJ := $(OBJ_runtime) $(OBJ_setup)
FIXED_OBJ := $(FIXED_SRC:%.c=$(OUT)/%.o) $(if $(filter avx2 neon,$(SIMD)),$(OUT)/app/skin/kernels/skin_fixed_$(SIMD).o)
APP_OBJ  := $(foreach m,$(APP_MODULES),$(OBJ_$(m)))

# One archive per module (app/sources.mk; platform's backends are one), and
# every link takes only the archives of the DEPS_ list of what it links,
# top layer first (app/sources.mk: LAYER_ORDER): skinplay links cli,
# platform and the core, skintool adds import, analysis and encode.
LIB_MODULES  := $(filter-out $(PROGRAM_MODULES),$(APP_MODULES)) platform
$(foreach m,$(LIB_MODULES),$(eval LIB_$(m) := $$(OUT)/libskp_$(m).a))
OBJ_platform  = $(PLAT_OBJ)
libs_of      = $(foreach l,$(LAYER_ORDER),$(if $(filter $(l),$(DEPS_$(1))),$(LIB_$(l))))
LAYER_LINKS  := $(LIB_MODULES:%=$(OUT)/layers/%)
SKINTOOL     := $(OUT)/skintool
SKINPLAY     := $(OUT)/skinplay
# the man pages (made by the board's programs: see $(RUN_DIR) below)
MAN_STAMP    := $(OUT)/man/.made

# The tests come in two tiers (tests/README.md): unit tests, seconds in
# all, and integration tests, which run the programs on real data.
TESTLIB_SRC := $(wildcard tests/support/*.c)
TESTLIB_OBJ := $(TESTLIB_SRC:tests/%.c=$(OUT)/tests/%.o)
test_bins    = $(patsubst %.c,$(OUT)/tests/%,$(notdir $(wildcard tests/$(1)/test_*.c)))
TEST_UNIT_BIN  := $(call test_bins,unit)
TEST_INTEG_BIN := $(call test_bins,integration)
TEST_BIN       := $(TEST_UNIT_BIN) $(TEST_INTEG_BIN)
# kept between runs (make would delete them as intermediates, and the
# next run would compile them again)
.SECONDARY: $(TESTLIB_OBJ) $(TEST_BIN:$(OUT)/tests/%=$(OUT)/tests/obj/%.o)
# Builds and test programs use every processor unless make was given -j.
JOBS      ?= $(shell nproc 2>/dev/null || echo 1)
SUB_MAKE  := $(MAKE) --no-print-directory $(if $(filter -j%,$(MAKEFLAGS)),,-j$(JOBS))
# Test programs: two a processor, as many of them wait on the programs
# they run.
TEST_JOBS ?= $(shell echo $$((2 * $(JOBS))))
# Under the sanitizers the programs a test starts run without LeakSanitizer
# (tests/support/test_sanitizer.c says why; the tests themselves keep it).
CHILD_ASAN := $(if $(filter 1,$(SANITIZE)),SKP_CHILD_ASAN_OPTIONS=detect_leaks=0)
RUN_TESTS  = $(TEST_WRAP) env SKP_TEST_JOBS=$(TEST_JOBS) $(CHILD_ASAN) sh tests/run_tests.sh $(OUT)

# Demo assets: the skeleton is authored text; the motion is generated by a
# host program so that it can be tuned as code.
HOSTCC   ?= cc
DEMO_ASF := assets/demo.asf
DEMO_AMC := $(OUT)/assets/demo.amc
# The default show (assets/README.md): the MakeHuman body with its own
# weights on the CMU skeleton, three CMU clips, then the synthetic tour of
# bends and twists written for that skeleton.
SHOW_ASF   := assets/cmu/02.asf
SHOW_TOUR  := $(OUT)/assets/tour.amc
SHOW_CLIPS := assets/cmu/02_01.amc assets/cmu/lambada.amc assets/cmu/kick.amc $(SHOW_TOUR)
SHOW_MESH  := assets/makehuman/base.obj
SHOW_RIG   := assets/makehuman/default.mhskel
SHOW_BODY  := --mesh $(SHOW_MESH) --rig $(SHOW_RIG) --weights mesh

CMOCKA_CFLAGS = $(shell $(PKG_CONFIG) --cflags cmocka 2>/dev/null)
CMOCKA_LIBS   = $(shell $(PKG_CONFIG) --libs cmocka 2>/dev/null || echo -lcmocka)

.PHONY: all test test-unit test-integration run size install clean help check-core check-layers check-link check-lean
all: $(SKINTOOL) $(SKINPLAY) $(DEMO_AMC) $(SHOW_TOUR) $(MAN_STAMP) $(LAYER_LINKS)

$(OUT)/assets/demo_motion: assets/demo_motion.c
	@mkdir -p $(@D)
	$(HOSTCC) -std=c11 -D_DEFAULT_SOURCE $(WARN) -O2 $< -o $@ -lm
$(DEMO_AMC): $(OUT)/assets/demo_motion
	$< > $@.tmp && mv $@.tmp $@
$(SHOW_TOUR): $(OUT)/assets/demo_motion
	$< cmu > $@.tmp && mv $@.tmp $@

# Objects depend on the flags they were built with, so switching SIMD,
# backends or board flags rebuilds them.
FLAGS_STAMP := $(OUT)/flags.stamp
FLAGS_NOW   := $(CC) $(CPPFLAGS) $(CFLAGS_CORE) $(CFLAGS_HOST) $(SIMD_FLAGS) $(DISPLAYS) $(INPUTS)
ifneq ($(strip $(shell cat $(FLAGS_STAMP) 2>/dev/null)),$(strip $(FLAGS_NOW)))
  $(shell mkdir -p $(OUT) && echo '$(FLAGS_NOW)' > $(FLAGS_STAMP))
endif
$(APP_OBJ) $(PLAT_OBJ): $(FLAGS_STAMP)

# $(call compile_module,SOURCE,OBJECT,FLAGS). A header reached through
# ".." (#include "../kiosk/controls.h" finds app/kiosk from app/base's own
# folder, whatever the include path allows) is refused: the dependency
# file the compiler writes lists every header by the path it was found by.
define compile_module
	@mkdir -p $(dir $(2))
	$(CC) $(CPPFLAGS) $(3) -c $(1) -o $(2)
	@if grep -q '/\.\./' $(2:.o=.d); then \
	  echo "$(1): includes $$(grep -o '[^ ]*/\.\./[^ ]*' $(2:.o=.d) | head -n 1), a path through '..': include a header by its name alone, from the module itself or one its DEPS_ in app/sources.mk allows"; \
	  rm -f $(2); exit 1; fi
endef
$(OUT)/app/%.o: app/%.c
	$(call compile_module,$<,$@,$(MOD_FLAGS))
$(OUT)/platform/%.o: platform/%.c
	$(call compile_module,$<,$@,$(MOD_FLAGS))

$(OUT)/app/skin/kernels/%_avx2.o: CPPFLAGS += $(SIMD_FLAGS)

# --version: rewritten only when its text changes, so a new commit rebuilds
# one object.
VERSION_H := $(OUT)/gen/skp_version.h
$(OUT)/app/cli/cli_version.o: $(VERSION_H)
$(OUT)/app/cli/cli_version.o: CPPFLAGS += -I$(OUT)/gen
# (through a temporary of its own: two makes of one build, CI's soak beside
# its lint, both write it)
$(VERSION_H): FORCE
	@mkdir -p $(@D)
	@t=$@.$$$$.tmp; printf '#define SKP_VERSION "%s"\n#define SKP_GIT_REV "%s"\n#define SKP_BOARD "%s"\n' \
	  '$(VERSION)' '$(GIT_REV)' '$(BOARD) ($(BOARD_DESC))' > $$t && \
	  if cmp -s $$t $@; then rm -f $$t; else mv $$t $@; fi
.PHONY: FORCE
FORCE:

# Tests see everything, privates included: they are white-box.
TEST_INC    := $(foreach m,$(APP_MODULES),$(call mod_inc,$(m))) $(PLAT_INC) -Iplatform/display -Itests/support
TEST_CFLAGS  = $(CPPFLAGS) $(sort $(TEST_INC)) $(CMOCKA_CFLAGS) $(CFLAGS_HOST)
$(OUT)/tests/obj/%.o: tests/unit/%.c
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -c $< -o $@
$(OUT)/tests/obj/%.o: tests/integration/%.c
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -c $< -o $@
$(OUT)/tests/support/%.o: tests/support/%.c
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -c $< -o $@

$(foreach m,$(LIB_MODULES),$(eval $(LIB_$(m)): $$(OBJ_$(m))))
$(foreach m,$(LIB_MODULES),$(LIB_$(m))):
	@mkdir -p $(@D)
	rm -f $@ && $(AR) rcs $@ $^

# the link map feeds `make size` (static RAM per module)
$(SKINPLAY): $(OBJ_skinplay) $(call libs_of,skinplay)
	$(CC) $(LDFLAGS) -Wl,-Map=$@.map -o $@ $^ $(VIDEO_LIBS) $(LDLIBS)
$(SKINTOOL): $(OBJ_skintool) $(call libs_of,skintool)
	$(CC) $(LDFLAGS) -o $@ $^ $(IMPORT_LIBS) $(LDLIBS)

# Test programs are white-box: they may use every module (DEPS_tests).
$(OUT)/tests/%: $(OUT)/tests/obj/%.o $(TESTLIB_OBJ) $(call libs_of,tests)
	@mkdir -p $(@D)
	$(CC) $(LDFLAGS) -o $@ $^ $(CMOCKA_LIBS) $(IMPORT_LIBS) $(VIDEO_LIBS) $(LDLIBS)

# The layers at link time: each module's archive, whole, linked with the
# archives of its DEPS_ only (and a main() that calls nothing): a call into
# a module above it or beside it, even through a prototype written by
# hand, is an undefined reference and the build stops. `make check-link`
# (part of `make test`) shows that it does.
LAYER_MAIN  := $(OUT)/layers/main.o
$(LAYER_MAIN):
	@mkdir -p $(@D)
	@printf 'int main(void)\n{\n\treturn 0;\n}\n' > $(@:.o=.c)
	@$(CC) $(CFLAGS_CORE) -c $(@:.o=.c) -o $@
define layer_link
	@mkdir -p $(dir $(1))
	@$(CC) $(LDFLAGS) -o $(1) $(LAYER_MAIN) -Wl,--whole-archive $(2) -Wl,--no-whole-archive $(3) \
	  $(IMPORT_LIBS) $(VIDEO_LIBS) $(LDLIBS) 2> $(1).log || { \
	  echo "layers: $(4) calls what its DEPS_ in app/sources.mk do not give it ($(or $(DEPS_$(4)),nothing)):"; \
	  grep -o "undefined reference to .*" $(1).log | sort -u | sed 's/^/  /'; rm -f $(1); exit 1; }
endef
.SECONDEXPANSION:
$(LAYER_LINKS): $(OUT)/layers/%: $(LAYER_MAIN) $$(LIB_$$*) $$(call libs_of,$$*)
	$(call layer_link,$@,$(LIB_$*),$(call libs_of,$*),$*)

# check-link: the two rules above at work on scratch copies in $(PROBE)
# (nothing in the tree changes). A copy of app/base/crc32.c that calls
# skin_soa_bytes (app/skin) through a prototype written by hand compiles,
# and base's link check refuses it; the same archive links once app/skin's
# archives are given (the call is real: one archive for the whole core
# linked it). A copy with #include "../kiosk/controls.h" does not build.
PROBE := $(OUT)/probe
$(PROBE)/app/base/%.o: $(PROBE)/app/base/%.c
	$(call compile_module,$<,$@,$(call mod_inc,base) $(CFLAGS_CORE))
$(PROBE)/layers/base: $(LAYER_MAIN) $(PROBE)/libskp_base.a
	$(call layer_link,$@,$(PROBE)/libskp_base.a,$(call libs_of,base),base)
$(PROBE)/layers/base+skin: $(LAYER_MAIN) $(PROBE)/libskp_base.a $(LIB_skin) $(call libs_of,skin)
	$(call layer_link,$@,$(PROBE)/libskp_base.a,$(LIB_skin) $(call libs_of,skin),base)
$(PROBE)/libskp_base.a: $(LIB_base) $(PROBE)/app/base/crc32.o
	cp $(LIB_base) $@ && $(AR) rs $@ $(PROBE)/app/base/crc32.o
check-link: $(LAYER_LINKS)
	@rm -rf $(PROBE) && mkdir -p $(PROBE)/app/base
	@{ cat app/base/crc32.c; printf '%s\n' '' '#include <stddef.h>' 'size_t skin_soa_bytes(int count);' \
	  'int crc32_probe(void);' 'int crc32_probe(void) { return (int)skin_soa_bytes(1); }'; } > $(PROBE)/app/base/crc32.c
	@{ echo '#include "../kiosk/controls.h"'; cat app/base/crc32.c; } > $(PROBE)/app/base/dotdot.c
	@$(MAKE) --no-print-directory -s $(PROBE)/layers/base+skin > $(PROBE)/control.log 2>&1 || \
	  { cat $(PROBE)/control.log; echo "check-link: the probe does not link even with app/skin"; exit 1; }
	@if $(MAKE) --no-print-directory -s $(PROBE)/layers/base > $(PROBE)/up.log 2>&1 || \
	  ! grep -q "undefined reference to .skin_soa_bytes" $(PROBE)/up.log; then \
	  cat $(PROBE)/up.log; echo "check-link: app/base calling app/skin linked"; exit 1; fi
	@if $(MAKE) --no-print-directory -s $(PROBE)/app/base/dotdot.o > $(PROBE)/dotdot.log 2>&1 || \
	  ! grep -q "a path through '..'" $(PROBE)/dotdot.log; then \
	  cat $(PROBE)/dotdot.log; echo "check-link: an include through '..' built"; exit 1; fi
	@echo "check-link: $(words $(LAYER_LINKS)) modules link with their DEPS_ only; app/base calling" \
	  "app/skin's skin_soa_bytes by a hand-written prototype does not link, #include \"../kiosk/controls.h\" does not build"
	@grep -h "undefined reference\|through '..'" $(PROBE)/up.log $(PROBE)/dotdot.log | sed 's/^ */  /'

# The core must not allocate or do stdio (the runtime is fixed-memory), nor
# may the frame's path above it; the fixed-point path has no floating point,
# and no module includes above its layer.
check-core: $(CORE_OBJ) $(PATH_OBJ)
	@sh tests/check_core_symbols.sh $(CORE_OBJ)
	@$(if $(PATH_OBJ),WHAT="runtime and setup objects" sh tests/check_core_symbols.sh $(PATH_OBJ))
	@for f in $(FIXED_SRC); do sh tests/check_fixed_integer.sh $(CC) $(call mod_inc,skin) -Iboard/$(BOARD) $$f || exit 1; done
	@OBJDUMP=$(CROSS_COMPILE)objdump sh tests/check_simd_integer.sh $(FIXED_OBJ)
check-layers: $(APP_OBJ) $(PLAT_OBJ)
	@sh tests/check_layers.sh "$(CC) -Iboard/$(BOARD) $(CFLAGS_CORE)" \
	  "$(foreach m,$(APP_MODULES),$(m)=$(DEPS_$(m)))" "$(DEPS_platform)" "$(PORT_HEADERS)" "$(PLATFORM_DIRS)"
	@sh tests/check_file_cycles.sh $(NM) $(foreach m,$(APP_MODULES) platform,"$(m)=$(OBJ_$(m))")

# skinplay, the device program, links none of the tool's code: no symbol
# the importer, the analysis library, the clip encoder or the report
# defines may be in it.
REPORT_OBJ := $(filter $(OUT)/app/skintool/report/%,$(OBJ_skintool))
check-lean: $(SKINPLAY) $(LIB_analysis) $(LIB_import) $(LIB_encode) $(REPORT_OBJ)
	@$(NM) --defined-only $(LIB_analysis) $(LIB_import) $(LIB_encode) $(REPORT_OBJ) | awk '$$2 ~ /^[TDBR]$$/ { print $$3 }' | sort -u > $(OUT)/tool-symbols.txt
	@leaked=$$($(NM) --defined-only $(SKINPLAY) | awk '{ print $$3 }' | grep -xFf $(OUT)/tool-symbols.txt | tr '\n' ' '); \
	if [ -n "$$leaked" ]; then echo "check-lean: skinplay links tool-only code: $$leaked"; exit 1; fi; \
	echo "check-lean: skinplay links none of the $$(wc -l < $(OUT)/tool-symbols.txt) symbols of the importer, analysis, encoder and report code"; \
	if $(NM) -D --undefined-only $(SKINPLAY) | grep -q ' ai[A-Z]'; then echo "check-lean: skinplay links libassimp"; exit 1; fi

# Every test: the build's checks, then both tiers, several programs at a
# time. The default show is rendered by test_render (natively: a cross
# board's rendering tests are skipped under its emulator).
test: deps
	@$(SUB_MAKE) all $(if $(TARGET_RUN),,$(DEMO_SKN)) $(TEST_BIN) check-core check-layers check-link check-lean
	@$(RUN_TESTS) $(TEST_BIN)

# The fast tier: the modules' unit tests (seconds; skintool for the few
# that run it).
test-unit: deps
	@$(SUB_MAKE) $(SKINTOOL) $(TEST_UNIT_BIN)
	@$(RUN_TESTS) $(TEST_UNIT_BIN)

# The programs on real data: every shared clip, rendering, the kiosk.
test-integration: deps
	@$(SUB_MAKE) all $(if $(TARGET_RUN),,$(DEMO_SKN)) $(TEST_INTEG_BIN)
	@$(RUN_TESTS) $(TEST_INTEG_BIN)

# On a console or desktop: the default show on the display. Without one:
# headless, compare view, the show once at 30 frames a second, every 75th
# frame and a contact sheet in out/.
run: deps
	@$(SUB_MAKE) all $(DEMO_SKN)
	@plat=$$($(SKINPLAY) --print-platform); \
	if [ "$$plat" = surfaceless ]; then \
	  rm -rf out && mkdir -p out && \
	  $(SKINPLAY) --image $(DEMO_SKN) --platform surfaceless --algo compare \
	    --size 1280x720 --display-rate 30 --out out --every 75 --sheet out/contact_sheet.png && \
	  echo "run: no display here, rendered headless: out/frame_*.png and out/contact_sheet.png"; \
	else \
	  $(SKINPLAY) --image $(DEMO_SKN) --platform $$plat --algo compare; \
	fi

# Code and static RAM of skinplay, the RAM per module and the largest
# buffers (tests/size_report.sh reads the link map and the symbols).
size: $(SKINPLAY)
	@sh tests/size_report.sh $(SKINPLAY) "$(BOARD)" "$(SIZE)" "$(NM)" \
	  "$(foreach m,$(APP_MODULES),$(foreach f,$(SRC_$(m)),$(notdir $(f:.c=.o))=$(m))) \
	   $(foreach f,$(PLAT_SRC),$(notdir $(f:.c=.o))=$(patsubst platform/%/,platform/%,$(dir $(f))))"

# Installed layout. The package (platform/debian/deb.mk) installs with
# PREFIX=/usr and Debian's unit and udev directories.
BINDIR     := $(PREFIX)/bin
DATADIR    := $(PREFIX)/share/skinplay
MANDIR     := $(PREFIX)/share/man/man1
UNITDIR    ?= /etc/systemd/system
UDEVDIR    ?= /etc/udev/rules.d
STRIP      ?= strip
SIZE       ?= size
NM         ?= nm
# The board's programs run on this machine (board.mk sets an emulator for a
# cross build): the demo image and the man pages are made by them.
RUN_DIR    := $(OUT)/run
DEMO_SKN   := $(OUT)/assets/demo.skn

# kept (not deleted as intermediates: no "rm" line after an install)
.SECONDARY: $(RUN_DIR)/skinplay $(RUN_DIR)/skintool
$(RUN_DIR)/%: $(OUT)/%
	@mkdir -p $(@D)
	@printf '#!/bin/sh\nexec %s %s "$$@"\n' '$(TARGET_RUN)' '$(abspath $<)' > $@ && chmod 755 $@

# sequence 0: older than any show a user packs, so it plays only when no
# image slot holds a valid show (board.ini lists it last). Packed by the
# board's skintool: in a cross build under the emulator, minutes (the bind
# and the encoder's search). The image's format is the same on every
# architecture, so DEMO_PACKER=build/skintool packs it in seconds with
# this machine's own build (CI and the fresh-machine check do).
DEMO_PACKER ?= $(RUN_DIR)/skintool
$(DEMO_SKN): $(DEMO_PACKER) $(SHOW_ASF) $(SHOW_CLIPS) $(SHOW_MESH) $(SHOW_RIG) assets/makehuman/default_weights.mhw
	@$(abspath $(DEMO_PACKER)) pack -q $(SHOW_ASF) $(SHOW_CLIPS) $(SHOW_BODY) --sequence 0 -o $@ >/dev/null

# The man pages, from --help (help2man: platform/debian/man_pages.sh), so
# they never drift from the code: skinplay.1, skintool.1 and one page per
# skintool command (skintool-pack.1, ...). Made again whenever a program is.
$(MAN_STAMP): $(RUN_DIR)/skinplay $(RUN_DIR)/skintool platform/debian/man_pages.sh $(wildcard platform/debian/*.h2m)
	@rm -f $(OUT)/man/*.1
	@sh platform/debian/man_pages.sh $(OUT)/man $(VERSION) $(abspath $(RUN_DIR))
	@touch $@

install: all $(DEMO_SKN)
	@install -d $(DESTDIR)$(BINDIR) $(DESTDIR)$(DATADIR)/board/$(BOARD) $(DESTDIR)$(MANDIR) \
	  $(DESTDIR)$(UNITDIR) $(DESTDIR)$(UDEVDIR) $(DESTDIR)/etc/skinplay
	@install -m 755 -s --strip-program=$(STRIP) $(SKINTOOL) $(SKINPLAY) $(DESTDIR)$(BINDIR)/
	@install -m 644 $(DEMO_SKN) $(DESTDIR)$(DATADIR)/
	@install -m 644 board/$(BOARD)/board.ini $(DESTDIR)$(DATADIR)/board/$(BOARD)/
	@for f in $(wildcard board/$(BOARD)/README.md); do \
	  install -D -m 644 $$f $(DESTDIR)$(PREFIX)/share/doc/skinplay/README.$(BOARD).md; done
	@for m in $(OUT)/man/*.1; do gzip -9n < $$m > $(DESTDIR)$(MANDIR)/$$(basename $$m).gz; done
	@sed 's|@PREFIX@|$(PREFIX)|g' platform/debian/skinplay.service > $(DESTDIR)$(UNITDIR)/skinplay.service
	@install -m 644 platform/debian/60-skinplay-gpio.rules $(DESTDIR)$(UDEVDIR)/
	@# the board config stays when there is one: it is the integrator's
	@[ -e $(DESTDIR)/etc/skinplay/board.ini ] || \
	  sed 's|/usr/share/skinplay/|$(DATADIR)/|' board/$(BOARD)/board.ini > $(DESTDIR)/etc/skinplay/board.ini
	@echo "install: skinplay and skintool in $(DESTDIR)$(BINDIR), the demo in $(DESTDIR)$(DATADIR)," \
	  "the unit in $(DESTDIR)$(UNITDIR), the udev rule in $(DESTDIR)$(UDEVDIR), the config in $(DESTDIR)/etc/skinplay"

clean:
	rm -rf $(BUILD)

help:
	@echo "make [BOARD=$(BOARD)]   build $(SKINTOOL), $(SKINPLAY) and the man pages in $(OUT)/man"
	@echo "make test               build and run every test (SANITIZE=1 for ASan+UBSan; JOBS=$(JOBS) at a time)"
	@echo "make test-unit          the fast tier: the unit tests alone (seconds)"
	@echo "make test-integration   the programs on real data, rendering, the kiosk"
	@echo "make run                play the default show (assets/: MakeHuman body, CMU clips, the tour)"
	@echo "make size               code size and static RAM of skinplay"
	@echo "make deps               check (and as root install) the Debian packages"
	@echo "make install PREFIX=/usr/local DESTDIR="
	@echo "make deb                skinplay and skinplay-tools_$(VERSION)_$(DEB_ARCH).deb (dpkg-deb; lintian when installed)"
	@echo "make HARDEN=0 ...       build without the packages' hardening flags (on by default: make deb packages the build)"

# fuzz, fuzz-smoke, lint, soak
include tests/hardening.mk
# deb
include platform/debian/deb.mk

-include $(APP_OBJ:.o=.d) $(PLAT_OBJ:.o=.d) $(TESTLIB_OBJ:.o=.d) $(TEST_BIN:$(OUT)/tests/%=$(OUT)/tests/obj/%.d)

endif # BOARD_KIND != mcu
