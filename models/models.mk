# The AUTO equations executable of the MLG model, linked with the c/ library.
# Drivers run it with e='<repo>/build/models/mlg'.
MLG_MODEL := build/models/mlg
MODEL_INCLUDES := -I$(CURDIR)/c -I$(CURDIR)/models
$(eval $(call auto_equations,$(MLG_MODEL),models/mlg.c,$(MLG_LIB),$(MODEL_INCLUDES)))
# The periodic orbits of eq. (14) as segments (models/mlg_segmented.c)
MLG_SEGMENTED := build/models/mlg_segmented
$(eval $(call auto_equations,$(MLG_SEGMENTED),models/mlg_segmented.c,$(MLG_LIB),$(MODEL_INCLUDES)))

# The AUTO constants every run of the model starts from: constants/c.mlg and
# the names of the states and PAR slots, printed from the library's tables
# (models/auto_names.c), so that a new parameter is named in one place.
# Built before either executable (order-only: the names do not change them).
MLG_AUTO_CONSTANTS := build/models/c.mlg
MLG_AUTO_NAMES := build/bin/mlg_auto_names
$(MLG_AUTO_NAMES): models/auto_names.c $(MLG_HEADERS) $(MLG_LIB)
	@mkdir -p $(@D)
	$(CC) $(MLG_CFLAGS) $< $(MLG_LIB) -lm -o $@
$(MLG_AUTO_CONSTANTS): constants/c.mlg $(MLG_AUTO_NAMES)
	@mkdir -p $(@D)
	set -e; { cat $<; $(MLG_AUTO_NAMES); } > $@.tmp; mv $@.tmp $@
$(MLG_MODEL).exe $(MLG_SEGMENTED).exe: | $(MLG_AUTO_CONSTANTS)

# make demo [DEMO_DIR=build/demo]: a run directory for AUTO's own workflow,
# as in AUTO's demos: `auto mlg.auto`, `@r mlg`, `@sv mlg` (docs/auto-workflow.md).
# AUTO's run() and @r compile <e>.c and link <e>.o with AUTO's commands only,
# which know neither c/'s headers nor the library. So make builds them here:
# mlg.c (models/mlg.c), then mlg.o = the model compiled with AUTO's flags
# and partially linked (ld -r) with the whole library, then mlg.exe with
# AUTO's link line; run() and @r then find both up to date and use them.
# Should they relink (an AUTO newer than mlg.exe, mlg.exe deleted), their
# own link line works, since mlg.o holds the library. Rerun make demo after
# AUTO's cl() / @cl (they delete *.o, *.exe).
#
# @r (cmds.make) recompiles an edited mlg.c with AUTO's flags alone, which fails
# on c/'s headers, and (cmds.make has .IGNORE) then ran the old mlg.exe. So
# auto.env sets MAKEFILES to mlg.mk, which gives cmds.make's make in this
# directory a rule for mlg.o: this make's, with the library; cmds.make then
# links mlg.exe with its own line. If the build fails the rule removes mlg.o
# and mlg.exe, so that nothing old runs. (AUTO's Python run() compiles without
# make: it stops at the compiler's error itself.)
DEMO_DIR ?= build/demo
DEMO := $(patsubst %/,%,$(DEMO_DIR))
DEMO_FILES := $(addprefix $(DEMO)/,mlg.c mlg.o mlg.exe c.mlg mlg.auto mlg.mk auto.env)
DEMO_ABS := $(abspath $(DEMO))

$(DEMO)/mlg.c: models/mlg.c
$(DEMO)/c.mlg: $(MLG_AUTO_CONSTANTS)
$(DEMO)/mlg.auto: models/mlg.auto
$(DEMO)/mlg.c $(DEMO)/c.mlg $(DEMO)/mlg.auto:
	@mkdir -p $(@D)
	cp $< $@

$(DEMO)/.obj/mlg.o: $(DEMO)/mlg.c $(AUTO_USED) | auto
	@mkdir -p $(@D)
	$(AUTO_CC) $(call AUTO_C_ONLY,$(AUTO_CFLAGS) $(AUTO_OPT)) $(MODEL_INCLUDES) -MMD -MP -c $< -o $@
-include $(DEMO)/.obj/mlg.d

$(DEMO)/mlg.o: $(DEMO)/.obj/mlg.o $(MLG_OBJECTS)
	ld -r -o $@ $^

$(DEMO)/mlg.exe: $(DEMO)/mlg.o $(wildcard $(AUTO_DIR)/lib/*.o) $(AUTO_QUIET_FPE) $(AUTO_USED) | auto
	$(AUTO_FC) -L$(AUTO_DIR)/lib $(AUTO_FFLAGS) $(AUTO_OPT) $< -o $@ \
	    $(AUTO_DIR)/lib/*.o -lauto_c $(AUTO_QUIET_LDFLAGS)

$(DEMO)/mlg.mk: models/models.mk
	@mkdir -p $(@D)
	@printf '%s\n' \
	    "# Read by every GNU make of a shell that sourced auto.env (MAKEFILES); it acts" \
	    "# only in AUTO's cmds.make for mlg here (@r mlg). Written by make demo (models/models.mk)." \
	    "# MAKEFLAGS: not cmds.make's -i (.IGNORE), which would hide a failed build." \
	    "ifeq (\$$(CURDIR) \$$(EQUATION_NAME),$(DEMO_ABS) mlg)" \
	    "mlg.o: mlg.c" \
	    "	@MAKEFILES= MAKEFLAGS= MFLAGS= \$$(MAKE) --no-print-directory -C $(CURDIR) AUTO_DIR=$(AUTO_DIR) DEMO_DIR=$(DEMO_ABS) $(DEMO_ABS)/mlg.o || \\" \
	    "	{ rm -f mlg.o mlg.exe; echo \"@r mlg: mlg.c does not build with the model library (above): mlg.o and mlg.exe removed, so that no old executable runs; fix mlg.c and run it again\" >&2; exit 1; }" \
	    "endif" > $@

# auto.env: AUTO_DIR and PATH for AUTO's commands, as AUTO's own
# cmds/auto.env.sh sets them, plus .bin/ with `auto` (AUTO's launcher, or
# Debian's auto-07p) and the `python`/`python3` it runs: $(PYTHON), which
# has numpy. OMP_NUM_THREADS as the drivers' (AUTO_THREADS): results depend on it.
$(DEMO)/auto.env: $(AUTO_USED) models/models.mk | auto
	@mkdir -p $(@D)/.bin
	@set -e; launcher=$(AUTO_DIR)/bin/auto; [ -x "$$launcher" ] || launcher=$$(command -v auto-07p) || \
	    { echo "demo: no AUTO launcher ($(AUTO_DIR)/bin/auto or auto-07p)" >&2; exit 1; }; \
	python=$$(command -v $(PYTHON)) || { echo "demo: no $(PYTHON)" >&2; exit 1; }; \
	ln -sfn "$$launcher" $(@D)/.bin/auto && ln -sfn "$$python" $(@D)/.bin/python && \
	ln -sfn "$$python" $(@D)/.bin/python3
	@printf '%s\n' \
	    "# Source in this directory (. ./auto.env) for AUTO-07p's commands, as after" \
	    "# AUTO's own cmds/auto.env.sh: auto (AUTO's CLUI), @r, @sv, @cl, ... of the" \
	    "# AUTO-07p make used. Written by make demo (models/models.mk)." \
	    "AUTO_DIR=$(AUTO_DIR)" \
	    "PATH=$(abspath $(DEMO))/.bin:\$$AUTO_DIR/cmds:\$$PATH" \
	    "OMP_NUM_THREADS=$(AUTO_THREADS)   # one thread, as the drivers: results depend on it" \
	    "MAKEFILES=$(DEMO_ABS)/mlg.mk   # @r mlg rebuilds an edited mlg.c with the library" \
	    "export AUTO_DIR PATH OMP_NUM_THREADS MAKEFILES" > $@
	@echo "demo: wrote $@ (AUTO_DIR=$(AUTO_DIR))"

.PHONY: demo
demo: $(DEMO_FILES)
	@echo "demo: $(DEMO)/ is an AUTO-07p run directory for the MLG model. In it:"
	@echo "    cd $(DEMO) && . ./auto.env"
	@echo "    auto mlg.auto          # Fig. 7 at F* = 1: Hopf point at V = 346.1 m/s, orbits (about 2 s)"
	@echo "    @r mlg && @sv mlg      # straight rolling from the STPNT with c.mlg, saved as b.mlg, s.mlg, d.mlg"
