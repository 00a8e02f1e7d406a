# Freeplay-magnitude figures (sections IV.D-IV.E, Figs. 13-19); included by
# ../Makefile after figures.mk.  Each computes on its own (its runs in
# $(RUN_ROOT)/<fig>/, shared recipes in shared.magnitude), except that Fig. 17
# draws Fig. 16's curves and Fig. 19 Fig. 18's kappa* (from their cached
# results), so `make -j2 fig13 fig14 ...` runs them side by side.  Each prints
# a progress line per AUTO run and its numbers (also in build/tables/<fig>.txt).
MAGNITUDE_FIGURES := fig13 fig14 fig15 fig16 fig17 fig18 fig19
$(eval $(call cached_figure,fig13))
$(eval $(call cached_figure,fig14))
$(eval $(call cached_figure,fig16))
$(eval $(call cached_figure,fig17,$(call result,fig16)))
$(eval $(call cached_figure,fig18))
# Fig. 18 with the printed strut spring (strut variant 1).
$(eval $(call cached_figure,fig18_v1,,fig18,--strut-variant 1))

# Eq. (15) only (fig15: no AUTO), and the profiles of both Fig. 18 readings'
# kappa* (fig19, from their cached results): nothing to cache.
.PHONY: fig15 fig15-plot fig19 fig19-plot
fig15 fig15-plot: $(MLG_SHARED) | packages
	$(PYTHON) -m mlgshimmy.figures.fig15
fig19: $(call result,fig18) $(call result,fig18_v1) $(MLG_SHARED)
	$(PYTHON) -m mlgshimmy.figures.fig19
# The redraw never recomputes Fig. 18, even with its inputs newer.
fig19-plot: | $(MLG_SHARED)
	$(PYTHON) -m mlgshimmy.figures.fig19

FIGURES += $(MAGNITUDE_FIGURES) fig18_v1
# Reference diagrams: fig13 (about 2 min), fig14 (about 5 min), fig16 (about
# 10 min; its set holds the curves Fig. 17 draws, and regress-fig16 also makes
# fig17 from its runs) and fig18 (its AUTO check of a and b in F*; about 13
# min, mostly the eigenvalue scans).
REGRESS_FIGURES += fig13 fig14 fig16 fig18
REGRESS_WITH_fig16 := fig17
