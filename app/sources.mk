# Every module of the build and the layers between them, in one place: the
# Makefile, board/mcu.mk and tests/hardening.mk include it, and
# tests/lint/lint.sh and tests/check_layers.sh read it through them. A
# module's files compile with -I for its own folders and for the folders of
# the modules in its DEPS_ list only, so an include of a module above it (or
# beside it) does not compile.
#
#   skinplay   skintool (+ report/)            the programs: argv, stdio, main()
#        \      /  |   \      \
#          |   import  analysis  encode        tool-only: rigged meshes (libassimp), measures, clip and ETC1 encoders
#          |   /
#          setup                               binding at start-up: mesh, pose, weights, the gate
#           |
#          runtime                             the frame's path: slots, acceptance, clip sources, skinning run
#           |
#          cli                                 argv, messages, outputs, --version
#         /   \
#   play   platform/{display,input,storage,sys}   the playback engine; the Linux backends
#      \      |  (base + the port headers of image, kiosk, render)
#   bind  image  render  kiosk                 features
#      \    |    /
#        skin (+ kernels/, private)            LBS, DQBS, DQBS fixed
#           |
#     mesh -> motion -> math -> base          (codec: base only; image and play read it)
#                                             (texture: base only; encode writes its ETC1)

# What each module owns (app/README.md has the whole map):
#   base      errors, readers, tokens, lines, CRC-32, INI, algorithm/view names
#   math      vec3, quat, rigid, dual quaternions, mat4, fixed point
#   motion    skeleton, ASF, streaming AMC and BVH, forward kinematics, roles, T-pose
#   codec     compressed motion clips: the format and its fixed-memory decoder
#   texture   textures: the ETC1 block layout and decoder, RGB565, mip chains, the box filter
#   encode    tool-only: the clip encoder (grid steps within an error budget, segments), the ETC1 encoder
#   mesh      meshes, normals, OBJ, the generated body
#   skin      weights, SoA vertices, bone transforms, skin_run; kernels/
#   bind      automatic and balanced weights, fitting, pose guessing, the weights CSV
#   image     the flash image: format, block device port, reader, writer, clip stream
#   render    the GLES2 renderer, camera, font, shaders, GL entry points
#   kiosk     controls (the buttons' state machine), debounce, board config, input port
#   play      the playback engine: clock, sampler, crossfades, root motion, facing, slot and clip policy
#   analysis  tool-only measures: volume, radius, overlap, scenes
#   import    tool-only: rigged glTF/FBX/COLLADA meshes through libassimp, joint maps
#   cli       the command lines: options, messages, progress, outputs, --version
#   runtime   the frame's path on Linux: bound body, show slots, acceptance, clip sources, skinning run
#   setup     binding at start-up: mesh pick and place, pose, weights, the gate
#   skinplay  the device program; skintool: the host tool (+ report/)

# The portable core, bottom up: no malloc, no stdio (make check-core).
CORE_MODULES  := base math motion codec texture mesh skin bind image render kiosk play
DEPS_base     :=
DEPS_codec    := base
DEPS_texture  := base
DEPS_math     := base
DEPS_motion   := math base
DEPS_mesh     := motion math base
DEPS_skin     := mesh motion math base
DEPS_bind     := skin mesh motion math base
DEPS_image    := codec texture skin mesh motion math base
DEPS_render   := texture skin mesh motion math base
DEPS_kiosk    := base
DEPS_play     := image codec texture skin mesh motion math base
# Host code, which may allocate and print: the tool-only measures and
# encoder, the command lines (cli), the frame's path (runtime), binding at
# start-up (setup), the importer, the programs.
DEPS_analysis := skin mesh motion math base
DEPS_encode   := codec texture motion math base
DEPS_cli      := $(CORE_MODULES) platform
DEPS_runtime  := cli $(CORE_MODULES) platform
DEPS_setup    := runtime cli $(CORE_MODULES) platform
DEPS_import   := setup runtime cli encode $(CORE_MODULES) platform
DEPS_skinplay := setup runtime cli $(CORE_MODULES) platform
DEPS_skintool := import setup runtime cli analysis encode $(CORE_MODULES) platform
HOST_MODULES  := analysis encode cli runtime setup import skinplay skintool
APP_MODULES   := $(CORE_MODULES) $(HOST_MODULES)
PROGRAM_MODULES := skinplay skintool
# The tests are white-box: every module but the programs (which they run).
DEPS_tests    := import setup runtime cli analysis encode $(CORE_MODULES) platform
# The modules top down: the order of the archives on a link line (each
# archive is searched once, so a module's calls resolve only downwards).
LAYER_ORDER   := import analysis encode setup runtime cli platform play kiosk render image bind skin mesh motion codec texture math base
# ... checked against the DEPS_ lists whenever make reads this file: every
# module but the programs is in it, after each module that depends on it.
layer_after = $(if $(2),$(if $(filter $(1),$(firstword $(2))),$(wordlist 2,999,$(2)),$(call layer_after,$(1),$(wordlist 2,999,$(2)))))
$(foreach m,$(filter-out $(PROGRAM_MODULES),$(APP_MODULES)) platform,$(if $(filter $(m),$(LAYER_ORDER)),,\
  $(error app/sources.mk: LAYER_ORDER lacks $(m))))
$(foreach m,$(LAYER_ORDER),$(foreach d,$(DEPS_$(m)),$(if $(filter $(d),$(call layer_after,$(m),$(LAYER_ORDER))),,\
  $(error app/sources.mk: LAYER_ORDER has $(d) before $(m), which depends on it (DEPS_$(m))))))

# A module's private folders: on its own include path, nobody else's.
PRIVATE_skin     := kernels
PRIVATE_skintool := report

# The skinning kernels (app/skin/kernels/) each SIMD setting builds
# (board.mk: SIMD; `make SIMD=scalar` builds the portable ones only).
KERNELS_scalar := skin_scalar skin_fixed skin_compact_scalar
KERNELS_avx2   := $(KERNELS_scalar) skin_avx2 skin_fixed_avx2 skin_compact_avx2
KERNELS_neon   := $(KERNELS_scalar) skin_neon skin_fixed_neon
# The fixed-point path, proven free of floating point by `make check-core`.
FIXED_SRC      := app/math/fixed.c app/math/fixed_move.c app/skin/kernels/skin_fixed.c

# platform/: one file per backend, each board listing the ones it builds
# (board.mk: DISPLAYS, INPUTS); the registries (display.c, input.c) are
# the only files that name them. Each backend's pkg-config modules:
PC_display_surfaceless := egl
PC_display_kms         := egl gbm libdrm
PC_display_x11         := egl x11
PC_display_osmesa      :=
PC_input_gpio          := libgpiod
PC_input_keyboard      :=
PC_input_script        :=
PC_platform            := libpng
# skinplay's video output (platform/sys/video_writer.c: -o F.mp4, F.webm),
# built where the board asks for it (board.mk: VIDEO) and pkg-config finds
# all four; only skinplay (and the tests) link them, skintool does not.
PC_video               := libavcodec libavformat libavutil libswscale
# The host tool's importer (app/import): the Open Asset Import Library,
# json-c for MakeHuman's rig files and libjpeg for JPEG textures (PNG ones
# through libpng, which platform links already).
PC_import              := assimp json-c libjpeg
# What platform code may include from app/: base, and the modules of the
# port headers it implements (image: blockdev.h; kiosk: the button port,
# input_port.h; render: the GL entry points, gl_api.h).
PLATFORM_DIRS  := display input storage sys
DEPS_platform  := base image kiosk render
PORT_HEADERS   := blockdev.h input_port.h gl_api.h

# Helpers for the makefiles. $(call mod_inc,M): the -I flags of module M
# (its own folders, its private ones, its DEPS_); SRC_M: its sources, the
# skin module's kernels as the board's SIMD setting has them.
PLAT_INC = $(addprefix -Iplatform/,$(PLATFORM_DIRS))
mod_inc  = $(foreach m,$(1) $(DEPS_$(1)),$(if $(filter platform,$(m)),$(PLAT_INC),-Iapp/$(m) \
             $(addprefix -Iapp/$(m)/,$(if $(filter $(1),$(m)),$(PRIVATE_$(m))))))
mod_src  = $(wildcard app/$(1)/*.c) $(foreach d,$(PRIVATE_$(1)),$(wildcard app/$(1)/$(d)/*.c))
$(foreach m,$(filter-out skin,$(APP_MODULES)),$(eval SRC_$(m) := $(call mod_src,$(m))))
SRC_skin = $(wildcard app/skin/*.c) $(KERNELS_$(SIMD):%=app/skin/kernels/%.c)
