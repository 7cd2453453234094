# skinplay build. `make help` lists the targets.
BOARD    ?= host
BUILD    ?= build
PREFIX   ?= /usr/local
DESTDIR  ?=

include board/$(BOARD)/board.mk

ifeq ($(SANITIZE),1)
  SAN_FLAGS := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
  OUT       := $(BUILD)/san
else
  SAN_FLAGS :=
  OUT       := $(BUILD)
endif

WARN     := -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wvla
CPPFLAGS := -Iapp -Iboard/$(BOARD) -MMD -MP
CFLAGS_APP  := -std=c11 $(WARN) $(BOARD_CFLAGS) $(SAN_FLAGS) $(EXTRA_CFLAGS)
# Platform code talks to Linux and POSIX APIs, so it may use GNU extensions.
CFLAGS_PLAT := -std=gnu11 $(WARN) $(BOARD_CFLAGS) $(SAN_FLAGS) $(EXTRA_CFLAGS)
LDFLAGS  := $(SAN_FLAGS) $(EXTRA_LDFLAGS)
LDLIBS   := -lm

# app/: the front ends (skintool*, skinplay*, and cli_* shared by both) may
# use stdio and platform/; the portable core may not.
CLI_SRC     := $(wildcard app/cli_*.c)
FRONT_SRC   := $(wildcard app/skintool*.c app/skinplay*.c) $(CLI_SRC)
CORE_SRC    := $(filter-out $(FRONT_SRC),$(wildcard app/*.c))
PLAT_SRC    := $(wildcard platform/*.c)
TOOL_SRC    := $(wildcard app/skintool*.c) $(CLI_SRC)
PLAY_SRC    := $(wildcard app/skinplay*.c) $(CLI_SRC)
UNIT_SRC    := $(wildcard tests/unit/test_*.c tests/integration/test_*.c)
TESTLIB_SRC := $(wildcard tests/support/*.c)

CORE_OBJ    := $(CORE_SRC:%.c=$(OUT)/%.o)
PLAT_OBJ    := $(PLAT_SRC:%.c=$(OUT)/%.o)
TOOL_OBJ    := $(TOOL_SRC:%.c=$(OUT)/%.o)
PLAY_OBJ    := $(PLAY_SRC:%.c=$(OUT)/%.o)
TESTLIB_OBJ := $(TESTLIB_SRC:tests/%.c=$(OUT)/tests/%.o)
UNIT_BIN    := $(addprefix $(OUT)/tests/,$(basename $(notdir $(UNIT_SRC))))

CORE_LIB := $(OUT)/libskp.a
PLAT_LIB := $(OUT)/libskp_platform.a
SKINTOOL := $(OUT)/skintool
SKINPLAY := $(OUT)/skinplay

CMOCKA_CFLAGS = $(shell pkg-config --cflags cmocka 2>/dev/null)
CMOCKA_LIBS   = $(shell pkg-config --libs cmocka 2>/dev/null || echo -lcmocka)

.PHONY: all deps test run size install clean help check-core
all: $(SKINTOOL) $(SKINPLAY)

$(OUT)/app/%.o: app/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS_APP) -c $< -o $@

# Front ends see the platform headers and POSIX.
$(FRONT_SRC:%.c=$(OUT)/%.o): $(OUT)/app/%.o: app/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Iplatform $(CFLAGS_PLAT) -c $< -o $@

$(OUT)/platform/%.o: platform/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Iplatform $(CFLAGS_PLAT) -c $< -o $@

TEST_CFLAGS = $(CPPFLAGS) -Iplatform -Itests/support $(CMOCKA_CFLAGS) $(CFLAGS_PLAT)
$(OUT)/tests/obj/%.o: tests/unit/%.c
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -c $< -o $@
$(OUT)/tests/obj/%.o: tests/integration/%.c
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -c $< -o $@
$(OUT)/tests/support/%.o: tests/support/%.c
	@mkdir -p $(@D)
	$(CC) $(TEST_CFLAGS) -c $< -o $@

$(CORE_LIB): $(CORE_OBJ)
	@mkdir -p $(@D)
	rm -f $@ && $(AR) rcs $@ $^

$(PLAT_LIB): $(PLAT_OBJ)
	@mkdir -p $(@D)
	rm -f $@ && $(AR) rcs $@ $^

$(SKINTOOL): $(TOOL_OBJ) $(PLAT_LIB) $(CORE_LIB)
	$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

$(SKINPLAY): $(PLAY_OBJ) $(PLAT_LIB) $(CORE_LIB)
	$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

$(OUT)/tests/%: $(OUT)/tests/obj/%.o $(TESTLIB_OBJ) $(PLAT_LIB) $(CORE_LIB)
	@mkdir -p $(@D)
	$(CC) $(LDFLAGS) -o $@ $^ $(CMOCKA_LIBS) $(LDLIBS)

# Check that the dependencies are present; as root install what is missing.
deps:
	@missing=""; \
	command -v pkg-config >/dev/null 2>&1 || missing="pkg-config"; \
	if [ -z "$$missing" ]; then \
	  for m in $(PC_MODULES); do pkg-config --exists $$m || missing="$$missing $$m"; done; \
	fi; \
	if [ -n "$$missing" ]; then \
	  echo "deps: missing:$$missing"; \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $(DEB_PKGS) >/dev/null || exit 1; \
	    echo "deps: installed $(DEB_PKGS)"; \
	  else \
	    echo "deps: run as root:  apt-get install -y $(DEB_PKGS)"; exit 1; \
	  fi; \
	fi

# app/ core objects must not allocate or do stdio: the runtime is fixed-memory.
check-core: $(CORE_OBJ)
	@sh tests/check_core_symbols.sh $(CORE_OBJ)

test: deps
	@$(MAKE) --no-print-directory all $(UNIT_BIN) check-core
	@sh tests/run_tests.sh $(OUT) $(UNIT_BIN)

run: deps all
	@sh tests/integration/demo_run.sh $(OUT)

size: $(SKINPLAY)
	@size $(SKINPLAY) | awk 'NR==2 { printf "skinplay (%s): code %d bytes (text), static RAM %d bytes (.data %d + .bss %d)\n", "$(BOARD)", $$1, $$2+$$3, $$2, $$3 }'

install: all
	install -d $(DESTDIR)$(PREFIX)/bin
	install -m 755 $(SKINTOOL) $(SKINPLAY) $(DESTDIR)$(PREFIX)/bin/

clean:
	rm -rf $(BUILD)

help:
	@echo "make [BOARD=$(BOARD)]   build $(SKINTOOL) and $(SKINPLAY)"
	@echo "make test               build and run every test (SANITIZE=1 for ASan+UBSan)"
	@echo "make run                play the demo assets"
	@echo "make size               code size and static RAM of skinplay"
	@echo "make deps               check (and as root install) the Debian packages"
	@echo "make install PREFIX=/usr/local DESTDIR="

-include $(CORE_OBJ:.o=.d) $(PLAT_OBJ:.o=.d) $(FRONT_SRC:%.c=$(OUT)/%.d) $(TESTLIB_OBJ:.o=.d) $(UNIT_BIN:$(OUT)/tests/%=$(OUT)/tests/obj/%.d)
