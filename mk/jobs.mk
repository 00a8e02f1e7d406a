# A grid of independent jobs (shared.jobs.grid) as make targets; included by
# ../Makefile before the makefiles that use it.
#
#   $(eval $(call job_grid,<tool>,<grid options>,<inputs>,<job command>[,<summary options>]))
#
# makes `make [-jN] <tool>`: `python3 -m mlgshimmy.studies.<tool> check <grid
# options>` once per grid (a stamp in $(RUN_ROOT)/<tool>/), then one make job
# `... <job command> <name>` per $(RUN_ROOT)/<tool>/<name>/result.json that
# `<tool> targets` lists, rebuilt when it is older than the check or one of
# <inputs>, then `<tool> summary` (with <summary options>, which no job
# sees).  <grid options> reach the shell only as words quoted with shell_quote.  The grid is read only when <tool> is a goal
# (never for `make clean` or another target); a rejected grid stops make with
# the tool's message, which names the variable.  ($(shell) of GNU make < 4.4
# does not see exported variables: PYTHONPATH, the run root and the geometry
# (mk/gear.mk) are passed explicitly, so that the targets lie in the
# geometry's tree.)
define job_grid
ifneq ($$(filter $(1),$$(MAKECMDGOALS)),)
$(1)_RESULTS := $$(shell PYTHONPATH=$$(call shell_quote,$$(PYTHONPATH)) \
    MLG_RUN_ROOT=$$(call shell_quote,$$(RUN_ROOT)) MLG_RHO_DEG=$$(call shell_quote,$$(MLG_RHO_DEG)) \
    MLG_MU_DEG=$$(call shell_quote,$$(MLG_MU_DEG)) MLG_EOM=$$(call shell_quote,$$(MLG_EOM)) \
    MLG_SET=$$(call shell_quote,$$(MLG_SET)) \
    $$(call shell_quote,$$(PYTHON)) -m mlgshimmy.studies.$(1) targets $(2) || echo $(1)_GRID_REJECTED)
ifneq ($$(filter $(1)_GRID_REJECTED,$$($(1)_RESULTS)),)
$$(error $(1): the grid is rejected (reason above))
endif
$(1)_CHECKED := $(RUN_ROOT)/$(1)/grid-$$(shell printf '%s\n' $(2) | md5sum | cut -c1-12).ok
$$($(1)_CHECKED): $(3)
	@mkdir -p $$(@D)
	$$(PYTHON) -m mlgshimmy.studies.$(1) check $(2)
	touch $$@
endif

.PHONY: $(1)
$(1): $$($(1)_RESULTS)
	$$(PYTHON) -m mlgshimmy.studies.$(1) summary $(2) $(5)

$(RUN_ROOT)/$(1)/%/result.json: $$($(1)_CHECKED) $(3)
	$$(PYTHON) -m mlgshimmy.studies.$(1) $(4) $$*
endef
