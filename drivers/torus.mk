# Torus points of the large-amplitude orbits (Figs. 7 and 10), checked on
# three meshes and by simulation, and continued in (V, F*) (drivers/torus.py):
# $(MLG_RUN_ROOT)/torus/result.json holds the curves for Fig. 11.
.PHONY: torus
torus: $(AUTO_DRIVER_DEPS) $(MLG_SIMULATE)
	$(PYTHON) drivers/torus.py
