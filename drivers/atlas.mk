# Attractor atlas over (V, F*) by time simulation (drivers/atlas.py); axes
# "a,b,c" or "start:stop:step", one job per cell:
#   make -j2 atlas                       the default grid (atlas.py DEFAULT_*)
#   make -j2 atlas ATLAS_GRID=coarse     8 x 5 cells of the default grid
#   make -j2 atlas ATLAS_V=100:600:100 ATLAS_FSTAR=0.5,1
# Results in $(MLG_RUN_ROOT)/atlas/ (default build/), plot build/figures/atlas.png.
ifeq ($(ATLAS_GRID),coarse)
ATLAS_V ?= 10,30,50,100,200,300,450,600
ATLAS_FSTAR ?= 0.2,0.5,1,1.8,3
else ifneq ($(ATLAS_GRID),)
$(error ATLAS_GRID=$(ATLAS_GRID): the only named grid is coarse)
endif
ATLAS_ARGS := $(if $(ATLAS_V),--V=$(ATLAS_V)) $(if $(ATLAS_FSTAR),--Fstar=$(ATLAS_FSTAR))
# The grid is read only when `atlas` is a goal; a rejected grid stops make
# with atlas.py's message, which names ATLAS_V or ATLAS_FSTAR.
ifneq ($(filter atlas,$(MAKECMDGOALS)),)
ATLAS_RESULTS := $(shell $(PYTHON) drivers/atlas.py targets $(ATLAS_ARGS) || echo ATLAS_GRID_REJECTED)
ifneq ($(filter ATLAS_GRID_REJECTED,$(ATLAS_RESULTS)),)
$(error atlas: ATLAS_V=$(ATLAS_V) ATLAS_FSTAR=$(ATLAS_FSTAR) rejected (reason above))
endif
endif
ATLAS_ROOT := $(abspath $(or $(MLG_RUN_ROOT),build))/atlas
ATLAS_CHECKED := $(ATLAS_ROOT)/grid-$(shell printf '%s' '$(ATLAS_ARGS)' | md5sum | cut -c1-12).ok
ATLAS_DEPS := $(MLG_SIMULATE) drivers/atlas_cell.py drivers/attractor.py drivers/simulator.py

.PHONY: atlas
atlas: $(ATLAS_RESULTS)
	$(PYTHON) drivers/atlas.py summary $(ATLAS_ARGS)

$(ATLAS_CHECKED): $(ATLAS_DEPS)
	@mkdir -p $(@D)
	$(PYTHON) drivers/atlas.py check $(ATLAS_ARGS)
	touch $@

$(ATLAS_ROOT)/%/result.json: $(ATLAS_CHECKED) $(ATLAS_DEPS)
	$(PYTHON) drivers/atlas.py cell $*

TEST_PROGRAMS += tests/test_atlas.py
