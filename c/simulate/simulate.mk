# Time simulator (SUNDIALS CVODE); included by ../../Makefile.  Fig. 8 is
# declared in its module (mlgshimmy.figures.fig08, mk/figures.mk).
SIM_CFLAGS := -std=c11 -O2 -Wall -Wextra -Werror -Ic
SIM_LIBS := -lsundials_cvode -lsundials_nvecserial -lsundials_sunlinsoldense \
            -lsundials_sunmatrixdense -lm
MLG_SIMULATE := build/bin/mlg_simulate

$(MLG_SIMULATE): c/simulate/mlg_simulate.c c/simulate/events.c c/simulate/events.h $(MLG_HEADERS) $(MLG_LIB) | $(PACKAGES_STAMP)
	@mkdir -p $(@D)
	$(CC) $(SIM_CFLAGS) $< c/simulate/events.c $(MLG_LIB) $(SIM_LIBS) -o $@

TEST_DEPS += $(MLG_SIMULATE)
BENCH_PROGRAMS += tests/bench/bench_fig08.py
# The bench script needs the simulator: build it when `make bench` lists it.
tests/bench/bench_fig08.py: $(MLG_SIMULATE)
