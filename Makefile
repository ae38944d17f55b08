# Makefile: non-recursive top-level build. Every source folder adds a Submakefile;
# see build/rules.mk for the helpers (userprog, userlib, rtmodule, unittest, pymodule).
TOPDIR := $(CURDIR)
.DEFAULT_GOAL := all
# A recipe that fails (halcompile keeps its partial output, as LinuxCNC's does) leaves no target behind.
.DELETE_ON_ERROR:

-include Makefile.inc

.PHONY: all setup configure run check test bench fuzz clean distclean headers

# --- set-up: dependencies and configure, used by run and check -----------------
setup:
	@scripts/install-deps
	@if [ ! -f Makefile.inc ] || [ configure.ac -nt Makefile.inc ] || [ Makefile.inc.in -nt Makefile.inc ]; then \
	    $(MAKE) --no-print-directory configure; fi

configure:
	autoreconf -fi
	./configure

# Plain `make` on a fresh clone (or after configure.ac changed) configures first: GNU make remakes
# the included Makefile.inc and restarts. A tree configured before keeps its options (--recheck).
ifeq ($(filter clean distclean configure setup run check,$(MAKECMDGOALS)),)
Makefile.inc: configure.ac Makefile.inc.in
	@echo "Makefile: configuring (autoreconf -fi, then configure)"
	@autoreconf -fi || { echo "Makefile: autoreconf failed; scripts/install-deps lists the Debian packages the build needs" >&2; exit 1; }
	@if [ -x config.status ]; then ./config.status --recheck && ./config.status; else ./configure; fi || \
	    { echo "Makefile: configure failed; scripts/install-deps lists the Debian packages the build needs" >&2; exit 1; }
	@touch $@
endif

run: setup
	@$(MAKE) --no-print-directory all
	@scripts/run-main

check: setup
	@$(MAKE) --no-print-directory all
	@$(MAKE) --no-print-directory test

ifeq ($(CONFIGURED),yes)
include build/rules.mk
SUBMAKEFILES := $(sort $(shell find src tests -name Submakefile 2>/dev/null))
include $(SUBMAKEFILES)

all: headers $(TARGETS)

test: all
	scripts/runtests -j 2 tests

bench: all
	@scripts/bench

fuzz: all $(FUZZ_TARGETS)
	@scripts/fuzz

-include $(shell find objects -name '*.d' 2>/dev/null)
else
all test bench fuzz:
	@echo "Makefile: not configured (see the messages above); run 'make setup' or './configure'" >&2
	@exit 1
endif

clean:
	rm -rf objects bin lib rtlib include share/man
	find . -name __pycache__ -prune -exec rm -rf {} + -o -name '*.pyc' -exec rm -f {} +

distclean: clean
	rm -rf Makefile.inc config.status config.log configure configure~ autom4te.cache \
	    src/config.h src/config.h.in src/config.h.in~ aclocal.m4
