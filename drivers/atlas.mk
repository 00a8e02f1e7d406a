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
$(eval $(call job_grid,atlas,$(ATLAS_ARGS),$(MLG_SIMULATE) $(MLG_SHARED) \
    drivers/atlas_cell.py drivers/attractor.py drivers/simulator.py,cell))

TEST_PROGRAMS += tests/test_atlas.py
