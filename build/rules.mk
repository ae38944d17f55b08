# build/rules.mk: compiler flags, pattern rules and the helpers Submakefiles call.
#
#   $(call userprog,NAME,SOURCES,LDLIBS)   -> bin/NAME            (user space, -DULAPI)
#   $(call userlib,NAME,SOURCES,LDLIBS)    -> lib/libNAME.so      (user space, -DULAPI)
#   $(call rtmodule,NAME,SOURCES,LDLIBS)   -> rtlib/NAME.so       (realtime, -DRTAPI)
#   $(call unittest,NAME,SOURCES,LDLIBS)   -> objects/unit/NAME   (run by tests/unit/*)
#   $(call pymodule,NAME,SOURCES,LDLIBS)   -> lib/python/NAME$(PYTHON_EXT_SUFFIX)
#   $(call script,SRC,DEST)                -> DEST, a copy of SRC marked executable
#   PUBLIC_HEADERS += src/x/y.h            -> include/y.h (for halcompile and out-of-tree code)
#   $(call manpage,src/x/NAME.N ...)       -> share/man/manN/NAME.N (hand-written man pages)
# Each helper appends its output to TARGETS. C sources may be .c, C++ sources .cc.

WARN_FLAGS := -Wall -Wextra
ifneq ($(CI),)
WARN_FLAGS += -Werror
endif
OPT_FLAGS ?= -O2 -g
INCLUDE_FLAGS := -Isrc -Isrc/rtapi -Isrc/hal -Isrc/emc/kinematics -Isrc/emc/motion -Isrc/emc/tp -Isrc/libnml -Isrc/emc/nml_intf -Iinclude
BASE_FLAGS := $(OPT_FLAGS) $(WARN_FLAGS) -fPIC -MMD -MP $(ASAN_FLAGS) $(INCLUDE_FLAGS)
CFLAGS_ALL = -std=gnu11 $(BASE_FLAGS) $(EXTRA_CFLAGS)
CXXFLAGS_ALL = -std=gnu++17 $(BASE_FLAGS) $(EXTRA_CXXFLAGS)
LDFLAGS_ALL = $(ASAN_FLAGS) -Llib -Wl,-rpath,'$$ORIGIN/../lib' $(EXTRA_LDFLAGS)

TARGETS :=
PUBLIC_HEADERS :=

# user-space objects (after the public headers are copied to include/: a changed header is
# never read from a stale copy when make runs jobs in parallel)
objects/%.o: %.c | headers
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_ALL) -DULAPI -c $< -o $@
objects/%.o: %.cc | headers
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS_ALL) -DULAPI -c $< -o $@

# realtime objects (same sources may be built both ways)
objects/rt/%.o: %.c | headers
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_ALL) -DRTAPI -c $< -o $@
objects/rt/%.o: %.cc | headers
	@mkdir -p $(@D)
	$(CXX) $(CXXFLAGS_ALL) -DRTAPI -c $< -o $@

uobjs = $(patsubst %.cc,objects/%.o,$(patsubst %.c,objects/%.o,$(1)))
robjs = $(patsubst %.cc,objects/rt/%.o,$(patsubst %.c,objects/rt/%.o,$(1)))
# link with g++ when any source is C++
linker = $(if $(filter %.cc,$(1)),$(CXX),$(CC))

define userprog_tmpl
bin/$(1): $(call uobjs,$(2)) $(filter lib/%.so,$(3))
	@mkdir -p $$(@D)
	$(call linker,$(2)) $$(LDFLAGS_ALL) -o $$@ $(call uobjs,$(2)) $(patsubst lib/lib%.so,-l%,$(3))
TARGETS += bin/$(1)
endef
userprog = $(eval $(call userprog_tmpl,$(1),$(2),$(3)))

define userlib_tmpl
lib/lib$(1).so: $(call uobjs,$(2)) $(filter lib/%.so,$(3))
	@mkdir -p $$(@D)
	$(call linker,$(2)) $$(LDFLAGS_ALL) -shared -Wl,-soname,lib$(1).so -o $$@ $(call uobjs,$(2)) $(patsubst lib/lib%.so,-l%,$(3))
TARGETS += lib/lib$(1).so
endef
userlib = $(eval $(call userlib_tmpl,$(1),$(2),$(3)))

# Realtime modules export only rtapi_app_main/exit, module-parameter metadata
# (rtapi_info_*) and the names their EXPORT_SYMBOL() put in section .rtapi_export.
define rtmodule_tmpl
rtlib/$(1).so: $(call robjs,$(2)) build/mkversion.sh
	@mkdir -p $$(@D) objects/rt/ver
	build/mkversion.sh objects/rt/ver/$(1).ver $(call robjs,$(2))
	$(call linker,$(2)) $$(LDFLAGS_ALL) -shared -Wl,--version-script=objects/rt/ver/$(1).ver -o $$@ $(call robjs,$(2)) $(3)
TARGETS += rtlib/$(1).so
endef
rtmodule = $(eval $(call rtmodule_tmpl,$(1),$(2),$(3)))

# Test-only realtime modules: built like rtmodule but into objects/testlib/, so rtlib/ holds only
# what users load. Tests reach them through tests/lib/testmods.sh (a private RTLIB_DIR).
define testmodule_tmpl
objects/testlib/$(1).so: $(call robjs,$(2)) build/mkversion.sh
	@mkdir -p $$(@D) objects/rt/ver
	build/mkversion.sh objects/rt/ver/$(1).ver $(call robjs,$(2))
	$(call linker,$(2)) $$(LDFLAGS_ALL) -shared -Wl,--version-script=objects/rt/ver/$(1).ver -o $$@ $(call robjs,$(2)) $(3)
TARGETS += objects/testlib/$(1).so
endef
testmodule = $(eval $(call testmodule_tmpl,$(1),$(2),$(3)))

define unittest_tmpl
objects/unit/$(1): $(call uobjs,$(2)) $(filter lib/%.so,$(3))
	@mkdir -p $$(@D)
	$(call linker,$(2)) $$(LDFLAGS_ALL) -Wl,-rpath,$(TOPDIR)/lib -o $$@ $(call uobjs,$(2)) $(patsubst lib/lib%.so,-l%,$(3))
TARGETS += objects/unit/$(1)
endef
unittest = $(eval $(call unittest_tmpl,$(1),$(2),$(3)))

define pymodule_tmpl
lib/python/$(1)$$(PYTHON_EXT_SUFFIX): EXTRA_CFLAGS += $$(PYTHON_CFLAGS)
lib/python/$(1)$$(PYTHON_EXT_SUFFIX): EXTRA_CXXFLAGS += $$(PYTHON_CFLAGS)
lib/python/$(1)$$(PYTHON_EXT_SUFFIX): $(call uobjs,$(2)) $(filter lib/%.so,$(3))
	@mkdir -p $$(@D)
	$(call linker,$(2)) $$(LDFLAGS_ALL) -Wl,-rpath,'$$$$ORIGIN/..' -shared -o $$@ $(call uobjs,$(2)) $(patsubst lib/lib%.so,-l%,$(3))
TARGETS += lib/python/$(1)$$(PYTHON_EXT_SUFFIX)
endef
pymodule = $(eval $(call pymodule_tmpl,$(1),$(2),$(3)))

define script_tmpl
$(2): $(1)
	@mkdir -p $$(@D)
	cp $$< $$@ && chmod +x $$@
TARGETS += $(2)
endef
script = $(eval $(call script_tmpl,$(1),$(2)))

define manpage_tmpl
share/man/man$(subst .,,$(suffix $(1)))/$(notdir $(1)): $(1)
	@mkdir -p $$(@D)
	cp $$< $$@
TARGETS += share/man/man$(subst .,,$(suffix $(1)))/$(notdir $(1))
endef
manpage = $(foreach page,$(1),$(eval $(call manpage_tmpl,$(page))))

headers: $(PUBLIC_HEADERS)
	@mkdir -p include
	@for h in $(PUBLIC_HEADERS); do cmp -s $$h include/$$(basename $$h) || cp $$h include/; done
