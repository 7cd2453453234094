# Debian's hardening flags for the board's architecture (dpkg-buildflags,
# every hardening feature on), as the packages are built: `make deb` builds
# with them in a directory of its own; HARDEN=1 puts them in this build, so
# that a later `make HARDEN=1 deb` packages what was built and tested
# (CI's builds for the packages). Not under SANITIZE=1: that build is not
# packaged, and _FORTIFY_SOURCE's checked calls would hide reads and writes
# from ASan. Read before the flags are set.
DEB_ARCH    ?= $(shell dpkg --print-architecture)
DEB_ENV     := DEB_HOST_ARCH=$(DEB_ARCH) DEB_BUILD_MAINT_OPTIONS=hardening=+all
DEB_FLAGS    = $(shell $(DEB_ENV) dpkg-buildflags --get $(1))
DEB_CFLAGS   = $(call DEB_FLAGS,CFLAGS) $(call DEB_FLAGS,CPPFLAGS)
DEB_LDFLAGS  = $(call DEB_FLAGS,LDFLAGS)
ifeq ($(HARDEN):$(SANITIZE),1:)
  EXTRA_CFLAGS  += $(DEB_CFLAGS)
  EXTRA_LDFLAGS += $(DEB_LDFLAGS)
endif
