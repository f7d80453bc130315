"""The universal map: the critical angles over the model's dimensionless groups (:func:`universal_map`).

Every angle of the model depends on the slip parameter ``S`` and the adhesion parameters ``Γ0``, ``Γ1`` alone
(:func:`mdr_events.theory.analytic.dimensionless_groups`). The map sweeps them (:func:`mdr_events.sweep`, on a
dask cluster where one is installed): ``S`` through τ0 and each ``Γ`` through its work of adhesion, from a base
parameter set. It holds the critical angle of scenario A over ``(S, Γ0)`` and, over ``(S, Γ1)`` at the base's
``Γ0``, the angle of scenario B above which the contact comes apart before any spring slides.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from mdr_events.analysis.sweep import sweep
from mdr_events.io.agreement import RoundOff, register_accuracy
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.parameters import Parameters
from mdr_events.theory.analytic import dimensionless_groups
from mdr_events.validation import real_array, shown

__all__ = ["universal_map", "UNIVERSAL_MAP_CONTENT", "GROUP_NAMES"]

#: The ``content`` attribute of the map.
UNIVERSAL_MAP_CONTENT = "critical angles over the dimensionless groups"
#: Coordinate -> (symbol, long name).
GROUP_NAMES = {"slip": ("S", "slip parameter S = π τ0 √R / (2 G* √d_max)"),
               "adhesion_in": ("Γ0", "adhesion parameter Γ0 = 2π Δγ0 √R / (E* d_max^(3/2))"),
               "adhesion_out": ("Γ1", "adhesion parameter Γ1 = 2π Δγ1 √R / (E* d_max^(3/2))")}


def universal_map(slip, adhesion, base: Parameters, *, scheduler: str | None = None,
                  workers: int | None = None, marked: dict[str, Parameters] | None = None) -> xr.Dataset:
    """Critical angles of scenarios A and B over the groups.

    Parameters
    ----------
    slip : array_like
        Values of ``S`` (> 0).
    adhesion : array_like
        Values of ``Γ0`` (scenario A) and of ``Γ1`` (scenario B), each >= 0.
    base : Parameters
        The parameter set whose τ0, Δγ0 and Δγ1 are scaled to reach the groups (any set gives the same map).
    scheduler, workers
        As in :func:`mdr_events.sweep`.
    marked : mapping of str to Parameters, optional
        Parameter sets to mark on the map (label -> set): their groups and angles are stored as attributes.

    Returns
    -------
    xarray.Dataset
        ``critical_angle_A`` over (``slip``, ``adhesion_in``) and ``critical_angle_B`` over (``slip``,
        ``adhesion_out``), degrees.
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
    options = dict(base=base, scheduler=scheduler, workers=workers)
    in_sweep = sweep({"tau0": tau0, "dgamma0": works}, "A", 45.0, quantities=("critical_angle_A",), **options)
    out_sweep = sweep({"tau0": tau0, "dgamma1": works}, "B", 45.0, quantities=("critical_angle_B",), **options)
    coords = {name: (name, adhesion if name != "slip" else slip, {"units": "1", "long_name": text})
              for name, (_, text) in GROUP_NAMES.items()}
    data = {"critical_angle_A": (("slip", "adhesion_in"), in_sweep["critical_angle_A"].values,
                                 {"units": "degree", "long_name": "critical angle of scenario A (slip while indenting "
                                                                  "below it)"}),
            "critical_angle_B": (("slip", "adhesion_out"), out_sweep["critical_angle_B"].values,
                                 {"units": "degree", "long_name": "angle of scenario B above which the contact comes "
                                                                  "apart before sliding"}),
            "failed": (("slip", "adhesion_in"), in_sweep["failed"].values | out_sweep["failed"].values,
                       {"units": "1", "long_name": "1: a run of the cell raised"})}
    attrs = {"content": UNIVERSAL_MAP_CONTENT, "adhesion_in_of_B": groups.adhesion_in}
    for label, params in (marked or {}).items():
        marks = dimensionless_groups(params)
        attrs.update({f"mark_{label}_slip": marks.slip, f"mark_{label}_adhesion_in": marks.adhesion_in,
                      f"mark_{label}_adhesion_out": marks.adhesion_out})
    return stamp(xr.Dataset(data, coords=coords), base, **attrs)


register_schema(UNIVERSAL_MAP_CONTENT, {"critical_angle_A": ("slip", "adhesion_in"),
                                        "critical_angle_B": ("slip", "adhesion_out")})
#: The critical angles are the phase diagram's closed forms (round-off), the groups closed forms of the inputs.
register_accuracy(UNIVERSAL_MAP_CONTENT, {name: RoundOff() for name in ("critical_angle_A", "critical_angle_B",
                                                                         *GROUP_NAMES)})
