"""wavyadhesion: adhesive contact of a wavy elastic surface against a flat.

Westergaard (no adhesion), JKR (Johnson 1995), double-Westergaard (DW) and
Maugis-Dugdale (MD) models in dimensionless form, computed by the Fortran library
through an f2py extension. Functions take numpy arrays and broadcast.

Loads are P* = mean traction / p*, p* = pi E* Delta / L (negative = tensile); widths
a* = a/L and c* = c/L lie in [0, 1/2]; parameters alpha > 0 (Johnson's) and mu >= 0
(transition parameter). Models are named "westergaard", "jkr", "dw", "md"; "lj" (the
smooth Lennard-Jones model: same work of adhesion, range eps = 2 Dcod Delta, so mu keeps
its meaning and its peak tension is 16/(9 sqrt 3) sigma0) in trace_branch, load_path,
gap_path, critical_forces and profile, with ``n=`` (grid) and ``profile=`` (samples of one period);
its results carry discretisation-error estimates (``P_fc_err``, ...).

Every result converts itself to SI units: ``result.to_si(params)`` with a
``Params.from_dimensional(...)`` gives loads in Pa and N/m, lengths and gaps in m and
energies in J/m^2; ``result.to_dataframe()`` gives a pandas table (pandas is needed only
then). Long sweeps take ``progress=True`` (or a callable ``fn(done, total)``).

Examples
--------
>>> import numpy as np, wavyadhesion as wa
>>> eq = wa.equilibrium("dw", alpha=0.3, mu=1.0, a_star=np.linspace(0.01, 0.49, 5))
>>> eq.zone_case.shape
(5,)
>>> P_fc, P_pf = wa.critical_forces("dw", alpha=0.3, mu=np.logspace(-2, 1, 4))
>>> P_fc.shape
(4,)

Matplotlib helpers that redraw the paper's figures are in ``wavyadhesion.plotting``
(matplotlib is imported only when one of them is called).
"""

from ._map import AdhesionMap, Boundary, SpecialPoint, adhesion_map, boundary_meaning
from ._map import GAP_APPROACH_NAMES, GAP_RETRACTION_NAMES
from ._gapcritical import GAP_CRITICAL_FIELDS, GapCritical, gap_critical
from ._energy import EnergyLost, energy_lost
from ._errors import (ConvergenceError, InvalidArgumentError, InvalidTypeError,
                      NoSolutionError, ResolutionError, WavyAdhesionError)
from ._args import MODELS
from ._equilibrium import Equilibrium, State, equilibrium, jkr_load, roots, westergaard_load
from ._branch import EVENTS, Branch, BranchEvent, trace_branch
from ._loadpath import (MECHANISMS, STAGES, CriticalForces, LoadPath, PathEvent,
                        critical_forces, load_path)
from ._profile import Profile, profile
from ._params import Params, Scales
from ._gap import GAP_EVENTS, GAP_STAGES, GapLaw, GapPath, gap_law, gap_path
from ._results import SIValues
from ._lj import (LJ_EVENTS, LJ_PATH_EVENTS, LJBranch, LJBranchEvent, LJCriticalForces,
                  LJGapPath, LJLoadPath)
from ._model_error import CELL_STATUSES, QUANTITIES, ModelErrorMap, model_error_map

# The version of the installed distribution, which meson-python takes from the file
# VERSION at the repository root (python/meson.build), the one source of the number.
from importlib.metadata import version as _dist_version

__version__ = _dist_version("wavyadhesion")
del _dist_version

__all__ = [
    "CELL_STATUSES",
    "QUANTITIES",
    "ModelErrorMap",
    "model_error_map",
    "LJ_EVENTS",
    "LJ_PATH_EVENTS",
    "LJBranch",
    "LJBranchEvent",
    "LJCriticalForces",
    "LJGapPath",
    "LJLoadPath",
    "GAP_CRITICAL_FIELDS",
    "GapCritical",
    "gap_critical",
    "EnergyLost",
    "energy_lost",
    "AdhesionMap",
    "Boundary",
    "SpecialPoint",
    "adhesion_map",
    "boundary_meaning",
    "GAP_APPROACH_NAMES",
    "GAP_RETRACTION_NAMES",
    "EVENTS",
    "MECHANISMS",
    "MODELS",
    "STAGES",
    "Branch",
    "BranchEvent",
    "CriticalForces",
    "LoadPath",
    "PathEvent",
    "Profile",
    "ConvergenceError",
    "Equilibrium",
    "InvalidArgumentError",
    "InvalidTypeError",
    "NoSolutionError",
    "ResolutionError",
    "Params",
    "Scales",
    "State",
    "WavyAdhesionError",
    "GapLaw",
    "SIValues",
    "critical_forces",
    "equilibrium",
    "gap_law",
    "gap_path",
    "GapPath",
    "GAP_EVENTS",
    "GAP_STAGES",
    "jkr_load",
    "load_path",
    "profile",
    "roots",
    "trace_branch",
    "westergaard_load",
    "__version__",
]
