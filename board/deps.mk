# `make deps`, and the check that stops any build before it: included by the
# Makefile and board/mcu.mk. board.mk lists DEB_PKGS, every Debian
# package the board's build, tests and packaging need (the compiler too),
# NAME:ARCH for another architecture's libraries; DEPS_PREPARE runs before
# apt-get (a cross board adds its architecture there).
DEPS_MISSING = $(shell sh board/deps.sh $(DEB_PKGS))

# Goals that need no packages, or that run `make deps` first themselves.
DEPS_FREE_GOALS := deps help clean test test-unit test-integration run
ifneq ($(filter-out $(DEPS_FREE_GOALS),$(or $(MAKECMDGOALS),all)),)
ifneq ($(SKP_DEPS_CHECKED),$(BOARD))
DEPS_NOW := $(DEPS_MISSING)
ifneq ($(DEPS_NOW),)
$(error BOARD=$(BOARD) needs Debian packages that are not installed: $(DEPS_NOW). Install them with: sudo make deps BOARD=$(BOARD))
endif
export SKP_DEPS_CHECKED := $(BOARD)
endif
endif

.PHONY: deps
deps:
	@missing="$(DEPS_MISSING)"; \
	if [ -z "$$missing" ]; then \
	  echo "deps: all $(words $(DEB_PKGS)) Debian packages BOARD=$(BOARD) needs are installed"; exit 0; fi; \
	echo "deps: missing: $$missing"; \
	if [ "$$(id -u)" != 0 ] || ! command -v apt-get >/dev/null 2>&1; then \
	  echo "deps: install them as root: sudo make deps BOARD=$(BOARD)  (or: sudo apt-get install $$missing)"; exit 1; fi; \
	echo "deps: installing them with apt-get (a minute or more on a fresh system)"; \
	$(DEPS_PREPARE) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null || exit 1; \
	echo "deps: installed $$missing"
