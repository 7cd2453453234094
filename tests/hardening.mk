# Hardening targets, included by the Makefile for Linux boards:
#   make fuzz [SECONDS=600]   libFuzzer (clang) on every tests/fuzz/fuzz_*.c
#   make fuzz-smoke           the same for 10 s each (CI, when clang is there)
#   make lint [LINT_NODES=225000]  cppcheck and clang-tidy over app/ and platform/
#   make soak [SOAK_FRAMES=1000000]   a long headless run of skinplay, then a week of faults
#   make import-sweep         every assimp-testmodels sample through skintool bind (ASan+UBSan)
#   make damage-sweep [DAMAGE_EVERY=2]  damaged images by class through skinplay, info and repair
# None of them is part of `make test`; the fuzzers' regression inputs are
# (tests/unit/test_fuzz_regressions.c).
.PHONY: fuzz fuzz-smoke fuzz-build lint soak import-sweep damage-sweep

FUZZ_CC      ?= clang
SECONDS      ?= 60
FUZZ_OUT     := $(BUILD)/fuzz
FUZZ_SRC     := $(wildcard tests/fuzz/fuzz_*.c)
FUZZ_NAMES   := $(filter-out harness,$(patsubst tests/fuzz/fuzz_%.c,%,$(FUZZ_SRC)))
FUZZ_BIN     := $(addprefix $(FUZZ_OUT)/fuzz_,$(FUZZ_NAMES))
# The core as the parsers see it (app/sources.mk): the portable kernels
# only (no SIMD defines), no GL.
FUZZ_MODULES := $(filter-out render,$(CORE_MODULES))
FUZZ_CORE    := $(foreach m,$(FUZZ_MODULES),$(filter-out app/skin/kernels/%,$(SRC_$(m)))) \
                $(KERNELS_scalar:%=app/skin/kernels/%.c) app/import/rig_map_file.c \
                $(addprefix app/import/,rig_json.c rig_makehuman.c rig_mtl.c rig_scene.c)
FUZZ_SAN     := -fsanitize=address,undefined -fno-sanitize-recover=undefined
FUZZ_CFLAGS  := -std=c11 -g -O1 -Wall -Wextra -Werror -Wno-unused-command-line-argument \
                -fsanitize=fuzzer-no-link $(FUZZ_SAN) $(sort $(foreach m,$(FUZZ_MODULES),$(call mod_inc,$(m)))) \
                -Iapp/import -Iboard/$(BOARD) -Itests/fuzz -MMD -MP

$(FUZZ_OUT)/%.o: %.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -c $< -o $@
$(FUZZ_OUT)/libskp.a: $(FUZZ_CORE:%.c=$(FUZZ_OUT)/%.o)
	rm -f $@ && ar rcs $@ $^
$(FUZZ_OUT)/fuzz_%: $(FUZZ_OUT)/tests/fuzz/fuzz_%.o $(FUZZ_OUT)/tests/fuzz/fuzz_harness.o $(FUZZ_OUT)/libskp.a
	$(FUZZ_CC) -fsanitize=fuzzer $(FUZZ_SAN) -o $@ $^ $(shell $(PKG_CONFIG) --libs json-c) -lm

# keep the targets' objects (make would delete them as intermediates)
.SECONDARY: $(FUZZ_SRC:%.c=$(FUZZ_OUT)/%.o)

fuzz-build: $(FUZZ_BIN)

# Seeds: the repository's own inputs (good and broken) and the regressions.
FUZZ_SEEDS_asf := tests/data assets tests/data/bad
FUZZ_SEEDS_amc := tests/data tests/data/bad
FUZZ_SEEDS_bvh := tests/fuzz/seeds/bvh
FUZZ_SEEDS_obj := tests/fuzz/seeds/obj
FUZZ_SEEDS_ini := board/host board/rpi4
FUZZ_SEEDS_board_config := board/host board/rpi4
FUZZ_SEEDS_image := tests/fuzz/seeds/image
FUZZ_SEEDS_joint_map := tests/fuzz/seeds/joint_map
FUZZ_SEEDS_makehuman := tests/fuzz/seeds/makehuman
FUZZ_SEEDS_mesh_format := tests/fuzz/seeds/mesh_format
FUZZ_SEEDS_codec := tests/fuzz/seeds/codec
FUZZ_SEEDS_mtl := tests/fuzz/seeds/mtl

# Each target runs SECONDS on a corpus kept in the build directory, one
# target a job (make -j: `make fuzz-smoke` runs one a processor). A crash
# leaves its input in $(FUZZ_OUT)/crash/<target>/: fix the parser, copy the
# input to tests/fuzz/regressions/<target>/ and `make test` keeps it fixed.
FUZZ_RUNS := $(FUZZ_NAMES:%=fuzz-run-%)
.PHONY: $(FUZZ_RUNS)
$(FUZZ_RUNS): fuzz-run-%: $(FUZZ_OUT)/fuzz_%
	@c=$(FUZZ_OUT)/corpus/$*; mkdir -p $$c $(FUZZ_OUT)/crash/$* tests/fuzz/regressions/$*; rm -f $(FUZZ_OUT)/$*.failed; \
	seeds=""; for d in $(FUZZ_SEEDS_$*) tests/fuzz/regressions/$*; do [ -d $$d ] && seeds="$$seeds $$d"; done; \
	$(FUZZ_OUT)/fuzz_$* -max_total_time=$(SECONDS) -max_len=8192 -timeout=10 -rss_limit_mb=4096 \
	  -print_final_stats=1 -artifact_prefix=$(FUZZ_OUT)/crash/$*/ $$c $$seeds > $(FUZZ_OUT)/$*.log 2>&1 \
	  || touch $(FUZZ_OUT)/$*.failed; \
	{ echo "== fuzz $* for $(SECONDS) s"; \
	  grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+ *DONE|ERROR:|SUMMARY:' $(FUZZ_OUT)/$*.log | sed "s/^/  $*: /"; }

fuzz: $(FUZZ_BIN)
	@rm -f $(FUZZ_OUT)/*.failed
	@$(SUB_MAKE) $(FUZZ_RUNS)
	@fail=$$(cd $(FUZZ_OUT) && ls *.failed 2>/dev/null | sed 's/\.failed$$//' | tr '\n' ' '); \
	if [ -n "$$fail" ]; then echo "fuzz: crashes in: $$fail(inputs in $(FUZZ_OUT)/crash/, logs $(FUZZ_OUT)/*.log)"; exit 1; fi; \
	echo "fuzz: $(words $(FUZZ_NAMES)) targets, $(SECONDS) s each, $(JOBS) at a time, no crash"

fuzz-smoke:
	@$(SUB_MAKE) fuzz SECONDS=10

-include $(wildcard $(FUZZ_OUT)/app/*/*.d $(FUZZ_OUT)/app/*/*/*.d $(FUZZ_OUT)/tests/fuzz/*.d)

# Import sweep: tests/import_sweep.sh with the sanitizer build of skintool
# and a CMU skeleton from the shared data (both skipped when absent).
SKP_SHARED ?= ../shared
import-sweep:
	@$(MAKE) --no-print-directory SANITIZE=1 $(BUILD)/san/skintool
	@sh tests/import_sweep.sh $(BUILD)/san/skintool $(SKP_SHARED)/data/mocap/cmu/02.asf

# Damage sweep (issue 45): a show packed compressed and --raw, damaged class
# by class (a bit flipped, a block zeroed or forged, two adjacent, block 0
# with its group or its copy, blocks of another pack, truncated, a forger's
# out-of-range rotation, wrong-length and zero-filled slots), each copy
# played headless (--pose-digest), given to info and repaired: a markdown
# table of the verdicts; fails on any wrong result with exit 0, crash or
# wrong repair. DAMAGE_EVERY=1 takes every block (about twice the time).
DAMAGE_EVERY ?= 2
damage-sweep: all
	python3 tests/damage_sweep.py $(OUT) --every $(DAMAGE_EVERY) --jobs $(JOBS)

# Soak: tests/soak.sh on the host build (not part of `make test`: about an
# hour for the default million frames at 160x90), then tests/soak_week.sh:
# a week of the show's clock through rotating faults, nothing drawn (a
# 7 Hz virtual display; a few minutes). RSS is sampled every second: it
# swings by about 5 MiB with the view on screen (llvmpipe's buffers), so a
# window of the run needs many samples for its peak to be the real one (at
# 5 s, 3 samples a window, one CI run saw 109.1 MB early and 112.3 MB late
# on a flat run that peaks at 112.8 MB throughout).
SOAK_FRAMES ?= 1000000
SOAK_EVERY  ?= 1
SOAK_HZ     ?= 7
SOAK_DAYS   ?= 7
soak: all
	sh tests/soak.sh $(OUT) $(SOAK_FRAMES) $(SOAK_EVERY)
	sh tests/soak_week.sh $(OUT) $(SOAK_HZ) $(SOAK_DAYS)

# Static analysis (cppcheck and clang-tidy are Debian packages: cppcheck,
# clang-tidy). Suppressions, each with its reason: tests/lint/*.supp.
lint: $(VERSION_H)
	@sh tests/lint/lint.sh $(BOARD) "$(PLAT_CFLAGS) $(BACKEND_DEFS)" "$(sort $(TEST_INC)) -I$(OUT)/gen" \
	  "$(foreach m,$(APP_MODULES),$(SRC_$(m))) $(PLAT_SRC)" "$(HOST_MODULES)"
