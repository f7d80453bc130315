r"""The normal contact of a :class:`~mdr_events.Contact` on its layer as labelled results: the adhesive branches
against the depth (:func:`layer_normal_curve`), an indentation to ``d_max`` and back to the jump-off
(:func:`layer_indentation_cycle`) and the pull-off force against the thickness (:func:`layer_pull_off_curve`).

Part of :mod:`mdr_events.theory.layer` (the relations (L1)–(L5) are stated there). The depth of the branch of radius
``a`` is ``d(a) = g(a) − Δl(a)`` (generalised (9)); its stable part is ``a ≥ a_jo`` (``∂d/∂a ≥ 0``, ``a_jo`` the
radius of the jump-off under depth control, the least depth). A depth is inverted on it by bisection in ``ln a``
inside the bracket of a logarithmic scan, for all depths at once (:mod:`~mdr_events.theory.layer.branch_scan`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import xarray as xr

from mdr_events.contact.layer import Layer
from mdr_events.contact.model import Contact
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.limits import Limits, check_limits, values_in
from mdr_events.parameters import PAPER_D_MAX, PAPER_V
from mdr_events.theory.job import rate_independent
from mdr_events.theory.layer.branch_scan import branch_jump_off, check_scales, layer_material, stable_radius
from mdr_events.theory.layer.force_control import pull_off
from mdr_events.theory.layer.relations import branch_depth, normal_force
from mdr_events.validation import check_count, check_distinct, check_real, real_array, shown

__all__ = ["layer_normal_curve", "layer_indentation_cycle", "layer_pull_off_curve", "LAYER_CURVE_CONTENT",
           "LAYER_CYCLE_CONTENT", "LAYER_PULL_OFF_CONTENT", "CURVE_POINT_STEPS", "PULL_OFF_STEPS",
           "CURVE_BYTES_PER_POINT", "thickness_axis"]

#: The ``content`` attribute of :func:`layer_normal_curve`.
LAYER_CURVE_CONTENT = "layer normal curve"
#: The ``content`` attribute of :func:`layer_indentation_cycle`.
LAYER_CYCLE_CONTENT = "layer indentation cycle"
#: The ``content`` attribute of :func:`layer_pull_off_curve`.
LAYER_PULL_OFF_CONTENT = "layer pull-off curve"
register_schema(LAYER_CURVE_CONTENT, {"contact_radius": ("branch", "depth"), "normal_force": ("branch", "depth"),
                                      "contact_area": ("branch", "depth"), "relative_radius": ("branch", "depth")})
register_schema(LAYER_CYCLE_CONTENT, {"depth": ("sample",), "contact_radius": ("sample",),
                                      "normal_force": ("sample",), "contact_area": ("sample",)})
register_schema(LAYER_PULL_OFF_CONTENT, {"pull_off_force": ("thickness",), "pull_off_radius": ("thickness",),
                                         "pull_off_depth": ("thickness",), "relative_radius": ("thickness",)})


#: What one point of a normal curve or a cycle counts against :attr:`~mdr_events.Limits.steps`: its share of the scan
#: and the bisection's 60 evaluations of the branch (:mod:`~mdr_events.theory.layer.branch_scan`), about 20 µs
#: here, where the discrete model's step takes about 1.5 µs (its default 2e7 steps about 30 s), so that a curve is
#: checked before it runs (1e9 samples of a cycle were taken, and the process killed for its memory).
CURVE_POINT_STEPS = 15.0
#: What one thickness of the pull-off curve counts against :attr:`~mdr_events.Limits.steps`: a scan of the branch
#: force and Brent's refinement, about 8 ms here.
PULL_OFF_STEPS = 5000.0
#: The memory of one point of a curve (its variables and the bisection's temporaries: 110 to 142 bytes measured),
#: counted against :attr:`~mdr_events.Limits.memory`.
CURVE_BYTES_PER_POINT = 256.0


#: The variables' units and long names.
_VARIABLES = {"contact_radius": ("m", "contact radius a"), "normal_force": ("N", "normal force F_N"),
              "contact_area": ("m2", "contact area pi a^2"), "relative_radius": ("1", "contact radius over thickness a/h"),
              "depth": ("m", "indentation depth d")}


def _checked(contact: Any, depth: float, what: str, points: int, steps_each: float, limits: Limits | None) -> None:
    """A curve's contact checked before it runs: a paraboloid or power law (:func:`layer_material`), the scales it
    computes with at ``depth`` (:func:`check_scales`), and the curve's ``points`` (each ``steps_each`` steps) within
    ``limits``. The curves are rate-independent: a ``RateDependentAdhesion`` is refused (its works at rest were read
    as the paper's law, which ``pull_off_force`` refuses on the half-space)."""
    layer_material(contact)
    rate_independent(contact, what)
    check_scales(contact, depth, what)
    _counted(what, points, steps_each, limits)


def _counted(what: str, points: float, steps_each: float, limits: Limits | None) -> None:
    """A curve's ``points`` (each ``steps_each`` steps) within ``limits``."""
    check_limits(limits).check(f"{what} ({points} points)", samples=float(points), steps=steps_each * points,
                               memory=CURVE_BYTES_PER_POINT * points)


def _grid(name: str, values, allowed: str, valid, counted: Callable[[int], None] | None = None) -> np.ndarray:
    """A curve's depths or thicknesses: real numbers on one non-empty axis for which ``valid`` holds (one line);
    ``counted`` is given their count before they are read (:func:`~mdr_events.limits.values_in`: 1e8 depths were
    copied and sorted before the limits refused them)."""
    if counted is not None:
        counted(values_in(values))
    array = np.atleast_1d(real_array(name, values, allowed)).astype(float)
    if array.ndim != 1 or array.size == 0 or not np.all(valid(array)):
        raise ValueError(f"{name}={shown(values)} is not allowed; allowed: {allowed}, one non-empty axis")
    check_distinct(name, array, values)
    return array


def thickness_axis(thicknesses, counted: Callable[[int], None] | None = None) -> np.ndarray:
    """Thicknesses of a curve against ``h``: numbers > 0 (m, ``inf`` the half-space) on one non-empty axis, as
    floats; else the one-line error naming ``thicknesses``.

    Parameters
    ----------
    thicknesses : float or array_like
        The thicknesses in m.
    counted : callable, optional
        Given the thicknesses' count before they are read (a check against the limits, which raises).

    Returns
    -------
    numpy.ndarray
        One axis of floats.

    Raises
    ------
    ValueError
        Not real numbers > 0, or not one non-empty axis.
    """
    return _grid("thicknesses", thicknesses, "numbers > 0 (m), inf the half-space", lambda values: values > 0.0,
                 counted)


def _variables(contact: Contact, depth, radius, dims: tuple[str, ...]) -> dict[str, xr.Variable]:
    """Radius, force, area and ``a/h`` as labelled variables (the force 0 and the radius 0 where ``nan``: no
    contact)."""
    E_star, nu, layer = layer_material(contact)
    inside = np.isfinite(radius)
    safe = np.where(inside, radius, 0.0)
    force = np.where(inside, normal_force(depth, safe, contact.indenter, E_star, nu, layer), np.nan)
    values = {"contact_radius": radius, "normal_force": force, "contact_area": np.pi * radius**2,
              "relative_radius": radius / layer.thickness}
    return {name: xr.Variable(dims, value, {"units": _VARIABLES[name][0], "long_name": _VARIABLES[name][1]})
            for name, value in values.items()}


def _stamped(dataset: xr.Dataset, contact: Contact, d_max: float, content: str) -> xr.Dataset:
    """The provenance, the contact's attributes (its layer's among them) and ``content``: the parameters with the depth
    ``d_max`` and the paper's speed, which every result the package writes and reads holds (the pull-off curve had
    none, and ``write_netcdf`` refused it)."""
    stamp(dataset, contact.parameters(d_max, PAPER_V), content=content)
    dataset.attrs.update(contact.to_attrs())
    dataset.attrs.update(contact.layer.to_attrs())  # (the half-space too: the curve is about the layer)
    return dataset


def layer_normal_curve(contact: Contact, depths, limits: Limits | None = None) -> xr.Dataset:
    r"""The adhesive branches of a paraboloid or power law on the contact's layer against the depth.

    .. math:: d = g(a) - \sqrt{\frac{4\pi a\,\Delta\gamma}{K'(a)}} \quad (9), \qquad
              F_N = F_0(a) + K(a)\,(d - g(a)) \quad (10)

    for ``Δγ0`` (the branch of indentation) and ``Δγ1`` (that of detachment), on the stable part of each (``a`` at or
    beyond the jump-off, ``∂d/∂a ≥ 0``); at ``h = inf`` the JKR branches of
    :func:`~mdr_events.jkr_contact_radius`.

    Parameters
    ----------
    contact : Contact
        A paraboloid or power law with its elastomer, adhesion and layer (``Contact.layer``; the half-space too).
    depths : float or array_like
        The depths ``d`` in m (finite; negative ones are tensile), one non-empty axis.
    limits : Limits or None, default None
        The work and memory the curve may take (:data:`CURVE_POINT_STEPS` steps and :data:`CURVE_BYTES_PER_POINT`
        bytes per point of each branch; ``None``: the defaults), checked before it runs.

    Returns
    -------
    xarray.Dataset
        Coordinates ``branch`` (``"dgamma0"``, ``"dgamma1"``) and ``depth``; variables ``contact_radius`` (m),
        ``normal_force`` (N), ``contact_area`` (m²) and ``relative_radius`` (``a/h``), ``nan`` below a branch's
        jump-off depth (no contact there); attributes of :meth:`~mdr_events.Contact.to_attrs` with the layer's.

    Raises
    ------
    TypeError
        ``contact`` not a Contact, depths not real numbers, a ``RateDependentAdhesion`` (the curves are
        rate-independent).
    ValueError
        Another indenter, a non-finite depth, no depth, the contact's scales beyond the double range, a radius beyond
        the tables (``a/h > 64``), or the points beyond ``limits`` (``ResourceLimitError``).
    """
    depth = _grid("depths", depths, "finite numbers (m)", np.isfinite,
                  lambda count: _counted(f"layer_normal_curve of {count} depths", 2 * count, CURVE_POINT_STEPS, limits))
    deepest = float(np.max(depth))
    _checked(contact, deepest if deepest > 0.0 else PAPER_D_MAX, f"layer_normal_curve to the depth {deepest!r} m",
             2 * depth.size, CURVE_POINT_STEPS, limits)
    radius = np.array([stable_radius(contact, dgamma, depth)
                       for dgamma in (contact.adhesion.dgamma0, contact.adhesion.dgamma1)])
    coords = {"branch": ("branch", ["dgamma0", "dgamma1"], {"units": "1", "long_name": "adhesive branch"}),
              "depth": ("depth", depth, {"units": "m", "long_name": _VARIABLES["depth"][1]})}
    dataset = xr.Dataset(_variables(contact, depth[None, :], radius, ("branch", "depth")), coords=coords)
    return _stamped(dataset, contact, deepest if deepest > 0.0 else PAPER_D_MAX, LAYER_CURVE_CONTENT)


def layer_indentation_cycle(contact: Contact, d_max: float, samples: int = 201,
                            limits: Limits | None = None) -> xr.Dataset:
    r"""Indentation to ``d_max`` on the ``Δγ0`` branch and back under depth control to the jump-off on ``Δγ1``.

    From the first touch (``d = 0``, the radius jumps in on ``Δγ0``) the radius grows on the ``Δγ0`` branch of (9);
    back from ``d_max`` it stays pinned at ``a_max`` (``F_N = F_0(a_max) + K(a_max)(d − g(a_max))``, (10)) until
    the depth reaches the ``Δγ1`` branch, along which it shrinks to the jump-off (its least depth), where the contact
    comes off.

    Parameters
    ----------
    contact : Contact
        A paraboloid or power law with its elastomer, adhesion (``Δγ0 ≤ Δγ1``) and layer.
    d_max : float
        The deepest depth in m, > 0.
    samples : int, default 201
        Samples of each of the three stages (loading, pinned, shrinking).
    limits : Limits or None, default None
        The work and memory the cycle may take (as :func:`layer_normal_curve`'s, per sample; ``None``: the defaults),
        checked before it runs.

    Returns
    -------
    xarray.Dataset
        Dimension ``sample``; variables ``depth`` (m), ``contact_radius`` (m), ``normal_force`` (N),
        ``contact_area`` (m²), ``relative_radius`` (``a/h``) and the coordinate ``stage`` (``"loading"``,
        ``"pinned"``, ``"shrinking"``); attributes of :meth:`~mdr_events.Contact.to_attrs` with the layer's.

    Raises
    ------
    TypeError
        ``contact`` not a Contact, or of a ``RateDependentAdhesion`` (the cycle is rate-independent).
    ValueError
        Another indenter, ``d_max`` not a finite number > 0, ``Δγ1 < Δγ0``, ``samples`` < 2, the contact's scales
        beyond the double range, or the samples beyond ``limits`` (``ResourceLimitError``).
    """
    d_max = check_real("d_max", d_max, "a finite number > 0 (m)", lambda value: value > 0.0)
    samples = check_count("samples", samples, 2)
    _checked(contact, d_max, f"layer_indentation_cycle to d_max={d_max!r} m", 3 * samples, CURVE_POINT_STEPS, limits)
    E_star, nu, layer = layer_material(contact)
    low, high = contact.adhesion.dgamma0, contact.adhesion.dgamma1
    if high < low:
        raise ValueError(f"contact.adhesion={contact.adhesion!r} is not allowed here; allowed: dgamma1 >= dgamma0")
    loading = np.linspace(0.0, d_max, samples)
    a_max = float(stable_radius(contact, low, np.array([d_max]))[0])
    unpinned = float(branch_depth(a_max, contact.indenter, E_star, nu, high, layer))
    least, fold = branch_jump_off(contact, high)
    pinned = np.linspace(d_max, unpinned, samples)
    shrinking = np.linspace(unpinned, least, samples)
    depth = np.concatenate([loading, pinned, shrinking])
    radius = np.concatenate([stable_radius(contact, low, loading), np.full(samples, a_max),
                             stable_radius(contact, high, shrinking)])
    # the last depth is the fold's: its radius the jump-off's (the closed form's on the half-space), not a bisection at
    # the fold, which gave it to ~sqrt(eps) on the half-space and nan on a layer where the rounding put the depth below
    # the fold's (inputs an ulp apart moved a figure's pixels)
    radius[-1] = fold
    stage = np.repeat(["loading", "pinned", "shrinking"], samples)
    variables = _variables(contact, depth, radius, ("sample",))
    variables["depth"] = xr.Variable(("sample",), depth, {"units": "m", "long_name": _VARIABLES["depth"][1]})
    dataset = xr.Dataset(variables, coords={"stage": ("sample", stage, {"units": "1", "long_name": "stage"})})
    return _stamped(dataset, contact, d_max, LAYER_CYCLE_CONTENT)


def layer_pull_off_curve(contact: Contact, thicknesses, limits: Limits | None = None) -> xr.Dataset:
    r"""The pull-off force under force control against the layer's thickness, on the contact's base, with ``Δγ1``.

    .. math:: F_\mathrm{po}(h) = \min_a\,[F_0(a) - K(a)\,\Delta l(a)] \qquad (10)

    (``−(3/2) π Δγ1 R`` for the paraboloid on the half-space, ``h = inf``); :func:`pull_off` at each thickness.

    Parameters
    ----------
    contact : Contact
        A paraboloid or power law with its elastomer, adhesion and the layer's base (its thickness is replaced).
    thicknesses : float or array_like
        The thicknesses ``h`` in m (> 0; ``inf`` the half-space), one non-empty axis.
    limits : Limits or None, default None
        The work the curve may take (:data:`PULL_OFF_STEPS` steps per thickness; ``None``: the defaults), checked
        before it runs.

    Returns
    -------
    xarray.Dataset
        Coordinate ``thickness`` (m); variables ``pull_off_force`` (N), ``pull_off_radius`` (m), ``pull_off_depth``
        (m) and ``relative_radius`` (``a/h`` at pull-off); the contact's attributes.

    Raises
    ------
    TypeError
        ``contact`` not a Contact, or of a ``RateDependentAdhesion`` (the pull-off is rate-independent).
    ValueError
        Another indenter, no adhesion (``Δγ1`` = 0), a thickness not > 0, no thickness or a repeated one, the
        contact's scales beyond the double range, a pull-off beyond the tables (``a/h > 64``), or the thicknesses
        beyond ``limits`` (``ResourceLimitError``).
    """
    E_star, nu, _ = layer_material(contact)
    h = thickness_axis(thicknesses, lambda count: _counted("layer_pull_off_curve", count, PULL_OFF_STEPS, limits))
    _checked(contact, PAPER_D_MAX, "layer_pull_off_curve", h.size, PULL_OFF_STEPS, limits)
    if not contact.adhesion.dgamma1 > 0.0:  # (pull_off named its own argument, dgamma=0.0, which the user never gave)
        raise ValueError(f"contact.adhesion.dgamma1={contact.adhesion.dgamma1!r} is not allowed in "
                         "layer_pull_off_curve; allowed: a work of adhesion > 0 (J/m²): without adhesion nothing pulls")
    found = [pull_off(contact.indenter, E_star, nu, contact.adhesion.dgamma1, Layer(float(value), contact.layer.base))
             for value in h]
    values = {"pull_off_force": ([p.force for p in found], "N", "pull-off force (force control, dgamma1)"),
              "pull_off_radius": ([p.radius for p in found], "m", "contact radius at pull-off"),
              "pull_off_depth": ([p.depth for p in found], "m", "depth at pull-off"),
              "relative_radius": ([p.relative_radius for p in found], "1", "a/h at pull-off")}
    dataset = xr.Dataset({name: ("thickness", np.array(v), {"units": u, "long_name": ln})
                          for name, (v, u, ln) in values.items()},
                         coords={"thickness": ("thickness", h, {"units": "m", "long_name": "layer thickness h"})})
    return _stamped(dataset, contact, PAPER_D_MAX, LAYER_PULL_OFF_CONTENT)
