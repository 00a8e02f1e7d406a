# mlg-shimmy: AUTO-07p plugin set for main landing gear shimmy.
#
#   make           the list of targets with typical times (make help, mk/help.mk)
#   make test      set up (Debian packages, AUTO-07p), build and run all tests
#   make figures   set up and produce every registered figure in build/figures/
#   make bench     set up and run the benchmark programs
#   make regress   run every figure with a reference and compare (tests/regression/)
#   make refs      regenerate the reference diagrams in tests/reference/
#   make setup     only the set-up steps
#   make clean     remove build/ (but build/auto-dir, the AUTO_DIR you chose)
#   make distclean remove build/ entirely
#
# Variables other makefiles (c/c.mk, ...) append to:
#   TEST_DEPS       files the tests need built first (C test programs, the
#                   model .exe); the tests themselves are pytest's tests/*/test_*.py
#   FIGURES         make targets (e.g. fig05) built by `make figures`
#   BENCH_PROGRAMS  programs run by `make bench` (executables or .py scripts)
#   BENCH_DEPS      other files the benchmarks need built first
#   REGRESS_FIGURES figure targets compared with tests/reference/<fig>/ by
#                   `make regress` (tests/regression/regression.mk)
#   REGRESS_QUICK   those of them `make test` also compares (fast ones)
#
# Settings (command line or environment):
#   AUTO_DIR=<dir>  use an already built or installed AUTO-07p (e.g. Debian's:
#                   /usr/lib/auto-07p) instead of building one; remembered
#                   in build/auto-dir for later runs (make forget-auto)
#   AUTO_SRC=<file> build AUTO-07p from this tarball, not the Debian source
#   PYTHON          interpreter with numpy and matplotlib (/usr/bin/python3)
#   AUTO_THREADS    OpenMP threads of each AUTO run (1; an OMP_NUM_THREADS in
#                   the environment is not used: results depend on it)
#   PYTEST_ARGS     extra pytest options for `make test` (e.g. -k jacobian)
#   TEST_JOBS       pytest workers of `make test` (2; one test file per worker)
#   RHO, MU, EOM    a side-stay geometry (degrees; EOM the eom_terms level, 2
#                   when an angle is given) for every figure and study, in its
#                   own tree build/geometry/<tag>/ (mk/gear.mk)
#   SET             any other constant or parameter, e.g. SET='k_tlk=3.51e7':
#                   the gear's own tree build/gear/<tag>/ (mk/gear.mk)
#   PAPER           1: figures for a paper, without their "Fig. N: ..." titles
#                   (sets MLG_PAPER_STYLE for the drivers; e.g. make fig10-plot PAPER=1)
#
# Useful for rules in included makefiles: $(AUTO_DIR), $(PYTHON), `| auto`
# (AUTO-07p is ready) and $(call auto_equations,...) from mk/auto.mk.

SHELL := /bin/bash

# Paths with spaces are not supported: make splits targets, prerequisites and
# $(abspath ...) on them (a clone under "My Files/" gave ~15 "overriding
# recipe" warnings and "No rule to make target ..."). Refused here, before any
# rule is read, naming the path.
ifneq ($(words x$(CURDIR)x),1)
$(error the tree's path '$(CURDIR)' contains a space: make cannot handle paths with spaces; clone or move it to a path without spaces)
endif
refuse_space = $(if $(filter-out 1,$(words x$($(1))x)),$(error $(1)='$($(1))' contains a space: make cannot handle paths with spaces; give a path without spaces))
$(foreach v,MLG_RUN_ROOT AUTO_DIR AUTO_SRC REGRESS_ROOT REFS_ROOT,$(call refuse_space,$(v)))

PYTHON ?= /usr/bin/python3
# a recipe that fails leaves no target behind that looks done
.DELETE_ON_ERROR:
shell_quote = '$(subst ','\'',$(1))'
AUTO_THREADS ?= 1
# A whole number >= 1, checked by make itself (no shell sees the value): one
# word, nothing left when its digits are removed, no leading 0.
ifneq ($(words $(AUTO_THREADS))|$(subst 0,,$(subst 1,,$(subst 2,,$(subst 3,,$(subst 4,,$(subst 5,,$(subst 6,,$(subst 7,,$(subst 8,,$(subst 9,,$(AUTO_THREADS)))))))))))|$(filter 0%,$(AUTO_THREADS)),1||)
$(error AUTO_THREADS='$(AUTO_THREADS)' must be a whole number >= 1 (threads of each AUTO run))
endif
PYTEST_ARGS ?=
TEST_JOBS ?= 2
ifneq ($(words $(TEST_JOBS))|$(subst 0,,$(subst 1,,$(subst 2,,$(subst 3,,$(subst 4,,$(subst 5,,$(subst 6,,$(subst 7,,$(subst 8,,$(subst 9,,$(TEST_JOBS)))))))))))|$(filter 0%,$(TEST_JOBS)),1||)
$(error TEST_JOBS='$(TEST_JOBS)' must be a whole number >= 1 (pytest workers))
endif
export PYTHON
export MLG_AUTO_THREADS := $(AUTO_THREADS)
export MPLBACKEND := Agg
export SOURCE_DATE_EPOCH := 0
ifneq ($(strip $(PAPER)),)
export MLG_PAPER_STYLE := $(PAPER)
endif

PACKAGES := gcc gfortran make liblapack-dev python3-numpy python3-matplotlib \
            python3-scipy python3-pytest python3-pytest-xdist pkgconf libsundials-dev dpkg-dev patch
PACKAGES_STAMP := build/.stamp-packages
# What only `make test` needs: Chromium, so that the report's browser test
# runs on every fresh machine (CI) instead of skipping.
TEST_PACKAGES := chromium
TEST_PACKAGES_STAMP := build/.stamp-test-packages

TEST_DEPS :=
FIGURES :=
BENCH_PROGRAMS :=
BENCH_DEPS :=
REGRESS_FIGURES :=
REGRESS_QUICK :=

.PHONY: all setup packages auto test figures bench clean distclean
all: test
# plain `make` prints the targets (mk/help.mk) instead of running the tests
.DEFAULT_GOAL := help

include mk/python.mk
include mk/gear.mk
include mk/auto.mk
include mk/help.mk
include c/c.mk
include c/simulate/simulate.mk
include models/models.mk
include mk/jobs.mk
include mk/figures.mk
include mk/studies.mk
include mk/geometries.mk
-include tests/regression/regression.mk

setup: packages auto

packages: $(PACKAGES_STAMP)

# the list itself is an input: a package added to it is installed on the next run
PACKAGES_LIST := build/.packages-list
$(call stamp,$(PACKAGES_LIST),$(PACKAGES))
$(PACKAGES_STAMP): mk/install-packages.sh $(PACKAGES_LIST)
	mk/install-packages.sh $(PACKAGES)
	@mkdir -p $(@D)
	touch $@

TEST_PACKAGES_LIST := build/.test-packages-list
$(call stamp,$(TEST_PACKAGES_LIST),$(TEST_PACKAGES))
$(TEST_PACKAGES_STAMP): mk/install-packages.sh $(TEST_PACKAGES_LIST)
	mk/install-packages.sh $(TEST_PACKAGES)
	@mkdir -p $(@D)
	touch $@

# Smoke test of the chain: a C model linked with a static library, compiled
# by our rules, run by AUTO from mlgshimmy.shared.autoglue.
SMOKE := build/tests/smoke/smoke
build/tests/smoke/libshift.a: tests/smoke/shift.c tests/smoke/shift.h | packages
	@mkdir -p $(@D)
	gcc -O2 -Wall -c $< -o $(@D)/shift.o
	ar rcs $@ $(@D)/shift.o
$(eval $(call auto_equations,$(SMOKE),tests/smoke/smoke.c,build/tests/smoke/libshift.a,-Itests/smoke))
TEST_DEPS += $(SMOKE).exe

# Every test, Python and C (tests/model/test_c_programs.py runs the C programs),
# on pytest: `make test PYTEST_ARGS='-k jacobian'` selects by name.
test: setup $(TEST_PACKAGES_STAMP) $(TEST_DEPS)
	MLG_REQUIRE_CHROMIUM=1 $(PYTHON) -m pytest -n $(TEST_JOBS) --dist loadfile $(PYTEST_ARGS)

figures: setup $(FIGURES)
	@set -e; if [ -z "$(strip $(FIGURES))" ]; then \
	    echo "figures: no figures are registered yet (FIGURES is empty)"; \
	else \
	    echo "figures: $(strip $(FIGURES)) -> build/figures/"; \
	fi

bench: setup $(BENCH_DEPS) $(BENCH_PROGRAMS)
	@set -e; if [ -z "$(strip $(BENCH_PROGRAMS))" ]; then \
	    echo "bench: no benchmark programs are registered yet (BENCH_PROGRAMS is empty)"; \
	fi
	@echo "bench: the figure suite (-j1 against -j2, about 25 min on 2 idle cores) is \`make bench-figures\`"
	@set -e; for prog in $(abspath $(BENCH_PROGRAMS)); do \
	    echo "bench: $$prog"; \
	    case $$prog in *.py) $(PYTHON) "$$prog" ;; *) "$$prog" ;; esac; \
	done

# clean keeps build/auto-dir, the AUTO-07p chosen with AUTO_DIR (mk/auto.mk);
# distclean removes it too.
clean:
	@set -e; if [ -f $(AUTO_CHOICE) ]; then \
	    echo "clean: keeping $(AUTO_CHOICE) (AUTO_DIR=$$(cat $(AUTO_CHOICE)); make distclean removes it)"; \
	    find build -mindepth 1 -maxdepth 1 ! -name $(notdir $(AUTO_CHOICE)) -exec rm -rf {} +; \
	else rm -rf build; fi

distclean:
	rm -rf build

# Cluster submissions (docs/cluster.md): make submit-<fig>, submit-sweep, submit-atlas, ...;
# read last, after the figures and grids it submits are defined.
-include mk/cluster/submit.mk
