r"""The universal map: the critical angles over the model's dimensionless groups (:func:`universal_map`).

Every angle of the model depends on the slip parameter ``S`` and the adhesion parameters ``Γ0``, ``Γ1`` alone
(:func:`mdr_events.theory.analytic.dimensionless_groups`). The map sweeps them (:func:`mdr_events.sweep`, on a
dask cluster where one is installed): ``S`` through τ0 and each ``Γ`` through its work of adhesion, from a base
parameter set. It holds the critical angle of scenario A over ``(S, Γ0)`` and, over ``(S, Γ1)`` at the base's
``Γ0``, the angle of scenario B above which the contact comes apart before any spring slides.

On a layer of thickness ``h`` bonded to a rigid base one more group enters, the layer's thinness

.. math:: \lambda = \frac{\sqrt{R\,d_\mathrm{max}}}{h} \qquad (0: \text{the half-space}),

the radius unit of the groups, the Hertz radius at ``d_max``, over the thickness. The layer's relations depend on the
radius only through ``a/h`` (its punch stiffness ``K(a) = 2E* a Φ(a/h)``, the equivalent profile ``g``, Heß's
``Δl = √(4π a Δγ / K'(a))`` and the tangential ``K_t(a) = 2G* a Φ_t(a/h)``, :mod:`mdr_events.theory.layer`), and
with ``a = √(R d_max) â`` that is ``â λ``: the branch reads ``d̂ = ĝ(â; λ) − √(Γ â / Ψ(â λ))`` and the cap
``ū/d_max = S â / Φ_t(â λ)``. So the angles depend on ``(S, Γ0, Γ1, λ)`` and, through ``Φ``, ``Ψ`` and ``Φ_t``, on
Poisson's ratio ``ν`` and the base's condition, which the half-space's do not: the map over ``λ`` holds for the
base set's ``ν`` and a bonded base alone (the layer's slip onset needs its tangential stiffness; a frictionless base
has none). ``λ`` rather than ``a/h``: the contact radius is a result, different for every angle and scenario, while
``λ`` is given with the inputs; and ``λ = 0`` is the half-space, where ``h/√(R d_max)`` would be infinite.
"""

from __future__ import annotations

import math
import sys
from typing import Sequence

import numpy as np
import xarray as xr

from mdr_events.analysis.sweep import sweep
from mdr_events.io.agreement import RoundOff, register_accuracy
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.parameters import Parameters
from mdr_events.theory.analytic import dimensionless_groups
from mdr_events.validation import real_array, shown

__all__ = ["universal_map", "UNIVERSAL_MAP_CONTENT", "GROUP_NAMES", "LAYER_GROUP", "thickness_of_thinness"]

#: The ``content`` attribute of the map.
UNIVERSAL_MAP_CONTENT = "critical angles over the dimensionless groups"
#: Coordinate -> (symbol, long name).
GROUP_NAMES = {"slip": ("S", "slip parameter S = π τ0 √R / (2 G* √d_max)"),
               "adhesion_in": ("Γ0", "adhesion parameter Γ0 = 2π Δγ0 √R / (E* d_max^(3/2))"),
               "adhesion_out": ("Γ1", "adhesion parameter Γ1 = 2π Δγ1 √R / (E* d_max^(3/2))")}
#: The layer's group (coordinate -> (symbol, long name)): an axis of the map only where asked for.
LAYER_GROUP = {"thinness": ("λ", "layer thinness λ = √(R d_max) / h (0: the half-space)")}
#: The base of the layer the map's ``λ`` axis is on: the slip onset on a layer needs its tangential stiffness.
LAYER_BASE = "bonded"


def thickness_of_thinness(thinness, base: Parameters) -> np.ndarray:
    r"""The layer's thickness of each thinness ``λ = √(R d_max)/h`` at the base set's ``R`` and ``d_max``.

    Parameters
    ----------
    thinness : array_like
        Values of ``λ``, finite and ``>= 0``.
    base : Parameters
        The set whose ``R`` and ``d_max`` make the unit ``√(R d_max)``.

    Returns
    -------
    numpy.ndarray
        ``h = √(R d_max)/λ`` in m (``inf`` at ``λ = 0``: the half-space).

    Raises
    ------
    ValueError
        A ``λ > 0`` whose thickness overflows (``5e-324`` had given ``inf``, the half-space, with NumPy's warning:
        beside ``λ = 0`` the grid then repeated ``h = inf``).
    """
    values = np.asarray(thinness, dtype=float)
    unit = math.sqrt(base.R * base.d_max)
    with np.errstate(divide="ignore", over="ignore"):
        thickness = unit / values
    overflowing = np.isinf(thickness) & (values > 0.0)
    if np.any(overflowing):
        raise ValueError(f"thinness={float(values[overflowing][0])!r} is not allowed: its thickness √(R d_max)/λ "
                         f"overflows; allowed: 0 (the half-space) or values of at least "
                         f"{unit / sys.float_info.max:.3g} (R={base.R!r} m, d_max={base.d_max!r} m)")
    return thickness


def universal_map(slip, adhesion, base: Parameters, *, thinness: Sequence[float] | np.ndarray | None = None,
                  scheduler: str | None = None,
                  workers: int | None = None, marked: dict[str, Parameters] | None = None) -> xr.Dataset:
    """Critical angles of scenarios A and B over the groups.

    Parameters
    ----------
    slip : array_like
        Values of ``S`` (> 0).
    adhesion : array_like
        Values of ``Γ0`` (scenario A) and of ``Γ1`` (scenario B), each >= 0.
    base : Parameters
        The parameter set whose τ0, Δγ0 and Δγ1 are scaled to reach the groups (any set gives the same map; with
        ``thinness``, any set of the same ``ν``).
    thinness : array_like, optional
        Values of the layer's group ``λ = √(R d_max)/h`` (distinct, finite, >= 0; 0 the half-space): an axis
        ``thinness`` of both angles, each ``λ`` reached through the thickness ``h`` of a layer bonded to its base
        (module docstring). Default: the half-space alone, no such axis (the map of before, bit for bit).
    scheduler, workers
        As in :func:`mdr_events.sweep`.
    marked : mapping of str to Parameters, optional
        Parameter sets to mark on the map (label -> set): their groups and angles are stored as attributes (they are
        half-spaces: ``λ = 0``).

    Returns
    -------
    xarray.Dataset
        ``critical_angle_A`` over (``slip``, ``adhesion_in``) and ``critical_angle_B`` over (``slip``,
        ``adhesion_out``), degrees; with ``thinness`` each also over ``thinness``, and the attribute
        ``param_layer_base`` (the base's ``ν`` is stamped as ``param_nu``, as always).

    Raises
    ------
    ValueError
        A group's values that are not allowed, a base without τ0 or a work of adhesion, a thinness whose contact
        radius lies beyond the layer's tables.
    """
    slip = real_array("slip", slip, "a list of values > 0")
    adhesion = real_array("adhesion", adhesion, "a list of values >= 0")
    if slip.ndim != 1 or not slip.size or not np.all(np.isfinite(slip) & (slip > 0)):
        raise ValueError(f"slip={shown(slip)} is not allowed; allowed: a non-empty list of finite values > 0")
    if adhesion.ndim != 1 or not adhesion.size or not np.all(np.isfinite(adhesion) & (adhesion >= 0)):
        raise ValueError(f"adhesion={shown(adhesion)} is not allowed; allowed: a non-empty list of finite values >= 0")
    if not (base.tau0 > 0 and (base.dgamma0 > 0 or base.dgamma1 > 0)):
        raise ValueError(f"base with tau0={base.tau0!r}, dgamma0={base.dgamma0!r}, dgamma1={base.dgamma1!r} is not "
                         "allowed; allowed: tau0 > 0 and a work of adhesion > 0 (the groups are reached by scaling "
                         "them)")
    groups = dimensionless_groups(base)
    tau0 = base.tau0 * slip / groups.slip
    unit_adhesion = groups.adhesion_in / base.dgamma0 if base.dgamma0 > 0 else groups.adhesion_out / base.dgamma1
    works = adhesion / unit_adhesion
    thinness = None if thinness is None else _thinness(thinness)
    layered = {} if thinness is None else {"h": thickness_of_thinness(thinness, base)}
    options = dict(base=base, scheduler=scheduler, workers=workers)
    in_sweep = sweep({"tau0": tau0, "dgamma0": works, **layered}, "A", 45.0, quantities=("critical_angle_A",),
                     **options)
    out_sweep = sweep({"tau0": tau0, "dgamma1": works, **layered}, "B", 45.0, quantities=("critical_angle_B",),
                      **options)
    coords = {name: (name, adhesion if name != "slip" else slip, {"units": "1", "long_name": text})
              for name, (_, text) in GROUP_NAMES.items()}
    axis = ()
    if layered:
        axis = tuple(LAYER_GROUP)
        coords.update({name: (name, thinness, {"units": "1", "long_name": text})
                       for name, (_, text) in LAYER_GROUP.items()})
    data = {"critical_angle_A": (("slip", "adhesion_in", *axis), in_sweep["critical_angle_A"].values,
                                 {"units": "degree", "long_name": "critical angle of scenario A (slip while indenting "
                                                                  "below it)"}),
            "critical_angle_B": (("slip", "adhesion_out", *axis), out_sweep["critical_angle_B"].values,
                                 {"units": "degree", "long_name": "angle of scenario B above which the contact comes "
                                                                  "apart before sliding"}),
            "failed": (("slip", "adhesion_in", *axis), in_sweep["failed"].values | out_sweep["failed"].values,
                       {"units": "1", "long_name": "1: a run of the cell raised"})}
    attrs = {"content": UNIVERSAL_MAP_CONTENT, "adhesion_in_of_B": groups.adhesion_in}
    if layered:
        attrs["param_layer_base"] = LAYER_BASE  # (the angles over λ hold for this base and the stamped param_nu)
    for label, params in (marked or {}).items():
        marks = dimensionless_groups(params)
        attrs.update({f"mark_{label}_slip": marks.slip, f"mark_{label}_adhesion_in": marks.adhesion_in,
                      f"mark_{label}_adhesion_out": marks.adhesion_out})
    return stamp(xr.Dataset(data, coords=coords), base, **attrs)


def _thinness(values) -> np.ndarray:
    """The layer's group ``λ``: distinct, finite values >= 0; else the one-line error naming ``thinness``."""
    thinness = real_array("thinness", values, "a list of values >= 0")
    if thinness.ndim != 1 or not thinness.size or not np.all(np.isfinite(thinness) & (thinness >= 0)) \
            or np.unique(thinness).size != thinness.size:
        raise ValueError(f"thinness={shown(values)} is not allowed; allowed: a non-empty list of distinct finite "
                         "values >= 0 (0: the half-space)")
    return thinness


register_schema(UNIVERSAL_MAP_CONTENT, {"critical_angle_A": ("slip", "adhesion_in"),
                                        "critical_angle_B": ("slip", "adhesion_out")})
#: A map with the layer's group: each angle over ``thinness`` too.
register_schema(UNIVERSAL_MAP_CONTENT, {"critical_angle_A": ("slip", "adhesion_in", "thinness"),
                                        "critical_angle_B": ("slip", "adhesion_out", "thinness")},
                when=("param_layer_base", LAYER_BASE))
#: The critical angles are the phase diagram's closed forms (round-off), the groups closed forms of the inputs. (On a
#: layer they are root-found: the map over λ is not among results/ files.)
register_accuracy(UNIVERSAL_MAP_CONTENT, {name: RoundOff() for name in ("critical_angle_A", "critical_angle_B",
                                                                         *GROUP_NAMES)})
