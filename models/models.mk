# The AUTO equations executable of the MLG model, linked with the c/ library.
# Drivers run it with e='<repo>/build/models/mlg'.
MLG_MODEL := build/models/mlg
$(eval $(call auto_equations,$(MLG_MODEL),models/mlg.c,$(MLG_LIB),-I$(CURDIR)/c))
