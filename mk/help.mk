# make help (the default goal): every target with one line and a typical
# time, measured on a built tree (AUTO and the library built) on one core of
# this project's 2-core machine; -j2 where it helps. Included by ../Makefile.
# tests/test_help.py checks that every figure and regression target of the
# makefiles is listed here and every listed target exists.
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
  help                        1 s  this list (also plain make)

Figures: build/figures/<fig>.png, .pdf; make <fig>-plot redraws from the cache
  fig06                       5 s  Fig. 6: torque-link force profiles, eqs. (14), (15)
  fig07                      10 s  Fig. 7: zero freeplay, diagrams in V at F* = 0.2, 1
  fig08                       5 s  Fig. 8: time simulation, V = 300 m/s, F* = 0.2 (CVODE)
  fig09                       5 s  Fig. 9: zero-freeplay Hopf curve in (V, F*)
  fig10                      40 s  Fig. 10: y_fp = 1 mm, F* = 1: three Hopf points, orbits, fold
  fig11                    11 min  Fig. 11: (V, F*) plane with freeplay, lift-off edge; -j2: 6 min
  fig12                      20 s  Fig. 12: V = 50 m/s: pitchforks, yawed states, orbits in F*
  fig12_v1                   20 s  Fig. 12 with the printed strut stage order
  fig13                     1 min  Fig. 13: eps = 0.1 y_fp, y_fp = 0.2-2 mm
  fig14                   1.5 min  Fig. 14: eps = 0.1 mm, y_fp = 0.05-1 mm, Hopf curves
  fig15                       5 s  Fig. 15: the profiles of Figs. 13 and 14 rescaled
  fig16                    10 min  Fig. 16: orbit surfaces over (V, y_fp), both scalings
  fig17                     + 5 s  Fig. 17: Fig. 16's curves in (V, y_fp/eps), after fig16
  fig18                      70 s  Fig. 18: a, b, c continued in F*, kappa*
  fig18_v1                   70 s  Fig. 18 with the printed strut stage order
  fig19                     + 5 s  Fig. 19: profiles allowed by kappa*, after fig18, fig18_v1

Studies
  criterion                 3 min  eq. (17): kappa* under each low-load assumption (use -j2)
  calibrate                   2 s  the c_psi of the `figures` parameter set
  sidestay RHO=10 MU=10      30 s  side-stay angles [deg] against rho = mu = 0 (EOM=0|1|2)
  sweep                      20 s  critical speed over a (rho, mu) grid (SWEEP_RHO, SWEEP_MU: 3 x 3)
  floquet RUN=<dir>/<run>    2 s  Floquet multipliers along one orbit run, torus/PD/fold crossings
  robustness              45 min  each parameter x0.8-1.2: what moves, and does every figure complete (-j2)
  design-map                5 min  H1-H3, S, allowed freeplay, y_tlk over (rho, mu) (5 x 5; -j2; RHO, MU marked)
  atlas                    17 min  attractor atlas by simulation over (V, F*); -j2: 9 min
  torus                   > 7 min  torus points of Figs. 7 and 10: meshes, windows, curves

Regression and benchmarks
  regress                  20 min  every figure with a reference set, compared with it; -j2: 10 min
  regress-<fig>               5 s  one of them (regress-fig07; regress-fig11: 11 min)
  fig10_rho10_mu10           50 s  Fig. 10 at rho = mu = 10 deg, EOM 2, for its reference set
  fig12_rho10_mu10           20 s  Fig. 12 at rho = mu = 10 deg, EOM 2, for its reference set
  refs, refs-<fig>                 regenerate reference sets, deliberately (as regress)
  bench                      15 s  the benchmark programs
  bench-figures            70 min  make -j1 figures against -j2; Fig. 11 and a design-map
                                   point at RHO=15 MU=-5 against the paper's gear
  bench-gear               45 min  only those last rows

Cluster (docs/cluster.md): SCHEDULER=slurm|parallel, SUBMIT_ARGS, SUBMIT_OPTIONS
  submit-<fig>                1 s  a figure: fig11, fig13, fig14, fig16 part by part, others as one job
  submit-sweep, submit-atlas  1 s  a study's grid, a job per point, then its summary
  submit-design-map, submit-robustness  1 s  the same for these grids

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
