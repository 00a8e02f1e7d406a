"""mlgshimmy: the Python drivers of mlg-shimmy, in three rooms.

  shared   the shared layer: AUTO recipes, spectra, the model, jobs, drawing
  figures  one module (or package) per figure of the paper
  studies  the studies beyond the paper's figures

and, beside them, report (make report: one page from what they cached).

Figures and studies import the shared layer, never each other; the shared
layer imports neither (tests/jobs/test_rooms.py).  drivers/README.md has the map.
"""
__version__ = "0.1.0"   # as c/mlg_version.h (tests/release/test_release_files.py)
