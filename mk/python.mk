# The Python drivers (the package drivers/mlgshimmy): how make runs them and
# what a driver's result depends on; included by ../Makefile first.
#
#   $(PYTHON) -m mlgshimmy.<room>.<module> ...   a driver (PYTHONPATH set here)
#   $(eval $(call py_deps,<name>,<module>))    $(PYDEPS_<name>): the files of
#                                              the module's import closure
#   $(call stamp,<file>,<text>)                <file> holds <text> (below)
# (shell_quote, the one way a value reaches a shell, is in ../Makefile.)
export PYTHONPATH := $(CURDIR)/drivers$(if $(PYTHONPATH),:$(PYTHONPATH))

# $(call stamp,<file>,<text>): <file> holds <text>, rewritten only when the
# text changes (so its time says when; a word added or removed is a change),
# while make reads its makefiles: no shell sees the text.  Only when a goal
# may build: `make help AUTO_THREADS=2` or a redraw with another AUTO_DIR
# must not mark every result out of date.  A dry run writes a missing stamp
# (a real make would, with the same effect) but never rewrites one (`make -n
# fig11 AUTO_THREADS=2` had left the stamp at 2, so the next plain make
# redid every result): a changed text makes <file> depend on a phony target
# instead, so that `make -n` still lists what depends on it.
STAMP_GOALS := $(filter-out help clean distclean forget-auto %-plot,$(or $(MAKECMDGOALS),help))
DRY_RUN := $(findstring n,$(firstword -$(MAKEFLAGS)))
stamp_write = $(shell mkdir -p $(call shell_quote,$(dir $(1))))$(file > $(1),$(strip $(2)))
stamp_differs = $(filter-out $(strip $(2)),$(strip $(file < $(1))))$(filter-out \
    $(strip $(file < $(1))),$(strip $(2)))
stamp = $(if $(STAMP_GOALS),$(if $(wildcard $(1)),$(if $(call stamp_differs,$(1),$(2)),$(if \
    $(DRY_RUN),$(eval $(1): stamp-changed ; @:),$(call stamp_write,$(1),$(2)))),$(call \
    stamp_write,$(1),$(2))))
.PHONY: stamp-changed
stamp-changed: ;

# `make -n` runs recipe lines that call $(MAKE); those check DRY_RUN (above)
# so that a dry run prints what it would do instead of doing it.
# No driver's import closure is needed to clean or to print the help.
PY_DEPS_WANTED := $(if $(filter-out clean help,$(or $(MAKECMDGOALS),all)),yes)

# Like gcc -MMD: build/deps/<name>.d sets PYDEPS_<name> to every file of the
# package that the module imports, imports inside functions included
# (shared.jobs.depends reads the sources and imports nothing, so it works
# before anything is built); the .d file depends on them and is remade when
# one changes.  It runs as a file, not with -m: the package's __init__s
# would import numpy, which the first make has not installed yet.
DEPS_DIR := build/deps
DEPENDS := drivers/mlgshimmy/shared/jobs/depends.py
define py_deps
ifndef PYDEPS_RULE_$(1)
PYDEPS_RULE_$(1) := 1
$(DEPS_DIR)/$(1).d:
	@mkdir -p $$(@D)
	@$$(PYTHON) $$(DEPENDS) PYDEPS_$(1) $$@ mlgshimmy.$(2) > $$@
ifeq ($(PY_DEPS_WANTED),yes)
-include $(DEPS_DIR)/$(1).d
endif
endif
endef

# make venv [VENV=v] [PYTHON=...]: a virtual environment that imports the
# drivers from drivers/ (mk/venv.sh says what it needs when PYTHON lacks it).
VENV ?= v
.PHONY: venv
venv:
	mk/venv.sh $(call shell_quote,$(PYTHON)) $(call shell_quote,$(VENV))
