# Debian's hardening flags for the board's architecture (dpkg-buildflags,
# every hardening feature on), as the packages are built. On by default
# (HARDEN=1) wherever dpkg-buildflags is (dpkg-dev, which `make deps`
# installs): the build a user runs and tests is then the one `make deb`
# packages, without compiling everything again (on a fresh Debian 13 root
# that second build took 170 s of CI's longest part), and a program that
# overruns a buffer stops rather than going on. HARDEN=0 builds without
# them, and `make deb` then builds with them in a directory of its own.
# Not under SANITIZE=1: that build is not packaged, and _FORTIFY_SOURCE's
# checked calls would hide reads and writes from ASan. Read before the
# flags are set.
HARDEN      ?= $(if $(shell command -v dpkg-buildflags 2>/dev/null),1,0)
DEB_ARCH    ?= $(shell dpkg --print-architecture)
DEB_ENV     := DEB_HOST_ARCH=$(DEB_ARCH) DEB_BUILD_MAINT_OPTIONS=hardening=+all
DEB_FLAGS    = $(shell $(DEB_ENV) dpkg-buildflags --get $(1))
DEB_CFLAGS   = $(call DEB_FLAGS,CFLAGS) $(call DEB_FLAGS,CPPFLAGS)
DEB_LDFLAGS  = $(call DEB_FLAGS,LDFLAGS)
HARDENED    := $(if $(filter 1:,$(HARDEN):$(SANITIZE)),1)
# Asked once (simple variables): EXTRA_CFLAGS is read by more than one
# flags variable, and each dpkg-buildflags is a Perl start.
ifeq ($(HARDENED),1)
  HARDEN_CFLAGS  := $(DEB_CFLAGS)
  HARDEN_LDFLAGS := $(DEB_LDFLAGS)
  EXTRA_CFLAGS   += $(HARDEN_CFLAGS)
  EXTRA_LDFLAGS  += $(HARDEN_LDFLAGS)
endif
