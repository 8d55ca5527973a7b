# Type stubs of the package roughwall (the docstrings, with units and frames, are in the
# modules themselves and in docs/python.md).
import os
from typing import NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str
VERSION: str
#: The rough-wall models a Wall takes (`model=`), as a case file's `[stochastic] model`.
MODELS: list[str]
#: Rebound.status: a rebound was computed.
OK: int
#: Rebound.status: the particle does not move across the wall; returned unchanged.
NOT_APPROACHING: int
#: Rebound.status: NaN or infinity, zero normal, lay along the normal, negative diameter.
INVALID_INPUT: int

Vec3 = npt.ArrayLike  # (3,) or (n, 3), float64 read in place
PerHit = npt.ArrayLike  # a number or (n,)

class RoughwallWarning(UserWarning): ...

class Rebound(NamedTuple):
    velocity: np.ndarray  # (n, 3) m/s, global axes, wall velocity added back
    spin: np.ndarray  # (n, 3) rad/s
    status: np.ndarray  # (n,) int32: OK, NOT_APPROACHING, INVALID_INPUT
    gamma: np.ndarray  # (n,) rad, Eq. 20
    gamma_star: np.ndarray  # (n,) rad, Eq. 21
    candidate_walls: np.ndarray  # (n,) uint32
    alpha_element: Optional[np.ndarray]  # (n,) rad, on the facet struck (element_angle=True)

class Wall:
    seed: int
    def __init__(
        self,
        *,
        delta_xi_deg: float = 0.0,
        delta_zeta_deg: float = 0.0,
        law: Optional[str] = "elastic",
        preset: Optional[str] = None,
        e_h: Optional[float] = None,
        alpha_e_deg: Optional[float] = None,
        mu_0: Optional[float] = None,
        mu_h: Optional[float] = None,
        alpha_mu_deg: Optional[float] = None,
        model: Optional[str] = None,
        psi: Optional[float] = None,
        seed: int = 0,
        delta_gamma_deg: Optional[float] = None,
        escape_table: Optional[str] = None,
        wall_table: Optional[str] = None,
    ) -> None: ...
    @property
    def warnings(self) -> list[str]: ...
    def rebound(
        self,
        velocity: Vec3,
        normal: Vec3,
        lay: Vec3,
        *,
        spin: Optional[Vec3] = None,
        wall_velocity: Optional[Vec3] = None,
        diameter: PerHit,
        particle_id: PerHit,
        collision_index: PerHit,
        threads: Optional[int] = None,
        element_angle: bool = False,
    ) -> Rebound: ...

class Surface(NamedTuple):
    heights: np.ndarray  # (nz, nx) m
    dx: float  # m
    dz: float  # m

class Scan(NamedTuple):
    heights: np.ndarray  # (ny, nx) m, NaN where missing
    dx: float  # m
    dy: float  # m
    format: str
    info: list[Tuple[str, str]]

def surface(
    *,
    length_m: float,
    nodes: int,
    rms_height_m: float,
    corr_length_x_m: Optional[float],
    corr_length_z_m: Optional[float],
    seed: int = 0,
    threads: Optional[int] = None,
) -> Surface: ...
def read_scan(
    path: Union[str, os.PathLike[str]],
    *,
    format: Optional[str] = None,
    pixel_m: Optional[Sequence[float]] = None,
    height_unit_m: Optional[float] = None,
) -> Scan: ...
def wall_card(
    scan: Union[Scan, str, os.PathLike[str], npt.ArrayLike],
    *,
    dy: Optional[float] = None,
    dx: Optional[float] = None,
    diameters_m: Sequence[float] = (),
    level_degree: int = 1,
    threads: Optional[int] = None,
) -> dict: ...
def measured_wall_table(
    scan: Union[Scan, str, os.PathLike[str], npt.ArrayLike],
    *,
    dy: Optional[float] = None,
    dx: Optional[float] = None,
    diameter_m: Optional[float] = None,
    level_degree: int = 1,
    histories_per_cell: int = 17711,
    seed: int = 2021,
    threads: Optional[int] = None,
) -> str: ...
def stochastic(
    wall: Wall,
    *,
    conditions: Sequence[Tuple[float, float]],
    particles: int = 10_000,
    speed_m_s: Tuple[float, float] = (1.0, 0.0),
    diameter_m: float = 500e-6,
    bin_width_deg: float = 1.0,
    target_se_deg: Optional[float] = None,
    seed: Optional[int] = None,
    threads: Optional[int] = None,
) -> dict: ...
def deterministic(
    wall: Wall,
    *,
    conditions: Sequence[Tuple[float, float]],
    particles: int = 10_000,
    speed_m_s: Tuple[float, float] = (1.0, 0.0),
    diameter_m: float = 500e-6,
    bin_width_deg: float = 1.0,
    target_se_deg: Optional[float] = None,
    seed: Optional[int] = None,
    threads: Optional[int] = None,
    max_collisions: int = 1000,
    spacing_per_corr_length: float = 8.0,
    side_per_corr_length: float = 100.0,
    surfaces: int = 1,
    triangulation: str = "alternating",
    wall_deviations: str = "normal-angles",
) -> dict: ...
