# `make deb`: two packages for the board (host: amd64, rpi4: arm64,
# cross-built), skinplay (the device program, its demo, config, unit and
# udev rule) and skinplay-tools (skintool: the host tool, which alone needs
# Assimp), made with dpkg-deb from one `make install` tree: the build as it
# is, which has Debian's hardening flags (dpkg-buildflags, harden.mk;
# HARDEN=1, the default), or else objects rebuilt with them in their own
# directory,
# Depends computed from each package's binary (dpkg-shlibdeps), so the same
# recipe gives libgpiod2 on bookworm and libgpiod3 on trixie. lintian, when
# installed, checks both (errors fail the build).
DEB_MAINTAINER ?= skinplay developers <skinplay@example.org>
DEB_PACKAGES   := skinplay skinplay-tools
DEB_FILES      := $(foreach p,$(DEB_PACKAGES),$(BUILD)/$(p)_$(VERSION)_$(DEB_ARCH).deb)
DEB_DIR        := $(BUILD)/deb
# A hardened build has the flags: it is packaged as it is.
DEB_SUB_MAKE    = $(if $(HARDENED),$(SUB_MAKE),$(SUB_MAKE) BUILD=$(DEB_DIR)/build \
                  EXTRA_CFLAGS="$(DEB_CFLAGS)" EXTRA_LDFLAGS="$(DEB_LDFLAGS)")
# dpkg 1.22 (trixie) packages units and udev rules under /usr/lib; 1.21
# (bookworm) under /lib, as each release's debhelper and lintian expect.
DEB_LIBDIR      = $(if $(shell dpkg --compare-versions "$$(dpkg-query -W -f='$${Version}' dpkg)" ge 1.22 && echo y),/usr/lib,/lib)

.PHONY: deb deb-tree
deb:
	@$(DEB_SUB_MAKE) SKP_DEB_OUT=$(abspath $(BUILD)) SKP_DEB_DIR=$(abspath $(DEB_DIR)) deb-tree
	@if command -v lintian >/dev/null 2>&1; then \
	  echo "deb: lintian $(notdir $(DEB_FILES))"; lintian --fail-on error $(DEB_FILES) && echo "deb: lintian: no errors"; \
	else echo "deb: lintian is not installed: not checked"; fi

# In the hardened build (BUILD=$(DEB_DIR)/build): the installed tree split
# in two, each package's control files, the archives.
DEB_STAGE := $(SKP_DEB_DIR)/debian
deb-tree:
	@rm -rf $(DEB_STAGE)
	@$(MAKE) --no-print-directory install DESTDIR=$(DEB_STAGE)/skinplay PREFIX=/usr \
	  UNITDIR=$(DEB_LIBDIR)/systemd/system UDEVDIR=$(DEB_LIBDIR)/udev/rules.d >/dev/null
	@install -d $(DEB_STAGE)/skinplay-tools/usr/bin $(DEB_STAGE)/skinplay-tools/usr/share/man/man1
	@mv $(DEB_STAGE)/skinplay/usr/bin/skintool $(DEB_STAGE)/skinplay-tools/usr/bin/
	@mv $(DEB_STAGE)/skinplay/usr/share/man/man1/skintool*.1.gz $(DEB_STAGE)/skinplay-tools/usr/share/man/man1/
	@install -m 755 platform/debian/postinst platform/debian/prerm platform/debian/postrm -D -t $(DEB_STAGE)/skinplay/DEBIAN/
	@install -m 644 platform/debian/conffiles $(DEB_STAGE)/skinplay/DEBIAN/
	@# dpkg-shlibdeps reads debian/control in the directory it runs in
	@mkdir -p $(SKP_DEB_DIR)/debian
	@printf 'Source: skinplay\n' > $(SKP_DEB_DIR)/debian/control
	@for p in $(DEB_PACKAGES); do printf '\nPackage: %s\nArchitecture: any\n' $$p; done >> $(SKP_DEB_DIR)/debian/control
	$(call deb_package,skinplay,skinplay)
	$(call deb_package,skinplay-tools,skintool)

# $(1) the package, $(2) its program: stripped, documented, its control file
# (Depends from the program), md5sums, the archive (under a temporary name
# until it is whole).
define deb_package
	@$(STRIP) --remove-section=.comment --remove-section=.note $(DEB_STAGE)/$(1)/usr/bin/$(2)
	@install -d $(DEB_STAGE)/$(1)/DEBIAN $(DEB_STAGE)/$(1)/usr/share/doc/$(1)
	@install -m 644 platform/debian/copyright $(DEB_STAGE)/$(1)/usr/share/doc/$(1)/
	@gzip -9n < platform/debian/changelog > $(DEB_STAGE)/$(1)/usr/share/doc/$(1)/changelog.gz
	@depends=$$(cd $(SKP_DEB_DIR) && $(DEB_ENV) dpkg-shlibdeps -O debian/$(1)/usr/bin/$(2) | \
	    sed -n 's/^shlibs:Depends=//p'); \
	  [ -n "$$depends" ] || { echo "deb: dpkg-shlibdeps found no dependencies of $(2)"; exit 1; }; \
	  size=$$(du -sk --exclude=DEBIAN $(DEB_STAGE)/$(1) | cut -f1); \
	  sed -e 's|@VERSION@|$(VERSION)|' -e 's|@ARCH@|$(DEB_ARCH)|' -e 's|@MAINTAINER@|$(DEB_MAINTAINER)|' \
	      -e '$(if $(filter osmesa,$(DISPLAYS)),,/^Recommends: libosmesa6/d)' \
	      -e "s|@SIZE@|$$size|" -e "s|@DEPENDS@|$$depends|" platform/debian/$(1).control.in \
	      > $(DEB_STAGE)/$(1)/DEBIAN/control
	@cd $(DEB_STAGE)/$(1) && find . -type f ! -path './DEBIAN/*' -printf '%P\0' | sort -z | xargs -0 md5sum > DEBIAN/md5sums
	@dpkg-deb --root-owner-group -Zxz --build $(DEB_STAGE)/$(1) $(SKP_DEB_OUT)/$(1)_$(VERSION)_$(DEB_ARCH).deb.tmp >/dev/null
	@mv $(SKP_DEB_OUT)/$(1)_$(VERSION)_$(DEB_ARCH).deb.tmp $(SKP_DEB_OUT)/$(1)_$(VERSION)_$(DEB_ARCH).deb
	@f=$(SKP_DEB_OUT)/$(1)_$(VERSION)_$(DEB_ARCH).deb; \
	  echo "deb: $$f ($$(du -k $$f | cut -f1) KiB), Depends: $$(dpkg-deb -f $$f Depends)"
endef
