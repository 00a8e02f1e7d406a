# The paper's figures (mlgshimmy.figures); included by ../Makefile.
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
# rewritten (when make reads its makefiles) only when it changes.
AUTO_THREADS_USED := build/auto-link/auto-threads
$(call stamp,$(AUTO_THREADS_USED),$(AUTO_THREADS))
MODEL_INPUTS := constants/c.mlg $(wildcard constants/runs/c.*) $(MLG_MODEL).exe $(MLG_SHARED) \
                $(AUTO_THREADS_USED)

# $(call cached_figure,<fig>,<more inputs>[,<driver>,<driver options>]): the
# driver is mlgshimmy.figures.<fig> unless named (fig12_v1: fig12 with
# --strut-variant 1).  A figure whose driver lists parts (FIGURES_WITH_PARTS)
# gets them as make jobs first (mk/parts.mk, with the rules the driver
# writes), so that `make -jN` runs them side by side.
define cached_figure
$(eval $(call py_deps,$(or $(3),$(1)),figures.$(or $(3),$(1))))
$(call result,$(1)): $$(PYDEPS_$(or $(3),$(1))) $(MODEL_INPUTS) $(2) | auto
	@set -e; $$(if $$(filter $(1),$$(FIGURES_WITH_PARTS)),$$(PYTHON) -m mlgshimmy.figures.$(1) rules; \
	    $$(MAKE) --no-print-directory -f mk/parts.mk FIGURE=$(1) \
	        INPUTS="$$(filter-out $$(DEPS_DIR)/%,$$^)")
	$$(PYTHON) -m mlgshimmy.figures.$(or $(3),$(1)) $(4) --compute
.PHONY: $(1) $(1)-plot
$(1): $(call result,$(1))
	$$(PYTHON) -m mlgshimmy.figures.$(or $(3),$(1)) $(4) --plot
$(1)-plot:
	$$(PYTHON) -m mlgshimmy.figures.$(or $(3),$(1)) $(4) --plot
endef

FIGURES_WITH_PARTS := fig11 fig13 fig14 fig16

# Zero freeplay (section IV.A): Figs. 7 and 9; Fig. 8 simulates (c/simulate).
$(eval $(call cached_figure,fig07))
$(eval $(call cached_figure,fig09))

# y_fp = 1 mm, eps = 0.1 y_fp (section IV.B-C): Figs. 10-12; fig06 needs no AUTO.
.PHONY: fig06 fig06-plot
fig06 fig06-plot: $(MLG_SHARED) | packages
	$(PYTHON) -m mlgshimmy.figures.fig06

$(eval $(call cached_figure,fig10))
# Fig. 11's lift-off edge simulates (shared.liftoff).
$(eval $(call cached_figure,fig11,$(MLG_SIMULATE)))
$(eval $(call cached_figure,fig12))
# Fig. 12 with the printed strut spring (strut variant 1).
$(eval $(call cached_figure,fig12_v1,,fig12,--strut-variant 1))

FIGURES += fig06 fig07 fig09 fig10 fig11 fig12 fig12_v1
REGRESS_FIGURES += fig07 fig09 fig10 fig11 fig12
REGRESS_QUICK += fig07 fig09
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
