"""The (V, F*) plane of Fig. 11: its ranges, the freeplay, the slice loads
and the grids the region map is painted on."""
import numpy

from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import freeplay
from mlgshimmy.shared import geometry

F_MIN, F_MAX = 0.02, 3.5
V_MIN, V_MAX = ct.V_MIN, ct.V_MAX
FREEPLAY = freeplay.NOMINAL
# the side-stay geometry ({} at the paper's, shared.geometry) and every
# parameter the figure's models have besides V and F*
GEOMETRY = geometry.parameters()
MODEL = {**FREEPLAY, **GEOMETRY}
# loads of the diagrams in V: denser where the low-load structure is
SLICES = numpy.concatenate((numpy.arange(0.0625, 2.0, 0.125), numpy.arange(2.125, 3.5, 0.25)))
F_GRID = numpy.arange(F_MIN, F_MAX + 1e-9, 0.01)
V_GRID = numpy.arange(V_MIN, V_MAX + 1e-9, 0.5)
STOP = {"Fstar": [F_MIN, F_MAX], "V": [V_MIN, V_MAX]}
V_SCAN = ct.SPEED_SCAN
