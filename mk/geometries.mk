# The design map over side-stay angles (studies.design_map, docs/design-map.md)
# included by ../Makefile after mk/studies.mk.  One job per geometry (mk/jobs.mk
# job_grid: make -jN, or `design_map.py jobs` for GNU parallel and Slurm), each
# at eom_terms = 2 with its runs and result.json in $(RUN_ROOT)/design_map/rho<r>_mu<m>/:
#   make -j2 design-map                         the default 5 x 5 grid, -20:20:10 each
#   make -j2 design-map DESIGN_RHO=-10,10 DESIGN_MU=0:20:5
#   make submit-design-map DESIGN_RHO=-20:20:2 DESIGN_MU=-20:20:2   on Slurm (mk/cluster/submit.mk)
# Then the maps $(RUN_ROOT)/figures/design_map.png, the table
# $(RUN_ROOT)/tables/design_map.txt and design_map.json.  The map sets its own
# angles and runs in the base tree whatever gear is given (it takes no SET:
# mk/gear.mk AT_BASELINE); RHO and MU, if given, are the user's geometry,
# marked on the map and in the table at its grid point or the nearest:
#   make -j2 design-map RHO=12 MU=7             the default grid, (10, 10) marked
DESIGN_RHO ?= -20:20:10
DESIGN_MU ?= -20:20:10
DESIGN_GEAR := $(strip $(RHO)$(MU)$(EOM)$(GEAR_SET))
# `design-map` is the job grid `design_map` (a module name has no hyphen);
# with a gear given it is that grid made again in the base tree, without
# the gear, the user's angles as DESIGN_MARK
ifeq ($(DESIGN_GEAR),)
ifneq ($(filter design-map,$(MAKECMDGOALS)),)
MAKECMDGOALS += design_map
endif
endif
$(eval $(call py_deps,design_map,studies.design_map))
DESIGN_GRID_ARGS = --rho=$(call shell_quote,$(DESIGN_RHO)) --mu=$(call shell_quote,$(DESIGN_MU))
DESIGN_SUMMARY_ARGS = $(if $(DESIGN_MARK),--mark=$(call shell_quote,$(DESIGN_MARK)))
$(eval $(call job_grid,design_map,$(DESIGN_GRID_ARGS),$$(PYDEPS_design_map) $(MODEL_INPUTS) | auto,point,$(DESIGN_SUMMARY_ARGS)))
.PHONY: design-map
ifeq ($(DESIGN_GEAR),)
design-map: design_map
else
design_mark_comma := ,
design-map:
	$(AT_BASELINE) $(MAKE) --no-print-directory design-map RHO= MU= EOM= \
	    MLG_RUN_ROOT=$(call shell_quote,$(BASE_RUN_ROOT)) \
	    DESIGN_MARK=$(if $(strip $(RHO)$(MU)),$(call shell_quote,$(RHO)$(design_mark_comma)$(MU)))
endif

# Figures of another gear with a regression reference, beside
# sidestay_rho10_mu10 (mk/studies.mk): $(call gear_reference,<target>,<fig>,<gear
# variables>,<its tree>) makes the target: `<fig> <gear variables>` in the gear's
# tree, its runs copied to $(RUN_ROOT)/<target>/, where `make regress-<target>`
# compares them with tests/reference/<target>/ (`make refs-<target>` writes that
# set).  $(call geometry_reference,fig10,10,10) is fig10_rho10_mu10: `fig10
# RHO=10 MU=10 EOM=2`.
define gear_reference
.PHONY: $(1)
$(1): $$(AUTO_DRIVER_DEPS)
	$$(MAKE) --no-print-directory $(2) $(3)
	set -e; rm -rf $$(RUN_ROOT)/$$@.tmp && cp -a $$(RUN_ROOT)/$(4)/$(2) $$(RUN_ROOT)/$$@.tmp
	set -e; rm -rf $$(RUN_ROOT)/$$@ && mv $$(RUN_ROOT)/$$@.tmp $$(RUN_ROOT)/$$@
REGRESS_FIGURES += $(1)
endef
geometry_reference = $(call gear_reference,$(1)_rho$(2)_mu$(3),$(1),RHO=$(2) MU=$(3) EOM=2,geometry/rho$(2)_mu$(3)_eom2)
$(eval $(call geometry_reference,fig10,10,10))
$(eval $(call geometry_reference,fig12,10,10))
# Fig. 10 with oleo seal friction (docs/friction.md): M_fric = 5 N m at the
# default v_fric = 1 mm/s, where H1 and H2 are subcritical
$(eval $(call gear_reference,fig10_fric5,fig10,SET='M_fric=5',gear/M_fric_5))
