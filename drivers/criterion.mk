# The allowable-freeplay criterion (eq. 17) under each low-load assumption;
# included by ../Makefile after figures.mk.  One job per group of
# assumptions (drivers/criterion.py GROUPS), so `make -j2 criterion` runs
# them side by side; `criterion` prints the table and draws the figure.
# Results are recomputed when the driver, magnitude.py or an input of the
# cached figures (COMPUTE_INPUTS of figures.mk: shared layer, constants,
# model) is newer.  They are parts of the result cache (drivers/results.py).
CRITERION_DIR := $(RUN_ROOT)/criterion/parts
CRITERION_GROUPS := strut stage c_psi tyre
CRITERION_DEPS := drivers/criterion.py drivers/magnitude.py $(COMPUTE_INPUTS) | auto

$(CRITERION_DIR)/%.json: $(CRITERION_DEPS)
	$(PYTHON) drivers/criterion.py scan $*

# AUTO's check starts from the scan's minimum of each strut variant.
$(CRITERION_DIR)/auto.json: $(CRITERION_DIR)/strut.json $(CRITERION_DEPS)
	$(PYTHON) drivers/criterion.py auto

.PHONY: criterion criterion-plot
criterion: $(CRITERION_GROUPS:%=$(CRITERION_DIR)/%.json) $(CRITERION_DIR)/auto.json
	$(PYTHON) drivers/criterion.py report
# The table and figure from the cached parts alone (no rescan).
criterion-plot:
	$(PYTHON) drivers/criterion.py report

FIGURES += criterion
TEST_PROGRAMS += tests/test_criterion.py
