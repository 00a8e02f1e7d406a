# The parts of one cached figure (drivers/results.py: Parts), run as separate
# make jobs under the caller's jobserver (`make -jN`):
#   $(MAKE) -f drivers/parts.mk FIGURE=fig11 PARTS="curves slice_0.0625 ..." INPUTS="..."
# Each part is rebuilt when one of INPUTS (the figure's compute inputs) is
# newer than it, so an interrupted figure resumes with the parts it has.
RUN_ROOT := $(abspath $(or $(MLG_RUN_ROOT),build))
PYTHON ?= /usr/bin/python3
PART_FILES := $(foreach part,$(PARTS),$(RUN_ROOT)/$(FIGURE)/parts/$(part).json)

.PHONY: all
all: $(PART_FILES)

$(RUN_ROOT)/$(FIGURE)/parts/%.json: $(INPUTS)
	$(PYTHON) drivers/$(FIGURE).py --part $*
