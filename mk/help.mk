# make help (the default goal): every target with one line and a typical
# time, measured on a built tree (AUTO and the library built) on one core of
# this project's 2-core machine; -j2 where it helps. Included by ../Makefile.
# The figures' and studies' lines come from their declarations (DECLARED,
# mk/figures.mk's catalogue); tests/jobs/test_help.py checks that every figure
# and regression target of the makefiles is listed and every listed target
# exists.
define MLG_HELP
mlg-shimmy $(MLG_VERSION): AUTO-07p plugins for main landing gear shimmy.
Usage: make <target> [VAR=value ...]    (typical times: a built tree, one core unless -j2)

Start here
  fig07                      10 s  Fig. 7: Hopf point and shimmy orbits at F* = 0.2 and 1
                        + 1-2 min  the first make also installs packages, builds AUTO-07p
  figures                  17 min  every figure into build/figures/ (PNG, PDF); -j2: 8 min
  test                      3 min  build and run all tests (C, Python, AUTO, quick regressions)
  report                     10 s  build/report/index.html: every figure beside the paper's numbers
  demo                       10 s  build/demo/ for AUTO's own commands: auto mlg.auto, @r mlg
  gear RHO=20 MU=5 [SET=]  30 min  "my gear": every figure, kappa* by freeplay law, design answers
                                   beside the paper's gear, motion; one page (-j2;
                                   GEAR_FIGURES=answers: 5 min; GEAR_STUDIES='laws atlas')
  fig11-motion              3 min  the gear's motion animated in each kind of region of Fig. 11
  venv VENV=v                 5 s  a Python virtual environment importing mlgshimmy (notebooks)
  help                        1 s  this list (also plain make)

Figures: build/figures/<fig>.png, .pdf; make <fig>-plot redraws from the cache
$(HELP_FIGURES)

Studies
$(HELP_STUDIES)

Regression and benchmarks
  regress                  20 min  every figure with a reference set, compared with it; -j2: 10 min
  regress-<fig>               5 s  one of them (regress-fig07; regress-fig11: 11 min)
  fig10_rho10_mu10           50 s  Fig. 10 at rho = mu = 10 deg, EOM 2, for its reference set
  fig12_rho10_mu10           20 s  Fig. 12 at rho = mu = 10 deg, EOM 2, for its reference set
  fig10_fric5               3 min  Fig. 10 with seal friction M_fric = 5 N m, for its reference set
  refs, refs-<fig>                 regenerate reference sets, deliberately (as regress)
  bench                      15 s  the benchmark programs
  bench-figures            70 min  make -j1 figures against -j2; Fig. 11 and a design-map
                                   point at RHO=15 MU=-5 against the paper's gear
  bench-gear               45 min  only those last rows
  profile-<fig>               1 s  what each cached part of a figure cost, most CPU first

Cluster (docs/cluster.md): SCHEDULER=slurm|parallel, SUBMIT_ARGS, SUBMIT_OPTIONS
  submit-<fig>                1 s  a figure: $(FIGURES_WITH_PARTS) part by part, others as one job
$(HELP_SUBMIT)

C library and AUTO-07p (docs/c-library.md, docs/auto-workflow.md)
  build/lib/libmlg.so        15 s  the model library (and build/lib/libmlg.a)
  install                    15 s  headers, libraries, mlg.pc into $(DESTDIR)$(PREFIX)
  uninstall                   1 s  remove what install wrote
  build/examples/evaluate     1 s  the example: f and its Jacobian at straight rolling
  setup                     2 min  Debian packages and AUTO-07p (built once, or AUTO_DIR)
  auto                        1 s  check and print which AUTO-07p is used
  forget-auto                 1 s  drop the remembered AUTO_DIR (back to the source build)
  clean                       1 s  remove build/ but the chosen AUTO (build/auto-dir)
  distclean                   1 s  remove build/ entirely

Settings: AUTO_DIR=<dir> (an AUTO-07p tree or install, e.g. /usr/lib/auto-07p;
remembered), AUTO_SRC=<tarball>, AUTO_THREADS (1), PYTHON (/usr/bin/python3),
TEST_TIMEOUT (600 s), PREFIX, DESTDIR, DEMO_DIR (build/demo), MLG_RUN_ROOT,
PAPER=1 (figures without their "Fig. N:" titles, for a paper).
Side-stay geometry of any figure or study: RHO=<deg> MU=<deg> [EOM=0|1|2, default 2],
e.g. make fig10 RHO=10 MU=10; its runs, tables and figures in build/geometry/<tag>/.
endef
export MLG_HELP

.PHONY: help
help:
	@printf '%s\n' "$$MLG_HELP"
