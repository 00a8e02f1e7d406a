# AUTO-07p: where it lives, how it is built, and how equations files are
# compiled and linked the way AUTO's run() does it, with extra libraries.
#
# AUTO_DIR=<dir>   use an already built AUTO-07p tree (skips the build)
# AUTO_SRC=<file>  build from this source tarball instead of the Debian package

ifdef AUTO_DIR
override AUTO_DIR := $(abspath $(AUTO_DIR))
AUTO_STAMP :=

auto:
	@set -e; for f in python/auto/__init__.py cmds/cmds.make include/auto_f2c.h lib/libauto_c.a; do \
	    if [ ! -f "$(AUTO_DIR)/$$f" ]; then \
	        echo "error: AUTO_DIR=$(AUTO_DIR) is not a built AUTO-07p tree (no $$f)" >&2; \
	        echo "error: unset AUTO_DIR to build AUTO-07p under build/auto/" >&2; \
	        exit 1; \
	    fi; \
	done
else
AUTO_DIR := $(CURDIR)/build/auto/07p
AUTO_STAMP := build/.stamp-auto

auto: $(AUTO_STAMP)

$(AUTO_STAMP): mk/build-auto.sh | $(PACKAGES_STAMP)
	mk/build-auto.sh build/auto $(if $(AUTO_SRC),$(abspath $(AUTO_SRC)))
	touch $@
endif
export AUTO_DIR

# The compiler settings AUTO's run() reads from $(AUTO_DIR)/cmds/cmds.make.
# Recursively expanded: only evaluated in recipes, after AUTO is built.
auto_make_var = $(subst $$(AUTO_DIR),$(AUTO_DIR),$(shell \
    sed -n 's/^$(1)[[:space:]]*=[[:space:]]*//p' $(AUTO_DIR)/cmds/cmds.make | head -n1))
AUTO_CC = $(call auto_make_var,CC)
AUTO_CFLAGS = $(call auto_make_var,CFLAGS)
AUTO_FC = $(call auto_make_var,FC)
AUTO_FFLAGS = $(call auto_make_var,FFLAGS)
AUTO_OPT = $(call auto_make_var,OPT)

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

$(1).o: $(1).c | auto
	$$(AUTO_CC) $$(AUTO_CFLAGS) $$(AUTO_OPT) $(4) -MMD -MP -c $$< -o $$@

$(1).exe: $(1).o $(3) $(wildcard $(AUTO_DIR)/lib/*.o) | auto
	$$(AUTO_FC) -L$$(AUTO_DIR)/lib $$(AUTO_FFLAGS) $$(AUTO_OPT) $$< -o $$@ \
	    $$(AUTO_DIR)/lib/*.o $(3) -lauto_c

-include $(1).d
endef
