"""The jobs part of the shared layer: the result cache (cache), a figure's
parts and their stages (parts), grids of independent jobs (grid), the
drivers' command line and job lines (cli), and the one atomic writer
(atomic).  The names most drivers use are here:

    jobs.write(fig, data); jobs.read(fig); jobs.stored(run, columns)
    jobs.run_figure(fig, compute, plot, parts=...); jobs.Needs([...], f)
"""
from mlgshimmy.shared.jobs.atomic import write_atomic, write_json, write_text
from mlgshimmy.shared.jobs.cache import (BadResult, Branch, MissingResult, loaded, path,
                                         provenance, read, stored, write)
from mlgshimmy.shared.jobs.cli import job_line, run_figure, run_variant_figure, variant_option
from mlgshimmy.shared.jobs.parts import Needs, Parts

__all__ = ["BadResult", "Branch", "MissingResult", "Needs", "Parts", "job_line", "loaded", "path",
           "provenance", "read", "run_figure", "run_variant_figure", "stored", "variant_option",
           "write", "write_atomic", "write_json", "write_text"]
