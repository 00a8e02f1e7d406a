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
from typing import Dict, Sequence, Tuple, Union

import numpy

from mlgshimmy.shared import paths
from mlgshimmy.shared.suggest import did_you_mean
from mlgshimmy.shared.jobs.atomic import write_text

LIBRARY = os.path.join(paths.BUILD, "lib", "libmlg.so")


class LibraryMissing(RuntimeError):
    """build/lib/libmlg.so is not built."""


class _Energy(ctypes.Structure):
    _fields_ = [("kinetic", ctypes.c_double), ("potential", ctypes.c_double)]


_lib = None
_tables: Dict[str, object] = {}


def library() -> ctypes.CDLL:
    """The c/ library, loaded (and its functions typed) on first use;
    LibraryMissing says what to build."""
    global _lib
    if _lib is not None:
        return _lib
    if not os.path.exists(LIBRARY):
        raise LibraryMissing(f"mlgmodel: {LIBRARY} is missing: build it with "
                             "`make build/lib/libmlg.so`")
    lib = ctypes.CDLL(LIBRARY)

    class Params(ctypes.Structure):
        _fields_ = [("values", ctypes.c_double * lib.mlg_params_field_count())]
    P, D = ctypes.POINTER(Params), ctypes.POINTER(ctypes.c_double)
    lib.mlg_params_table.restype = Params
    lib.mlg_params_figures.restype = Params
    lib.mlg_param_ref.restype = D
    lib.mlg_param_ref.argtypes = [P, ctypes.c_char_p]
    lib.mlg_par_name.restype = ctypes.c_char_p
    lib.mlg_constant_name.restype = ctypes.c_char_p
    lib.mlg_measure_name.restype = ctypes.c_char_p
    lib.mlg_diagnostic_name.restype = ctypes.c_char_p
    lib.mlg_state_name.restype = ctypes.c_char_p
    lib.mlg_params_check.argtypes = [P, ctypes.c_char_p, ctypes.c_size_t]
    lib.mlg_status_text.restype = ctypes.c_char_p
    lib.mlg_equilibrium.argtypes = [P, ctypes.c_double, D]
    lib.mlg_rhs.argtypes = [P, D, D]
    lib.mlg_rhs_jacobian.argtypes = [P, D, D, D, D]
    lib.mlg_rhs_jacobian_in_modes.argtypes = [P, ctypes.POINTER(ctypes.c_int), D, D, D, D]
    lib.mlg_rhs_taylor.argtypes = [P, D, D, D]
    lib.mlg_form.argtypes = [P, D, ctypes.c_int, ctypes.POINTER(D), D]
    lib.mlg_r_tlk.restype = ctypes.c_double
    lib.mlg_r_tlk.argtypes = [P, ctypes.c_double]
    lib.mlg_epsilon_m.restype = ctypes.c_double
    lib.mlg_epsilon_m.argtypes = [P]
    lib.mlg_torque_link_force.restype = ctypes.c_double
    lib.mlg_torque_link_force.argtypes = [ctypes.c_int] + [ctypes.c_double] * 4
    lib.mlg_freeplay_law_name.restype = ctypes.c_char_p
    lib.mlg_energy.argtypes = [P, D, ctypes.c_double, ctypes.POINTER(_Energy)]
    lib.mlg_switching.argtypes = [P, ctypes.POINTER(ctypes.c_int), D, D, D]
    lib.mlg_switching_name.restype = ctypes.c_char_p
    lib.mlg_switching_mode_after.argtypes = [ctypes.c_int, ctypes.c_int]
    _lib = lib
    return lib


def _name(getter, k):
    name = getter(k)
    return None if name is None else name.decode()


def _names(getter):
    names = []
    while _name(getter, len(names)) is not None:
        names.append(_name(getter, len(names)))
    return names


def _table(key: str):
    """The library's name tables, read once (see __getattr__)."""
    if not _tables:
        lib = library()
        _tables.update(
            # PARNAMES[k] is PAR(k+1): the continuation parameters, the switches
            # AUTO reads and "constants" (PAR(15)); None where no name is given
            PARNAMES=[_name(lib.mlg_par_name, k) for k in range(lib.mlg_par_slot_count())],
            MEASURES=_names(lib.mlg_measure_name),  # PAR(21) onwards, written by PVLS
            FIELDS=_names(lib.mlg_constant_name),   # every parameter, constant and switch
            UNAMES=_names(lib.mlg_state_name),      # UNAMES[i] is U(i+1)
            LAWS=_names(lib.mlg_freeplay_law_name),  # LAWS[k]: freeplay law k
            # mlg_diagnostics, in order: (field, its doubles: 1, or 2 for a tyre pair)
            DIAGNOSTICS=[(name, lib.mlg_diagnostic_size(k))
                         for k, name in enumerate(_names(lib.mlg_diagnostic_name))],
            C_PSI_FIGURES=ctypes.c_double.in_dll(lib, "MLG_C_PSI_FIGURES").value,
            # the switching functions (c/mlg_model.h): name -> (mode below, mode above)
            SWITCHING={name: (lib.mlg_switching_mode_after(k, -1),
                             lib.mlg_switching_mode_after(k, 1))
                      for k, name in enumerate(_names(lib.mlg_switching_name))})
        _tables["NX"] = len(_tables["UNAMES"])
        _tables["TAYLOR_ORDER"] = lib.mlg_taylor_order()   # the highest derivative of taylor()
    return _tables[key]


def __getattr__(name: str):
    """PARNAMES, MEASURES, FIELDS, UNAMES, LAWS, DIAGNOSTICS, NX, C_PSI_FIGURES,
    TAYLOR_ORDER, SWITCHING: read from the library when first asked for, so
    importing this module needs no build."""
    if name in ("PARNAMES", "MEASURES", "FIELDS", "UNAMES", "LAWS", "DIAGNOSTICS", "NX",
                "C_PSI_FIGURES", "TAYLOR_ORDER", "SWITCHING"):
        return _table(name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


CONSTANTS_FILE = "constants"              # PAR(15): k of mlg.constants.<k>, 0 none
MEASURES_FIRST_PAR = 21
_EPSILON_PARTS = ("eps_abs", "eps_rel")
# {k: text of mlg.constants.<k>}: the constants files of the runs this
# process started (register_constants), written into each run directory
_constants_files: Dict[int, str] = {}


State = Union[Dict[str, float], Sequence[float]]


def _vector(name: str, v: Sequence[float]):
    """v as the library's array of NX doubles; ValueError naming it if it
    has another shape (a short one would reach C padded with zeros)."""
    nx = _table("NX")
    v = numpy.asarray(v, dtype=float)
    if v.shape != (nx,):
        raise ValueError(f"{name} has shape {v.shape}, not ({nx},)")
    return (ctypes.c_double * nx)(*v)


def _state(u: State):
    """u as the library's array: a {name: value} dict (every state named,
    KeyError with a suggestion otherwise) or a sequence of NX values."""
    names = _table("UNAMES")
    if isinstance(u, dict):
        unknown = [k for k in u if k not in names]
        if unknown:
            raise KeyError(f"no state named {unknown[0]!r}{did_you_mean(unknown[0], names)}")
        u = [u[name] for name in names]
    if len(u) != len(names):
        raise ValueError(f"a state has {len(names)} values ({', '.join(names)}), not {len(u)}")
    return (ctypes.c_double * len(names))(*u)


class Model:
    """A parameter set of the c/ library: 'table' (the paper as printed) or
    'figures' (c_psi calibrated), with any parameter or constant overridden
    by name, validated at construction (ValueError naming the parameter).

    Smoothing width (eq. 15): epsilon = eps_abs + eps_rel * yfp [mm]. The
    sets have eps_abs = 0, eps_rel = 0.1; giving only one of the two parts
    (here or in set()) sets the other to 0, so epsilon is what was given:
    Model(yfp=1, eps_abs=0.1) has epsilon = 0.1 mm."""

    def __init__(self, parameter_set: str = "figures", **values: float):
        if parameter_set not in ("table", "figures"):
            raise ValueError(f"unknown parameter set {parameter_set!r}"
                             f"{did_you_mean(parameter_set, ('table', 'figures'))}")
        self.parameter_set = parameter_set
        self._p = getattr(library(), f"mlg_params_{parameter_set}")()
        self.set(**values)
        self.check()

    def __repr__(self) -> str:
        changed = {name: self[name] for name in _table("PARNAMES")
                   if name not in (None, CONSTANTS_FILE)}
        base = Model.__new__(Model)
        base._p = getattr(library(), f"mlg_params_{self.parameter_set}")()
        differ = {k: v for k, v in changed.items() if v != base[k]}
        differ.update(self.constants())
        return f"Model({self.parameter_set!r}" + "".join(
            f", {k}={v!r}" for k, v in differ.items()) + ")"

    def _ref(self, name: str):
        # ctypes cuts a name at a NUL: "V\0x" would be V
        if "\0" in name:
            raise KeyError(f"no parameter or constant named {name!r} (a name holds no NUL)")
        ref = library().mlg_param_ref(ctypes.byref(self._p), name.encode())
        if not ref:
            raise KeyError(f"no parameter or constant named {name!r}"
                           f"{did_you_mean(name, _table('FIELDS'))}")
        return ref

    def __getitem__(self, name: str) -> float:
        return self._ref(name)[0]

    def set(self, **values: float) -> "Model":
        """Set parameters by name, each a finite number (ranges are not
        validated: see check()). One part of epsilon without the other sets
        the other to 0."""
        given = [part for part in _EPSILON_PARTS if part in values]
        if len(given) == 1:
            values = dict(values, **{part: 0.0 for part in _EPSILON_PARTS if part not in given})
        for name, value in values.items():
            ref = self._ref(name)
            try:
                number = float(value)
            except (TypeError, ValueError):
                raise ValueError(f"parameter {name} = {value!r} is not a number") from None
            except OverflowError:
                raise ValueError(f"parameter {name} is beyond the range of a double "
                                 "(|value| < 1.8e308)") from None
            if not numpy.isfinite(number):
                raise ValueError(f"parameter {name} = {number!r} is not finite")
            ref[0] = number
        return self

    def constants(self) -> Dict[str, float]:
        """The constants that differ from the `table` set and are not in PAR,
        as {name: value}: what AUTO reads from mlg.constants.<k>."""
        table = Model.__new__(Model)
        table._p = library().mlg_params_table()
        in_par = set(_table("PARNAMES"))
        return {name: self[name] for name in _table("FIELDS")
                if name not in in_par and self[name] != table[name]}

    def constants_file(self) -> Tuple[int, str]:
        """(k, text) of the file mlg.constants.<k> that carries constants(),
        k named by the text's checksum; (0, "") if none differs."""
        changed = self.constants()
        text = "".join(f"{name} {value!r}\n" for name, value in changed.items())
        return (zlib.crc32(text.encode()) % (2**31 - 1) + 1 if changed else 0), text

    def par(self) -> Dict[str, float]:
        """The PAR values AUTO reads, as {name: value}, in PAR order; with
        constants changed, PAR(15) names the file that carries them
        (constants_file; a run needs it written: register_constants)."""
        par = {name: self[name] for name in _table("PARNAMES")
               if name not in (None, CONSTANTS_FILE)}
        par[CONSTANTS_FILE] = self.constants_file()[0]
        return par

    def check(self) -> None:
        msg = ctypes.create_string_buffer(256)
        if library().mlg_params_check(ctypes.byref(self._p), msg, len(msg)):
            raise ValueError(msg.value.decode())

    def equilibrium(self, eta_guess: float = -1.0) -> Dict[str, float]:
        """Straight rolling as {state name: value}; raises if not found."""
        self.check()
        names = _table("UNAMES")
        u = (ctypes.c_double * len(names))()
        status = library().mlg_equilibrium(ctypes.byref(self._p), eta_guess, u)
        if status != 0:
            why = "no convergence" if status < 0 else library().mlg_status_text(status).decode()
            raise RuntimeError(f"straight-rolling equilibrium not found: {why}")
        return dict(zip(names, u))

    def rhs(self, u: State) -> numpy.ndarray:
        """du/dt at the state u ({name: value} or a sequence in UNAMES order),
        in UNAMES order; raises if the state is outside the model's domain."""
        x = _state(u)
        f = (ctypes.c_double * len(x))()
        status = library().mlg_rhs(ctypes.byref(self._p), x, f)
        if status != 0:
            raise RuntimeError(f"rhs: {library().mlg_status_text(status).decode()}")
        return numpy.array(f, dtype=float)

    def jacobian(self, u: State) -> numpy.ndarray:
        """df/du at the state u ({name: value} or a sequence in UNAMES order),
        an NX x NX array; raises if the state is outside the model's domain."""
        nx = _table("NX")
        x = _state(u)
        f = (ctypes.c_double * nx)()
        J = (ctypes.c_double * (nx * nx))()   # column-major
        status = library().mlg_rhs_jacobian(ctypes.byref(self._p), x, f, J, None)
        if status != 0:
            raise RuntimeError(f"jacobian: {library().mlg_status_text(status).decode()}")
        return numpy.array(J, dtype=float).reshape(nx, nx).T

    def jacobian_in_mode(self, u: State, mode: int) -> Tuple[numpy.ndarray, numpy.ndarray]:
        """(f, df/du) of eq. (14) held in the freeplay mode `mode` (0 gap, 1
        contact+, 2 contact-: c/mlg_model.h), each mode's field continued
        beyond its switching surfaces; needs freeplay_law nonsmooth."""
        return self._in_mode(u, mode, None)[:2]

    def derivatives_in_mode(self, u: State, mode: int,
                            parameter: str) -> Tuple[numpy.ndarray, numpy.ndarray, numpy.ndarray]:
        """(f, df/du, df/d parameter) in the freeplay mode `mode`, as
        jacobian_in_mode, with the derivative in a continuation parameter
        (a name of PARNAMES: V, Fstar, ...), exact."""
        return self._in_mode(u, mode, parameter)

    def _in_mode(self, u, mode, parameter):
        nx, names = _table("NX"), _table("PARNAMES")
        if parameter is not None and parameter not in names:
            raise KeyError(f"derivatives_in_mode: no continuation parameter {parameter!r}"
                           f"{did_you_mean(parameter, [n for n in names if n])}")
        x = _state(u)
        f = (ctypes.c_double * nx)()
        J = (ctypes.c_double * (nx * nx))()   # column-major
        P = (ctypes.c_double * (nx * len(names)))() if parameter is not None else None
        # enum mlg_discrete (c/mlg_model.h): the freeplay held, the friction by
        # state (MLG_MODE_BY_STATE = -1)
        modes = (ctypes.c_int * 2)(mode, -1)
        status = library().mlg_rhs_jacobian_in_modes(ctypes.byref(self._p), modes, x, f, J, P)
        if status != 0:
            raise RuntimeError(f"jacobian_in_mode: {library().mlg_status_text(status).decode()}")
        out = (numpy.array(f, dtype=float), numpy.array(J, dtype=float).reshape(nx, nx).T)
        if parameter is None:
            return out
        k = names.index(parameter)    # df/dPAR(k+1) is the k-th column of nx
        return out + (numpy.array(P[k * nx:(k + 1) * nx], dtype=float),)

    def switching(self, u: State) -> Dict[str, Tuple[float, numpy.ndarray]]:
        """{name: (h, dh/du)} of every switching function (SWITCHING; h+- =
        r_tlk(eta) psi_s -+ y_fp for the freeplay), exact (forward mode),
        the discrete variables by state."""
        nx, names = _table("NX"), list(_table("SWITCHING"))
        h = (ctypes.c_double * len(names))()
        dh = (ctypes.c_double * (len(names) * nx))()
        self._call(library().mlg_switching, None, _state(u), h, dh)
        return {name: (h[k], numpy.array(dh[k * nx:(k + 1) * nx], dtype=float))
                for k, name in enumerate(names)}

    def taylor(self, u: Sequence[float], d: Sequence[float]) -> numpy.ndarray:
        """[f, D f[d], D^2 f[d, d], ..., D^K f[d, ..., d]] at the state u along
        d (sequences in UNAMES order), a (K + 1) x NX array, K = TAYLOR_ORDER,
        exact to rounding; at a kink of f (|eta'| eta' at eta' = 0) the
        one-sided derivatives, t -> 0+."""
        nx, order = _table("NX"), _table("TAYLOR_ORDER")
        out = (ctypes.c_double * ((order + 1) * nx))()
        self._call(library().mlg_rhs_taylor, _vector("taylor: u", u), _vector("taylor: d", d), out)
        return numpy.array(out, dtype=float).reshape(order + 1, nx)

    def form(self, u: Sequence[float], *vectors: Sequence[float]) -> numpy.ndarray:
        """The n-th multilinear form of f at the state u for n = len(vectors)
        real arguments (1 <= n <= TAYLOR_ORDER), sequences in UNAMES order:
        F_i = sum d^n f_i / du_j1 ... du_jn v1_j1 ... vn_jn, Kuznetsov's B, C,
        D, E for n = 2..5, exact to rounding (c/vector_field_taylor.c)."""
        order = _table("TAYLOR_ORDER")
        if not 1 <= len(vectors) <= order:
            raise ValueError(f"form: {len(vectors)} vectors; the library's forms take 1 to {order}")
        arguments = (ctypes.POINTER(ctypes.c_double) * len(vectors))(
            *[_vector(f"form: vector {k + 1}", v) for k, v in enumerate(vectors)])
        out = (ctypes.c_double * _table("NX"))()
        self._call(library().mlg_form, _vector("form: u", u), len(vectors), arguments, out)
        return numpy.array(out, dtype=float)

    def _call(self, function, *arguments):
        """function(params, *arguments); a status other than 0 raised, naming it."""
        status = function(ctypes.byref(self._p), *arguments)
        if status != 0:
            raise RuntimeError(f"{function.__name__}: {library().mlg_status_text(status).decode()}")

    def energy(self, u: Sequence[float], eta_ref: float) -> Tuple[float, float]:
        """(kinetic, potential) of the model's Lagrangian at the state u (a
        sequence in U order); the oleo potential counts from eta_ref."""
        x = (ctypes.c_double * _table("NX"))(*u)
        out = _Energy()
        status = library().mlg_energy(ctypes.byref(self._p), x, eta_ref, ctypes.byref(out))
        if status != 0:
            raise RuntimeError(f"energy: {library().mlg_status_text(status).decode()}")
        return out.kinetic, out.potential

    def r_tlk(self, eta: float) -> float:
        return library().mlg_r_tlk(ctypes.byref(self._p), eta)

    def epsilon_m(self) -> float:
        return library().mlg_epsilon_m(ctypes.byref(self._p))


def register_constants(model: Model) -> int:
    """Remember the model's constants file for the runs of this process
    (a run started from a solution of it carries its PAR(15)); its k."""
    k, text = model.constants_file()
    if k:
        _constants_files[k] = text
    return k


def registered_constants(k: float) -> Dict[str, float]:
    """The constants of file k registered in this process ({} for k = 0):
    what a solution whose PAR(15) is k was computed with."""
    if not k:
        return {}
    text = _constants_files.get(int(k))
    if text is None:
        raise KeyError(f"constants file {int(k)} was not registered in this process")
    return {name: float(value) for name, value in (line.split() for line in text.splitlines())}


def write_constants_files(rundir: str) -> None:
    """Write mlg.constants.<k> into rundir for every k registered in this
    process (each replaced atomically, the same text for the same k)."""
    for k, text in _constants_files.items():
        write_text(os.path.join(rundir, f"mlg.constants.{k}"),
                   f"# constants that differ from the `table` set (mlgshimmy.shared.mlgmodel)\n"
                   f"{text}")


def torque_link_force(law: int, k_tlk: float, y_tlk: float, yfp_m: float,
                      eps_m: float) -> float:
    """Freeplay law `law` (index in LAWS; 0: eq. 15) at eps_m > 0, or eq.
    (14) at eps_m == 0: force [N] at y_tlk [m]."""
    return library().mlg_torque_link_force(law, k_tlk, y_tlk, yfp_m, eps_m)
