"""`roughwall.Wall`: the stochastic rough-wall model as a CFD code calls it, for NumPy."""

from __future__ import annotations

import warnings
from typing import NamedTuple, Optional

import numpy as np

from . import _args
from ._roughwall import WallCore

#: A rebound was computed.
OK = 0
#: The particle does not move across the wall (velocity relative to the wall parallel to
#: it, or zero): returned unchanged.
NOT_APPROACHING = 1
#: A NaN or infinity, a zero normal, a lay direction along the normal or a negative
#: diameter: returned unchanged (non-finite components as 0).
INVALID_INPUT = 2


class RoughwallWarning(UserWarning):
    """A wall parameter outside the range where the model is validated (e.g. a deviation
    beyond the low-roughness range of 7.5°)."""


class Rebound(NamedTuple):
    """The rebounds of a batch of hits (global axes, SI units), one row per hit.

    velocity: (n, 3) rebound velocities (m/s), the wall velocity added back; for a hit not
        rebounded, its incident velocity (non-finite components as 0).
    spin: (n, 3) rebound angular velocities (rad/s); with the elastic law, the incident spin.
    status: (n,) int32: OK, NOT_APPROACHING or INVALID_INPUT.
    gamma: (n,) inclination γ (rad) of the virtual wall element in the incident plane
        (Radenkovic & Simonin 2021, Eq. 20); 0 for a smooth wall or an unchanged particle.
    gamma_star: (n,) inclination γ* (rad) normal to the incident plane (Eq. 21).
    candidate_walls: (n,) uint32: virtual walls drawn (≥ 1 for a rebound).
    alpha_element: with `element_angle=True`, (n,) impact angle (rad, 0 … π/2) on the wall
        element that produced the rebound: the facet struck, which erosion laws take (the C
        library's `rw_element_impact_angle`); on a smooth wall the angle to the wall; 0 for
        a hit not rebounded. None otherwise.

    With every input a single vector or number, the rows are squeezed: velocity (3,), status
    a 0-d array, and so on.
    """

    velocity: np.ndarray
    spin: np.ndarray
    status: np.ndarray
    gamma: np.ndarray
    gamma_star: np.ndarray
    candidate_walls: np.ndarray
    alpha_element: Optional[np.ndarray]


class Wall:
    """A rough wall: the stochastic model of Radenkovic & Simonin (2021) (or another
    rough-wall model) with a collision law, as the C library's `rw_wall_new` builds it.

    Parameters (keyword only; names and ranges of a case file's keys):
        delta_xi_deg: Δξ, standard deviation (degrees) of the wall normal's angle along the
            lay direction (Eq. 15): 0 … 20, beyond 7.5 a RoughwallWarning.
        delta_zeta_deg: Δζ, the same across the lay (0 for 2-D roughness).
        law: "elastic" (default) or "sommerfeld-huber" (Eqs. 36–42).
        preset: "glass-steel" (Sommerfeld–Huber parameters of Sec. 4) or None.
        e_h, alpha_e_deg, mu_0, mu_h, alpha_mu_deg: Sommerfeld–Huber parameters (None: the
            preset's).
        model: the rough-wall model, one of roughwall.MODELS (None: "radenkovic-simonin-2021").
        psi: ψ of the single-collision probability (Eq. 34), 0.01 … 100 (None: 2).
        seed: seed of every hit's random stream, 0 … 2**64 - 1.
        delta_gamma_deg: Δγ (degrees) of the isotropic models (None: (Δξ + Δζ)/2).
        escape_table: the text of an escape_table.csv for model="calibrated" (None: built in).
        wall_table: the text of a measured-wall table (``rebound scan --measured-wall`` writes
            it beside the wall card) for model="measured-wall", which requires it; the wall's
            deviations are then the table's, and the sign of ``lay`` matters.

    A bad value raises ValueError with the one-line message of the C library and the
    command line, e.g. ``invalid `wall.delta_xi_deg` = 25: allowed 0 to 20 degrees``.
    The wall is immutable; share it between threads.
    """

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
    ) -> None:
        num = _args.number
        delta_xi_deg, delta_zeta_deg = num("delta_xi_deg", delta_xi_deg), num("delta_zeta_deg", delta_zeta_deg)
        e_h, alpha_e_deg = num("e_h", e_h, True), num("alpha_e_deg", alpha_e_deg, True)
        mu_0, mu_h = num("mu_0", mu_0, True), num("mu_h", mu_h, True)
        alpha_mu_deg, psi = num("alpha_mu_deg", alpha_mu_deg, True), num("psi", psi, True)
        delta_gamma_deg = num("delta_gamma_deg", delta_gamma_deg, True)
        law, preset, model = _args.name("law", law), _args.name("preset", preset), _args.name("model", model)
        escape_table = _args.name("escape_table", escape_table)
        wall_table = _args.name("wall_table", wall_table)
        self._params = dict(
            delta_xi_deg=delta_xi_deg,
            delta_zeta_deg=delta_zeta_deg,
            law=law,
            preset=preset,
            collision=(e_h, alpha_e_deg, mu_0, mu_h, alpha_mu_deg),
            model=model,
            delta_gamma_deg=delta_gamma_deg,
            psi=psi,
            escape_table=escape_table,
            wall_table=wall_table,
        )
        self._core = WallCore(
            delta_xi_deg,
            delta_zeta_deg,
            law,
            preset,
            e_h,
            alpha_e_deg,
            mu_0,
            mu_h,
            alpha_mu_deg,
            psi,
            _args.seed(seed),
            model,
            delta_gamma_deg,
            escape_table,
            wall_table,
        )
        self.seed = int(seed)
        for w in self._core.warnings:
            warnings.warn(w, RoughwallWarning, stacklevel=2)

    @property
    def warnings(self) -> list[str]:
        """The parameters' warnings, also issued as RoughwallWarning when the wall was built."""
        return self._core.warnings

    def __repr__(self) -> str:
        xi, zeta, psi, seed, model = self._core.description
        return (
            f"Wall(delta_xi_deg={xi:g}, delta_zeta_deg={zeta:g}, law={self._params['law']!r}, "
            f"preset={self._params['preset']!r}, model={model!r}, psi={psi:g}, seed={seed})"
        )

    def rebound(
        self,
        velocity,
        normal,
        lay,
        *,
        spin=None,
        wall_velocity=None,
        diameter,
        particle_id,
        collision_index,
        threads: Optional[int] = None,
        element_angle: bool = False,
    ) -> Rebound:
        """The rebounds of n particle–wall hits, each exactly what the C library's
        rw_rebound returns for the same key (seed, particle_id, collision_index).

        Global axes, SI units. Vector arguments are (n, 3) arrays or one (3,) vector
        broadcast to every hit; per-hit numbers are (n,) arrays or one number.
            velocity: particle velocities before the hit (m/s, not relative to the wall).
            normal: face normals, either orientation, any non-zero length; the wall's frame
                has y along the normal into the flow.
            lay: the wall's lay direction (its principal roughness direction, that of Δξ),
                projected onto the wall plane: the frame's x.
            spin: angular velocities (rad/s); None: zero.
            wall_velocity: wall velocities (m/s); None: a wall at rest.
            diameter: particle diameters (m, ≥ 0; the Sommerfeld–Huber spin terms).
            particle_id, collision_index: the key of each hit's random stream (integers
                0 … 2**64 - 1): the same key gives the same rebound on any thread or rank.
            threads: threads to split the hits over (None: every core); the results do not
                depend on it.
            element_angle: also return each hit's impact angle on the facet struck
                (`Rebound.alpha_element`, for erosion laws; it costs a frame and three
                arcsines a hit).

        C-contiguous float64 inputs are read in place (no copy); the GIL is released while
        the hits run. A bad hit (NaN, zero normal, …) gets its status and finite outputs,
        never an exception; bad shapes or dtypes raise ValueError or TypeError, and outputs
        too large for the memory the process may use MemoryError (before any is allocated).
        """
        v, nv = _args.vec3("velocity", velocity)
        n_, nn = _args.vec3("normal", normal)
        l_, nl = _args.vec3("lay", lay)
        w, nw = _args.vec3("spin", np.zeros(3) if spin is None else spin)
        u, nu = _args.vec3("wall_velocity", np.zeros(3) if wall_velocity is None else wall_velocity)
        d, nd = _args.per_hit_float("diameter", diameter)
        pid, npid = _args.per_hit_u64("particle_id", particle_id)
        cix, ncix = _args.per_hit_u64("collision_index", collision_index)
        rows = {
            "velocity": nv,
            "normal": nn,
            "lay": nl,
            "spin": nw,
            "wall_velocity": nu,
            "diameter": nd,
            "particle_id": npid,
            "collision_index": ncix,
        }
        given = {k: r for k, r in rows.items() if r is not None}
        sizes = set(given.values()) - {1}
        if len(sizes) > 1:
            shown = ", ".join(f"{k} {r}" for k, r in given.items())
            raise ValueError(f"the hits' rows do not broadcast ({shown}): allowed 1 or n rows each")
        n = sizes.pop() if sizes else 1
        # The argument whose rows set n: a MemoryError for outputs too large names it.
        n_from = next((k for k, r in given.items() if r == n), "n")
        out = Rebound(
            *self._core.rebound(
                n, v, n_, l_, w, u, d, pid, cix, _args.threads(threads), n_from, bool(element_angle)
            )
        )
        if not given:
            return Rebound(*(None if a is None else a[0] for a in out))
        return out
