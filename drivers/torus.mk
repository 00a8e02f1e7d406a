# Torus points of the large-amplitude orbits (Figs. 7 and 10), checked on
# three meshes and by simulation, their windows of instability on a fine
# mesh, and continued in (V, F*) (drivers/torus.py): results in
# $(MLG_RUN_ROOT)/torus/result.json (Fig. 11 continues its own torus curve).
.PHONY: torus
torus: $(AUTO_DRIVER_DEPS) $(MLG_SIMULATE)
	$(PYTHON) drivers/torus.py
