# `make deb`: skinplay_VERSION_ARCH.deb for the board (host: amd64, rpi4:
# arm64, cross-built), made with dpkg-deb from a `make install` tree:
# objects rebuilt with Debian's hardening flags (dpkg-buildflags) in their
# own directory, Depends computed from the binaries (dpkg-shlibdeps), so the
# same recipe gives libgpiod2 on bookworm and libgpiod3 on trixie. lintian,
# when installed, checks the result (errors fail the build).
DEB_ARCH       ?= $(shell dpkg --print-architecture)
DEB_MAINTAINER ?= skinplay developers <skinplay@example.org>
DEB_FILE       := $(BUILD)/skinplay_$(VERSION)_$(DEB_ARCH).deb
DEB_DIR        := $(BUILD)/deb
DEB_ENV        := DEB_HOST_ARCH=$(DEB_ARCH) DEB_BUILD_MAINT_OPTIONS=hardening=+all
DEB_FLAGS       = $(shell $(DEB_ENV) dpkg-buildflags --get $(1))
# dpkg 1.22 (trixie) packages units and udev rules under /usr/lib; 1.21
# (bookworm) under /lib, as each release's debhelper and lintian expect.
DEB_LIBDIR      = $(if $(shell dpkg --compare-versions "$$(dpkg-query -W -f='$${Version}' dpkg)" ge 1.22 && echo y),/usr/lib,/lib)

.PHONY: deb deb-tree
deb:
	@$(MAKE) --no-print-directory BUILD=$(DEB_DIR)/build SKP_DEB_FILE=$(abspath $(DEB_FILE)) SKP_DEB_DIR=$(abspath $(DEB_DIR)) \
	  EXTRA_CFLAGS="$(call DEB_FLAGS,CFLAGS) $(call DEB_FLAGS,CPPFLAGS)" EXTRA_LDFLAGS="$(call DEB_FLAGS,LDFLAGS)" deb-tree
	@if command -v lintian >/dev/null 2>&1; then \
	  echo "deb: lintian $(notdir $(DEB_FILE))"; lintian --fail-on error $(DEB_FILE) && echo "deb: lintian: no errors"; \
	else echo "deb: lintian is not installed: not checked"; fi

# In the hardened build (BUILD=$(DEB_DIR)/build): the tree, its control
# files, the archive.
DEB_STAGE := $(SKP_DEB_DIR)/stage
deb-tree:
	@rm -rf $(DEB_STAGE)
	@$(MAKE) --no-print-directory install DESTDIR=$(DEB_STAGE) PREFIX=/usr \
	  UNITDIR=$(DEB_LIBDIR)/systemd/system UDEVDIR=$(DEB_LIBDIR)/udev/rules.d >/dev/null
	@$(STRIP) --remove-section=.comment --remove-section=.note $(DEB_STAGE)/usr/bin/skinplay $(DEB_STAGE)/usr/bin/skintool
	@install -d $(DEB_STAGE)/DEBIAN $(DEB_STAGE)/usr/share/doc/skinplay
	@install -m 644 platform/debian/copyright $(DEB_STAGE)/usr/share/doc/skinplay/
	@gzip -9n < platform/debian/changelog > $(DEB_STAGE)/usr/share/doc/skinplay/changelog.gz
	@install -m 755 platform/debian/postinst platform/debian/prerm platform/debian/postrm $(DEB_STAGE)/DEBIAN/
	@install -m 644 platform/debian/conffiles $(DEB_STAGE)/DEBIAN/
	@# dpkg-shlibdeps reads debian/control in the directory it runs in
	@mkdir -p $(SKP_DEB_DIR)/debian
	@printf 'Source: skinplay\n\nPackage: skinplay\nArchitecture: any\n' > $(SKP_DEB_DIR)/debian/control
	@depends=$$(cd $(SKP_DEB_DIR) && $(DEB_ENV) dpkg-shlibdeps -O stage/usr/bin/skinplay stage/usr/bin/skintool | \
	    sed -n 's/^shlibs:Depends=//p'); \
	  [ -n "$$depends" ] || { echo "deb: dpkg-shlibdeps found no dependencies"; exit 1; }; \
	  size=$$(du -sk --exclude=DEBIAN $(DEB_STAGE) | cut -f1); \
	  sed -e 's|@VERSION@|$(VERSION)|' -e 's|@ARCH@|$(DEB_ARCH)|' -e 's|@MAINTAINER@|$(DEB_MAINTAINER)|' \
	      -e '$(if $(filter osmesa,$(DISPLAYS)),,/^Recommends: libosmesa6/d)' \
	      -e "s|@SIZE@|$$size|" -e "s|@DEPENDS@|$$depends|" platform/debian/control.in > $(DEB_STAGE)/DEBIAN/control
	@cd $(DEB_STAGE) && find . -type f ! -path './DEBIAN/*' -printf '%P\0' | sort -z | xargs -0 md5sum > DEBIAN/md5sums
	@dpkg-deb --root-owner-group -Zxz --build $(DEB_STAGE) $(SKP_DEB_FILE).tmp >/dev/null
	@mv $(SKP_DEB_FILE).tmp $(SKP_DEB_FILE)
	@echo "deb: $(SKP_DEB_FILE) ($$(du -k $(SKP_DEB_FILE) | cut -f1) KiB), Depends: $$(dpkg-deb -f $(SKP_DEB_FILE) Depends)"
