# The gear every figure and study is made for (shared.gear): the paper's,
# changed by a side-stay geometry and by an overlay of any constant or
# parameter; included by ../Makefile after mk/python.mk and before
# mk/figures.mk (which reads MLG_RUN_ROOT):
#
#   make fig10 RHO=10 MU=10 [EOM=2]        angles in degrees; EOM: eom_terms, 0, 1 or 2
#   make fig10 SET='k_tlk=3.51e7 I_psi=160' any constant or parameter by its name in
#                                           c/mlg_parameters.h, in its units there
#   make fig10 FREEPLAY=tanh               a freeplay law of c/freeplay_laws.h by its name:
#                                           the overlay entry freeplay_law=tanh
#   make regress-fig10 SET='k_tlk=3.51e7'  what moved, against the paper's gear's reference
#
# With any of them given, the drivers get MLG_RHO_DEG, MLG_MU_DEG, MLG_EOM and
# MLG_SET, and the gear's runs, caches, tables and figures go to its own tree
# under the base run root (MLG_RUN_ROOT or build/): geometry/<tag>/ for a
# geometry alone, gear/<tag>/ with an overlay (GEAR_SUBDIR), exported as
# MLG_RUN_ROOT.  A MLG_RUN_ROOT given on the command line is that base, never
# the gear's tree itself, so two gears never share a tree.  RHO=0 MU=0 EOM=0
# with no SET is the paper's gear: the baseline tree itself.  A rejected gear
# stops make with a message naming the variable.  The studies that take their
# angles explicitly (sidestay, design-map) run in the base tree and take no
# SET yet (AT_BASELINE refuses it).
GEAR_SET := $(strip $(SET) $(if $(strip $(FREEPLAY)),freeplay_law=$(strip $(FREEPLAY))))
GEAR_GIVEN := $(strip $(RHO)$(MU)$(EOM)$(GEAR_SET))
GEAR_BASE := $(abspath $(or $(MLG_BASE_RUN_ROOT),$(MLG_RUN_ROOT),build))
GEAR_SUBDIR :=
ifneq ($(GEAR_GIVEN),)
GEAR_VARS := $(shell PYTHONPATH=$(call shell_quote,$(PYTHONPATH)) \
    MLG_RHO_DEG=$(call shell_quote,$(RHO)) MLG_MU_DEG=$(call shell_quote,$(MU)) \
    MLG_EOM=$(call shell_quote,$(EOM)) MLG_SET=$(call shell_quote,$(GEAR_SET)) \
    $(call shell_quote,$(PYTHON)) -m mlgshimmy.shared.gear make $(call shell_quote,$(GEAR_BASE)) \
    || echo GEAR_REJECTED)
ifneq ($(filter GEAR_REJECTED,$(GEAR_VARS)),)
$(error gear: RHO=$(RHO) MU=$(MU) EOM=$(EOM) SET='$(GEAR_SET)' rejected (reason above))
endif
GEAR_TAG := $(word 1,$(GEAR_VARS))
export MLG_RHO_DEG := $(word 3,$(GEAR_VARS))
export MLG_MU_DEG := $(word 4,$(GEAR_VARS))
export MLG_EOM := $(word 5,$(GEAR_VARS))
export MLG_SET := $(GEAR_SET)
export MLG_BASE_RUN_ROOT := $(GEAR_BASE)
override export MLG_RUN_ROOT := $(word 2,$(GEAR_VARS))
GEAR_SUBDIR := $(patsubst $(GEAR_BASE)/%,%,$(filter $(GEAR_BASE)/%,$(MLG_RUN_ROOT)))
endif
# The run root of the paper's gear, for the studies that choose their angles.
BASE_RUN_ROOT := $(GEAR_BASE)
# A recipe prefix that runs a command at the baseline in the base tree.
AT_BASELINE = $(if $(strip $(GEAR_SET)),$(error $@ takes no SET yet (nor FREEPLAY): it sets its own gear; run it without them))MLG_RUN_ROOT=$(call shell_quote,$(BASE_RUN_ROOT)) MLG_RHO_DEG= MLG_MU_DEG= MLG_EOM= MLG_SET=
