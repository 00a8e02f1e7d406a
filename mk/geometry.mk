# The side-stay geometry of every figure and study (shared.geometry); included
# by ../Makefile after mk/python.mk and before mk/figures.mk (which reads
# MLG_RUN_ROOT):
#
#   make fig10 RHO=10 MU=10 [EOM=2]    angles in degrees; EOM: eom_terms, 0, 1 or 2
#   make figures criterion RHO=-10 MU=20
#
# With RHO, MU or EOM given, the drivers get MLG_RHO_DEG, MLG_MU_DEG and MLG_EOM
# (a missing angle is 0; EOM is 2 when an angle is given) and the geometry's
# runs, caches, tables and figures go to their own tree
# $(MLG_BASE_RUN_ROOT)/geometry/<tag>/ (tag e.g. rho10_mu10_eom2; the base is
# MLG_RUN_ROOT or build/), exported as MLG_RUN_ROOT.  RHO=0 MU=0 EOM=0 is the
# paper's gear: the baseline tree itself.  A rejected geometry stops make with
# a message naming the variable.  The studies that take their angles
# explicitly (sidestay, sweep, design-map) run in the base tree.
GEOMETRY_GIVEN := $(strip $(RHO)$(MU)$(EOM))
ifneq ($(GEOMETRY_GIVEN),)
GEOMETRY_BASE := $(abspath $(or $(MLG_BASE_RUN_ROOT),$(MLG_RUN_ROOT),build))
GEOMETRY_VARS := $(shell PYTHONPATH=$(call shell_quote,$(PYTHONPATH)) \
    MLG_RHO_DEG=$(call shell_quote,$(RHO)) MLG_MU_DEG=$(call shell_quote,$(MU)) \
    MLG_EOM=$(call shell_quote,$(EOM)) \
    $(call shell_quote,$(PYTHON)) -m mlgshimmy.shared.geometry make $(call shell_quote,$(GEOMETRY_BASE)) \
    || echo GEOMETRY_REJECTED)
ifneq ($(filter GEOMETRY_REJECTED,$(GEOMETRY_VARS)),)
$(error geometry: RHO=$(RHO) MU=$(MU) EOM=$(EOM) rejected (reason above))
endif
GEOMETRY_TAG := $(word 1,$(GEOMETRY_VARS))
export MLG_RHO_DEG := $(word 3,$(GEOMETRY_VARS))
export MLG_MU_DEG := $(word 4,$(GEOMETRY_VARS))
export MLG_EOM := $(word 5,$(GEOMETRY_VARS))
export MLG_BASE_RUN_ROOT := $(GEOMETRY_BASE)
export MLG_RUN_ROOT := $(word 2,$(GEOMETRY_VARS))
endif
# The run root of the paper's gear, for the studies that choose their angles.
BASE_RUN_ROOT := $(abspath $(or $(MLG_BASE_RUN_ROOT),$(MLG_RUN_ROOT),build))
# A recipe prefix that runs a command at the baseline in the base tree.
AT_BASELINE := MLG_RUN_ROOT=$(call shell_quote,$(BASE_RUN_ROOT)) MLG_RHO_DEG= MLG_MU_DEG= MLG_EOM=
