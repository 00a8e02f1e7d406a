# A grid of independent jobs (drivers/jobgrid.py) as make targets; included
# by ../Makefile before the makefiles that use it.
#
#   $(eval $(call job_grid,<tool>,<grid options>,<inputs>,<job command>))
#
# makes `make [-jN] <tool>`: `drivers/<tool>.py check <grid options>` once per
# grid (a stamp in $(MLG_RUN_ROOT)/<tool>/, default build/), then one make job
# `drivers/<tool>.py <job command> <name>` per $(MLG_RUN_ROOT)/<tool>/<name>/
# result.json that `<tool>.py targets` lists, rebuilt when it is older than
# the check or one of <inputs>, then `<tool>.py summary`.  The grid is read
# only when <tool> is a goal (never for `make clean` or another target); a
# rejected grid stops make with the tool's message, which names the variable.
JOB_GRID_ROOT = $(abspath $(or $(MLG_RUN_ROOT),build))

define job_grid
ifneq ($$(filter $(1),$$(MAKECMDGOALS)),)
$(1)_RESULTS := $$(shell $$(PYTHON) drivers/$(1).py targets $(2) || echo $(1)_GRID_REJECTED)
ifneq ($$(filter $(1)_GRID_REJECTED,$$($(1)_RESULTS)),)
$$(error $(1): the grid $(strip $(2)) is rejected (reason above))
endif
$(1)_CHECKED := $(JOB_GRID_ROOT)/$(1)/grid-$$(shell printf '%s' '$(strip $(2))' | md5sum | cut -c1-12).ok
$$($(1)_CHECKED): $(3)
	@mkdir -p $$(@D)
	$$(PYTHON) drivers/$(1).py check $(2)
	touch $$@
endif

.PHONY: $(1)
$(1): $$($(1)_RESULTS)
	$$(PYTHON) drivers/$(1).py summary $(2)

$(JOB_GRID_ROOT)/$(1)/%/result.json: $$($(1)_CHECKED) $(3)
	$$(PYTHON) drivers/$(1).py $(4) $$*
endef
