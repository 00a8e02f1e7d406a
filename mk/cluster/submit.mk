# Cluster submissions (docs/cluster.md) as make targets; to be included by ../../Makefile
# after the makefiles that define the figures and the grids:
#
#   make submit-<fig> [SCHEDULER=slurm|parallel]   a staged figure (fig11 fig13 fig14
#                                                   fig16): its parts stage after stage,
#                                                   then `make <fig>` assembles and draws
#   make submit-sweep [SWEEP_RHO=... SWEEP_MU=...]  the side-stay sweep, then its summary
#   make submit-atlas [ATLAS_V=... ATLAS_FSTAR=...] the atlas, then its summary
#
#   SUBMIT_ARGS     options of the submit command (--per-task 50, --throttle 20,
#                   --jobs 8 for parallel, --env VAR=VALUE, --dry-run)
#   SUBMIT_OPTIONS  options for every sbatch, or for parallel (--time=0:30:00 --mem=1G
#                   --partition=...; --sshloginfile nodes.txt)
#
# Each prints its submission directory; `status` and `resume` follow from there:
#   PYTHONPATH=drivers $(PYTHON) -m mlgshimmy.shared.jobs.submit status|resume <dir>
# The prerequisites are built here first, on the submitting host: the tasks only run.
SCHEDULER ?= slurm
SUBMIT_ARGS ?=
SUBMIT_OPTIONS ?=
SUBMIT = PYTHONPATH=drivers $(PYTHON) -m mlgshimmy.shared.jobs.submit submit \
    --scheduler $(SCHEDULER) $(SUBMIT_ARGS)
SUBMIT_PREREQUISITES := setup $(MLG_MODEL).exe $(MLG_SHARED) $(MLG_SIMULATE)

.PHONY: $(addprefix submit-,$(FIGURES_WITH_PARTS)) submit-sweep submit-atlas
$(addprefix submit-,$(FIGURES_WITH_PARTS)): submit-%: $(SUBMIT_PREREQUISITES)
	$(SUBMIT) --name $* --stages-from '$(PYTHON) drivers/$*.py jobs --stage {k}' \
	    --assemble 'make --no-print-directory $*' -- $(SUBMIT_OPTIONS)

submit-sweep: $(SUBMIT_PREREQUISITES)
	$(PYTHON) drivers/sweep.py check --rho=$(SWEEP_RHO) --mu=$(SWEEP_MU)
	$(PYTHON) drivers/sweep.py jobs --rho=$(SWEEP_RHO) --mu=$(SWEEP_MU) | $(SUBMIT) \
	    --name sweep --stage - \
	    --assemble '$(PYTHON) drivers/sweep.py summary --rho=$(SWEEP_RHO) --mu=$(SWEEP_MU)' \
	    -- $(SUBMIT_OPTIONS)

submit-atlas: $(SUBMIT_PREREQUISITES)
	$(PYTHON) drivers/atlas.py check $(ATLAS_ARGS)
	$(PYTHON) drivers/atlas.py jobs $(ATLAS_ARGS) | $(SUBMIT) --name atlas --stage - \
	    --assemble '$(PYTHON) drivers/atlas.py summary $(ATLAS_ARGS)' -- $(SUBMIT_OPTIONS)
