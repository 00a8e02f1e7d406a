# Regression runs against the reviewed reference sets in tests/reference/<fig>/
# (AUTO b-files and a MANIFEST); included by ../../Makefile.
#
#   make regress         every figure of REGRESS_FIGURES: run it and compare
#                        with its reference set
#   make regress-<fig>   one figure: its runs go to a private directory
#                        build/regress/.<fig>.XXXXXX/, are compared there and
#                        then published as build/regress/<fig>/ in one rename,
#                        so runs started side by side never share a directory
#   make refs            rerun every figure and replace its reference set
#                        (deliberately: review `git diff --stat tests/reference`)
#   make refs-<fig>      one figure: the new set is written beside the old one,
#                        verified, then swapped in atomically
#                        (tests/regression/reference_set.py); a failed or
#                        interrupted run leaves the old set as it was
#
# A figure <fig> of REGRESS_FIGURES is a make target whose driver writes its
# runs to $MLG_RUN_ROOT/<fig>/ (shared.paths.rundir; default build/).
# REGRESS_QUICK lists the fast ones that `make test` also compares
# (tests/regression/test_regression_quick.py). REGRESS_WITH_<fig> names figures drawn
# from <fig>'s cached result that run no AUTO of their own (fig16: fig17):
# regress-<fig> and refs-<fig> make them too, from the same private runs, so
# a change that breaks them fails there; <fig>'s set holds their curves.
# tests/regression/test_reference_sets.py checks that REGRESS_FIGURES and the sets in
# tests/reference/ name the same figures. A failed figure run keeps its private
# directory (named in the message) for its logs.
# Only the refs recipes write into tests/reference/.
# A changed gear (mk/gear.mk) publishes under its own subtree of build/regress,
# and is compared with the paper's gear's reference: what moved.
REGRESS_ROOT := build/regress$(if $(GEAR_SUBDIR),/$(GEAR_SUBDIR))
# What moved (compare_diagrams.py --what-moved): a changed gear always, and
# WHAT_MOVED=1 for a change made by editing c/ (the named points first, and
# the exit status fails only where a named point could not be followed), with
# the figure $(REGRESS_ROOT)/figures/<fig>_what_moved.png: reference and new.
COMPARE_HOW := $(if $(or $(GEAR_SUBDIR),$(WHAT_MOVED)),--what-moved)
REFS_ROOT := build/refs
REFERENCE_ROOT := tests/reference
COMPARE := tests/regression/compare_diagrams.py
REFERENCE_SET := tests/regression/reference_set.py
WHAT_MOVED_FIGURE := tests/regression/what_moved_figure.py
export REGRESS_QUICK REGRESS_FIGURES

# $(call private_run,<root>,<fig>,$(MAKE),<on failure>): shell code that runs
# figure <fig> with MLG_RUN_ROOT a new directory under <root>, left in
# $scratch (with the figures of REGRESS_WITH_<fig>); if the figure fails, it
# says so and runs the shell code <on failure>.  The caller writes $(MAKE) in
# its recipe line so that make sees a recursive call and passes its jobserver
# on (a $(MAKE) only inside this variable runs the figure's parts at -j1).
# Used after `set -e`: a failed mkdir or mktemp (read-only tree, no inode)
# stops the recipe with its own message; nothing runs with an empty $scratch.
private_run = mkdir -p $(1); scratch=$$(mktemp -d $(abspath $(1))/.$(2).XXXXXX); \
    $(3) --no-print-directory MLG_RUN_ROOT=$$scratch MLG_BASE_RUN_ROOT=$$scratch \
      $(2) $(REGRESS_WITH_$(2)) & $(wait_forwarding) || \
      { echo "$(2): failed; its runs are kept in $$scratch" >&2; $(4); }; \
    trap - TERM INT HUP; runs=$$scratch$(if $(GEAR_SUBDIR),/$(GEAR_SUBDIR))

# Shell code after `<sub-make> &`: wait for it, its exit status; a TERM, INT or
# HUP to the recipe's shell reaches it as TERM.  bash runs no trap while a
# child runs in the foreground and passes it no signal, so an interrupted
# make left the sub-make and its driver running.  (Run in the background,
# the sub-make ignores a terminal's INT: it gets the TERM instead.)
wait_forwarding = child=$$!; \
    trap "kill -TERM $$child 2>/dev/null; wait $$child; exit 143" TERM INT HUP; wait $$child

.PHONY: regress refs
regress: setup
	@set -e; if [ -z "$(strip $(REGRESS_FIGURES))" ]; then \
	    echo "regress: no figures are registered (REGRESS_FIGURES is empty)"; exit 1; fi
	@set -e; failed=; for fig in $(REGRESS_FIGURES); do \
	    $(MAKE) --no-print-directory regress-$$fig & $(wait_forwarding) || failed="$$failed $$fig"; \
	done; trap - TERM INT HUP; \
	if [ -n "$$failed" ]; then echo "regress: DIFFERENT or failed:$$failed"; exit 1; fi; \
	echo "regress: $(strip $(REGRESS_FIGURES)) agree with tests/reference/"

ifneq ($(DRY_RUN),)
# `make -n`: the figure's own dry run (its runs shown in build/regress/.dry-run/)
# and what would follow; nothing is compared, published or replaced.
regress-%: setup
	@$(MAKE) --no-print-directory MLG_RUN_ROOT=$(abspath $(REGRESS_ROOT))/.dry-run $* \
	    $(REGRESS_WITH_$*)
	$(PYTHON) $(COMPARE) $(REFERENCE_ROOT)/$* <private run root>/$*
	$(PYTHON) $(REFERENCE_SET) publish <private run root>/$* $(REGRESS_ROOT)/$*
refs-%: setup
	@$(MAKE) --no-print-directory MLG_RUN_ROOT=$(abspath $(REFS_ROOT))/.dry-run $* \
	    $(REGRESS_WITH_$*)
	$(PYTHON) $(REFERENCE_SET) replace $* <private run root>/$*
else
# A figure that stops (a run that fails its driver's checks) is still compared
# as far as it got, so the table shows how far its finished runs moved.
regress-%: setup
	@set -e; stopped=; $(call private_run,$(REGRESS_ROOT),$*,$(MAKE),stopped=1); \
	if [ -n "$$stopped" ]; then \
	    echo "$*: its runs up to the stop, against $(REFERENCE_ROOT)/$*:"; \
	    $(PYTHON) $(COMPARE) $(REFERENCE_ROOT)/$* $$runs/$* || true; exit 1; fi; \
	status=0; $(PYTHON) $(COMPARE) $(COMPARE_HOW) $(REFERENCE_ROOT)/$* $$runs/$* || status=$$?; \
	$(if $(COMPARE_HOW),$(PYTHON) $(WHAT_MOVED_FIGURE) $(REFERENCE_ROOT)/$* $$runs/$* \
	    $$runs/figures/$*_what_moved.png || status=1;) \
	$(PYTHON) $(REFERENCE_SET) publish $$runs/$* $(REGRESS_ROOT)/$*; \
	mkdir -p $(REGRESS_ROOT)/figures; \
	for f in $$runs/figures/*; do \
	    if [ -e "$$f" ]; then mv -f "$$f" $(REGRESS_ROOT)/figures/; fi; done; \
	rm -rf $$scratch; \
	echo "regress-$*: runs in $(REGRESS_ROOT)/$*/"; exit $$status

refs: setup
	@set -e; for fig in $(REGRESS_FIGURES); do \
	    $(MAKE) --no-print-directory refs-$$fig & $(wait_forwarding); done

refs-%: setup
	$(if $(GEAR_SUBDIR),$(error refs-$*: reference sets are made at the paper's gear: run it without RHO, MU, EOM or SET))
	@set -e; $(call private_run,$(REFS_ROOT),$*,$(MAKE),exit 1); \
	$(PYTHON) $(REFERENCE_SET) replace $* $$scratch/$* || \
	    { echo "refs-$*: $(REFERENCE_ROOT)/$* left as it was; runs in $$scratch" >&2; exit 1; }; \
	rm -rf $$scratch
endif
