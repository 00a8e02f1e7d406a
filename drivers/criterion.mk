# The allowable-freeplay criterion (eq. 17) under each low-load assumption;
# included by ../Makefile after figures.mk.  One job per group of
# assumptions (drivers/criterion.py GROUPS), so `make -j2 criterion` runs
# them side by side; `criterion` prints the table and draws the figure.
CRITERION_DIR := $(or $(MLG_RUN_ROOT),build)/criterion
CRITERION_GROUPS := strut stage c_psi tyre
CRITERION_DEPS := drivers/criterion.py drivers/magnitude.py $(AUTO_DRIVER_DEPS)

$(CRITERION_DIR)/%.json: $(CRITERION_DEPS)
	$(PYTHON) drivers/criterion.py scan $*

# AUTO's check starts from the scan's minimum of each strut variant.
$(CRITERION_DIR)/auto.json: $(CRITERION_DIR)/strut.json $(CRITERION_DEPS)
	$(PYTHON) drivers/criterion.py auto

.PHONY: criterion
criterion: $(CRITERION_GROUPS:%=$(CRITERION_DIR)/%.json) $(CRITERION_DIR)/auto.json
	$(PYTHON) drivers/criterion.py report

FIGURES += criterion
TEST_PROGRAMS += tests/test_criterion.py
