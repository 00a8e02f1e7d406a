# The studies (mlgshimmy.studies): the side-stay geometry, the sweep over
# it, the allowable-freeplay criterion, the attractor atlas, the torus check
# and the c_psi calibration; included by ../Makefile after figures.mk.

# Side-stay geometry (angles in degrees): make sidestay RHO=10 MU=10 [EOM=0|1|2]
# (EOM: the eom_terms level, default 2, the complete equations).  The study
# sets its own angles: it runs in the base tree (mk/gear.mk AT_BASELINE),
# not in the geometry tree that RHO and MU give every other target.
EOM ?= 2
.PHONY: sidestay sidestay_rho10_mu10 calibrate
sidestay: $(AUTO_DRIVER_DEPS)
	$(if $(and $(RHO),$(MU)),,$(error make sidestay needs RHO=<deg> MU=<deg>))
	$(if $(filter-out 0 1 2,$(EOM))$(filter-out 1,$(words $(EOM))),$(error make sidestay: \
	    EOM=$(EOM) must be 0 (as printed), 1 (side-stay corrections) or 2 (complete equations)))
	$(AT_BASELINE) $(PYTHON) -m mlgshimmy.studies.sidestay --rho $(call shell_quote,$(RHO)) \
	    --mu $(call shell_quote,$(MU)) --eom-terms $(EOM)

# The non-zero geometry with a regression reference (tests/reference/).
sidestay_rho10_mu10: $(AUTO_DRIVER_DEPS)
	$(AT_BASELINE) $(PYTHON) -m mlgshimmy.studies.sidestay --rho 10 --mu 10
REGRESS_FIGURES += sidestay_rho10_mu10

# The c_psi of the `figures` set (MLG_C_PSI_FIGURES in c/parameters.c).
calibrate: $(AUTO_DRIVER_DEPS)
	$(PYTHON) -m mlgshimmy.studies.calibrate_c_psi

# Sweep over side-stay angles (degrees, comma-separated), one job per grid
# point (mk/jobs.mk):
#   make -j2 sweep SWEEP_RHO=-10,0,10 SWEEP_MU=-10,0,10
SWEEP_RHO ?= -10,0,10
SWEEP_MU ?= -10,0,10
$(eval $(call py_deps,sweep,studies.sweep))
$(eval $(call job_grid,sweep,--rho=$(call shell_quote,$(SWEEP_RHO)) \
    --mu=$(call shell_quote,$(SWEEP_MU)),$$(PYDEPS_sweep) $(MODEL_INPUTS) | auto,point))

# The Floquet multipliers along one periodic-orbit run, from its d-file (no
# AUTO run): make floquet RUN=build/fig10/po3 (studies.floquet_plot).
.PHONY: floquet
floquet:
	$(if $(strip $(RUN)),,$(error make floquet needs RUN=<run directory>/<run name>, e.g. RUN=build/fig10/po3))
	$(PYTHON) -m mlgshimmy.studies.floquet_plot $(call shell_quote,$(RUN))

# Robustness of the answers to a changed model (studies.robustness): one job
# per variation of one parameter (x0.8, x0.9, x1.1, x1.2 by default), each
# making fig07, fig09, fig10 and fig12 for that gear and its kappa*:
#   make -j2 robustness                                   every parameter
#   make -j2 robustness ROBUST_PARAMETERS=k_tlk ROBUST_FACTORS=0.9,1.1
# Then the completion fraction and $(RUN_ROOT)/tables/robustness.txt.
ROBUST_PARAMETERS ?= k_tlk,c_psi,I_psi,k_beta,c_beta,M,I_0,a4_F,a3_M,a4_M,l_tlk,a_tlk,b_tlk
ROBUST_FACTORS ?= 0.8,0.9,1.1,1.2
ROBUST_ARGS := --parameters=$(call shell_quote,$(ROBUST_PARAMETERS)) \
               --factors=$(call shell_quote,$(ROBUST_FACTORS))
$(eval $(call py_deps,robustness,studies.robustness))
$(eval $(call job_grid,robustness,$(ROBUST_ARGS),$$(PYDEPS_robustness) $(MODEL_INPUTS) | auto,job))

# The allowable-freeplay criterion (eq. 17) under each low-load assumption:
# one job per group of assumptions (studies.criterion GROUPS), so `make -j2
# criterion` runs them side by side; `criterion` prints the table and draws
# the figure.  The groups are parts of the result cache (shared.jobs),
# recomputed when a file of the study's import closure, the constants or the
# model is newer.
CRITERION_DIR := $(RUN_ROOT)/criterion/parts
CRITERION_GROUPS := strut stage c_psi tyre
$(eval $(call py_deps,criterion,studies.criterion))
CRITERION_DEPS = $(PYDEPS_criterion) $(MODEL_INPUTS) | auto

$(CRITERION_DIR)/%.json: $(CRITERION_DEPS)
	$(PYTHON) -m mlgshimmy.studies.criterion scan $*

# AUTO's check starts from the scan's minimum of each strut variant.
$(CRITERION_DIR)/auto.json: $(CRITERION_DIR)/strut.json $(CRITERION_DEPS)
	$(PYTHON) -m mlgshimmy.studies.criterion auto

.PHONY: criterion criterion-plot
criterion: $(CRITERION_GROUPS:%=$(CRITERION_DIR)/%.json) $(CRITERION_DIR)/auto.json
	$(PYTHON) -m mlgshimmy.studies.criterion report
# The table and figure from the cached parts alone (no rescan).
criterion-plot:
	$(PYTHON) -m mlgshimmy.studies.criterion report

# $(call cached_study,<name>): studies.<name>, its result cached (--compute,
# on its imports and the model's inputs) and drawn from the cache (--plot).
define cached_study
$(eval $(call py_deps,$(1),studies.$(1)))
$(call result,$(1)): $$(PYDEPS_$(1)) $(MODEL_INPUTS) | auto
	$$(PYTHON) -m mlgshimmy.studies.$(1) --compute
.PHONY: $(1) $(1)-plot
$(1): $(call result,$(1))
	$$(PYTHON) -m mlgshimmy.studies.$(1) --plot
$(1)-plot:
	$$(PYTHON) -m mlgshimmy.studies.$(1) --plot
endef

# Oleo seal friction against the low-speed shimmy (studies.friction): the
# critical friction moment of Fig. 10's low-frequency orbits, its v_fric
# ladder and its freeplays; cached in $(RUN_ROOT)/friction/result.json.
$(eval $(call cached_study,friction))
# Fig. 10's diagram at three friction levels (studies.friction_fig10).
$(eval $(call cached_study,friction_fig10))

# Attractor atlas over (V, F*) by time simulation (studies.atlas); axes
# "a,b,c" or "start:stop:step", one job per cell:
#   make -j2 atlas                       the default grid (atlas DEFAULT_*)
#   make -j2 atlas ATLAS_GRID=coarse     8 x 5 cells of the default grid
#   make -j2 atlas ATLAS_V=100:600:100 ATLAS_FSTAR=0.5,1
# Results in $(RUN_ROOT)/atlas/, plot $(RUN_ROOT)/figures/atlas.png.
ifeq ($(ATLAS_GRID),coarse)
ATLAS_V ?= 10,30,50,100,200,300,450,600
ATLAS_FSTAR ?= 0.2,0.5,1,1.8,3
else ifneq ($(ATLAS_GRID),)
$(error ATLAS_GRID=$(ATLAS_GRID): the only named grid is coarse)
endif
ATLAS_ARGS := $(if $(ATLAS_V),--V=$(call shell_quote,$(ATLAS_V))) \
              $(if $(ATLAS_FSTAR),--Fstar=$(call shell_quote,$(ATLAS_FSTAR)))
$(eval $(call py_deps,atlas,studies.atlas))
$(eval $(call job_grid,atlas,$(ATLAS_ARGS),$$(PYDEPS_atlas) $(MLG_SIMULATE) $(MLG_SHARED),cell))

# Torus points of the large-amplitude orbits (Figs. 7 and 10), checked on
# three meshes and by simulation, their windows of instability on a fine
# mesh, and continued in (V, F*) (studies.torus_check): results in
# $(RUN_ROOT)/torus/result.json (Fig. 11 continues its own torus curves).
.PHONY: torus
torus: $(AUTO_DRIVER_DEPS) $(MLG_SIMULATE)
	$(PYTHON) -m mlgshimmy.studies.torus_check

# The reproduction report (mlgshimmy.report): one HTML page from the cached
# results, tables and PNGs of what has been made -- it computes nothing, so
# make the figures first (make figures) -- in $(RUN_ROOT)/report/index.html,
# and report.pdf beside it when Chromium is installed (headless print).
REPORT_DIR := $(RUN_ROOT)/report
.PHONY: report
report: | $(MLG_SHARED)
	$(PYTHON) -m mlgshimmy.report --out $(REPORT_DIR)
	@set -e; if command -v chromium >/dev/null 2>&1; then \
	    timeout 120 chromium --headless --no-sandbox --disable-gpu --no-pdf-header-footer \
	        --print-to-pdf=$(REPORT_DIR)/report.pdf file://$(REPORT_DIR)/index.html \
	        >$(REPORT_DIR)/chromium.log 2>&1 \
	    && echo "report: wrote $(REPORT_DIR)/report.pdf" \
	    || echo "report: no PDF (chromium failed: $(REPORT_DIR)/chromium.log)"; \
	else echo "report: no PDF (install chromium for one)"; fi

# The smoothing error of eq. (15) (or FREEPLAY=<law>) against the non-smooth
# eq. (14) by eps / y_fp, with fitted orders (studies.smoothing): H1-H3, a_12
# and b_12 by eigenvalue scans, the stable orbit and its fold S by simulation
# with every switch located, Fig. 10's torus points by AUTO, kappa* by the
# criterion; about 25 min; the table in $(RUN_ROOT)/tables/smoothing.txt, Fig. 10
# overlaid by eps in $(RUN_ROOT)/figures/smoothing_fig10.png.
$(eval $(call cached_study,smoothing))
# under regression: tests/reference/smoothing holds the eps table as named
# points with their tolerances (docs/regression.md)
REGRESS_FIGURES += smoothing

# Fig. 14's Hopf curves and orbit in y_fp at several fixed eps and with eq. (14)
# (studies.smoothing_fig14): a few minutes.
$(eval $(call cached_study,smoothing_fig14))

# Fig. 10 under the non-smooth eq. (14): its periodic orbits as segmented
# boundary-value problems (studies.segmented, models/mlg_segmented.c), checked
# against the event-located simulation; about 5 min; the table in
# $(RUN_ROOT)/tables/segmented.txt.
$(eval $(call cached_study,segmented))
$(call result,segmented): $(MLG_SEGMENTED).exe
# under regression: tests/reference/segmented holds its segmented runs and its
# named points with their tolerances (docs/regression.md)
REGRESS_FIGURES += segmented
# tests/continuation/test_segmented.py runs its orbits
TEST_DEPS += $(MLG_SEGMENTED).exe

# Eq. (17)'s kappa* for every freeplay law of c/freeplay_laws.h (studies.laws,
# eigenvalue scans): under a minute; the table in $(RUN_ROOT)/tables/laws.txt.
$(eval $(call cached_study,laws))

# The gear's motion at one (V, F*), animated from the simulator (studies.animate):
#   make animate V=300 FSTAR=1 [START=shimmy|rolling|yawed] [YFP=1] [RHO= MU= SET=]
# (NEAR=1 with START=yawed: at the load nearest FSTAR where the gear has a
# yawed state, as make gear asks)
# (a GIF, an MP4 where ffmpeg is installed, a contact sheet of frames);
# make animate-plot redraws the cached motion.
START ?= shimmy
YFP ?= 1
.PHONY: animate animate-plot
animate animate-plot: $(MLG_SIMULATE) $(MLG_SHARED)
	$(if $(and $(V),$(FSTAR)),,$(error make $@ needs V=<m/s> FSTAR=<load>, e.g. make animate V=300 FSTAR=1))
	$(PYTHON) -m mlgshimmy.studies.animate --V=$(call shell_quote,$(V)) \
	    --Fstar=$(call shell_quote,$(FSTAR)) --start=$(call shell_quote,$(START)) \
	    --yfp=$(call shell_quote,$(YFP))$(if $(NEAR), --near)$(if $(filter animate-plot,$@), --plot)

# One animation per kind of attractor of Fig. 11 (studies.animate --fig11:
# a point deep inside each kind's region of Fig. 11's cached map, listed in
# figures/fig11_motion.json for the report).  It reads the cached map as it
# is (make fig11 first), with no prerequisite on it: make would remake a map
# older than the drivers first, an 11-minute figure for a choice of points.
FIG11_CASES := $(RUN_ROOT)/figures/fig11_motion.cases
.PHONY: fig11-motion
fig11-motion: $(MLG_SIMULATE) $(MLG_SHARED)
	@mkdir -p $(dir $(FIG11_CASES))
	$(PYTHON) -m mlgshimmy.studies.animate --fig11 > $(FIG11_CASES)
	set -e; while read V F S; do $(MAKE) --no-print-directory animate V=$$V FSTAR=$$F \
	    START=$$S; done < $(FIG11_CASES)

# One labelled point of any diagram (studies.point_view): orbit profile, phase
# portrait, Floquet multipliers, a simulation from it:
#   make point RUN=build/fig10/po3 LABEL=5
.PHONY: point
point: $(MLG_SIMULATE) $(MLG_SHARED)
	$(if $(and $(strip $(RUN)),$(strip $(LABEL))),,$(error make point needs RUN=<run directory>/<run name> LABEL=<label>, e.g. RUN=build/fig10/po3 LABEL=5))
	$(PYTHON) -m mlgshimmy.studies.point_view $(call shell_quote,$(RUN)) $(call shell_quote,$(LABEL))

# "My gear" in one page: make gear RHO=20 MU=5 [SET=...]: the figures of
# GEAR_FIGURES (every figure; GEAR_FIGURES=answers: only the three the design
# answers read) at the gear and at the paper's gear (for the numbers beside;
# the gear's exported MLG_* cleared, or the base tree would get the gear's),
# the studies of GEAR_STUDIES at the gear (default laws: kappa* for every
# freeplay law, a minute or two; atlas too takes ~9 min at -j2; none with
# GEAR_STUDIES=), the animations of GEAR_MOTION (V:F*:start), then the gear
# tree's report, which opens with the design answers (shared.gear_answers).
# An animation that fails leaves the others and the page; make gear names
# it and fails.
GEAR_FIGURES ?= $(FIGURES)
GEAR_ANSWERS := fig07 fig10 fig18
override GEAR_FIGURES := $(if $(filter answers,$(GEAR_FIGURES)),$(GEAR_ANSWERS),$(GEAR_FIGURES))
GEAR_STUDIES ?= laws
GEAR_STUDY_CHOICES := laws atlas
GEAR_MOTION ?= 15:1:rolling 300:1:shimmy 450:0.3:shimmy 50:0.2:yawed
.PHONY: gear
gear:
	$(if $(GEAR_SUBDIR),,$(error make gear needs a changed gear: RHO=<deg> MU=<deg> and/or SET='name=value', e.g. make gear RHO=20 MU=5))
	$(if $(filter-out $(FIGURES),$(GEAR_FIGURES)),$(error GEAR_FIGURES: not a figure: $(filter-out $(FIGURES),$(GEAR_FIGURES)) (the figures: $(FIGURES), or answers)))
	$(if $(filter-out $(GEAR_STUDY_CHOICES),$(GEAR_STUDIES)),$(error GEAR_STUDIES: not a study made at a gear: $(filter-out $(GEAR_STUDY_CHOICES),$(GEAR_STUDIES)) (the choices: $(GEAR_STUDY_CHOICES), or none: GEAR_STUDIES=)))
	MLG_RHO_DEG= MLG_MU_DEG= MLG_EOM= MLG_SET= MLG_BASE_RUN_ROOT= $(MAKE) --no-print-directory \
	    MLG_RUN_ROOT=$(call shell_quote,$(BASE_RUN_ROOT)) RHO= MU= EOM= SET= $(GEAR_FIGURES)
	$(MAKE) --no-print-directory $(GEAR_FIGURES) $(GEAR_STUDIES)
	set -e; failed=; $(foreach m,$(GEAR_MOTION),$(MAKE) --no-print-directory animate \
	    V=$(word 1,$(subst :, ,$(m))) FSTAR=$(word 2,$(subst :, ,$(m))) \
	    START=$(word 3,$(subst :, ,$(m))) NEAR=1 || failed="$$failed "$(call shell_quote,$(m));) \
	$(MAKE) --no-print-directory report || exit 1; \
	if [ -n "$$failed" ]; then echo "gear: the page is written without the animations" \
	    "that failed (V:F*:start, reasons above):$$failed"; exit 1; fi
