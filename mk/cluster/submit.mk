# Cluster submissions (docs/cluster.md) as make targets; to be included by ../../Makefile
# after the makefiles that define the figures and the grids:
#
#   make submit-<fig> [SCHEDULER=slurm|parallel]   a figure with parts (FIGURES_WITH_PARTS):
#                                                   its parts stage after stage, then
#                                                   `make <fig>` assembles and draws; any
#                                                   other figure or study: one job, `make
#                                                   <target>` (with the RHO, MU, EOM, SET
#                                                   given, and what it declares it carries)
#   make submit-sweep [SWEEP_RHO=... SWEEP_MU=...]  a study with a grid (SUBMIT_GRIDS): a job
#                                                   per point, then its summary (likewise
#                                                   atlas, design-map, robustness)
# Every figure and study has one: the lists come from their declarations
# (mk/figures.mk's catalogue).
#
#   SUBMIT_ARGS     options of the submit command (--per-task 50, --throttle 20,
#                   --jobs 8 for parallel, --env VAR=VALUE, --dry-run)
#   SUBMIT_OPTIONS  options for every sbatch, or for parallel (--time=0:30:00 --mem=1G
#                   --partition=...; --sshloginfile nodes.txt)
#   SUBMIT_ALL=1    every job; by default only those without a valid result (`jobs
#                   --missing`: a grid point without a result of the current provenance,
#                   a part not cached), so that the same command, run again after a
#                   failure, redoes just those (stages left empty are skipped; the
#                   assembly always runs)
#
# Both option lists are split at spaces, each word reaching the submit command (or
# sbatch, parallel) as one argument, quoted; so are the grids' axes. Each target prints
# its submission directory; `status` and `resume` follow from there:
#   PYTHONPATH=drivers $(PYTHON) -m mlgshimmy.shared.cluster status|resume <dir>
# The prerequisites are built here first, on the submitting host: the tasks only run.
SCHEDULER ?= slurm
SUBMIT_ARGS ?=
SUBMIT_OPTIONS ?=
SUBMIT_ALL ?=
ifneq ($(filter submit-%,$(MAKECMDGOALS)),)
ifneq ($(filter-out slurm parallel,$(SCHEDULER))$(filter-out 1,$(words $(SCHEDULER))),)
$(error SCHEDULER=$(SCHEDULER) must be slurm or parallel)
endif
ifneq ($(filter-out 1,$(SUBMIT_ALL)),)
$(error SUBMIT_ALL=$(SUBMIT_ALL): give SUBMIT_ALL=1 (every job) or leave it unset (the missing ones))
endif
endif
submit_words = $(foreach word,$(1),$(call shell_quote,$(word)))
SUBMIT = $(PYTHON) -m mlgshimmy.shared.cluster submit --scheduler $(SCHEDULER) \
    $(if $(SUBMIT_ALL),,--allow-empty) $(call submit_words,$(SUBMIT_ARGS))
SUBMIT_AFTER = -- $(call submit_words,$(SUBMIT_OPTIONS))
SUBMIT_MISSING := $(if $(SUBMIT_ALL),,--missing)
SUBMIT_PREREQUISITES := setup $(MLG_MODEL).exe $(MLG_SHARED) $(MLG_SIMULATE)
# the assembly runs where the task starts (sbatch --export=NONE: no PYTHONPATH there);
# its make runs AUTO with the threads the parts had
SUBMIT_PY = PYTHONPATH=$(call shell_quote,$(CURDIR)/drivers) $(PYTHON)
SUBMIT_MAKE = make --no-print-directory AUTO_THREADS=$(AUTO_THREADS)

# SUBMIT_WHOLE (one job each) and SUBMIT_GRIDS (<target>:<module>:<variable of
# its grid options>) come from the catalogue
SUBMIT_TARGETS := $(addprefix submit-,$(FIGURES_WITH_PARTS) $(SUBMIT_WHOLE) \
    $(foreach grid,$(SUBMIT_GRIDS),$(firstword $(subst :, ,$(grid)))))
.PHONY: $(SUBMIT_TARGETS)
# the figure says how many stages it has (`stages`), so an empty `jobs --missing`
# stage does not end the list
$(addprefix submit-,$(FIGURES_WITH_PARTS)): submit-%: $(SUBMIT_PREREQUISITES)
	set -e; stages=$$($(PYTHON) -m mlgshimmy.figures.$* stages); \
	$(SUBMIT) --name $* --stages "$$stages" \
	    --stages-from $(call shell_quote,$(PYTHON) -m mlgshimmy.figures.$* jobs --stage {k} $(SUBMIT_MISSING)) \
	    --assemble $(call shell_quote,$(SUBMIT_MAKE) $*) $(SUBMIT_AFTER)

# the job carries the gear as mk/gear.mk read it (the task's make may not inherit
# the submitting shell's environment)
SUBMIT_GEAR = $(if $(GEAR_GIVEN),RHO=$(call shell_quote,$(MLG_RHO_DEG)) \
    MU=$(call shell_quote,$(MLG_MU_DEG)) EOM=$(call shell_quote,$(MLG_EOM)) \
    SET=$(call shell_quote,$(GEAR_SET)))
$(addprefix submit-,$(SUBMIT_WHOLE)): submit-%: $(SUBMIT_PREREQUISITES)
	set -eo pipefail; printf '%s\n' $(call shell_quote,$(SUBMIT_MAKE) $* $(SUBMIT_GEAR)$(if \
	    $(SUBMIT_CARRY), $(SUBMIT_CARRY))) | \
	    $(SUBMIT) --name $* --stage - $(SUBMIT_AFTER)

# anything else named submit-*: one line saying what can be submitted
submit-%:
	@set -e; echo "submit-$*: nothing of that name can be submitted; the submit targets are" \
	    "$(SUBMIT_TARGETS) (make help)" >&2; exit 1

SWEEP_GRID_ARGS = --rho=$(call shell_quote,$(SWEEP_RHO)) --mu=$(call shell_quote,$(SWEEP_MU))
# submit-<target>: a job grid (shared.jobs.grid) of the study <module>, its axes in the
# variable <args> (expanded when the recipe runs): its points in one stage, then its summary
define submit_grid
submit-$(1): $$(SUBMIT_PREREQUISITES)
	$$(PYTHON) -m mlgshimmy.studies.$(2) check $$($(3))
	set -eo pipefail; \
	$$(PYTHON) -m mlgshimmy.studies.$(2) jobs $$(SUBMIT_MISSING) $$($(3)) | $$(SUBMIT) \
	    --name $(2) --stage - \
	    --assemble $$(call shell_quote,$$(SUBMIT_PY) -m mlgshimmy.studies.$(2) summary $$($(3))) \
	    $$(SUBMIT_AFTER)
endef
grid_word = $(word $(1),$(subst :, ,$(2)))
$(foreach grid,$(SUBMIT_GRIDS),$(eval $(call submit_grid,$(call grid_word,1,$(grid)),$(call \
    grid_word,2,$(grid)),$(call grid_word,3,$(grid)))))
