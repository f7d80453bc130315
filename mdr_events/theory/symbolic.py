"""SymPy derivation of every relation of section 4, eqs. (3)–(21).

Nothing here is typed in as a result: each relation is *derived* from the
model's statements (the Abel transform (3), the spring displacement (7),
Heß's rule (8), the stationary-sliding sum (12), the trajectories (14) and
(19)) by integration, differentiation, ``solve`` and polynomial reduction.
The numerical layers (:mod:`mdr_events.theory.analytic`, and later the continuum and
discrete simulators) evaluate these very expressions through
:attr:`Relation.numeric`, built once with :func:`sympy.lambdify` and cached.

Use
---
>>> from mdr_events import symbolic
>>> rel = symbolic.relation("jkr_depth")
>>> rel.equation, rel.eq                                    # doctest: +SKIP
('(9)', Eq(d, a**2/R - sqrt(2)*sqrt(pi)*sqrt(a)*sqrt(dgamma)/sqrt(E_star)))
>>> rel.numeric(a=3e-3, R=0.03, E_star=4.32e5, dgamma=0.01)  # doctest: +SKIP

Symbols (all SI): ``x`` MDR coordinate, ``r`` radial coordinate, ``R``
indenter radius, ``E_star``/``G_star`` effective moduli, ``tau0`` critical
shear stress, ``dgamma`` work of adhesion, ``d`` indentation depth, ``d_max``
turning depth, ``a`` contact radius, ``s = sqrt(a)``, ``alpha`` path angle.

Why one module of about 760 lines: the on-disk cache of the derivations is keyed by the hash of this file's
source (:func:`cache_path`), so everything that can change a derived relation (the symbols, the
:class:`Relation` whose fields the cache stores, every derivation and its helpers) lives here, where an edit
cannot leave a stale cache behind. Each derivation is split into sections of one step of the paper each
(:func:`derive_afresh`).
"""

from __future__ import annotations

import functools
import hashlib
import pickle
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np
import sympy as sp

from mdr_events.theory.cache_files import cache_directory, read_cached, store_cached
from mdr_events.validation import shown

__all__ = [
    "Relation",
    "derive",
    "derive_afresh",
    "cache_path",
    "cached_relations",
    "derivation_check",
    "sibling_cache_path",
    "source_digest",
    "relation",
    "UnknownRelationError",
    "relations",
    "abel_transform",
    "derive_power_law_model",
    "POWER_LAW_KEYS",
    "derive_friction_model",
    "FRICTION_KEYS",
    "derive_adhesive_friction_model",
    "ADHESIVE_FRICTION_KEYS",
    "derive_rate_dependent_adhesion",
    "RATE_ADHESION_KEYS",
    "SYMBOLS",
]

# ----------------------------------------------------------------------------
# symbols
x = sp.Symbol("x", positive=True)
r = sp.Symbol("r", positive=True)
t = sp.Symbol("t", positive=True)
n = sp.Symbol("n", positive=True)
c = sp.Symbol("c", positive=True)
theta = sp.Symbol("theta", positive=True)
R = sp.Symbol("R", positive=True)
E_star = sp.Symbol("E_star", positive=True)
G_star = sp.Symbol("G_star", positive=True)
tau0 = sp.Symbol("tau0", positive=True)
dgamma = sp.Symbol("dgamma", positive=True)
d = sp.Symbol("d", real=True)
d_max = sp.Symbol("d_max", positive=True)
a = sp.Symbol("a", positive=True)
s = sp.Symbol("s", positive=True)
alpha = sp.Symbol("alpha", positive=True)
tan_alpha = sp.Symbol("tan_alpha", positive=True)
u_bar = sp.Symbol("u_bar", positive=True)
dx = sp.Symbol("Delta_x", positive=True)
n_springs = sp.Symbol("n", positive=True, integer=True)
g = sp.Function("g")
f = sp.Function("f")
u_z = sp.Symbol("u_z", real=True)
dl_max = sp.Symbol("Delta_l_max", positive=True)
F_N = sp.Symbol("F_N", real=True)
tau = sp.Symbol("tau", real=True)
k = sp.Symbol("k", positive=True)
X = sp.Symbol("X", positive=True)
W = sp.Symbol("W", positive=True)
mu = sp.Symbol("mu", positive=True)
u_x = sp.Symbol("u_x", positive=True)
F_x = sp.Symbol("F_x", real=True)

#: Every symbol by its name, for users building their own expressions.
SYMBOLS: dict[str, sp.Symbol] = {
    sym.name: sym
    for sym in (x, r, R, E_star, G_star, tau0, dgamma, d, d_max, a, s, alpha,
                tan_alpha, u_bar, dx, c, n, theta, k, X, W, mu, u_x)
}

#: Pretty LaTeX names (``sympy.latex(..., symbol_names=LATEX_NAMES)``).
LATEX_NAMES: dict[sp.Symbol, str] = {
    E_star: r"E^{*}",
    G_star: r"G^{*}",
    tau0: r"\tau_{0}",
    dgamma: r"\Delta\gamma",
    d_max: r"d_{\max}",
    u_bar: r"\bar{u}",
    dx: r"\Delta x",
    tan_alpha: r"\tan\alpha",
    u_x: r"u_{x}",
    dl_max: r"\Delta l_{\max}",
}


@dataclass(frozen=True)
class Relation:
    """One derived relation ``lhs = rhs`` of the model.

    Parameters
    ----------
    key : str
        Stable identifier, e.g. ``"jkr_depth"``.
    equation : str
        The paper's equation number, e.g. ``"(9)"`` (``""`` for consequences
        the paper uses without numbering them).
    title : str
        What the relation says, in words.
    lhs : sympy.Expr
        The left-hand side; for a polynomial reduction the polynomial.
    rhs : sympy.Expr
        The right-hand side; ``0`` for a polynomial reduction.
    args : tuple of sympy.Symbol, default ()
        The arguments, in order, of :attr:`numeric` (keyword names are the
        symbol names).
    variable : sympy.Symbol or None, default None
        For a polynomial relation, its unknown (:attr:`coefficients` are the
        coefficients in that variable, highest power first).
    """

    key: str
    equation: str
    title: str
    lhs: sp.Expr
    rhs: sp.Expr
    args: tuple[sp.Symbol, ...] = field(default=())
    variable: sp.Symbol | None = None

    @property
    def eq(self) -> sp.Eq:
        """The relation as a SymPy equation (for notebooks and printing)."""
        return sp.Eq(self.lhs, self.rhs, evaluate=False)

    def latex(self) -> str:
        """LaTeX of the relation with the paper's symbols.

        Returns
        -------
        str
            ``lhs = rhs`` in LaTeX, the symbols named by :data:`LATEX_NAMES`.
        """
        return sp.latex(self.eq, symbol_names=LATEX_NAMES)

    def pretty(self) -> str:
        """Unicode pretty print of the relation.

        Returns
        -------
        str
            SymPy's two-dimensional rendering, in Unicode.
        """
        return sp.pretty(self.eq, use_unicode=True)

    @functools.cached_property
    def _numeric(self) -> Callable[..., object]:
        expr = self.lhs if self.variable is not None else self.rhs
        return sp.lambdify(self.args, expr, modules="numpy", cse=True)

    def numeric(self, *values, **named):
        """Evaluate the right-hand side with NumPy (vectorised, built once).

        Arguments are given positionally in the order of :attr:`args` or by
        the symbol names. For a polynomial relation the polynomial itself is
        evaluated (its :attr:`variable` must be among the arguments).

        Parameters
        ----------
        *values : float or array_like
            The arguments in the order of :attr:`args` (Python numbers become NumPy floats: 1/0 gives ``inf``).
        **named : float or array_like
            Or all of them by their symbols' names; not both.

        Returns
        -------
        float or numpy.ndarray
            The right-hand side (the polynomial for a polynomial relation), broadcast over the arguments.

        Raises
        ------
        TypeError
            Arguments both positional and named, unknown, missing or too many.
        """
        return self._numeric(*self._ordered(values, named))

    @functools.cached_property
    def scalar(self) -> Callable[..., float]:
        """The same expression as :attr:`numeric`, compiled for Python floats.

        Built once with the ``math`` module (no NumPy scalars), for scalar hot
        loops such as the continuum right-hand side. Arguments are positional,
        in the order of :attr:`args`; where :meth:`numeric` would give ``nan``
        (e.g. the square root of a negative number) it raises ``ValueError``.
        """
        expr = self.lhs if self.variable is not None else self.rhs
        return sp.lambdify(self.args, expr, modules="math", cse=True)

    @functools.cached_property
    def scalar_coefficients(self) -> Callable[..., list]:
        """:meth:`coefficients` for Python floats (``math`` module), positional arguments."""
        args, _ = self._coefficients
        coeffs = sp.Poly(self.lhs, self.variable).all_coeffs()
        return sp.lambdify(args, coeffs, modules="math", cse=True)

    @functools.cached_property
    def _coefficients(self) -> Callable[..., list]:
        if self.variable is None:
            raise TypeError(f"relation {self.key!r} is not a polynomial")
        coeffs = sp.Poly(self.lhs, self.variable).all_coeffs()
        args = tuple(a_ for a_ in self.args if a_ != self.variable)
        return args, sp.lambdify(args, coeffs, modules="numpy", cse=True)

    def coefficients(self, *values, **named) -> list:
        """Coefficients of the polynomial in :attr:`variable`, highest first.

        Parameters
        ----------
        *values : float or array_like
            The arguments of :attr:`args` but :attr:`variable`, in order.
        **named : float or array_like
            Or all of them by their symbols' names; not both.

        Returns
        -------
        list
            The coefficients (floats or arrays), highest power first.

        Raises
        ------
        TypeError
            A relation that is not a polynomial, or arguments as :meth:`numeric` refuses them.
        """
        args, fn = self._coefficients
        return fn(*self._ordered(values, named, args))

    def bound_numeric(self, *trailing) -> Callable[..., object]:
        """:meth:`numeric` with its last arguments fixed, converted once (a model's constants: a run calls it many
        times); the function of the first arguments gives :meth:`numeric`'s values, bit for bit.

        Parameters
        ----------
        *trailing : float or array_like
            The last arguments of :attr:`args`, in order.

        Returns
        -------
        callable
            ``f(*leading)``: :meth:`numeric` of ``(*leading, *trailing)``; wrong counts raise ``TypeError``.
        """
        return _bound(self.key, self._numeric, self.args, trailing)

    def bound_coefficients(self, *trailing) -> Callable[..., list]:
        """:meth:`coefficients` with its last arguments fixed, converted once (:meth:`bound_numeric`'s way).

        Parameters
        ----------
        *trailing : float or array_like
            The last arguments of :meth:`coefficients`, in order.

        Returns
        -------
        callable
            ``f(*leading)``: :meth:`coefficients` of ``(*leading, *trailing)``; wrong counts raise ``TypeError``.
        """
        args, function = self._coefficients
        return _bound(self.key, function, args, trailing)

    def _ordered(self, values, named, args=None):
        args = self.args if args is None else args
        if values and named:
            raise TypeError(f"{self.key}: give arguments by position or by name, not both")
        if named:
            names = [a_.name for a_ in args]
            unknown = set(named) - set(names)
            missing = [nm for nm in names if nm not in named]
            if unknown or missing:
                raise TypeError(
                    f"{self.key}: arguments are {names}; "
                    f"unknown {sorted(unknown)}, missing {missing}"
                )
            return [_as_numpy_scalar(named[nm]) for nm in names]
        if len(values) != len(args):
            raise TypeError(
                f"{self.key}: expected {len(args)} arguments {[a_.name for a_ in args]}, "
                f"got {len(values)}"
            )
        return [_as_numpy_scalar(value) for value in values]


def _bound(key: str, function: Callable, args: tuple, trailing: tuple) -> Callable:
    """``function`` of ``args`` with its last ones ``trailing`` fixed, each argument converted as
    :func:`_as_numpy_scalar` converts it (:meth:`Relation.bound_numeric`)."""
    fixed = tuple(_as_numpy_scalar(value) for value in trailing)
    count = len(args) - len(fixed)
    if count < 0:
        raise TypeError(f"{key}: expected at most {len(args)} arguments {[a_.name for a_ in args]}, got {len(fixed)}")

    def bound(*values):
        if len(values) != count:
            raise TypeError(f"{key}: expected {count} arguments {[a_.name for a_ in args[:count]]}, got {len(values)}")
        return function(*[_as_numpy_scalar(value) for value in values], *fixed)

    return bound


def _as_numpy_scalar(value):
    """Python ints and floats become NumPy floats, so 1/0 gives inf, not ZeroDivisionError."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return np.float64(value)
    return value


# ----------------------------------------------------------------------------
# the Abel transform (3)
def abel_transform(profile: sp.Expr, radial: sp.Symbol = r, coordinate: sp.Symbol = x) -> sp.Expr:
    r"""MDR equivalent profile of an axisymmetric profile ``f(r)``, eq. (3).

    .. math:: g(x) = |x| \int_0^{|x|} \frac{f'(r)}{\sqrt{x^2 - r^2}}\, \mathrm{d}r \qquad (3)

    (for ``x > 0``), evaluated with the substitution ``r = x t`` so that SymPy meets a
    Beta-type integral for power laws.

    Parameters
    ----------
    profile : sympy.Expr
        ``f(r)``, an expression in ``radial``.
    radial : sympy.Symbol, optional
        The radius ``r`` of ``profile`` (default the module's ``r``).
    coordinate : sympy.Symbol, optional
        The springs' coordinate ``x`` of the result (default the module's ``x``).

    Returns
    -------
    sympy.Expr
        ``g(x)``, simplified.
    """
    integrand = sp.diff(profile, radial).subs(radial, coordinate * t) / sp.sqrt(1 - t**2)
    value = coordinate * sp.integrate(integrand, (t, 0, 1))
    return sp.simplify(sp.gammasimp(sp.hyperexpand(value)))


def _single_positive(solutions: list[sp.Expr], what: str) -> sp.Expr:
    nonzero = [sol for sol in solutions if sol != 0]
    if len(nonzero) != 1:
        raise RuntimeError(f"derivation of {what}: expected one nonzero solution, got {solutions}")
    return sp.simplify(nonzero[0])


# ----------------------------------------------------------------------------
# ----------------------------------------------------------------------------
# on-disk cache of the derivations
def source_digest(source_file: str | Path) -> str:
    """The key of the relations a module of derivations files: a hash of its source and of SymPy's version.

    A module takes it when it is imported, not when its cache is used, so that a process never files the derivations
    of the code it runs under the name of a source edited since.

    Parameters
    ----------
    source_file : str or pathlib.Path
        The module's file (its ``__file__``).

    Returns
    -------
    str
        16 hexadecimal digits.
    """
    return hashlib.sha256(Path(source_file).read_bytes() + sp.__version__.encode()).hexdigest()[:16]


#: Hash of this module's source as it was imported, and of the SymPy version: the cache key (:func:`source_digest`).
_SOURCE_DIGEST = source_digest(__file__)


def sibling_cache_path(stem: str, digest: str) -> Path | None:
    """The cache file of a sibling module of derivations, beside :func:`cache_path` (``None``: caching is off).

    Parameters
    ----------
    stem : str
        The file's name before its key (``"layer-relations"``, ...).
    digest : str
        The sibling's :func:`source_digest`.

    Returns
    -------
    pathlib.Path or None
        ``<stem>-<digest>.pickle`` in the cache directory, or ``None``.
    """
    root = cache_directory()
    return None if root is None else root / f"{stem}-{digest}.pickle"


def cache_path() -> Path | None:
    """Where derived relations are kept between processes (``None``: caching is off).

    ``$MDR_EVENTS_CACHE_DIR`` or ``$XDG_CACHE_HOME/mdr_events`` or
    ``~/.cache/mdr_events``; ``MDR_EVENTS_NO_CACHE=1`` turns it off. The file
    name carries a hash of this module's source and the SymPy version, so a
    changed derivation is never read from an old cache.

    Returns
    -------
    pathlib.Path or None
        The cache file ``relations-<hash>.pickle`` in that directory, or ``None``.
    """
    return sibling_cache_path("relations", _SOURCE_DIGEST)


def _fields(rel: Relation) -> tuple:
    return (rel.key, rel.equation, rel.title, rel.lhs, rel.rhs, rel.args, rel.variable)


def _cached(name: str, build: Callable[[], list[Relation]],
            where: Callable[[], Path | None] | None = None) -> list[Relation]:
    """``build()``'s relations, read from the cache file if it holds ``name``, else built and stored.

    ``where`` gives the cache file (default :func:`cache_path`; a sibling module of derivations passes its own, keyed by
    its own source). Any trouble with the cache (unwritable, damaged, foreign) falls back to deriving afresh.
    """
    path = (where or cache_path)()
    store = read_cached(path, pickle.load)  # (missing, unreachable or damaged: None)
    store = store if isinstance(store, dict) else {}
    try:
        if name in store:
            return [Relation(*fields) for fields in store[name]]
    except Exception:  # noqa: BLE001 - a foreign cache file is only a missed shortcut
        store = {}
    relations_built = build()
    if path is not None:
        store[name] = [_fields(rel) for rel in relations_built]
        store_cached(path, lambda stream: pickle.dump(store, stream))
    return relations_built


def cached_relations(name: str, afresh: Callable[[], dict[str, Relation]],
                     where: Callable[[], Path | None] | None = None) -> dict[str, Relation]:
    """The relations ``afresh()`` derives, by key in derivation order, read from the cache file if it holds ``name``
    (:func:`_cached`; ``where`` gives a sibling module's own file, default :func:`cache_path`).

    Parameters
    ----------
    name : str
        The derivation's name in the cache file.
    afresh : callable
        Derives the relations with SymPy, by key.
    where : callable, optional
        The cache file (``None``: caching is off); default :func:`cache_path`.

    Returns
    -------
    dict of str to Relation
        The relations by key.
    """
    return {rel.key: rel for rel in _cached(name, lambda: list(afresh().values()), where)}


def derivation_check(what: str) -> Callable[[bool, str], None]:
    """A derivation's check of its own steps: raises ``RuntimeError("<what>: <step>")`` where a step's condition fails.

    Parameters
    ----------
    what : str
        The derivation's name in the message.

    Returns
    -------
    callable
        ``check(condition, step)``.
    """
    def check(condition: bool, step: str) -> None:
        if not condition:
            raise RuntimeError(f"{what}: {step}")
    return check


@functools.cache
def derive() -> dict[str, Relation]:
    """Derive every relation once per process (and once per cache, see :func:`cache_path`).

    Returns the relations by key in derivation order.
    """
    return cached_relations("model", derive_afresh)


#: What a derivation section is handed: it files one relation (in derivation order) and returns it.
AddRelation = Callable[[Relation], Relation]


def derive_afresh() -> dict[str, Relation]:
    """Run every derivation with SymPy (about 4 s), bypassing any cache.

    The sections run in the paper's order, each adding its relations and handing on the expressions the
    next ones build on.

    Returns
    -------
    dict of str to Relation
        The relations of the model by key, in derivation order.
    """
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> Relation:
        out[rel.key] = rel
        return rel

    g_parab = _derive_profiles(add)
    displacement, depth_of_radius = _derive_adhesive_branch(add, g_parab)
    force_pinned, force_jkr = _derive_normal_forces(add, displacement, depth_of_radius)
    hertz_radius = _derive_branch_points(add, depth_of_radius, force_pinned, force_jkr)
    critical_shift = _derive_tangential_springs(add, depth_of_radius)
    _derive_scenario_A(add, depth_of_radius, hertz_radius, critical_shift)
    _derive_scenario_B(add, depth_of_radius, hertz_radius, critical_shift)
    return out


def _derive_profiles(add: AddRelation) -> sp.Expr:
    """(3), (4): the Abel transform and the profiles of the paraboloid and the cone; returns the paraboloid's."""
    g_abel = sp.Eq(
        g(x),
        x * sp.Integral(sp.Derivative(f(r), r) / sp.sqrt(x**2 - r**2), (r, 0, x)),
    )
    add(Relation("abel_transform", "(3)", "Abel transform to the MDR profile", g_abel.lhs, g_abel.rhs))
    g_parab = abel_transform(r**2 / (2 * R))
    add(Relation("profile_paraboloid", "(4)", "MDR profile of the paraboloid f = r^2/(2R)", g(x), g_parab, (x, R)))
    g_cone = abel_transform(r * sp.tan(theta))
    add(Relation("profile_cone", "(3)", "MDR profile of the cone f = r tan(theta)", g(x), g_cone, (x, theta)))
    return g_parab


def _derive_adhesive_branch(add: AddRelation, g_parab: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """(7), (8), (9): Heß's rule gives JKR; returns the springs' displacement and the branch's depth ``d(a)``."""
    displacement = d - g_parab  # (7), positive = compressed
    add(Relation("normal_displacement", "(7)", "normal spring displacement u_z = d - g(x)",
                 u_z, displacement, (d, x, R)))
    hess = sp.sqrt(2 * sp.pi * a * dgamma / E_star)  # (8)
    add(Relation("hess_max_elongation", "(8)", "Heß: maximum elongation of the boundary spring",
                 dl_max, hess, (a, dgamma, E_star)))
    # the boundary spring at x = a is stretched by exactly Δl_max: -u_z(a) = Δl_max
    depth_of_radius = sp.solve(sp.Eq(-displacement.subs(x, a), hess), d)[0]
    add(Relation("jkr_depth", "(9)", "indentation depth of the adhesive contact of radius a",
                 d, depth_of_radius, (a, R, E_star, dgamma)))

    add(Relation("jkr_depth_slope", "(9)", "slope dd/da of the adhesive branch (9)",
                 sp.Derivative(d, a), sp.diff(depth_of_radius, a), (a, R, E_star, dgamma)))
    return displacement, depth_of_radius


def _derive_normal_forces(add: AddRelation, displacement: sp.Expr, depth_of_radius: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """(10): the normal force at any depth and radius and on the adhesive branch; returns both."""
    force_pinned = sp.expand(2 * E_star * sp.integrate(displacement, (x, 0, a)))
    add(Relation("normal_force", "(10)", "normal force of the springs in contact, any d and a",
                 F_N, force_pinned, (d, a, R, E_star)))
    force_jkr = sp.simplify(sp.expand(force_pinned.subs(d, depth_of_radius)))
    add(Relation("jkr_normal_force", "(10)", "normal force of the adhesive contact of radius a",
                 F_N, force_jkr, (a, R, E_star, dgamma)))
    return force_pinned, force_jkr


def _derive_branch_points(add: AddRelation, depth_of_radius: sp.Expr, force_pinned: sp.Expr,
                          force_jkr: sp.Expr) -> sp.Expr:
    """Consequences of (9), (10): Hertz's contact, the jump-in, the pull-off and the jump-off; returns Hertz's
    radius ``a(d)``."""
    hertz_radius = sp.solve(sp.Eq(d, depth_of_radius.subs(dgamma, 0)), a)[0]
    add(Relation("hertz_radius", "(16)", "non-adhesive (Hertz) contact radius", a, hertz_radius, (d, R)))
    hertz_force = sp.simplify(force_pinned.subs(a, hertz_radius))
    add(Relation("hertz_normal_force", "", "Hertz normal force", F_N, hertz_force, (d, R, E_star)))
    jump_in = _single_positive(sp.solve(sp.Eq(depth_of_radius, 0), a), "jump-in radius")
    add(Relation("jump_in_radius", "", "contact radius at zero depth (JKR jump-in)",
                 a, jump_in, (R, E_star, dgamma)))
    a_force_control = _single_positive(sp.solve(sp.diff(force_jkr, a), a), "pull-off radius")
    add(Relation("pull_off_radius", "", "radius of minimal force, dF_N/da = 0 (force control)",
                 a, a_force_control, (R, E_star, dgamma)))
    add(Relation("pull_off_force", "", "JKR pull-off force (minimum of F_N on a branch)",
                 F_N, sp.simplify(force_jkr.subs(a, a_force_control)), (R, dgamma)))
    a_jump_off = _single_positive(sp.solve(sp.diff(depth_of_radius, a), a), "jump-off radius")
    add(Relation("jump_off_radius", "", "radius where dd/da = 0: jump-off under displacement control",
                 a, a_jump_off, (R, E_star, dgamma)))
    add(Relation("jump_off_depth", "", "depth at the jump-off under displacement control",
                 d, sp.simplify(depth_of_radius.subs(a, a_jump_off)), (R, E_star, dgamma)))
    add(Relation("jump_off_force", "", "normal force at the jump-off under displacement control",
                 F_N, sp.simplify(force_jkr.subs(a, a_jump_off)), (R, dgamma)))
    return hertz_radius


def _derive_tangential_springs(add: AddRelation, depth_of_radius: sp.Expr) -> sp.Expr:
    """(11)–(13): the tangential springs' critical shift, a fixed contact's fretting loop, and the branch's
    integral over the radius (for attach maps); returns the critical shift ``ū(a)``."""
    # (11) τ = Σ G* Δx u_x / (π a²); stationary sliding: n springs all at ū, n Δx = 2a
    tau_stationary = (G_star * dx * n_springs * u_bar / (sp.pi * a**2)).subs(n_springs, 2 * a / dx)
    add(Relation("stationary_shear_stress", "(12)", "mean shear stress with every spring at ū",
                 tau0, sp.simplify(tau_stationary), (u_bar, a, G_star)))
    critical_shift = sp.solve(sp.Eq(tau0, tau_stationary), u_bar)[0]
    jkr_depth_integral = sp.integrate(depth_of_radius.subs(a, x), (x, 0, a))
    add(Relation("critical_shift", "(13)", "critical spring shift ū(a)",
                 u_bar, critical_shift, (a, tau0, G_star)))
    add(Relation("fretting_dissipated_energy", "", "energy dissipated per cycle x: −X → X → −X of a fixed "
                 "contact (X > ū): the parallelogram's area", W, _fretting_loop_work(critical_shift),
                 (a, X, tau0, G_star)))
    add(Relation("jkr_depth_integral", "(9)", "integral of the branch (9) over the radius, for attach maps",
                 sp.Integral(d, (a, 0, a)), jkr_depth_integral, (a, R, E_star, dgamma)))
    return critical_shift


def _fretting_loop_work(critical_shift: sp.Expr) -> sp.Expr:
    """The work of one fretting cycle of a fixed contact: every spring shares one anchor, clipped to
    ``[x − ū, x + ū]``; ``x: −X → X → −X`` (``X > ū``). ``F_x = 2G* a (x − Y)`` rises from ``−P`` with slope
    ``2G* a`` to the plateau ``P = 2G* a ū``, and back."""
    plateau = 2 * G_star * a * u_bar
    rising = sp.integrate(-plateau + 2 * G_star * a * (x + X), (x, -X, -X + 2 * u_bar)) \
        + sp.integrate(plateau, (x, -X + 2 * u_bar, X))
    falling = sp.integrate(-plateau, (x, -X, X - 2 * u_bar)) \
        + sp.integrate(plateau - 2 * G_star * a * (X - x), (x, X - 2 * u_bar, X))
    return sp.factor(sp.simplify((rising - falling).subs(u_bar, critical_shift)))


def _derive_scenario_A(add: AddRelation, depth_of_radius: sp.Expr, hertz_radius: sp.Expr,
                       critical_shift: sp.Expr) -> None:
    """(14), (17), (18): slip onset in scenario A, the critical angles of both scenarios, and the branch's radius
    at a given depth as a quartic."""
    # on the path (14) x = d / tan α; slip starts when x reaches ū(a)
    onset_A = sp.Eq(d / tan_alpha, critical_shift)
    d_crit_A_hertz = _single_positive(sp.solve(onset_A.subs(a, hertz_radius), d), "(17)")
    add(Relation("d_crit_A_hertz", "(17)", "slip-onset depth, scenario A, non-adhesive",
                 d, d_crit_A_hertz, (tan_alpha, R, tau0, G_star)))
    cubic = _reduce_to_polynomial(tan_alpha * critical_shift, depth_of_radius, divide_by=s)
    add(Relation("slip_A_jkr_cubic", "(18)", "scenario A with adhesion, cubic in s = sqrt(a)",
                 cubic, sp.Integer(0), (s, tan_alpha, R, tau0, G_star, E_star, dgamma), variable=s))
    add(Relation("slip_A_jkr_cardano", "(18)", "positive root of the cubic (Cardano)",
                 s, _positive_cubic_root(cubic), (tan_alpha, R, tau0, G_star, E_star, dgamma)))
    add(Relation("slip_depth_A", "(18)", "depth of slip onset from its contact radius, scenario A",
                 d, tan_alpha * critical_shift, (a, tan_alpha, tau0, G_star)))
    critical_angle = sp.atan(sp.solve(sp.Eq(d_max / tan_alpha, critical_shift), tan_alpha)[0])
    add(Relation("critical_angle_A", "", "critical angle: slip onset exactly at d_max, scenario A",
                 alpha, critical_angle, (a, d_max, tau0, G_star)))
    critical_angle_B = sp.atan(sp.solve(sp.Eq(d, d_max - tan_alpha * critical_shift), tan_alpha)[0])
    add(Relation("critical_angle_B", "(21)",
                 "angle of a pull-off path (19) from d_max that reaches slip onset at (a, d)",
                 alpha, critical_angle_B, (a, d, d_max, tau0, G_star)))
    critical_angle_B_plus = sp.atan(sp.solve(sp.Eq(d, d_max + tan_alpha * critical_shift), tan_alpha)[0])
    add(Relation("critical_angle_B_indentation", "(21)",
                 "angle of an indentation path from d_max (the + sign) that reaches slip onset at (a, d)",
                 alpha, critical_angle_B_plus, (a, d, d_max, tau0, G_star)))
    depth_quartic = _reduce_to_polynomial(d, depth_of_radius)
    add(Relation("jkr_radius_quartic", "(9)", "contact radius at a given depth, quartic in s = sqrt(a)",
                 depth_quartic, sp.Integer(0), (s, d, R, E_star, dgamma), variable=s))


def _derive_scenario_B(add: AddRelation, depth_of_radius: sp.Expr, hertz_radius: sp.Expr,
                       critical_shift: sp.Expr) -> None:
    """(19), (20), (21): slip onset in scenario B, out of ``d_max`` (pull-off) and further in (indentation)."""
    onset_B = sp.Eq((d_max - d) / tan_alpha, critical_shift.subs(a, hertz_radius))
    kk = sp.pi * tau0 * sp.sqrt(R) * tan_alpha / (2 * G_star)
    squared = sp.expand((onset_B.lhs**2 - onset_B.rhs**2) * tan_alpha**2)
    quadratic = sp.expand(squared.subs(tau0, k * 2 * G_star / (sp.pi * sp.sqrt(R) * tan_alpha)))
    add(Relation("slip_B_hertz_quadratic", "(20)", "scenario B non-adhesive, squared slip condition",
                 sp.collect(quadratic, d), sp.Integer(0), (d, d_max, k), variable=d))
    add(Relation("slip_B_hertz_k", "(20)", "k of the quadratic (20)", k, kk, (tan_alpha, R, tau0, G_star)))
    roots = sp.solve(quadratic, d)
    lower, upper = sorted(roots, key=lambda e: float(e.subs({d_max: 1, k: 1})))
    add(Relation("d_crit_B_hertz_pull_off_textbook", "(20)", "smaller root of (20), as the quadratic formula gives it",
                 d, lower, (d_max, k)))
    # Vieta: the product of the roots is the constant coefficient d_max²; dividing it by the
    # larger root avoids the cancellation of the quadratic formula when k² >> d_max (α → 90°).
    product = sp.Poly(quadratic, d).all_coeffs()[-1]
    add(Relation("d_crit_B_hertz_pull_off", "(20)", "smaller root of (20): pull-off at angle α (Vieta form)",
                 d, product / upper, (d_max, k)))
    add(Relation("d_crit_B_hertz_indentation", "(20)", "larger root of (20): indentation at angle α from d_max",
                 d, upper, (d_max, k)))
    for sign, branch in ((-1, "pull_off"), (+1, "indentation")):
        quartic = _reduce_to_polynomial(d_max + sign * tan_alpha * critical_shift, depth_of_radius)
        add(Relation(f"slip_B_jkr_quartic_{branch}", "(21)",
                     f"scenario B with adhesion ({'−' if sign < 0 else '+'} sign), quartic in s = sqrt(a)",
                     quartic, sp.Integer(0), (s, tan_alpha, d_max, R, tau0, G_star, E_star, dgamma), variable=s))
        add(Relation(f"slip_depth_B_{branch}", "(21)", "depth of slip onset from its contact radius, scenario B",
                     d, d_max + sign * tan_alpha * critical_shift, (a, tan_alpha, d_max, tau0, G_star)))


@functools.cache
def derive_power_law() -> Relation:
    """The MDR profile of ``f = c r^n`` for general ``n`` (eq. (3)).

    Kept apart from :func:`derive` because SymPy needs several seconds for
    the general Beta-type integral; the paraboloid (4) and the cone are its
    cases ``n = 2, c = 1/(2R)`` and ``n = 1, c = tan θ`` (the tests check it).
    """
    return _cached("power_law", lambda: [power_law_afresh()])[0]


def power_law_afresh() -> Relation:
    """The derivation of :func:`derive_power_law` with SymPy (about 6 s), bypassing any cache."""
    return Relation("profile_power_law", "(3)", "MDR profile of f = c r^n", g(x),
                    abel_transform(c * r**n), (x, c, n))


#: Keys of the power-law relations (:func:`derive_power_law_model`), beside ``profile_power_law``.
POWER_LAW_KEYS = ("power_law_depth", "power_law_depth_slope", "power_law_depth_integral", "power_law_normal_force",
                  "power_law_branch_normal_force", "power_law_hertz_radius", "power_law_jump_in_radius",
                  "power_law_pull_off_radius", "power_law_pull_off_force", "power_law_jump_off_radius",
                  "power_law_jump_off_depth", "power_law_jump_off_force", "power_law_d_crit_A_hertz",
                  "flat_punch_normal_force", "flat_punch_pull_off_depth", "flat_punch_pull_off_force",
                  "flat_punch_d_crit_A", "abel_transform_angular")


@functools.cache
def derive_power_law_model() -> dict[str, Relation]:
    """Heß's rule for the power law ``f = c rⁿ`` and for the flat punch, derived as (7)–(10), (17) are for
    the paraboloid (their cases ``n = 2, c = 1/(2R)``; the tests check it).

    The depth of the adhesive contact of radius ``a`` is ``d = κ c aⁿ − sqrt(2π a Δγ / E*)`` (generalised
    (9)); the pull-off radius under force control ``a^(2n−1) = 9 Δγ / (2 E* n² κ² c²)``, ``κ = √π Γ(n/2 + 1) /
    Γ(n/2 + 1/2)`` (Heß, in Popov & Heß, *Method of Dimensionality Reduction in Contact Mechanics and
    Friction*, Springer 2015, ch. 6; Borodich, Galanov & Suarez-Alvarez, J. Mech. Phys. Solids 68 (2014) 14,
    for the JKR-type problem of power-law punches). The radius at a given depth has no closed form for
    general ``n`` (nor has the slip onset with adhesion, (18)): the analytic layer solves for it.
    """
    return cached_relations("power_law_model", power_law_model_afresh)


def power_law_model_afresh() -> dict[str, Relation]:
    """The derivation of :func:`derive_power_law_model` with SymPy (about 8 s), bypassing any cache."""
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> Relation:
        out[rel.key] = rel
        return rel

    profile = derive_power_law().rhs  # g(x) = κ c xⁿ
    _derive_angular_abel_transform(add, profile)
    hess, hertz_radius = _derive_power_law_branch(add, profile)
    # (17) for the power law: on the path (14) x = d / tan α slip starts when x reaches ū(a) = K a, a = a(d);
    # d^((n−1)/n) ∝ tan α: a closed form for n ≠ 1. The cone (n = 1) slides from first contact or never.
    critical_shift = derive()["critical_shift"].rhs  # (13)
    onset = sp.Eq(d / tan_alpha, critical_shift.subs(a, hertz_radius))
    add(Relation("power_law_d_crit_A_hertz", "(17)", "slip-onset depth, scenario A, non-adhesive power law "
                 "(n != 1)", d, _single_positive(sp.solve(onset, d), "power-law (17)"), (tan_alpha, c, n, tau0, G_star)))
    _derive_flat_punch(add, hess, critical_shift)
    return out


def _derive_angular_abel_transform(add: AddRelation, profile: sp.Expr) -> None:
    """(3) with ``r = x sin θ``: ``g(x) = x ∫_0^{π/2} f'(x sin θ) dθ``, no singularity at ``r = x`` (the tabulated
    profile's quadrature); checked against ``profile``, the power law's ``g(x)``, on whole exponents (SymPy
    integrates ``sinⁿ⁻¹ θ`` for those, not for a symbol ``n``)."""
    angular = x * sp.Integral(sp.Subs(sp.Derivative(f(r), r), r, x * sp.sin(theta)), (theta, 0, sp.pi / 2))
    for exponent in (1, 2, 3, 4):
        power = c * r**exponent
        on_power_law = x * sp.integrate(sp.diff(power, r).subs(r, x * sp.sin(theta)), (theta, 0, sp.pi / 2))
        if sp.simplify(on_power_law - profile.subs(n, exponent)) != 0:
            raise RuntimeError(f"the angular form of the Abel transform does not give g(x) of c r^{exponent}")
    add(Relation("abel_transform_angular", "(3)", "Abel transform with r = x sin(theta): no singular integrand",
                 g(x), angular))


def _derive_power_law_branch(add: AddRelation, profile: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """(7)–(10) for the power law of MDR profile ``profile``: the adhesive branch, its forces, its jump-in,
    pull-off and jump-off; returns Heß's limit (8) and the non-adhesive radius ``a(d)``."""
    displacement = d - profile  # (7)
    hess = sp.sqrt(2 * sp.pi * a * dgamma / E_star)  # (8)
    depth_of_radius = sp.solve(sp.Eq(-displacement.subs(x, a), hess), d)[0]
    arguments = (a, c, n, E_star, dgamma)
    add(Relation("power_law_depth", "(9)", "indentation depth of the adhesive power-law contact of radius a",
                 d, depth_of_radius, arguments))
    add(Relation("power_law_depth_slope", "(9)", "slope dd/da of the adhesive power-law branch",
                 sp.Derivative(d, a), sp.diff(depth_of_radius, a), arguments))
    add(Relation("power_law_depth_integral", "(9)", "integral of the power-law branch over the radius",
                 sp.Integral(d, (a, 0, a)), sp.simplify(sp.integrate(depth_of_radius.subs(a, x), (x, 0, a))),
                 arguments))
    force_pinned = sp.expand(2 * E_star * sp.integrate(displacement, (x, 0, a)))  # (10)
    add(Relation("power_law_normal_force", "(10)", "normal force of the springs in contact under a power law, "
                 "any d and a", F_N, force_pinned, (d, a, c, n, E_star)))
    force_branch = sp.simplify(sp.expand(force_pinned.subs(d, depth_of_radius)))
    add(Relation("power_law_branch_normal_force", "(10)", "normal force of the adhesive power-law contact of "
                 "radius a", F_N, force_branch, arguments))
    hertz_radius = _single_positive(sp.solve(sp.Eq(d, depth_of_radius.subs(dgamma, 0)), a), "power-law radius")
    add(Relation("power_law_hertz_radius", "(16)", "non-adhesive contact radius of the power law",
                 a, hertz_radius, (d, c, n)))
    _derive_power_law_branch_points(add, depth_of_radius, force_branch)
    return hess, hertz_radius


def _derive_power_law_branch_points(add: AddRelation, depth_of_radius: sp.Expr, force_branch: sp.Expr) -> None:
    """The power law's jump-in, pull-off (force control) and jump-off (displacement control) on its branch."""
    fixed = (c, n, E_star, dgamma)
    add(Relation("power_law_jump_in_radius", "", "contact radius at zero depth (jump-in), power law",
                 a, _single_positive(sp.solve(sp.Eq(depth_of_radius, 0), a), "power-law jump-in"), fixed))
    a_force_control = _single_positive(sp.solve(sp.diff(force_branch, a), a), "power-law pull-off radius")
    add(Relation("power_law_pull_off_radius", "", "radius of minimal force dF_N/da = 0 (force control), power law",
                 a, a_force_control, fixed))
    add(Relation("power_law_pull_off_force", "", "pull-off force under force control, power law",
                 F_N, sp.simplify(force_branch.subs(a, a_force_control)), fixed))
    a_jump_off = _single_positive(sp.solve(sp.diff(depth_of_radius, a), a), "power-law jump-off radius")
    add(Relation("power_law_jump_off_radius", "", "radius where dd/da = 0: jump-off under displacement control, "
                 "power law", a, a_jump_off, fixed))
    add(Relation("power_law_jump_off_depth", "", "depth at the jump-off under displacement control, power law",
                 d, sp.simplify(depth_of_radius.subs(a, a_jump_off)), fixed))
    add(Relation("power_law_jump_off_force", "", "normal force at the jump-off under displacement control, "
                 "power law", F_N, sp.simplify(force_branch.subs(a, a_jump_off)), fixed))


def _derive_flat_punch(add: AddRelation, hess: sp.Expr, critical_shift: sp.Expr) -> None:
    """The flat punch of radius ``a``: ``g = 0`` under it, every spring compressed by ``d``; its force, Kendall's
    pull-off (Heß's limit ``hess`` at every spring at once) and scenario A's onset (``critical_shift`` (13))."""
    punch_force = 2 * E_star * sp.integrate(d, (x, 0, a))
    add(Relation("flat_punch_normal_force", "(10)", "normal force of a flat punch of radius a at depth d",
                 F_N, punch_force, (d, a, E_star)))
    pull_off_depth = sp.solve(sp.Eq(-d, hess), d)[0]  # the edge spring (as every spring) at Heß's limit (8)
    add(Relation("flat_punch_pull_off_depth", "", "depth at which the flat punch comes off (all springs at once)",
                 d, pull_off_depth, (a, E_star, dgamma)))
    add(Relation("flat_punch_pull_off_force", "", "pull-off force of the flat punch (Kendall 1971)",
                 F_N, sp.simplify(punch_force.subs(d, pull_off_depth)), (a, E_star, dgamma)))
    # every spring attaches at first contact at one x: all reach ū together (onset is full slip)
    add(Relation("flat_punch_d_crit_A", "(17)", "slip-onset (and full-slip) depth, scenario A, flat punch",
                 d, sp.solve(sp.Eq(d / tan_alpha, critical_shift), d)[0], (a, tan_alpha, tau0, G_star)))


#: Keys of the friction-law relations (:func:`derive_friction_model`).
FRICTION_KEYS = ("coulomb_critical_shift", "cattaneo_mindlin_stick_radius", "cattaneo_mindlin_force",
                 "cattaneo_mindlin_full_slip_shift")


@functools.cache
def derive_friction_model() -> dict[str, Relation]:
    """The local Coulomb law of the MDR springs and the Cattaneo–Mindlin solution it gives.

    A spring of width ``Δx`` holds the tangential force ``G* Δx u`` up to ``μ`` times its normal force
    ``E* Δx u_z``: its cap is ``ū = μ (E*/G*) u_z`` (Popov & Heß 2015, ch. 5). Under a constant depth ``d``
    of a non-adhesive power-law indenter, a tangential shift ``u_x`` of the indenter from rest leaves the
    springs with ``μ (E*/G*) (d − g(ξ)) > u_x`` sticking: the stick radius ``c`` has ``g(c) = d − u_x G*/(μ E*)``,
    and ``F_x = 2G* (u_x c + ∫_c^a μ (E*/G*)(d − g) dξ)``. The derivation checks that this is
    ``μ (F_N(d) − F_N(d − u_x G*/(μ E*)))`` (Cattaneo 1938, Mindlin 1949; for any profile, Jäger 1998 and
    Ciavarella 1998): the tangential curve is the normal one, shifted and scaled.
    """
    return cached_relations("friction_model", friction_model_afresh)


def friction_model_afresh() -> dict[str, Relation]:
    """The derivation of :func:`derive_friction_model` with SymPy (about 15 s), bypassing any cache."""
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> None:
        out[rel.key] = rel

    # the spring slides once its tangential force reaches μ times its normal force
    cap = sp.solve(sp.Eq(G_star * dx * u_bar, mu * E_star * dx * u_z), u_bar)[0]
    add(Relation("coulomb_critical_shift", "(13)", "Coulomb's critical spring shift: mu (E*/G*) times the "
                 "spring's compression", u_bar, cap, (u_z, mu, E_star, G_star)))
    model = derive_power_law_model()
    hertz_radius = model["power_law_hertz_radius"].rhs  # a(d) of the non-adhesive power law
    normal_force = model["power_law_normal_force"].rhs.subs(a, hertz_radius)  # F_N(d)
    lowered = d - u_x / cap.subs(u_z, 1)  # the depth whose radius is the stick radius
    stick = hertz_radius.subs(d, lowered)
    profile = derive_power_law().rhs
    force = 2 * G_star * (u_x * stick + cap.subs(u_z, 1) * sp.integrate(d - profile, (x, stick, hertz_radius)))
    jager_ciavarella = mu * (normal_force - normal_force.subs(d, lowered))
    if sp.simplify(sp.expand(force - jager_ciavarella)) != 0:
        raise RuntimeError("the Cattaneo-Mindlin force of the springs is not mu (F_N(d) - F_N(d - u_x/kappa))")
    arguments = (u_x, d, mu, c, n, E_star, G_star)
    add(Relation("cattaneo_mindlin_stick_radius", "", "stick radius of a power-law contact at depth d shifted "
                 "by u_x (Coulomb's law, from rest)", a, stick, arguments))
    add(Relation("cattaneo_mindlin_force", "", "tangential force of a power-law contact at depth d shifted by u_x "
                 "from rest (Cattaneo-Mindlin), u_x below full slip", F_x, jager_ciavarella, arguments))
    add(Relation("cattaneo_mindlin_full_slip_shift", "", "tangential shift at which the whole contact slides "
                 "(Coulomb's law, from rest): the centre's cap", u_x, sp.solve(sp.Eq(lowered, 0), u_x)[0],
                 (d, mu, E_star, G_star)))
    return out


#: Keys of the relations of Coulomb's law with adhesion (:func:`derive_adhesive_friction_model`).
ADHESIVE_FRICTION_KEYS = ("compression_boundary", "compression_boundary_rate", "adhesive_friction_cap",
                          "adhesive_virgin_force", "adhesive_full_slip_shift", "adhesive_full_slip_force",
                          "compressed_normal_force", "flat_punch_friction_cap", "flat_punch_full_slip_force",
                          "flat_punch_loop_energy", "adhesive_seen_piece_turn", "adhesive_compressed_level",
                          "adhesive_tensile_level", "adhesive_crossing_anchor", "adhesive_onset_excess_A",
                          "adhesive_onset_turn_A", "adhesive_onset_excess_B")


@functools.cache
def derive_adhesive_friction_model() -> dict[str, Relation]:
    """Coulomb's law of the springs in an adhesive contact (Heß's rule (8)–(9) with the caps of
    :func:`derive_friction_model`).

    A spring at ``ξ`` is compressed where ``d > g(ξ)``, in tension (the adhesive annulus) where ``d < g(ξ) <= g(a)``;
    its cap is ``ū(ξ) = K a + κ max(d − g(ξ), 0)``. The boundary ``x_c`` (``g(x_c) = d``) is the non-adhesive radius
    (16) of the depth, whatever the adhesive radius ``a >= x_c`` does: it moves with the depth alone,
    ``dx_c/dd = 1/g'(x_c)``. The cap is continuous there (``K a`` on both sides), so a spring crossing ``x_c`` keeps
    its shift. Under ``"coulomb"`` alone (``K = 0``) every spring in tension slides with zero shift (it follows the
    indenter) and enters compression at ``x_c`` with none, as a spring attaching to a contact without adhesion does:
    the compressed zone is the non-adhesive contact of the same depth history. At a constant depth, from rest,
    the derivation sums the springs (stick, compressed at the cap, tensile at ``K a``) and checks that
    ``F_x = τ0 π a² + μ (F_N^H(d) − F_N^H(d − (u_x − K a)/κ))`` for ``u_x >= K a``: the Coulomb part is
    Cattaneo–Mindlin's of the compressed zone, free of ``Δγ`` and of ``a``; full slip is ``τ0 π a² + μ F_N^H(d)``,
    ``F_N^H(d) = F_N(d, a) + 2E* ∫_{x_c}^a (g − d) dξ`` the compressed springs' push alone.
    """
    return cached_relations("adhesive_friction_model", adhesive_friction_model_afresh)


def adhesive_friction_model_afresh() -> dict[str, Relation]:
    """The derivation of :func:`derive_adhesive_friction_model` with SymPy, bypassing any cache."""
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> None:
        out[rel.key] = rel

    profile = derive_power_law().rhs  # g(ξ) = κ_n c ξⁿ
    model = derive_power_law_model()
    hertz_radius = model["power_law_hertz_radius"].rhs
    boundary = _single_positive(sp.solve(sp.Eq(profile, d), x), "compression boundary")
    if not _vanishes(boundary - hertz_radius):
        raise RuntimeError("the compression boundary g(x_c) = d is not the non-adhesive radius (16)")
    add(Relation("compression_boundary", "(7)", "boundary x_c between compressed and tensile springs, g(x_c) = d: the "
                 "non-adhesive radius of the depth", x, boundary, (d, c, n)))
    rate = sp.simplify(sp.diff(boundary, d))
    if not _vanishes(rate * sp.diff(profile, x).subs(x, boundary) - 1):
        raise RuntimeError("dx_c/dd is not 1/g'(x_c)")
    add(Relation("compression_boundary_rate", "(7)", "dx_c/dd: the boundary moves with the depth alone", 
                 sp.Derivative(x, d), rate, (d, c, n)))
    kappa = derive_friction_model()["coulomb_critical_shift"].rhs.subs(u_z, 1)  # κ = μ E*/G*
    tau0_cap = derive()["critical_shift"].rhs  # K a (13)
    cap = tau0_cap + kappa * sp.Max(d - profile, 0)
    if not (_vanishes(cap.subs(x, boundary) - tau0_cap) and _vanishes(cap.subs(x, 0) - tau0_cap - kappa * d)):
        raise RuntimeError("the cap is not K a at the compression boundary and K a + κ d at the centre")
    add(Relation("adhesive_friction_cap", "(13)", "the cap of the spring at x: K a + mu (E*/G*) max(d - g(x), 0)",
                 u_bar, cap, (x, d, a, tau0, mu, c, n, E_star, G_star)))
    _derive_adhesive_virgin_curve(add, profile, boundary, kappa, tau0_cap, model)
    _derive_flat_punch_friction(add, cap, kappa, tau0_cap)
    _derive_seen_piece_turn(add, profile, model)
    _derive_crossing_anchor(add, cap, profile, boundary, kappa, tau0_cap)
    _derive_adhesive_onset_A(add, profile, model, kappa, tau0_cap)
    _derive_adhesive_onset_B(add, cap, profile, model, tau0_cap)
    return out


def _derive_adhesive_onset_B(add: AddRelation, cap: sp.Expr, profile: sp.Expr, model: dict[str, Relation],
                             tau0_cap: sp.Expr) -> None:
    """Scenario B's pull-off at angle with both parts of the cap and adhesion, before any spring slides.

    After the vertical stroke every spring in contact is anchored at ``x = 0``: going out along
    ``x = (d_max − d) cot α`` all hold the same shift. On any adhesive branch (9) ``d = g(a) − Δl(a)`` with ``Δl >= 0``,
    so the edge is in tension (``d <= g(a)``) and its cap is ``K a``, the least of all (the caps rise inwards): the
    first spring to slide is the edge's, where ``(d_max − d) cot α = K a`` — (21) of ``τ0`` alone on the same branch,
    free of ``μ``. (The indentation branch, further in, is scenario A's springs about the contact of ``d_max``, the
    excess and turn of :func:`_derive_adhesive_onset_A`.)"""
    cot = sp.Symbol("cot_alpha", positive=True)
    branch = model["power_law_depth"].rhs  # d on the branch of the work dgamma at the radius a
    edge_cap = cap.subs(x, a).subs(d, branch)
    if not _vanishes(sp.simplify(edge_cap - tau0_cap)):
        raise RuntimeError("the edge of an adhesive contact is not in tension: its cap is not K a")
    excess = (d_max - d) * cot - edge_cap
    add(Relation("adhesive_onset_excess_B", "(21)", "shift over cap of the edge spring on scenario B's pull-off at "
                 "angle (every spring anchored at x = 0; the edge in tension, its cap K a): (d_max - d) cot - K a", X,
                 sp.simplify(excess), (d, d_max, a, cot, tau0, G_star)))


def _derive_adhesive_onset_A(add: AddRelation, profile: sp.Expr, model: dict[str, Relation], kappa: sp.Expr,
                             tau0_cap: sp.Expr) -> None:
    """Scenario A's springs with both parts of the cap and adhesion, before any slides.

    Along ``x = d cot α`` from the first contact at ``d = 0`` (the springs under the jump-in radius ``a_J`` attach
    there, ``d_ξ = 0``; the others at their depth on the ``Δγ0`` branch, ``d_ξ = d0(ξ)``) a spring holds the shift
    ``(d − d_ξ) cot α`` against its cap ``K a + κ max(d − g(ξ), 0)``. The excess of shift over cap is largest at
    ``a_J`` among the jump-in springs (their caps fall outwards), decreases outwards in the tensile annulus
    (``d0`` rises), and in the compressed grown springs has ``∂/∂ξ = cot α Δl0'(ξ) − (cot α − κ) g'(ξ)``: increasing
    where ``cot α <= κ``, else with one maximum, at ``ξ*`` (``adhesive_onset_turn_A``, free of ``d``). The onset is the
    least depth where the largest excess, over ``a_J``, ``x_c`` and ``ξ*`` where they lie in the contact, reaches 0."""
    cot = sp.Symbol("cot_alpha", positive=True)
    grown = model["power_law_depth"].rhs.subs(a, x)  # d0(ξ)
    excess = (d - grown) * cot - tau0_cap - kappa * (d - profile)
    add(Relation("adhesive_onset_excess_A", "(13)", "shift over cap of a compressed spring grown along the dgamma0 "
                 "branch in scenario A (cot alpha the path's): (d - d0(xi)) cot - K a - mu (E*/G*) (d - g(xi))", X,
                 excess, (x, d, a, cot, tau0, mu, dgamma, c, n, E_star, G_star)))
    slope = sp.diff(excess, x)
    if sp.diff(slope, d) != 0 or sp.diff(slope, a) != 0:
        raise RuntimeError("the excess's slope in xi depends on the depth or the radius")
    turns = sp.solve(sp.Eq(sp.expand(slope * sp.sqrt(x)), 0), x)
    if len(turns) != 1:
        raise RuntimeError(f"the scenario A excess has {len(turns)} turns, not one")
    add(Relation("adhesive_onset_turn_A", "(9)", "radius of the largest shift over cap of the compressed springs "
                 "grown along the dgamma0 branch in scenario A (exists where cot alpha > mu E*/G*)", x, turns[0],
                 (cot, mu, dgamma, c, n, E_star, G_star)))


def _derive_crossing_anchor(add: AddRelation, cap: sp.Expr, profile: sp.Expr, boundary: sp.Expr, kappa: sp.Expr,
                            tau0_cap: sp.Expr) -> None:
    """The levels of the two regions and the anchor a spring keeps crossing ``x_c`` at a cap.

    A spring at ``ξ`` is at the cap ``σ`` (``σ = ±1``) where ``σ (x − Y) >= ū(ξ)``, i.e. where its anchor is at or
    beyond ``x − σ ū(ξ)``. In the compressed zone (``g < d``) that bound is ``x − σ (K a + κ d) + σ κ g(ξ)``: the cap
    compares ``Y − σ κ g`` with the level ``x − σ (K a + κ d)``, one for all its springs; in the tensile annulus
    (``g > d``) the bound is the level ``x − σ K a`` itself. At ``x_c`` both are ``x − σ K a`` (the cap is continuous),
    so a spring crossing ``x_c`` at a cap keeps ``x(τ) − σ K a(τ)`` of the instant ``τ`` it crosses, ``d(τ) = g(ξ)``:
    on a path segment (``x = x_s + v_x (t − t_s)``, ``d = d_s + v_d (t − t_s)``)
    ``Y(ξ) = x_s + (v_x/v_d)(g(ξ) − d_s) − σ K a`` with ``a`` the radius at that depth (constant while pinned, on a
    branch of (9) while it moves), the anchor seen by either region at the level it had then.
    """
    sigma = sp.Symbol("sigma", real=True)
    position, x_s, d_s = sp.Symbol("x_i", real=True), sp.Symbol("x_s", real=True), sp.Symbol("d_s", real=True)
    v_x, v_d, time, t_s = (sp.Symbol(name, real=True) for name in ("v_x", "v_d", "t_cross", "t_s"))
    compressed_cap = tau0_cap + kappa * (d - profile)
    compressed_level = sp.simplify(position - sigma * compressed_cap - sigma * kappa * profile)
    if sp.diff(compressed_level, x) != 0:
        raise RuntimeError("the compressed zone's level depends on the spring")
    tensile_level = position - sigma * tau0_cap
    if not (_vanishes(cap.subs(x, boundary) - tau0_cap)
            and _vanishes(compressed_level + sigma * kappa * profile.subs(x, boundary) - tensile_level)):
        raise RuntimeError("the regions' bounds differ at x_c")
    arguments = (position, sigma, d, a, tau0, mu, E_star, G_star)
    add(Relation("adhesive_compressed_level", "(13)", "level of the cap sigma in the compressed zone, against which it "
                 "compares Y - sigma mu (E*/G*) g: x - sigma (K a + mu (E*/G*) d)", X, compressed_level, arguments))
    add(Relation("adhesive_tensile_level", "(13)", "level of the cap sigma in the tensile annulus: x - sigma K a",
                 X, tensile_level, (position, sigma, a, tau0, G_star)))
    crossing = sp.solve(sp.Eq(d_s + v_d * (time - t_s), profile), time)[0]  # d(τ) = g(ξ)
    anchor = sp.expand((x_s + v_x * (time - t_s)).subs(time, crossing) - sigma * tau0_cap)
    seen = compressed_level.subs({position: x_s + v_x * (crossing - t_s), d: profile})
    if not _vanishes(anchor - sigma * kappa * profile - seen):
        raise RuntimeError("the crossing anchor is not at the compressed level of its instant")
    add(Relation("adhesive_crossing_anchor", "(13)", "anchor a spring at xi keeps crossing x_c at the cap sigma on a "
                 "path segment: x_s + (v_x/v_d)(g(xi) - d_s) - sigma K a", X, anchor,
                 (x, x_s, d_s, v_x, v_d, sigma, a, tau0, c, n, G_star)))


def _derive_seen_piece_turn(add: AddRelation, profile: sp.Expr, model: dict[str, Relation]) -> None:
    """Where a piece of anchors laid along the ``Δγ0`` branch turns, as a cap sees it in the compressed zone.

    Springs attaching as the radius grows along the ``Δγ0`` branch ``d0(ξ)`` (9) get ``Y = x0 + r (d0(ξ) − d_ref)``
    (``r = v_x/v_d`` of the segment); once ``x_c`` passes them the cap ``±`` compares ``Z = Y − σ g(ξ)`` with its level
    (``σ = ±κ``). With adhesion ``d0 ≠ g``, so ``Z`` is no piece of the same kind and not monotone: ``dZ/dξ = 0`` where
    ``(r − σ) g'(ξ) = r sqrt(2π Δγ0/(E* ξ))/2``, one radius when ``r/(r − σ) > 0`` (none otherwise), derived here
    for the power law. (The groundwork of ``"tau0+coulomb"`` with adhesion in the continuum: the pieces split there.)
    """
    ratio, sigma = sp.Symbol("r_Y", real=True), sp.Symbol("sigma", real=True)
    attach = model["power_law_depth"].rhs.subs(a, x)
    seen = ratio * attach - sigma * profile  # Z up to the constant x0 − r d_ref
    slope = sp.simplify(sp.diff(seen, x) * sp.sqrt(x))
    roots = sp.solve(sp.Eq(slope, 0), x)
    if len(roots) != 1:
        raise RuntimeError(f"the seen piece's slope has {len(roots)} roots, not one")
    add(Relation("adhesive_seen_piece_turn", "(9)", "radius where a piece of anchors laid along the dgamma0 branch "
                 "turns as a cap sees it in the compressed zone, Y - sigma g with sigma = cap mu E*/G* (exists where "
                 "r_Y/(r_Y - sigma) > 0)", x, roots[0], (ratio, sigma, dgamma, c, n, E_star)))


def _derive_flat_punch_friction(add: AddRelation, cap: sp.Expr, kappa: sp.Expr, tau0_cap: sp.Expr) -> None:
    """The friction laws on the flat punch of radius ``a``: ``g = 0`` under the face, so every spring has the cap
    ``K a + κ max(d, 0)`` (the power law's ``cap`` at ``g = 0``; in tension at ``d < 0``, the adhesive punch held
    above the surface, ``K a`` alone) and, attached together at the first touch, one anchor history: the springs are
    one play operator ``u ← clip(u + Δx, −ū, ū)``, ``F_x = 2G* a u``, piecewise linear in time on a straight path
    segment (``ū`` linear in ``d`` on either side of ``d = 0``). Full slip is ``τ0 π a² + μ F_N^H``, ``F_N^H`` the
    punch's push ``2E* a max(d, 0)``; the loop ``−X → X → −X`` at a constant depth (``X >= ū``) is a parallelogram,
    checked against Masing's ``8 ∫_0^X F₀ − 4 X F₀(X)`` of the virgin curve ``F₀ = 2G* a min(u, ū)``."""
    punch_cap = cap.subs(x, 0)  # g(0) = 0: the cap of every spring under the face
    under_face = sp.Max(d, 0)
    if not _vanishes(punch_cap - tau0_cap - kappa * d) or sp.simplify(punch_cap.subs(d, -d_max) - tau0_cap) != 0:
        raise RuntimeError("the flat punch's cap is not K a + κ d when pressed and K a in tension")
    add(Relation("flat_punch_friction_cap", "(13)", "the cap of every spring under a flat punch of radius a: "
                 "K a + mu (E*/G*) max(d, 0)", u_bar, tau0_cap + kappa * under_face, (d, a, tau0, mu, E_star, G_star)))
    push = 2 * E_star * sp.integrate(under_face, (x, 0, a))  # the compressed springs' push, 0 in tension
    full = sp.simplify(2 * G_star * sp.integrate(tau0_cap + kappa * under_face, (x, 0, a)))
    if sp.simplify(full - sp.pi * tau0 * a**2 - mu * push) != 0:
        raise RuntimeError("the flat punch's full slip is not tau0 pi a^2 + mu 2 E* a max(d, 0)")
    add(Relation("flat_punch_full_slip_force", "", "tangential force of full slip of a flat punch of radius a: "
                 "tau0 pi a^2 + mu 2 E* a max(d, 0)", F_x, sp.pi * tau0 * a**2 + mu * push, (d, a, tau0, mu, E_star)))
    u = sp.Symbol("u", positive=True)
    virgin = 2 * G_star * a * sp.Min(u, u_bar)  # F₀ from rest: every spring sticks up to the common cap
    masing = sp.simplify(8 * sp.integrate(virgin.subs(u, x), (x, 0, X)) - 4 * X * virgin.subs(u, X))
    parallelogram = 4 * (2 * G_star * a * u_bar) * (X - u_bar)  # ± the full slip force over the sliding stroke
    excess = sp.Symbol("excess", positive=True)  # X − ū > 0: the sliding stroke
    if sp.simplify(masing.subs(X, u_bar + excess) - parallelogram.subs(X, u_bar + excess)) != 0:
        raise RuntimeError("the flat punch's Masing loop is not the parallelogram 8 G* a u_bar (X - u_bar)")
    add(Relation("flat_punch_loop_energy", "", "energy dissipated per cycle -X -> X -> -X of a flat punch of radius a "
                 "at a constant depth whose cap is u_bar, X >= u_bar", W, sp.expand(parallelogram), (X, a, u_bar, G_star)))


def _vanishes(expr: sp.Expr) -> bool:
    """Whether ``expr`` is identically 0 where the springs are compressed (``d > 0``: powers of ``d`` combine)."""
    depth = sp.Symbol("d_positive", positive=True)
    expr = sp.expand_power_base(sp.expand(expr.subs(d, depth)), force=True)
    return sp.simplify(sp.powsimp(expr, force=True)) == 0


def _derive_adhesive_virgin_curve(add: AddRelation, profile: sp.Expr, boundary: sp.Expr, kappa: sp.Expr,
                                  tau0_cap: sp.Expr, model: dict[str, Relation]) -> None:
    """The virgin curve at a constant depth ``d`` of a contact of radius ``a >= x_c`` from rest, summed over the
    springs: those sticking (``ξ < c'``, shift ``u_x``), the compressed ones at their caps (``c' < ξ < x_c``) and the
    tensile ones at ``K a`` (``x_c < ξ < a``); checked against Cattaneo–Mindlin's form of the compressed zone."""
    pinned_force = model["power_law_normal_force"].rhs  # F_N(d, a) (10), any a
    hertz_force = pinned_force.subs(a, boundary)  # F_N^H(d): the springs under x_c
    lowered = d - (u_x - tau0_cap) / kappa  # the compressed springs with K a + κ (d − g) > u_x stick
    stick = boundary.subs(d, lowered)
    springs = 2 * G_star * (u_x * stick + sp.integrate(tau0_cap + kappa * (d - profile), (x, stick, boundary))
                            + tau0_cap * (a - boundary))
    closed = sp.pi * tau0 * a**2 + mu * (hertz_force - hertz_force.subs(d, lowered))
    if not _vanishes(springs - closed):
        raise RuntimeError("the adhesive virgin curve of the springs is not tau0 pi a^2 + mu (F_H(d) - F_H(d'))")
    if sp.simplify(2 * G_star * tau0_cap * a - sp.pi * tau0 * a**2) != 0:
        raise RuntimeError("the tau0 part of full slip is not tau0 pi a^2")
    arguments = (u_x, d, a, tau0, mu, c, n, E_star, G_star)
    add(Relation("adhesive_virgin_force", "", "tangential force of an adhesive power-law contact of radius a at depth "
                 "d shifted by u_x from rest, K a <= u_x <= K a + mu (E*/G*) d (the Coulomb part is Cattaneo-Mindlin's "
                 "of the compressed zone, free of dgamma)", F_x, closed, arguments))
    add(Relation("adhesive_full_slip_shift", "", "shift from rest at which every spring of an adhesive contact slides: "
                 "the centre's cap K a + mu (E*/G*) d", u_x, sp.solve(sp.Eq(lowered, 0), u_x)[0],
                 (d, a, tau0, mu, E_star, G_star)))
    tension = 2 * E_star * sp.integrate(profile - d, (x, boundary, a))  # the tensile springs' pull
    if not _vanishes(pinned_force + tension - hertz_force):
        raise RuntimeError("F_N(d, a) plus the tensile springs' pull is not the compressed springs' push")
    add(Relation("compressed_normal_force", "(10)", "normal force of the compressed springs alone, F_N(d, a) + "
                 "2 E* int_{x_c}^a (g - d): the non-adhesive force of the depth", F_N, hertz_force, (d, c, n, E_star)))
    add(Relation("adhesive_full_slip_force", "", "tangential force of full slip of an adhesive contact: "
                 "tau0 pi a^2 + mu F_N^H(d)", F_x, sp.pi * tau0 * a**2 + mu * hertz_force, (d, a, tau0, mu, c, n, E_star)))
    if not _vanishes(closed.subs(u_x, tau0_cap + kappa * d) - sp.pi * tau0 * a**2 - mu * hertz_force):
        raise RuntimeError("the virgin curve at the centre's cap is not the force of full slip")


#: Keys of the relations of the rate-dependent adhesion law (:func:`derive_rate_dependent_adhesion`).
RATE_ADHESION_KEYS = ("energy_release_rate", "receding_work_of_adhesion", "advancing_work_of_adhesion",
                      "receding_edge_speed", "advancing_edge_speed", "paraboloid_release_rate",
                      "flat_punch_detachment_time", "let_go_depth", "rate_springs_record_force")

#: The edge's reference speed and its speed ``|ȧ|`` (m/s), the energy release rate ``Γ`` (J/m²), the works at rest.
v_ref = sp.Symbol("v_ref", positive=True)
edge_speed = sp.Symbol("v_a", positive=True)
release = sp.Symbol("Gamma", positive=True)
dgamma0 = sp.Symbol("dgamma0", positive=True)
dgamma1 = sp.Symbol("dgamma1", positive=True)
LATEX_NAMES.update({v_ref: r"v_{\mathrm{ref}}", edge_speed: r"|\dot a|", release: r"\Gamma",
                    dgamma0: r"\Delta\gamma_{0}", dgamma1: r"\Delta\gamma_{1}"})


@functools.cache
def derive_rate_dependent_adhesion() -> dict[str, Relation]:
    """Heß's rule (8) with a work of adhesion that depends on the edge's speed: the edge's equation of motion.

    The boundary spring of a contact of radius ``a`` at depth ``d`` is stretched by ``Δl = g(a) − d``; Heß's rule (8)
    ``Δl = sqrt(2π a Δγ / E*)`` read the other way gives the energy the edge releases, ``Γ = E* Δl² / (2π a)``. The
    edge moves where ``Γ`` leaves the band of rest ``Δγ0 <= Γ <= Δγ1``: receding (``ȧ < 0``) where ``Γ > Δγ1`` at the
    speed that makes ``Δγ1 [1 + (|ȧ|/v_ref)^n] = Γ``, advancing where ``Γ < Δγ0`` at the speed that makes
    ``Δγ0 / [1 + (ȧ/v_ref)^n] = Γ``. Derived and checked: both speeds vanish at the band's edges; for ``v_ref → ∞``
    the works are ``Δγ1`` and ``Δγ0`` (the paper's law: the radius on the branches (9)); for ``v_ref → 0`` the works
    grow without bound receding and vanish advancing, and the speeds go to 0 (the edge held). For the flat punch held at
    a constant depth ``d < 0`` beyond Kendall's pull-off, ``n = 1``, the receding edge's time to reach ``a`` from
    ``a0`` is a closed form, and its time to detach (``a → 0``) is finite.
    """
    return cached_relations("rate_dependent_adhesion", rate_dependent_adhesion_afresh)


def rate_dependent_adhesion_afresh() -> dict[str, Relation]:
    """The derivation of :func:`derive_rate_dependent_adhesion` with SymPy, bypassing any cache."""
    out: dict[str, Relation] = {}

    def add(rel: Relation) -> None:
        out[rel.key] = rel

    elongation = sp.Symbol("Delta_l", positive=True)
    hess = derive()["hess_max_elongation"].rhs  # Δl = sqrt(2π a Δγ / E*) (8)
    released = _single_positive(sp.solve(sp.Eq(elongation, hess), dgamma), "energy release rate")
    add(Relation("energy_release_rate", "(8)", "energy released per area by the edge whose spring is stretched by "
                 "Delta_l: Hess's rule (8) solved for the work of adhesion", release, released, (elongation, a, E_star)))
    ratio = (edge_speed / v_ref) ** n
    works = {"receding": dgamma1 * (1 + ratio), "advancing": dgamma0 / (1 + ratio)}
    at_rest = {"receding": dgamma1, "advancing": dgamma0}
    for way, work in works.items():
        if sp.limit(work, v_ref, sp.oo) != at_rest[way]:
            raise RuntimeError(f"the {way} work does not tend to the work at rest as v_ref -> oo")
        add(Relation(f"{way}_work_of_adhesion", "(8)", f"work of adhesion of a {way} edge moving at |da/dt| = v_a",
                     dgamma, work, (edge_speed, at_rest[way], v_ref, n)))
        speed = _single_positive(sp.solve(sp.Eq(work, release), edge_speed), f"{way} edge speed")
        if sp.simplify(speed.subs(release, at_rest[way])) != 0:
            raise RuntimeError(f"the {way} edge's speed does not vanish at the work at rest")
        held = sp.limit(speed.subs(release, 2 * dgamma1 if way == "receding" else dgamma0 / 2), v_ref, 0, "+")
        if held != 0:
            raise RuntimeError(f"the {way} edge's speed does not vanish as v_ref -> 0")
        add(Relation(f"{way}_edge_speed", "(8)", f"speed |da/dt| of a {way} edge that releases Gamma "
                     f"({'Gamma > dgamma1' if way == 'receding' else 'Gamma < dgamma0'})", edge_speed, speed,
                     (release, at_rest[way], v_ref, n)))
    if sp.limit(works["receding"], v_ref, 0, "+") != sp.oo or sp.limit(works["advancing"], v_ref, 0, "+") != 0:
        raise RuntimeError("the works do not diverge receding and vanish advancing as v_ref -> 0")
    parabolic = released.subs(elongation, a**2 / R - d)  # g(a) = a²/R (4)
    add(Relation("paraboloid_release_rate", "(8)", "energy release rate of a paraboloid's edge of radius a at depth d "
                 "(edge spring stretched, a^2/R > d)", release, parabolic, (a, d, R, E_star)))
    _derive_flat_punch_detachment(add, released, elongation)
    _derive_let_go(add, released, elongation)
    _derive_rate_springs_force(add)
    return out


def _derive_let_go(add: AddRelation, released: sp.Expr, elongation: sp.Symbol) -> None:
    """Where a receding edge lets go: the release rate ``Γ(a, d) = E* (g(a) − d)² / (2π a)`` at a fixed depth stops
    falling as the radius shrinks, ``∂Γ/∂a = 0`` (Griffith's stability of the edge: beyond it ``Γ`` rises as the edge
    recedes, and with it the speed, so the edge runs to 0 whatever the path does next). Solved for the depth with
    ``g`` and ``g'`` as symbols; on the paraboloid it is the jump-off of the branch (9) of any work, the paper's
    displacement-controlled pull-off (the limit ``v_ref → ∞``)."""
    profile, slope = sp.Symbol("g_a", real=True), sp.Symbol("g_slope", real=True)
    shape = sp.Function("g")
    rate = released.subs(elongation, shape(a) - d)
    roots = [root for root in sp.solve(sp.diff(rate, a), d) if sp.simplify(root - shape(a)) != 0]
    if len(roots) != 1:
        raise RuntimeError(f"the let-go depth is not one root of dGamma/da = 0: {roots}")
    depth = roots[0].subs(sp.Derivative(shape(a), a), slope).subs(shape(a), profile)
    paraboloid = depth.subs({profile: a**2 / R, slope: 2 * a / R})
    model = derive()
    off = model["jump_off_radius"].rhs
    if sp.simplify(paraboloid.subs(a, off) - model["jump_off_depth"].rhs) != 0:
        raise RuntimeError("the let-go depth of the paraboloid is not the jump-off of the branch (9)")
    add(Relation("let_go_depth", "(8)", "depth below which the edge of radius a lets go: dGamma/da = 0 at a fixed "
                 "depth, with g_a = g(a) and g_slope = g'(a) (on the paraboloid the jump-off of the branch (9))",
                 d, sp.expand(depth), (profile, slope, a)))


def _derive_rate_springs_force(add: AddRelation) -> None:
    """The tangential force of springs under one cap ``ū = K a`` whose anchors have only been pushed up (the play
    operator's lower level, its running maximum ``M``), attached at the times ``τ`` of an advancing edge with the
    anchors ``X(τ)`` (the path's ``x`` then, non-decreasing): ``2 G* ∫_0^a (x − max(X, M)) dξ`` over a record of
    springs ``[a(τ_lo), a(τ_hi)]``, cut at ``τ*`` where ``X = M``, by parts in ``τ``: the sliding ones carry
    ``M``, the sticking ones ``X a|_{τ*}^{τ_hi} − ∫ Ẋ a dτ``."""
    level, x_now = sp.Symbol("M", real=True), sp.Symbol("x", real=True)
    lo, star, hi = sp.symbols("a_lo a_star a_hi", positive=True)
    anchor_star, anchor_hi, swept = sp.symbols("X_star X_hi I_Xa", real=True)
    clock, start, end = sp.symbols("tau tau_star tau_hi", real=True)
    anchor, radius = sp.Function("X")(clock), sp.Function("A")(clock)
    by_parts = (anchor * radius).subs(clock, end) - (anchor * radius).subs(clock, start) \
        - sp.Integral(sp.diff(anchor, clock) * radius, (clock, start, end))
    if sp.simplify(sp.diff(by_parts, end) - (anchor * sp.diff(radius, clock)).subs(clock, end)) != 0:
        raise RuntimeError("the anchors' integral by parts does not differentiate back to X(tau) a'(tau)")
    held = level * (star - lo) + anchor_hi * hi - anchor_star * star - swept
    force = 2 * G_star * (x_now * (hi - lo) - held)
    add(Relation("rate_springs_record_force", "(11), (13)", "tangential force of the springs attached on [a_lo, a_hi] "
                 "at x = X(tau), those with X < M sliding at M: 2 G* int (x - max(X, M)) dxi, with I_Xa the integral "
                 "of X' a over the sticking ones' times", F_x, force,
                 (x_now, level, lo, star, hi, anchor_star, anchor_hi, swept, G_star)))


def _derive_flat_punch_detachment(add: AddRelation, released: sp.Expr, elongation: sp.Symbol) -> None:
    """The flat punch of radius ``a0`` held at ``d < 0`` with ``Γ(a0) > Δγ1`` and ``n = 1``: ``g = 0`` under the face,
    ``Γ = E* d² / (2π a)`` grows as the edge recedes, ``da/dt = −v_ref (Γ/Δγ1 − 1)``; separated and integrated."""
    depth = sp.Symbol("d_held", positive=True)  # |d|
    start, radius = sp.Symbol("a0", positive=True), sp.Symbol("a_t", positive=True)
    rate = released.subs(elongation, depth)  # Δl = g − d = |d| under the face
    speed = v_ref * (rate / dgamma1 - 1)  # n = 1
    reach = sp.solve(sp.Eq(rate, dgamma1), a)[0]  # c: the radius whose Γ is Δγ1 (a0 < c: the edge recedes)
    integral = sp.integrate(1 / speed, (a, radius, start))  # SymPy's antiderivative carries log(a − c), a < c
    # the same in logarithms of positive numbers (c − a > 0 on the way), so that it evaluates in real arithmetic
    time = ((start - radius) + reach * sp.log((reach - start) / (reach - radius))) / v_ref * -1
    checks = (sp.diff(time, radius) + 1 / speed.subs(a, radius), time.subs(radius, start),
              sp.diff(integral - time, radius))
    if any(sp.simplify(check) != 0 for check in checks):
        raise RuntimeError("the flat punch's detachment time is not the integral of the receding edge's law")
    add(Relation("flat_punch_detachment_time", "", "time for the edge of a flat punch of radius a0, held at depth "
                 "-d_held beyond Kendall's pull-off, to recede to a_t (n = 1; a_t -> 0: the detachment)", t, time,
                 (radius, start, depth, dgamma1, v_ref, E_star)))


def _reduce_to_polynomial(depth_a: sp.Expr, depth_b: sp.Expr, divide_by: sp.Expr | None = None) -> sp.Expr:
    """Eliminate ``d`` from ``d = depth_a(a)`` and ``d = depth_b(a)``.

    Returns the monic polynomial in ``s = sqrt(a)`` whose positive roots are
    the solutions, optionally divided by a trivial factor (``s``).
    """
    difference = (depth_a - depth_b).subs(a, s**2)
    poly_expr = sp.expand(sp.powsimp(difference, force=True))
    if divide_by is not None:
        poly_expr = sp.expand(sp.cancel(poly_expr / divide_by))
    poly = sp.Poly(poly_expr, s)
    monic = poly.monic()
    return sp.expand(monic.as_expr())


def _positive_cubic_root(cubic: sp.Expr) -> sp.Expr:
    """Cardano's root of the depressed cubic ``s³ − p s − q`` (p, q > 0) that is positive.

    Descartes' rule (one sign change) gives exactly one positive root. With
    principal complex branches it is ``u + p/(3u)``, ``u = (q/2 + sqrt(q²/4 − p³/27))^(1/3)``,
    also when all three roots are real (then it equals ``2 Re u``). Which of
    SymPy's three solutions that is depends on its ordering, so it is picked
    by evaluation at one point of each regime (three real roots, one real root).
    """
    free = sorted(cubic.free_symbols - {s}, key=lambda sym: sym.name)
    samples = [
        {sym: (3.0 if sym == tan_alpha else 1.0) for sym in free},   # three real roots
        {sym: (0.1 if sym == tan_alpha else 1.0) for sym in free},   # one real root
    ]
    for root in sp.solve(cubic, s):
        values = [complex(root.evalf(subs=sample)) for sample in samples]
        if all(abs(v.imag) < 1e-12 * abs(v) and v.real > 0 for v in values):
            return root
    raise RuntimeError("no Cardano root of the cubic (18) is positive in both regimes")


def relations() -> dict[str, Relation]:
    """All derived relations by key, in derivation order (derived once, then cached).

    Returns
    -------
    dict of str to Relation
        The paraboloid's model, the power law's, the friction laws' and the adhesive friction's.
    """
    model = derive()
    power_law = derive_power_law()
    ordered = {"abel_transform": model["abel_transform"], power_law.key: power_law}
    ordered.update(model)
    ordered.update(derive_power_law_model())
    ordered.update(derive_friction_model())
    ordered.update(derive_adhesive_friction_model())
    ordered.update(derive_rate_dependent_adhesion())
    return ordered


class UnknownRelationError(KeyError, ValueError):
    """A key no derived relation has (:func:`relation`): a ``KeyError`` as a look-up by key, and a ``ValueError`` as
    every other unknown name the package is given; its message is shown as written (not quoted as a key)."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


def relation(key: str) -> Relation:
    """One derived relation by key.

    Parameters
    ----------
    key : str
        The relation's key (``mdr-events derive`` lists them), e.g. ``"jkr_depth"``.

    Returns
    -------
    Relation
        The relation, derived (or read from the cache) once per process.

    Raises
    ------
    TypeError
        If ``key`` is not a ``str``.
    UnknownRelationError
        A ``KeyError`` and ``ValueError`` naming ``key`` and the known keys, if no relation has it.
    """
    if not isinstance(key, str):
        raise TypeError(f"key={shown(key)} ({type(key).__name__}) is not allowed; allowed: a relation's key (str), "
                        "as mdr-events derive lists them")
    if key == "profile_power_law":
        return derive_power_law()
    if key in POWER_LAW_KEYS:
        return derive_power_law_model()[key]
    if key in FRICTION_KEYS:
        return derive_friction_model()[key]
    if key in ADHESIVE_FRICTION_KEYS:
        return derive_adhesive_friction_model()[key]
    if key in RATE_ADHESION_KEYS:
        return derive_rate_dependent_adhesion()[key]
    rels = derive()
    try:
        return rels[key]
    except KeyError:
        known = sorted([*rels, "profile_power_law", *POWER_LAW_KEYS, *FRICTION_KEYS, *ADHESIVE_FRICTION_KEYS,
                        *RATE_ADHESION_KEYS])
        raise UnknownRelationError(f"key={key!r} is not allowed (unknown relation {key!r}); allowed: "
                                   f"{', '.join(known)}") from None
