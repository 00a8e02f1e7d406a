# The paper's figures (mlgshimmy.figures) and the catalogue of every figure
# and study; included by ../Makefile.
# Each AUTO figure computes its runs under $(RUN_ROOT)/<fig>/ and caches its
# result there (result.json: shared.jobs.cache); `make <fig>` draws from it,
# recomputing first when one of its inputs is newer: a file of the driver's
# import closure (mk/python.mk: PYDEPS_<fig>), the constants or the model.
# `make <fig>-plot` redraws from the cache alone (no AUTO needed).  Figures
# go to $(RUN_ROOT)/figures/<fig>.png and .pdf.
RUN_ROOT := $(abspath $(or $(MLG_RUN_ROOT),build))
result = $(RUN_ROOT)/$(1)/result.json
AUTO_DRIVER_DEPS := $(MLG_MODEL).exe $(MLG_SHARED) | auto
# What a result depends on besides the drivers: the constants, the model as
# linked (mlg.exe is relinked when AUTO_DIR changes: mk/auto.mk) and the
# thread count of the AUTO runs (their rounding depends on it), a stamp
# rewritten (when make reads its makefiles) only when it changes, and the
# simulator: the shared layer's criticality check simulates (naming.simulated).
AUTO_THREADS_USED := build/auto-link/auto-threads
$(call stamp,$(AUTO_THREADS_USED),$(AUTO_THREADS))
MODEL_INPUTS := constants/c.mlg $(wildcard constants/runs/c.*) $(MLG_MODEL).exe $(MLG_SHARED) \
                $(AUTO_THREADS_USED) $(MLG_SIMULATE)

# $(call cached_figure,<fig>,<more inputs>[,<driver>,<driver options>]): the
# driver is mlgshimmy.figures.<fig> unless named (fig12_v1: fig12 with
# --strut-variant 1).  A figure whose driver lists parts (FIGURES_WITH_PARTS)
# gets them as make jobs first (mk/parts.mk, with the rules the driver
# writes), so that `make -jN` runs them side by side.
# The figure is drawn in the job that computed it, as soon as its result
# exists: a separate job would wait for a job slot, which the parts of a
# long figure (a sub-make reading the same jobserver) take first, for as
# long as they run.  The draw marks the figure with the make that drew it
# (DRAWN_BY), so that `make <fig>` draws once; a draw that fails there
# leaves the result as it is and is repeated by `make <fig>`, which reports it.
DRAWN_BY = $(RUN_ROOT)/figures/.$(1).drawn-by-make
define cached_figure
$(eval $(call py_deps,$(or $(3),$(1)),figures.$(or $(3),$(1))))
$(call result,$(1)): $$(PYDEPS_$(or $(3),$(1))) $(MODEL_INPUTS) $(2) | auto
	@set -e; $$(if $$(filter $(1),$$(FIGURES_WITH_PARTS)),$$(PYTHON) -m mlgshimmy.figures.$(1) rules; \
	    $$(MAKE) --no-print-directory -f mk/parts.mk FIGURE=$(1) \
	        INPUTS="$$(filter-out $$(DEPS_DIR)/%,$$^)")
	$$(PYTHON) -m mlgshimmy.figures.$(or $(3),$(1)) $(4) --compute
	@set -e; if out=$$$$($$(PYTHON) -m mlgshimmy.figures.$(or $(3),$(1)) $(4) --plot 2>&1); then \
	    printf '%s\n' "$$$$out"; { mkdir -p $$(RUN_ROOT)/figures && \
	    echo $$$$PPID > $$(call DRAWN_BY,$(1)); } || true; fi
.PHONY: $(1) $(1)-plot
$(1): $(call result,$(1))
	@set -e; if [ "$$$$(cat $$(call DRAWN_BY,$(1)) 2>/dev/null)" != $$$$PPID ]; then \
	    $$(PYTHON) -m mlgshimmy.figures.$(or $(3),$(1)) $(4) --plot; fi
$(1)-plot:
	$$(PYTHON) -m mlgshimmy.figures.$(or $(3),$(1)) $(4) --plot
endef

# $(call uncached_figure,<fig>,<inputs>,<redraw inputs>,<redraw options>): a
# figure with no cached result (it computes nothing, or simulates, or draws
# other figures' results): `make <fig>` runs its driver, `make <fig>-plot`
# runs it again on <redraw inputs> only, with <redraw options> (fig08: --plot).
define uncached_figure
.PHONY: $(1) $(1)-plot
$(1): $(2)
	$$(PYTHON) -m mlgshimmy.figures.$(1)
$(1)-plot: $(3)
	$$(PYTHON) -m mlgshimmy.figures.$(1)$(if $(4), $(4))
endef

# Every figure and study as it declares itself (DECLARED in its module, read
# by shared.jobs.catalogue without importing it): the figures' rules,
# FIGURES, REGRESS_FIGURES, REGRESS_QUICK, REGRESS_WITH_<fig>,
# FIGURES_WITH_PARTS, the submit lists and the lines of make help.  Remade
# when a module of figures/ or studies/ is newer, or one it read is gone.
# It needs only python3; on a machine without it the packages come first.
CATALOGUE := drivers/mlgshimmy/shared/jobs/catalogue.py
CATALOGUE_MK := $(DEPS_DIR)/catalogue.mk
CATALOGUE_SOURCES := $(wildcard $(addprefix drivers/mlgshimmy/,figures/*.py figures/*/declared.py \
    studies/*.py studies/*/declared.py))
include $(CATALOGUE_MK)
ifneq ($(filter-out $(CATALOGUE_SOURCES),$(CATALOGUE_READ)),)
$(CATALOGUE_MK): stamp-changed
endif
$(CATALOGUE_MK): $(CATALOGUE) $(CATALOGUE_SOURCES) $(if $(wildcard $(PYTHON)),,| $(PACKAGES_STAMP))
	@mkdir -p $(@D)
	@set -e; $(PYTHON) $(CATALOGUE) make > $@.tmp; mv $@.tmp $@

TEST_DEPS += $(MLG_MODEL).exe $(MLG_SHARED)
BENCH_PROGRAMS += tests/bench/bench_auto_jacobian.py
BENCH_DEPS += $(MLG_MODEL).exe $(MLG_SHARED)

# The figure-suite benchmark (-j1 against -j2, about 25 min on 2 idle cores; `make bench` names it),
# then Fig. 11 and a design-map point at a side-stay geometry against the paper's gear (bench-gear).
.PHONY: bench-figures bench-gear
bench-figures: setup
	$(PYTHON) tests/bench/bench_figures.py
bench-gear: setup
	$(PYTHON) tests/bench/bench_figures.py --gear-rows

# What each cached part of a figure cost (CPU and wall seconds, most first), at the
# gear RHO, MU, EOM and SET name (shared/jobs/costs.py).
profile-%:
	$(PYTHON) -m mlgshimmy.shared.jobs.costs $*
