# AUTO-07p: where it lives, how it is built, and how equations files are
# compiled and linked the way AUTO's run() does it, with extra libraries.
#
# AUTO_DIR=<dir>   use this AUTO-07p: a built source tree, or an installed one
#                  such as Debian's package auto-07p (AUTO_DIR=/usr/lib/auto-07p,
#                  headers in /usr/include); checked by mk/check-auto.sh and
#                  remembered in build/auto-dir, so that later runs without
#                  AUTO_DIR use it too (make clean keeps it)
# AUTO_SRC=<file>  build from this source tarball instead of the Debian source
#
# Which AUTO: AUTO_DIR if given (command line or environment), else the one
# remembered in build/auto-dir, else the source build under build/auto/07p
# (built the first time, saying so). AUTO_DIR=build/auto/07p or
# `make forget-auto` returns to the source build. `make auto` prints which.
AUTO_BUILT_DIR := $(CURDIR)/build/auto/07p
AUTO_CHOICE := build/auto-dir

ifneq ($(filter command line environment environment override,$(origin AUTO_DIR)),)
override AUTO_DIR := $(abspath $(AUTO_DIR))
AUTO_FROM := given
else ifneq ($(wildcard $(AUTO_CHOICE)),)
AUTO_DIR := $(abspath $(strip $(file < $(AUTO_CHOICE))))
AUTO_FROM := remembered
else
AUTO_DIR := $(AUTO_BUILT_DIR)
AUTO_FROM := default
endif
# print which AUTO once, from the make the user started
auto_say = $(if $(filter 0,$(MAKELEVEL)),echo $(1),:)

.PHONY: forget-auto
forget-auto:
	rm -f $(AUTO_CHOICE)

ifeq ($(AUTO_DIR),$(AUTO_BUILT_DIR))
AUTO_STAMP := build/.stamp-auto

auto: $(AUTO_STAMP)
	@$(if $(filter given,$(AUTO_FROM)),rm -f $(AUTO_CHOICE))
	@$(call auto_say,"auto: using AUTO-07p built from source in $(AUTO_DIR)")

$(AUTO_STAMP): mk/build-auto.sh $(wildcard mk/auto-patches/*.patch) | $(PACKAGES_STAMP)
	@echo "auto: building AUTO-07p from source under build/auto/ (the first time, or when mk/auto-patches changes; about 80 s;" \
	    "to use an installed one instead, e.g. Debian's auto-07p: make ... AUTO_DIR=/usr/lib/auto-07p)"
	mk/build-auto.sh build/auto $(if $(AUTO_SRC),$(abspath $(AUTO_SRC)))
	touch $@
else
AUTO_STAMP :=

auto:
	@$(if $(filter 0,$(MAKELEVEL)),mk/check-auto.sh,mk/check-auto.sh >/dev/null) $(AUTO_DIR)
	@set -e; if [ "$(AUTO_FROM)" = given ] && [ "$$(cat $(AUTO_CHOICE) 2>/dev/null)" != "$(AUTO_DIR)" ]; then \
	    mkdir -p $(dir $(AUTO_CHOICE)) && echo "$(AUTO_DIR)" > $(AUTO_CHOICE) && \
	    echo "auto: remembered AUTO_DIR=$(AUTO_DIR) in $(AUTO_CHOICE): later runs use it" \
	         "without AUTO_DIR (make forget-auto: back to the source build)"; \
	elif [ "$(AUTO_FROM)" = remembered ]; then \
	    $(call auto_say,"auto: ... as remembered in $(AUTO_CHOICE) (AUTO_DIR=<dir> to change," \
	                    "make forget-auto for the source build)"); \
	fi
endif
export AUTO_DIR

# The compiler settings AUTO's run() reads from $(AUTO_DIR)/cmds/cmds.make.
# Recursively expanded: only evaluated in recipes, after AUTO is built (a dry
# run before it is built prints the commands without AUTO's settings).
auto_make_var = $(if $(wildcard $(AUTO_DIR)/cmds/cmds.make),$(subst $$(AUTO_DIR),$(AUTO_DIR),\
    $(shell sed -n 's/^$(1)[[:space:]]*=[[:space:]]*//p' \
        $(call shell_quote,$(AUTO_DIR)/cmds/cmds.make) | head -n1)))
AUTO_CC = $(call auto_make_var,CC)
AUTO_CFLAGS = $(call auto_make_var,CFLAGS)
AUTO_FC = $(call auto_make_var,FC)
AUTO_FFLAGS = $(call auto_make_var,FFLAGS)
AUTO_OPT = $(call auto_make_var,OPT)
# The C compile of an equations file: AUTO's flags without the Fortran-only
# ones that cmds.make's OPT holds and run() also passes to gcc ("cc1:
# warning: command-line option ... is valid for Fortran but not for C"):
# -fallow-argument-mismatch (our source build), -std=legacy (Debian's
# package). gcc ignores them, so the object code is the same.
AUTO_FORTRAN_ONLY := -fallow-argument-mismatch -std=legacy
AUTO_C_ONLY = $(filter-out $(AUTO_FORTRAN_ONLY),$(1))

# gfortran prints "Note: The following floating-point exceptions are
# signalling: IEEE_UNDERFLOW_FLAG IEEE_DENORMAL" when AUTO's main program
# STOPs after most orbit runs. What it prints is fixed when the main program
# is compiled (-ffpe-summary=, passed to libgfortran by the _gfortran_set_options
# call in main()); AUTO's lib/main.o is prebuilt, so the flag on our link
# line would do nothing, and no GFORTRAN_* variable controls it. Instead
# every equations executable is linked with -Wl,--wrap=_gfortran_set_options
# and mk/fpe_summary.c, which passes the same options with the summary off:
# what -ffpe-summary=none in main.o would have done. Nothing else changes
# (no trapping, no flag is cleared).
# Which AUTO the equations executables were built with: rewritten only when
# AUTO_DIR changes, so that switching AUTO recompiles and relinks them (an
# installed AUTO's lib/*.o can be older than an executable built with another).
AUTO_USED := build/auto-link/auto-dir
$(call stamp,$(AUTO_USED),$(AUTO_DIR))

AUTO_QUIET_FPE := build/auto-link/fpe_summary.o
AUTO_QUIET_LDFLAGS := -Wl,--wrap=_gfortran_set_options $(AUTO_QUIET_FPE)
$(AUTO_QUIET_FPE): mk/fpe_summary.c $(AUTO_USED) | auto
	@mkdir -p $(@D)
	$(AUTO_CC) -O2 -Wall -Wextra -c $< -o $@

# $(call auto_equations,<dir>/<name>,<source.c>,<link inputs>,<compile flags>)
#
# Rules for <dir>/<name>.exe, an AUTO equations executable that links extra
# objects or static libraries. Drivers run it with e='<dir>/<name>' (absolute
# path). AUTO's run() recompiles <name>.o when <name>.c is newer, and relinks
# <name>.exe when <name>.o or $(AUTO_DIR)/lib/*.o is newer; these rules leave
# all three up to date, so run() uses the executable as built here. Its own
# link line would drop the extra inputs.
define auto_equations
$(1).c: $(2)
	@mkdir -p $$(@D)
	cp $$< $$@

$(1).o: $(1).c $$(AUTO_USED) | auto
	$$(AUTO_CC) $$(call AUTO_C_ONLY,$$(AUTO_CFLAGS) $$(AUTO_OPT)) $(4) -MMD -MP -c $$< -o $$@

$(1).exe: $(1).o $(3) $(wildcard $(AUTO_DIR)/lib/*.o) $$(AUTO_QUIET_FPE) $$(AUTO_USED) | auto
	$$(AUTO_FC) -L$$(AUTO_DIR)/lib $$(AUTO_FFLAGS) $$(AUTO_OPT) $$< -o $$@ \
	    $$(AUTO_DIR)/lib/*.o $(3) -lauto_c $$(AUTO_QUIET_LDFLAGS)

-include $(1).d
endef
