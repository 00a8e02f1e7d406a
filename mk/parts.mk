# The parts of one cached figure (shared.jobs.parts), run as separate make
# jobs under the caller's jobserver (`make -jN`):
#   $(MAKE) -f mk/parts.mk FIGURE=fig11 INPUTS="..."
# The driver writes the part list and which parts need others
# (`python3 -m mlgshimmy.figures.<fig> rules`: $(RUN_ROOT)/<fig>/parts.mk), so
# a part that reads others starts when they are done.  Each part is rebuilt
# when one of INPUTS (the figure's compute inputs) or a part it needs is
# newer than it, so an interrupted figure resumes with the parts it has.
RUN_ROOT := $(abspath $(or $(MLG_RUN_ROOT),build))
PYTHON ?= /usr/bin/python3
include $(RUN_ROOT)/$(FIGURE)/parts.mk
PART_FILES := $(foreach part,$(PARTS),$(RUN_ROOT)/$(FIGURE)/parts/$(part).json)

# (the included rules come first: without this their first target would be the goal)
.DEFAULT_GOAL := all
.PHONY: all
.DELETE_ON_ERROR:
all: $(PART_FILES)

# the inputs are made by the calling make (nothing to do here, even in a dry run)
$(filter-out $(PART_FILES),$(INPUTS)):

$(RUN_ROOT)/$(FIGURE)/parts/%.json: $(INPUTS)
	$(PYTHON) -m mlgshimmy.figures.$(FIGURE) --part $*
