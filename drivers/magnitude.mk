Makefile after figures.mk.  Each target is independent (its own runs in$eeplay-magnitude figures (sections IV.D-IV.E, Figs. 13-19); included by
Makefile after figures.mk.  Each target is independent (its own runs in$/Makefile after figures.mk.  Each target is independent (its own runs in
Makefile after figures.mk.  Each target is independent (its own runs in$ild/<fig>/, shared code in drivers/magnitude.py), so `make -j2 fig13
Makefile after figures.mk.  Each target is independent (its own runs in$g14 ...` runs them side by side; each prints a progress line per run and
Makefile after figures.mk.  Each target is independent (its own runs in$s numbers (also in build/figures/<fig>.txt).
MAGNITUDE_FIGURES := fig13 fig14 fig15 fig16 fig17 fig18 fig19 bistable_v50
.PHONY: $(MAGNITUDE_FIGURES)
$(MAGNITUDE_FIGURES): %: $(AUTO_DRIVER_DEPS)
	$(PYTHON) drivers/$*.py

Makefile after figures.mk.  Each target is independent (its own runs in$g. 19 draws the kappa* that Fig. 18 computes (build/figures/fig18.json).
fig19: fig18

FIGURES += $(MAGNITUDE_FIGURES)
TEST_PROGRAMS += tests/test_magnitude.py
