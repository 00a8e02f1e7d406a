# Time simulator (SUNDIALS CVODE) and Fig. 8; included by ../../Makefile.
SIM_CFLAGS := -std=c11 -O2 -Wall -Wextra -Werror -Ic
SIM_LIBS := -lsundials_cvode -lsundials_nvecserial -lsundials_sunlinsoldense \
            -lsundials_sunmatrixdense -lm
MLG_SIMULATE := build/bin/mlg_simulate

$(MLG_SIMULATE): c/simulate/mlg_simulate.c $(MLG_HEADERS) $(MLG_LIB) | $(PACKAGES_STAMP)
	@mkdir -p $(@D)
	$(CC) $(SIM_CFLAGS) $< $(MLG_LIB) $(SIM_LIBS) -o $@

# Fig. 8: 15 s at V = 300 m/s, F* = 0.2, zero freeplay (section IV.A);
# fig08-plot redraws the last simulation (build/fig08/).
.PHONY: fig08 fig08-plot
fig08: $(MLG_SIMULATE)
	$(PYTHON) -m mlgshimmy.figures.fig08
fig08-plot:
	$(PYTHON) -m mlgshimmy.figures.fig08 --plot

FIGURES += fig08
TEST_DEPS += $(MLG_SIMULATE)
BENCH_PROGRAMS += tests/bench/bench_fig08.py
# The bench script needs the simulator: build it when `make bench` lists it.
tests/bench/bench_fig08.py: $(MLG_SIMULATE)
