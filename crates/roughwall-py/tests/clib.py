"""The C library libroughwall.so through ctypes: the reference the Python package is checked
against (tests) and measured against (scripts/bench-python.sh). Mirrors include/roughwall.h."""

from __future__ import annotations

import ctypes as C
import os

import numpy as np

D3 = C.c_double * 3
LAWS = {"elastic": 0, "sommerfeld-huber": 1}
PRESETS = {None: 0, "glass-steel": 1}


class WallParams(C.Structure):
    _fields_ = [
        ("delta_xi_deg", C.c_double),
        ("delta_zeta_deg", C.c_double),
        ("law", C.c_int32),
        ("preset", C.c_int32),
        ("e_h", C.c_double),
        ("alpha_e_deg", C.c_double),
        ("mu_0", C.c_double),
        ("mu_h", C.c_double),
        ("alpha_mu_deg", C.c_double),
        ("psi", C.c_double),
        ("seed", C.c_uint64),
        ("model", C.c_int32),
        ("delta_gamma_deg", C.c_double),
        ("escape_table_csv", C.c_char_p),
        ("wall_table_text", C.c_char_p),
    ]


class Hit(C.Structure):
    _fields_ = [
        ("velocity", D3),
        ("spin", D3),
        ("normal", D3),
        ("lay", D3),
        ("wall_velocity", D3),
        ("diameter", C.c_double),
        ("particle_id", C.c_uint64),
        ("collision_index", C.c_uint64),
    ]


class Result(C.Structure):
    _fields_ = [
        ("velocity", D3),
        ("spin", D3),
        ("gamma", C.c_double),
        ("gamma_star", C.c_double),
        ("candidate_walls", C.c_uint32),
        ("status", C.c_int32),
    ]


P = C.POINTER(C.c_double)
_BATCH_IN = ["ux", "uy", "uz", "wx", "wy", "wz", "nx", "ny", "nz", "lx", "ly", "lz", "vx", "vy", "vz", "diameter"]
_BATCH_OUT = ["out_ux", "out_uy", "out_uz", "out_wx", "out_wy", "out_wz", "out_gamma", "out_gamma_star"]


class Batch(C.Structure):
    _fields_ = (
        [("n", C.c_size_t)]
        + [(k, P) for k in _BATCH_IN]
        + [("particle_id", C.POINTER(C.c_uint64)), ("collision_index", C.POINTER(C.c_uint64))]
        + [(k, P) for k in _BATCH_OUT]
        + [("out_candidate_walls", C.POINTER(C.c_uint32)), ("out_status", C.POINTER(C.c_int32))]
    )


def load(path: str | None = None) -> C.CDLL:
    """libroughwall.so: `path`, else $ROUGHWALL_CLIB."""
    path = path or os.environ.get("ROUGHWALL_CLIB")
    if not path or not os.path.exists(path):
        raise RuntimeError(
            f"libroughwall.so not found (ROUGHWALL_CLIB={path!r}): build it with "
            "`cargo build --release -p roughwall` and set ROUGHWALL_CLIB"
        )
    lib = C.CDLL(path)
    lib.rw_wall_params_default.argtypes = [C.POINTER(WallParams)]
    lib.rw_wall_new.argtypes = [C.POINTER(WallParams), C.POINTER(C.c_void_p), C.c_char_p, C.c_size_t]
    lib.rw_wall_free.argtypes = [C.c_void_p]
    lib.rw_rebound.argtypes = [C.c_void_p, C.POINTER(Hit), C.POINTER(Result)]
    lib.rw_rebound_batch.argtypes = [C.c_void_p, C.POINTER(Batch), C.c_int32]
    lib.rw_element_impact_angle.argtypes = [C.POINTER(Hit), C.POINTER(Result)]
    lib.rw_element_impact_angle.restype = C.c_double
    return lib


class CWall:
    """A C wall handle built from the keywords of roughwall.Wall."""

    def __init__(self, lib, *, delta_xi_deg=0.0, delta_zeta_deg=0.0, law="elastic", preset=None,
                 psi=2.0, seed=0, model=0, e_h=None, mu_0=None, wall_table=None):
        self.lib = lib
        p = WallParams()
        lib.rw_wall_params_default(C.byref(p))
        p.delta_xi_deg, p.delta_zeta_deg = delta_xi_deg, delta_zeta_deg
        p.law, p.preset, p.psi, p.seed, p.model = LAWS.get(law, 99), PRESETS.get(preset, 99), psi, seed, model
        if e_h is not None:
            p.e_h = e_h
        if mu_0 is not None:
            p.mu_0 = mu_0
        if wall_table is not None:
            self._table = wall_table.encode()  # kept alive while the handle is built
            p.wall_table_text = self._table
        self.handle = C.c_void_p()
        msg = C.create_string_buffer(512)
        self.status = lib.rw_wall_new(C.byref(p), C.byref(self.handle), msg, 512)
        self.message = msg.value.decode()

    def __del__(self):
        if getattr(self, "handle", None):
            self.lib.rw_wall_free(self.handle)

    def rebound_one(self, v, n, l, d, pid, cix, spin=(0, 0, 0), wall_velocity=(0, 0, 0)) -> Result:
        h = Hit(D3(*v), D3(*spin), D3(*n), D3(*l), D3(*wall_velocity), d, pid, cix)
        r = Result()
        self.lib.rw_rebound(self.handle, C.byref(h), C.byref(r))
        return r

    def element_angle(self, v, n, l, d, pid, cix, spin=(0, 0, 0), wall_velocity=(0, 0, 0)) -> float:
        """rw_element_impact_angle of one hit's rw_rebound."""
        h = Hit(D3(*v), D3(*spin), D3(*n), D3(*l), D3(*wall_velocity), d, pid, cix)
        r = Result()
        self.lib.rw_rebound(self.handle, C.byref(h), C.byref(r))
        return self.lib.rw_element_impact_angle(C.byref(h), C.byref(r))

    def batch_inputs(self, velocity, normal, lay, diameter, particle_id, collision_index, spin=None, wall_velocity=None):
        """Struct-of-arrays columns (kept alive in the returned dict) and their rw_batch."""
        n = velocity.shape[0]
        cols = {}
        for name, a in [("u", velocity), ("n", normal), ("l", lay), ("w", spin), ("v", wall_velocity)]:
            if a is None:
                continue
            for k, axis in enumerate("xyz"):
                cols[name + axis] = np.ascontiguousarray(a[:, k])
        cols["diameter"] = np.ascontiguousarray(diameter, dtype=np.float64)
        cols["particle_id"] = np.ascontiguousarray(particle_id, dtype=np.uint64)
        cols["collision_index"] = np.ascontiguousarray(collision_index, dtype=np.uint64)
        for k in _BATCH_OUT:
            cols[k] = np.empty(n)
        cols["out_candidate_walls"] = np.empty(n, dtype=np.uint32)
        cols["out_status"] = np.empty(n, dtype=np.int32)
        b = Batch()
        b.n = n
        for k, a in cols.items():
            ty = {np.dtype(np.float64): P, np.dtype(np.uint64): C.POINTER(C.c_uint64),
                  np.dtype(np.uint32): C.POINTER(C.c_uint32), np.dtype(np.int32): C.POINTER(C.c_int32)}[a.dtype]
            setattr(b, k, a.ctypes.data_as(ty))
        return cols, b

    def run_batch(self, batch, threads: int) -> int:
        return self.lib.rw_rebound_batch(self.handle, C.byref(batch), threads)


def outputs(cols):
    """The batch's outputs as roughwall.Rebound's arrays."""
    v = np.stack([cols["out_ux"], cols["out_uy"], cols["out_uz"]], axis=1)
    w = np.stack([cols["out_wx"], cols["out_wy"], cols["out_wz"]], axis=1)
    return v, w, cols["out_status"], cols["out_gamma"], cols["out_gamma_star"], cols["out_candidate_walls"]
