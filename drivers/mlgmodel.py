"""The c/ model library from Python, through ctypes (build/lib/libmlg.so).

Used by the drivers for what AUTO does not do: validating parameters before
a run, the straight-rolling equilibrium that starts a run at given
parameters (AUTO applies the constants' PAR after STPNT), and plain
evaluations such as the torque-link profiles and the freeplay boundary.

    m = Model("figures", Fstar=0.2, V=300)   # ValueError naming a bad parameter
    u = m.equilibrium()            # {"psi": 0.0, ..., "eta": 0.27, ...}

A constant set here (Model(k_relax=0.9)) reaches AUTO's FUNC through a file
mlg.constants.<k> in the run directory, named by PAR(15) = k (Model.par(),
write_constants_files(); docs/model.md 2.1).
"""
import ctypes
import os
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LIBRARY = os.path.join(ROOT, "build", "lib", "libmlg.so")
if not os.path.exists(LIBRARY):
    raise SystemExit(f"mlgmodel: {LIBRARY} is missing (make build/lib/libmlg.so)")
_lib = ctypes.CDLL(LIBRARY)


class _Params(ctypes.Structure):
    _fields_ = [("values", ctypes.c_double * _lib.mlg_params_field_count())]


_P = ctypes.POINTER(_Params)
_D = ctypes.POINTER(ctypes.c_double)
_lib.mlg_params_table.restype = _Params
_lib.mlg_params_figures.restype = _Params
_lib.mlg_param_ref.restype = _D
_lib.mlg_param_ref.argtypes = [_P, ctypes.c_char_p]
_lib.mlg_par_name.restype = ctypes.c_char_p
_lib.mlg_constant_name.restype = ctypes.c_char_p
_lib.mlg_measure_name.restype = ctypes.c_char_p
_lib.mlg_state_name.restype = ctypes.c_char_p
_lib.mlg_params_check.argtypes = [_P, ctypes.c_char_p, ctypes.c_size_t]
_lib.mlg_status_text.restype = ctypes.c_char_p
_lib.mlg_equilibrium.argtypes = [_P, ctypes.c_double, _D]
_lib.mlg_rhs_jacobian.argtypes = [_P, _D, _D, _D, _D]
_lib.mlg_r_tlk.restype = ctypes.c_double
_lib.mlg_r_tlk.argtypes = [_P, ctypes.c_double]
_lib.mlg_epsilon_m.restype = ctypes.c_double
_lib.mlg_epsilon_m.argtypes = [_P]
_lib.mlg_torque_link_force.restype = ctypes.c_double
_lib.mlg_torque_link_force.argtypes = [ctypes.c_double] * 4


class _Energy(ctypes.Structure):
    _fields_ = [("kinetic", ctypes.c_double), ("potential", ctypes.c_double)]


_lib.mlg_energy.argtypes = [_P, _D, ctypes.c_double, ctypes.POINTER(_Energy)]


def _name(getter, k):
    name = getter(k)
    return None if name is None else name.decode()


def _names(getter):
    names = []
    while _name(getter, len(names)) is not None:
        names.append(_name(getter, len(names)))
    return names


# PARNAMES[k] is PAR(k+1): the continuation parameters, the switches AUTO
# reads and "constants" (PAR(15)); None where no name is given (AUTO's slots).
PARNAMES = [_name(_lib.mlg_par_name, k) for k in range(_lib.mlg_par_slot_count())]
CONSTANTS_FILE = "constants"              # PAR(15): k of mlg.constants.<k>, 0 none
MEASURES = _names(_lib.mlg_measure_name)  # PAR(21) onwards, written by PVLS
MEASURES_FIRST_PAR = 21
FIELDS = _names(_lib.mlg_constant_name)   # every parameter, constant and switch
UNAMES = _names(_lib.mlg_state_name)      # UNAMES[i] is U(i+1)
NX = len(UNAMES)
C_PSI_FIGURES = ctypes.c_double.in_dll(_lib, "MLG_C_PSI_FIGURES").value
_EPSILON_PARTS = ("eps_abs", "eps_rel")
_constants_files = {}                     # {k: text of mlg.constants.<k>} of par()


class Model:
    """A parameter set of the c/ library: 'table' (the paper as printed) or
    'figures' (c_psi calibrated), with any parameter or constant overridden
    by name, validated at construction (ValueError naming the parameter).

    Smoothing width (eq. 15): epsilon = eps_abs + eps_rel * yfp [mm]. The
    sets have eps_abs = 0, eps_rel = 0.1; giving only one of the two parts
    (here or in set()) sets the other to 0, so epsilon is what was given:
    Model(yfp=1, eps_abs=0.1) has epsilon = 0.1 mm."""

    def __init__(self, parameter_set="figures", **values):
        if parameter_set not in ("table", "figures"):
            raise ValueError(f"unknown parameter set {parameter_set!r}")
        self._p = getattr(_lib, f"mlg_params_{parameter_set}")()
        self.set(**values)
        self.check()

    def _ref(self, name):
        ref = _lib.mlg_param_ref(ctypes.byref(self._p), name.encode())
        if not ref:
            raise KeyError(f"no parameter or constant named {name!r}")
        return ref

    def __getitem__(self, name):
        return self._ref(name)[0]

    def set(self, **values):
        """Set parameters by name (not validated: see check()). One part of
        epsilon without the other sets the other to 0."""
        given = [part for part in _EPSILON_PARTS if part in values]
        if len(given) == 1:
            values = dict(values, **{part: 0.0 for part in _EPSILON_PARTS if part not in given})
        for name, value in values.items():
            ref = self._ref(name)
            try:
                ref[0] = float(value)
            except (TypeError, ValueError):
                raise ValueError(f"parameter {name} = {value!r} is not a number") from None
        return self

    def constants(self):
        """The constants that differ from the `table` set and are not in PAR,
        as {name: value}: what AUTO reads from mlg.constants.<k>."""
        table = Model.__new__(Model)
        table._p = _lib.mlg_params_table()
        in_par = set(PARNAMES)
        return {name: self[name] for name in FIELDS
                if name not in in_par and self[name] != table[name]}

    def par(self):
        """The PAR values AUTO reads, as {name: value}, in PAR order; with
        constants changed, PAR(15) names the file that carries them (written
        to a run directory by write_constants_files)."""
        par = {name: self[name] for name in PARNAMES if name not in (None, CONSTANTS_FILE)}
        changed = self.constants()
        text = "".join(f"{name} {value!r}\n" for name, value in changed.items())
        k = zlib.crc32(text.encode()) % (2**31 - 1) + 1 if changed else 0
        if k:
            _constants_files[k] = text
        par[CONSTANTS_FILE] = k
        return par

    def check(self):
        msg = ctypes.create_string_buffer(256)
        if _lib.mlg_params_check(ctypes.byref(self._p), msg, len(msg)):
            raise ValueError(msg.value.decode())

    def equilibrium(self, eta_guess=-1.0):
        """Straight rolling as {state name: value}; raises if not found."""
        self.check()
        u = (ctypes.c_double * len(UNAMES))()
        status = _lib.mlg_equilibrium(ctypes.byref(self._p), eta_guess, u)
        if status != 0:
            why = "no convergence" if status < 0 else _lib.mlg_status_text(status).decode()
            raise RuntimeError(f"straight-rolling equilibrium not found: {why}")
        return dict(zip(UNAMES, u))

    def jacobian(self, u):
        """df/du at the state u ({name: value} or a sequence in UNAMES order),
        as a list of rows; raises if the state is outside the model's domain."""
        if isinstance(u, dict):
            u = [u[name] for name in UNAMES]
        x = (ctypes.c_double * NX)(*u)
        f = (ctypes.c_double * NX)()
        J = (ctypes.c_double * (NX * NX))()   # column-major
        status = _lib.mlg_rhs_jacobian(ctypes.byref(self._p), x, f, J, None)
        if status != 0:
            raise RuntimeError(f"jacobian: {_lib.mlg_status_text(status).decode()}")
        return [[J[i + NX * j] for j in range(NX)] for i in range(NX)]

    def energy(self, u, eta_ref):
        """(kinetic, potential) of the model's Lagrangian at the state u (a
        sequence in U order); the oleo potential counts from eta_ref."""
        x = (ctypes.c_double * NX)(*u)
        out = _Energy()
        status = _lib.mlg_energy(ctypes.byref(self._p), x, eta_ref, ctypes.byref(out))
        if status != 0:
            raise RuntimeError(f"energy: {_lib.mlg_status_text(status).decode()}")
        return out.kinetic, out.potential

    def r_tlk(self, eta):
        return _lib.mlg_r_tlk(ctypes.byref(self._p), eta)

    def epsilon_m(self):
        return _lib.mlg_epsilon_m(ctypes.byref(self._p))


def write_constants_files(rundir):
    """Write mlg.constants.<k> into rundir for every k that par() handed out
    in this process (each replaced atomically, the same text for the same k)."""
    for k, text in _constants_files.items():
        path = os.path.join(rundir, f"mlg.constants.{k}")
        with open(path + ".tmp", "w") as out:
            out.write(f"# constants that differ from the `table` set (drivers/mlgmodel.py)\n{text}")
        os.replace(path + ".tmp", path)


def torque_link_force(k_tlk, y_tlk, yfp_m, eps_m):
    """Eq. (15) (eps_m > 0) or eq. (14) (eps_m == 0): force [N] at y_tlk [m]."""
    return _lib.mlg_torque_link_force(k_tlk, y_tlk, yfp_m, eps_m)
