# Regression runs against the reviewed reference diagrams in
# tests/reference/<fig>/ (AUTO b-files); included by ../../Makefile.
#
#   make regress         every figure of REGRESS_FIGURES: run it into
#                        build/regress/<fig>/ and compare with its reference
#   make regress-<fig>   one figure
#   make refs            rerun every figure into build/refs/<fig>/ and replace
#                        the b-files of tests/reference/<fig>/ (deliberately:
#                        review `git diff --stat tests/reference` before committing)
#   make refs-<fig>      one figure
#
# A figure <fig> of REGRESS_FIGURES is a make target whose driver writes its
# runs to $MLG_RUN_ROOT/<fig>/ (drivers/paths.py: rundir; default build/).
# REGRESS_QUICK lists the fast ones that `make test` also compares
# (tests/test_regression_quick.py runs drivers/<fig>.py for each).
# Only the refs recipes write into tests/reference/.
REGRESS_ROOT := build/regress
REFS_ROOT := build/refs
REFERENCE_ROOT := tests/reference
COMPARE := tests/regression/compare_diagrams.py
export REGRESS_QUICK

.PHONY: regress refs
regress: setup
	@if [ -z "$(strip $(REGRESS_FIGURES))" ]; then \
	    echo "regress: no figures are registered (REGRESS_FIGURES is empty)"; exit 1; fi
	@failed=; for fig in $(REGRESS_FIGURES); do \
	    $(MAKE) --no-print-directory regress-$$fig || failed="$$failed $$fig"; \
	done; \
	if [ -n "$$failed" ]; then echo "regress: DIFFERENT or failed:$$failed"; exit 1; fi; \
	echo "regress: $(strip $(REGRESS_FIGURES)) agree with tests/reference/"

regress-%: setup
	rm -rf $(REGRESS_ROOT)/$*
	MLG_RUN_ROOT=$(abspath $(REGRESS_ROOT)) $(MAKE) --no-print-directory $*
	$(PYTHON) $(COMPARE) $(REFERENCE_ROOT)/$* $(REGRESS_ROOT)/$*

refs: setup
	@set -e; for fig in $(REGRESS_FIGURES); do $(MAKE) --no-print-directory refs-$$fig; done

refs-%: setup
	rm -rf $(REFS_ROOT)/$*
	MLG_RUN_ROOT=$(abspath $(REFS_ROOT)) $(MAKE) --no-print-directory $*
	mkdir -p $(REFERENCE_ROOT)/$*
	rm -f $(REFERENCE_ROOT)/$*/b.*
	cp $(REFS_ROOT)/$*/b.* $(REFERENCE_ROOT)/$*/
	@echo "refs: wrote $(REFERENCE_ROOT)/$*/ ($$(cd $(REFERENCE_ROOT)/$* && echo b.*))"

TEST_PROGRAMS += tests/test_compare_diagrams.py tests/test_regression_quick.py
