# Freeplay-magnitude figures (sections IV.D-IV.E, Figs. 13-19); included by
# ../Makefile after figures.mk.  Each target runs on its own (its runs in
# build/<fig>/, shared code in drivers/magnitude.py; only fig19 needs fig18),
# so `make -j2 fig13 fig14 ...` runs them side by side.  Each prints a
# progress line per AUTO run and its numbers (also in build/tables/<fig>.txt).
MAGNITUDE_FIGURES := fig13 fig14 fig15 fig16 fig17 fig18 fig19
.PHONY: $(MAGNITUDE_FIGURES)
$(MAGNITUDE_FIGURES): %: $(AUTO_DRIVER_DEPS)
	$(PYTHON) drivers/$*.py

# Fig. 18 with the printed strut spring (strut variant 1).
.PHONY: fig18_v1
fig18_v1: $(AUTO_DRIVER_DEPS)
	$(PYTHON) drivers/fig18.py --strut-variant 1

# Fig. 19 draws the kappa* that Fig. 18 computes for both strut variants
# (build/figures/fig18.json, fig18_v1.json).
fig19: fig18 fig18_v1

FIGURES += $(MAGNITUDE_FIGURES) fig18_v1
TEST_PROGRAMS += tests/test_magnitude.py
# Cheap, stable AUTO runs (about 2 min each) with reference diagrams.
REGRESS_FIGURES += fig13 fig17
