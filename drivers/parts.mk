# The parts of one cached figure (drivers/results.py: Parts), run as separate
# make jobs under the caller's jobserver (`make -jN`):
#   $(MAKE) -f drivers/parts.mk FIGURE=fig11 INPUTS="..."
# The driver writes the part list and which parts need others
# (`drivers/<fig>.py rules`: $(RUN_ROOT)/<fig>/parts.mk), so a part that reads
# others starts when they are done.  Each part is rebuilt when one of INPUTS
# (the figure's compute inputs) or a part it needs is newer than it, so an
# interrupted figure resumes with the parts it has.
RUN_ROOT := $(abspath $(or $(MLG_RUN_ROOT),build))
PYTHON ?= /usr/bin/python3
include $(RUN_ROOT)/$(FIGURE)/parts.mk
PART_FILES := $(foreach part,$(PARTS),$(RUN_ROOT)/$(FIGURE)/parts/$(part).json)

# (the included rules come first: without this their first target would be the goal)
.DEFAULT_GOAL := all
.PHONY: all
all: $(PART_FILES)

$(RUN_ROOT)/$(FIGURE)/parts/%.json: $(INPUTS)
	$(PYTHON) drivers/$(FIGURE).py --part $*
