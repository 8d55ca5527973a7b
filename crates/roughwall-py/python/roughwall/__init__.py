"""roughwall: particles bouncing off anisotropic rough walls, for NumPy.

The physics library of the `rebound` project (Radenkovic & Simonin, Powder Technology 393
(2021) 165–183): the stochastic rough-wall model a particle tracker calls at each wall hit
(`Wall.rebound`, bit for bit the C library's `rw_rebound`), Garcia–Stoll surfaces
(`surface`), measured scans, their wall cards and their own model (`read_scan`, `wall_card`,
`measured_wall_table`), and whole runs
of the stochastic and deterministic models (`stochastic`, `deterministic`). SI units, angles
in degrees where named `_deg`. See docs/python.md.
"""

from ._roughwall import MODELS, VERSION
from ._runs import deterministic, stochastic
from ._surface import Scan, Surface, measured_wall_table, read_scan, surface, wall_card
from ._wall import INVALID_INPUT, NOT_APPROACHING, OK, Rebound, RoughwallWarning, Wall

__version__ = VERSION

__all__ = [
    "INVALID_INPUT",
    "MODELS",
    "NOT_APPROACHING",
    "OK",
    "Rebound",
    "RoughwallWarning",
    "Scan",
    "Surface",
    "Wall",
    "deterministic",
    "measured_wall_table",
    "read_scan",
    "stochastic",
    "surface",
    "wall_card",
]
