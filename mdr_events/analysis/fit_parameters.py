"""The free parameters of a fit (:func:`mdr_events.analysis.fit.fit`): which names may be free, their units, their
scaling, bounds and start values (:class:`FreeParameters`, :func:`free_parameters`).

``scipy.optimize.least_squares`` works on the scaled parameters ``θ``: :data:`LOG_SCALED` on a log scale (their
start must be > 0, the fit moves them by factors), ``ν`` itself, the offsets (:data:`OFFSETS`, the experiment's
zero) relative to the path's duration and depth. Bounds default to the physical ranges; a bound given is checked
against the range and the start, and every error names the argument, its value and what is allowed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping, Sequence

import numpy as np

from mdr_events.contact.friction import TAU0, FrictionLaw
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.parameters import PARAMETER_LONG_NAMES, PARAMETER_UNITS, Parameters
from mdr_events.validation import check_mapping, check_real, shown

__all__ = ["FreeParameters", "free_parameters", "FREE_NAMES", "LOG_SCALED", "OFFSETS"]

#: Free parameters fitted on a log scale (moduli, radius, critical shear stress, works of adhesion): their
#: start must be > 0, and the fit moves them by factors.
LOG_SCALED = ("E", "R", "tau0", "dgamma0", "dgamma1", "mu", "h")
#: The experiment's zero: ``time_offset`` (s; the measured clock reads it at the path's time 0, after
#: ``time_origin``) and ``depth_offset`` (m; the path's depth zero lies this far above the real surface).
OFFSETS = ("time_offset", "depth_offset")
#: Every name ``free`` may hold. ``d_max`` and ``v`` are the path's, not the material's: give the path.
FREE_NAMES = ("E", "nu", "R", "tau0", "dgamma0", "dgamma1", "mu", "h") + OFFSETS
#: The coefficient of friction of a law with Coulomb's part (:mod:`mdr_events.contact.friction`), free beside the parameters.
FRICTION_NAME = "mu"
#: The thickness of a contact's layer (``Contact.layer``), free beside the parameters on a layer of finite thickness:
#: each trial the same tables at another ``a/h``, so a free ``h`` costs what a fixed one does.
LAYER_NAME = "h"
OFFSET_UNITS = {"time_offset": "s", "depth_offset": "m", "mu": "1", "h": "m"}
OFFSET_LONG_NAMES = {"time_offset": "the measured clock's reading at the path's time 0 (after time_origin)",
                     "depth_offset": "height of the path's depth zero above the real surface",
                     "mu": "coefficient of friction of the law's Coulomb part",
                     "h": "thickness of the elastomer layer on its rigid base"}
#: ``ν`` stays below 0.5 and above −1 by this much inside the fit (the bounds of :class:`Parameters`).
NU_MARGIN = 1e-9
#: A finite bound of an offset lies within this many of its scales (the path's duration, its deepest point):
#: farther, the model leaves the measured window long before, and the optimizer's step scaling (the distance
#: to a bound) would overflow. ``±inf`` is no bound.
OFFSET_BOUND_REACH = 1e6


def unit_of(name: str) -> str:
    """The unit of a free parameter (``"1"`` for a dimensionless one)."""
    return OFFSET_UNITS.get(name) or PARAMETER_UNITS[name]


def _in_unit(name: str) -> str:
    """`` <unit>`` after a value, nothing for a dimensionless one."""
    unit = unit_of(name)
    return "" if unit == "1" else f" {unit}"


def _long_name(name: str) -> str:
    """The long name of a free parameter."""
    return OFFSET_LONG_NAMES.get(name) or PARAMETER_LONG_NAMES[name]



@dataclass(frozen=True)
class FreeParameters:
    """The free parameters of a fit, their scaling and bounds: ``θ`` (scaled) ↔ natural values.

    ``θ = log(value)`` for :data:`LOG_SCALED`, ``ν`` itself, ``time_offset / duration`` and
    ``depth_offset / depth_scale`` (the path's duration and deepest point give the offsets their scale).
    """

    names: tuple[str, ...]
    start: Parameters
    lower: np.ndarray  #: natural units
    upper: np.ndarray
    duration: float
    depth_scale: float
    #: the friction law of the fit (``μ`` its start where free)
    friction: FrictionLaw = TAU0
    #: the contact's layer (its thickness the start where ``h`` is free)
    layer: Layer = HALF_SPACE

    def scale(self, name: str) -> float:
        """The scale of a parameter not on a log scale: the path's duration or deepest point for an offset, else 1."""
        return {"time_offset": self.duration, "depth_offset": self.depth_scale}.get(name, 1.0)

    def to_scaled(self, values: Sequence[float]) -> np.ndarray:
        """``θ`` of natural values (a bound of 0 of a log-scaled parameter is ``-inf``)."""
        return np.array([(math.log(v) if v > 0 else -math.inf) if n in LOG_SCALED else v / self.scale(n)
                         for n, v in zip(self.names, values)])

    def to_natural(self, theta: np.ndarray) -> np.ndarray:
        """The natural values of ``θ`` (the inverse of :meth:`to_scaled`)."""
        return np.array([_exp(t) if n in LOG_SCALED else t * self.scale(n) for n, t in zip(self.names, theta)])

    def scaled_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """The lower and upper bounds of ``θ``."""
        return self.to_scaled(self.lower), self.to_scaled(self.upper)

    def start_values(self) -> np.ndarray:
        """The start of each free parameter in natural units (0 for an offset)."""
        return np.array([_start_value(n, self.start, self.friction, self.layer) for n in self.names])

    def model(self, theta: np.ndarray) -> tuple[Parameters, float, float]:
        """The parameters, time offset and depth offset at ``θ``."""
        values = dict(zip(self.names, map(float, self.to_natural(theta))))
        offsets = [values.pop(name, 0.0) for name in OFFSETS]
        values.pop(FRICTION_NAME, None)
        values.pop(LAYER_NAME, None)
        return self.start.replace(**values) if values else self.start, offsets[0], offsets[1]

    def friction_at(self, theta: np.ndarray) -> FrictionLaw:
        """The friction law at ``θ``: the start's, with the fitted ``μ`` where it is free."""
        if FRICTION_NAME not in self.names:
            return self.friction
        return FrictionLaw(self.friction.law, mu=float(self.to_natural(theta)[self.names.index(FRICTION_NAME)]))

    def layer_at(self, theta: np.ndarray) -> Layer:
        """The layer at ``θ``: the start's, with the fitted thickness where ``h`` is free (its base kept)."""
        if LAYER_NAME not in self.names:
            return self.layer
        return Layer(float(self.to_natural(theta)[self.names.index(LAYER_NAME)]), self.layer.base)


def _start_value(name: str, start: Parameters, friction: FrictionLaw, layer: Layer = HALF_SPACE) -> float:
    """A free parameter's start: 0 for an offset, the law's ``μ``, the layer's thickness, else the field of
    ``start``."""
    if name in OFFSETS:
        return 0.0
    if name == LAYER_NAME:
        return layer.thickness
    return friction.coulomb_mu if name == FRICTION_NAME else getattr(start, name)


def _default_bounds(name: str) -> tuple[float, float]:
    """A free parameter's physical range: ``ν`` in (−1, 0.5], the log-scaled > 0, the offsets unbounded."""
    if name == "nu":
        return -1.0 + NU_MARGIN, 0.5
    if name in LOG_SCALED:
        return 0.0, math.inf
    return -math.inf, math.inf


def _check_offset_bounds(name: str, given: Sequence[float], duration: float, depth_scale: float) -> None:
    """An offset's finite bounds within :data:`OFFSET_BOUND_REACH` of its scale."""
    if name not in OFFSETS:
        return
    reach = OFFSET_BOUND_REACH * (duration if name == "time_offset" else depth_scale)
    if any(math.isfinite(bound) and abs(bound) > reach for bound in given):
        raise ValueError(f"bounds[{name!r}]=({given[0]!r}, {given[1]!r}) is not allowed; allowed: finite bounds within "
                         f"±{reach:.3g} {unit_of(name)} ({OFFSET_BOUND_REACH:g} times the path's "
                         f"{'duration' if name == 'time_offset' else 'deepest point'}), or ±inf for no bound")


def free_parameters(free: str | Sequence[str], start: Parameters, bounds: Mapping[str, tuple[float, float]] | None,
                    duration: float, depth_scale: float, friction: FrictionLaw = TAU0,
                    layer: Layer = HALF_SPACE) -> FreeParameters:
    """Check ``free``, ``start`` and ``bounds`` (errors name the argument, its value and what is allowed).

    Parameters
    ----------
    free : str or sequence of str
        The names to fit, from :data:`FREE_NAMES`, each once (``mu`` only with a law that has Coulomb's part).
    start : Parameters
        The start; a log-scaled free parameter's start must be > 0.
    bounds : mapping or None
        Free name → ``(lower, upper)`` in its unit, overlapping its physical range and holding the start.
    duration, depth_scale : float
        The path's duration (s) and deepest point (m): the scales of the offsets.
    friction : FrictionLaw
        The fit's friction law (``μ`` its start where free).
    layer : Layer, default the half-space
        The contact's layer (its thickness the start where ``h`` is free: only on a layer of finite thickness).

    Returns
    -------
    FreeParameters

    Raises
    ------
    ValueError, TypeError
        Naming the argument, its value and what is allowed.
    """
    if isinstance(free, str):
        free = (free,)
    names = tuple(free) if isinstance(free, Sequence) else ()
    if not names or not all(isinstance(name, str) for name in names):
        raise ValueError(f"free={shown(free)} is not allowed; allowed: a non-empty sequence of names from "
                         f"{', '.join(FREE_NAMES)}")
    for name in names:
        if name not in FREE_NAMES:
            hint = " (the path's, not the material's: give the path)" if name in ("d_max", "v") else ""
            raise ValueError(f"free: {shown(name)} is not allowed{hint}; allowed: {', '.join(FREE_NAMES)}")
    if len(set(names)) != len(names):
        raise ValueError(f"free={shown(free)} names a parameter twice; allowed: each name once")
    if not isinstance(start, Parameters):
        raise TypeError(f"start={shown(start)} ({type(start).__name__}) is not allowed; allowed: a Parameters")
    if FRICTION_NAME in names and not friction.uses_mu:
        raise ValueError(f"free: 'mu' is not allowed with the friction law {friction.law!r}; allowed: a law with Coulomb's "
                         "part, e.g. friction=FrictionLaw('coulomb', mu=0.3) (its mu the start)")
    if LAYER_NAME in names and layer.is_half_space:
        raise ValueError("free: 'h' is not allowed on the half-space; allowed: a contact on a layer of finite "
                         "thickness, e.g. Contact.replace(h=5e-3) (its thickness the start)")
    bounds = check_mapping("bounds", bounds, "{'tau0': (1e3, 1e6)}")
    for name in bounds:
        if name not in names:
            raise ValueError(f"bounds: {name!r} is not allowed; allowed: the free parameters ({', '.join(names)})")
    lower, upper = [], []
    for name in names:
        low, high = _default_bounds(name)
        if name in bounds:
            pair = bounds[name]
            if isinstance(pair, (str, bytes)) or not (isinstance(pair, (Sequence, np.ndarray)) and len(pair) == 2):
                raise ValueError(f"bounds[{name!r}]={shown(pair)} is not allowed; allowed: a pair (lower, upper) "
                                 f"in {unit_of(name)}")
            given = [check_real(f"bounds[{name!r}]", value, f"a pair (lower, upper) of numbers in {unit_of(name)}",
                                finite=False) for value in pair]
            _check_offset_bounds(name, given, duration, depth_scale)
            if max(low, given[0]) >= min(high, given[1]):
                raise ValueError(f"bounds[{name!r}]=({given[0]!r}, {given[1]!r}) is not allowed: it leaves nothing of "
                                 f"{name}'s range [{low!r}, {high!r}]{_in_unit(name)}; allowed: lower < upper, "
                                 "overlapping that range")
            low, high = max(low, given[0]), min(high, given[1])
        shown_bounds = f"({given[0]!r}, {given[1]!r})" if name in bounds else f"({low!r}, {high!r})"
        value = _start_value(name, start, friction, layer)
        if name in LOG_SCALED and not value > 0:
            where = {FRICTION_NAME: "friction.mu", LAYER_NAME: "layer.thickness"}.get(name, f"start.{name}")
            raise ValueError(f"{where}={value!r} is not allowed for a free {name}; allowed: > 0 (it is fitted "
                             "on a log scale)")
        if not low <= value <= high or not low < high:
            raise ValueError(f"bounds[{name!r}]={shown_bounds} is not allowed: it excludes the start "
                             f"{value!r}{_in_unit(name)}; allowed: lower < upper with the start between them")
        lower.append(low)
        upper.append(high)
    return FreeParameters(names, start, np.array(lower), np.array(upper), duration, depth_scale, friction, layer)


def _exp(value: float) -> float:
    """``exp(value)``, ``inf`` where it overflows (an optimizer's step far out: the trial is then refused, named)."""
    try:
        return math.exp(value)
    except OverflowError:
        return math.inf
