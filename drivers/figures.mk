# Figure targets that run AUTO on the MLG model; included by ../Makefile.
# Each driver computes its runs under build/<name>/ and writes
# build/figures/<name>.png and .pdf (with MLG_RUN_ROOT=<dir> set: <dir>/<name>/
# and <dir>/figures/); it exits non-zero on MX or a missing special point,
# naming the run.
AUTO_DRIVER_DEPS := $(MLG_MODEL).exe $(MLG_SHARED) | auto

# A cached figure <fig> (drivers/results.py): `drivers/<fig>.py --compute`
# writes $(RUN_ROOT)/<fig>/result.json, rebuilt only when one of its inputs
# is newer (the driver, the shared layer, the constants, the model); `make
# <fig>` then draws from it and `make <fig>-plot` redraws from it alone.
RUN_ROOT := $(abspath $(or $(MLG_RUN_ROOT),build))
SHARED_LAYER := $(addprefix drivers/,autoglue.py branches.py continuation.py mlgmodel.py \
                  paths.py results.py spectrum.py)
COMPUTE_INPUTS := $(SHARED_LAYER) constants/c.mlg $(wildcard constants/runs/c.*) \
                  $(MLG_MODEL).exe $(MLG_SHARED)
result = $(RUN_ROOT)/$(1)/result.json

# $(call cached_figure,<fig>,<more inputs>[,<driver>,<driver options>]): the
# driver is drivers/<fig>.py unless named (fig12_v1: fig12, --strut-variant 1).
# A figure whose driver lists parts (`drivers/<fig>.py parts`) gets them as
# make jobs first (drivers/parts.mk, with the rules the driver writes), so
# that `make -jN` runs them side by side.
define cached_figure
$(call result,$(1)): drivers/$(or $(3),$(1)).py $(COMPUTE_INPUTS) $(2) | auto
	$$(if $$(filter $(1),$$(FIGURES_WITH_PARTS)),$$(PYTHON) drivers/$(1).py rules && \
	    $$(MAKE) --no-print-directory -f drivers/parts.mk FIGURE=$(1) INPUTS="$$^")
	$$(PYTHON) drivers/$(or $(3),$(1)).py $(4) --compute
.PHONY: $(1) $(1)-plot
$(1): $(call result,$(1))
	$$(PYTHON) drivers/$(or $(3),$(1)).py $(4) --plot
$(1)-plot:
	$$(PYTHON) drivers/$(or $(3),$(1)).py $(4) --plot
endef

FIGURES_WITH_PARTS := fig11 fig13 fig14 fig16
$(eval $(call cached_figure,fig07))
$(eval $(call cached_figure,fig09))

.PHONY: calibrate

# Side-stay geometry (angles in degrees): make sidestay RHO=10 MU=10 [EOM=0|1|2]
# (EOM: the eom_terms level, default 2, the complete equations)
EOM ?= 2
.PHONY: sidestay
sidestay: $(AUTO_DRIVER_DEPS)
	$(if $(and $(RHO),$(MU)),,$(error make sidestay needs RHO=<deg> MU=<deg>))
	$(if $(filter-out 0 1 2,$(EOM))$(filter-out 1,$(words $(EOM))),$(error make sidestay: \
	    EOM=$(EOM) must be 0 (as printed), 1 (side-stay corrections) or 2 (complete equations)))
	$(PYTHON) drivers/sidestay.py --rho $(RHO) --mu $(MU) --eom-terms $(EOM)

# The non-zero geometry with a regression reference (tests/reference/).
.PHONY: sidestay_rho10_mu10
sidestay_rho10_mu10: $(AUTO_DRIVER_DEPS)
	$(PYTHON) drivers/sidestay.py --rho 10 --mu 10
REGRESS_FIGURES += sidestay_rho10_mu10

# The c_psi of the `figures` set (MLG_C_PSI_FIGURES in c/parameters.c).
calibrate: $(AUTO_DRIVER_DEPS)
	$(PYTHON) drivers/calibrate_c_psi.py

# The figure-suite benchmark (-j1 against -j2, about 25 min on 2 idle cores; `make bench` names it).
.PHONY: bench-figures
bench-figures: setup
	$(PYTHON) tests/bench/bench_figures.py

FIGURES += fig07 fig09
REGRESS_FIGURES += fig07 fig09
REGRESS_QUICK += fig07 fig09
TEST_DEPS += $(MLG_MODEL).exe $(MLG_SHARED)
TEST_PROGRAMS += tests/test_auto_plugin.py tests/test_sidestay_drivers.py tests/test_isolated_runs.py
BENCH_PROGRAMS += tests/bench/bench_auto_jacobian.py
BENCH_DEPS += $(MLG_MODEL).exe $(MLG_SHARED)

# Freeplay figures (y_fp = 1 mm, epsilon = 0.1 y_fp); fig06 needs no AUTO.
.PHONY: fig06 fig06-plot
fig06 fig06-plot: $(MLG_SHARED) | packages
	$(PYTHON) drivers/fig06.py

$(eval $(call cached_figure,fig10))
# fig11's lift-off edge simulates (drivers/liftoff.py; the atlas's start); its
# torus curve is continued by drivers/torus.py (Floquet crossings: floquet.py).
$(eval $(call cached_figure,fig11,drivers/regionmap.py drivers/liftoff.py drivers/simulator.py \
    drivers/atlas_cell.py drivers/torus.py drivers/floquet.py $(MLG_SIMULATE)))
$(eval $(call cached_figure,fig12))
# Fig. 12 with the printed strut spring (strut variant 1).
$(eval $(call cached_figure,fig12_v1,,fig12,--strut-variant 1))

FIGURES += fig06 fig10 fig11 fig12 fig12_v1
REGRESS_FIGURES += fig10 fig11 fig12
TEST_PROGRAMS += tests/test_freeplay_diagrams.py tests/test_regionmap.py tests/test_fig11_regions.py \
                 tests/test_liftoff.py tests/test_torus_seed.py

# Sweep over side-stay angles (drivers/sweep.py; degrees, comma-separated),
# one job per grid point (drivers/jobs.mk):
#   make -j2 sweep SWEEP_RHO=-10,0,10 SWEEP_MU=-10,0,10
SWEEP_RHO ?= -10,0,10
SWEEP_MU ?= -10,0,10
$(eval $(call job_grid,sweep,--rho=$(SWEEP_RHO) --mu=$(SWEEP_MU),$(AUTO_DRIVER_DEPS),point))
