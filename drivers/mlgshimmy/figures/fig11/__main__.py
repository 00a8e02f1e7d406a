"""python3 -m mlgshimmy.figures.fig11: compute (by parts) and plot Fig. 11."""
from mlgshimmy.figures.fig11 import compute, parts
from mlgshimmy.figures.fig11.plot import plot
from mlgshimmy.shared import jobs

jobs.run_figure("fig11", compute, plot, parts)
