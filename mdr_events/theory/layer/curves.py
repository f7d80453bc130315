r"""The normal contact of a :class:`~mdr_events.Contact` on its layer as labelled results: the adhesive branches
against the depth (:func:`layer_normal_curve`), an indentation to ``d_max`` and back to the jump-off
(:func:`layer_indentation_cycle`) and the pull-off force against the thickness (:func:`layer_pull_off_curve`).

Part of :mod:`mdr_events.theory.layer` (the relations (L1)–(L5) are stated there). The depth of the branch of radius
``a`` is ``d(a) = g(a) − Δl(a)`` (generalised (9)); its stable part is ``a ≥ a_jo`` (``∂d/∂a ≥ 0``, ``a_jo`` the
radius of the jump-off under depth control, the least depth). A depth is inverted on it by bisection in ``ln a``
inside the bracket of a logarithmic scan, for all depths at once.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import xarray as xr

from mdr_events.contact.indenters import Paraboloid, PowerLaw
from mdr_events.contact.layer import Layer
from mdr_events.contact.model import Contact
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.limits import Limits, check_limits
from mdr_events.parameters import PAPER_D_MAX, PAPER_V
from mdr_events.theory.layer.compliance import LAMBDA_MAX
from mdr_events.theory.layer.force_control import pull_off
from mdr_events.theory.layer.relations import _abel_factor, _power_law, branch_depth, normal_force
from mdr_events.validation import SCALE_MAX, SCALE_MIN, check_count, check_real, real_array, shown

__all__ = ["layer_normal_curve", "layer_indentation_cycle", "layer_pull_off_curve", "LAYER_CURVE_CONTENT",
           "LAYER_CYCLE_CONTENT", "LAYER_PULL_OFF_CONTENT", "CURVE_POINT_STEPS", "PULL_OFF_STEPS",
           "CURVE_BYTES_PER_POINT", "layer_material", "half_space_radii", "check_scales", "stable_radius",
           "branch_jump_off", "scan_ceiling", "beyond_tables", "thickness_axis", "INSIDE_TABLES"]

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

#: Points of the logarithmic scan of ``d(a)`` that brackets each depth (the bisection refines it).
_SCAN_POINTS = 400
#: Bisection steps in ``ln a`` inside one scan interval (its width ``< 0.05``): ``0.05 · 2⁻⁶⁰`` is far below ulps.
_BISECTIONS = 60
#: The scan starts this far below the half-space's pull-off radius (``d`` falls from 0 there, the least depth lies
#: above it).
_SCAN_BELOW = 1e-4

#: The scan's scale without adhesion at depth 0 (m): no contact to scan, any positive radius serves.
_SMALLEST_SCALE = 1e-9
#: A scan ends this close inside the tables' last radius ``64 h``: its nodes are ``exp(ln a)``, which may round above
#: ``a`` (a contact whose scan reached the tables' end was refused with ``a/h = 64.00000000000001``).
INSIDE_TABLES = 1.0 - 1e-12

#: What one point of a normal curve or a cycle counts against :attr:`~mdr_events.Limits.steps`: its share of the scan
#: and :data:`_BISECTIONS` evaluations of the branch, about 20 µs here, where the discrete model's step takes about
#: 1.5 µs (its default 2e7 steps about 30 s), so that a curve is checked before it runs (1e9 samples of a cycle were
#: taken, and the process killed for its memory).
CURVE_POINT_STEPS = 15.0
#: What one thickness of the pull-off curve counts against :attr:`~mdr_events.Limits.steps`: a scan of the branch
#: force and Brent's refinement, about 8 ms here.
PULL_OFF_STEPS = 5000.0
#: The memory of one point of a curve (its variables and the bisection's temporaries: 110 to 142 bytes measured),
#: counted against :attr:`~mdr_events.Limits.memory`.
CURVE_BYTES_PER_POINT = 256.0

#: What the scales of a curve's contact must be (:func:`check_scales`).
_SCALES = (f"a contact whose scales lie within {SCALE_MIN:.2g} to {SCALE_MAX:.2g} in SI units, so that their products "
           "stay finite in double precision")

#: The variables' units and long names.
_VARIABLES = {"contact_radius": ("m", "contact radius a"), "normal_force": ("N", "normal force F_N"),
              "contact_area": ("m2", "contact area pi a^2"), "relative_radius": ("1", "contact radius over thickness a/h"),
              "depth": ("m", "indentation depth d")}


def layer_material(contact: Any) -> tuple[float, float, Layer]:
    """``(E*, ν, layer)`` of a contact of a paraboloid or power law; else the one-line error.

    Parameters
    ----------
    contact : Contact
        A contact of a paraboloid or power law (on any layer, the half-space too).

    Returns
    -------
    tuple of (float, float, Layer)
        ``E*`` (Pa), Poisson's ratio and the contact's layer.

    Raises
    ------
    TypeError
        ``contact`` not a :class:`~mdr_events.Contact`.
    ValueError
        Another indenter (the layer's factors are tabulated for the power laws).
    """
    if not isinstance(contact, Contact):
        raise TypeError(f"contact={shown(contact)} ({type(contact).__name__}) is not allowed; allowed: a "
                        "mdr_events.Contact, e.g. Contact.paper().replace(h=5e-3)")
    if not isinstance(contact.indenter, (Paraboloid, PowerLaw)):
        raise ValueError(f"contact.indenter={contact.indenter!r} is not allowed on a layer yet; allowed: a Paraboloid "
                         "or a PowerLaw (the tabulated factors; a general profile: theory.layer.equivalent_profile)")
    return contact.elastomer.E_star, contact.elastomer.nu, contact.layer


def half_space_radii(contact: Contact, dgamma: float, depth: float) -> tuple[float, float]:
    """The half-space's pull-off radius of ``dgamma`` (``a^(2n−1) = 9Δγ/(2E* n² κₙ² c²)``) and its radius without
    adhesion at ``depth`` (``κₙ c aⁿ = d``, 0 at ``d ≤ 0``): the scales of a scan (m).

    Parameters
    ----------
    contact : Contact
        A contact of a paraboloid or power law.
    dgamma : float
        The work of adhesion (J/m²).
    depth : float
        The depth (m).

    Returns
    -------
    tuple of (float, float)
        The pull-off radius and the radius without adhesion (m).

    Raises
    ------
    ZeroDivisionError, OverflowError
        A power of a scale beyond the double range (:func:`check_scales` turns it into its one line).
    """
    E_star, _, _ = layer_material(contact)
    c, n = _power_law(contact.indenter)
    kappa = _abel_factor(n)
    pulled = (9.0 * dgamma / (2.0 * E_star * n**2 * kappa**2 * c**2)) ** (1.0 / (2.0 * n - 1.0))
    hertz = (max(depth, 0.0) / (kappa * c)) ** (1.0 / n)
    return pulled, hertz


def check_scales(contact: Contact, depth: float, what: str) -> None:
    """The scales a curve computes with at the depth ``depth`` (> 0), each within ``SCALE_MIN`` to ``SCALE_MAX`` (so
    that their products stay finite), as the simulators' are (``R = 1e308`` gave a ``ZeroDivisionError``, ``1e-300``
    an ``OverflowError``); else the one-line ``ValueError`` naming the first and ``what``.

    Parameters
    ----------
    contact : Contact
        A contact of a paraboloid or power law.
    depth : float
        The deepest depth computed (m, > 0).
    what : str
        The function asked, named in the error.

    Raises
    ------
    ValueError
        A scale (``E*``, the profile's ``c``, the depth, the works of adhesion, the half-space's radii) outside
        ``SCALE_MIN`` to ``SCALE_MAX``.
    """
    E_star, _, _ = layer_material(contact)
    c, _ = _power_law(contact.indenter)
    scales = [("E*", E_star, "Pa"), ("the profile's c", c, "SI units"), ("the depth", depth, "m")]
    for dgamma, name in ((contact.adhesion.dgamma1, "Δγ1"), (contact.adhesion.dgamma0, "Δγ0")):
        try:
            pulled, hertz = half_space_radii(contact, dgamma, depth)
        except (ZeroDivisionError, OverflowError) as error:  # (a power of a scale beyond the double range)
            raise ValueError(f"{what}: the half-space's radii overflow ({error}) ({contact!r}); allowed: {_SCALES}")
        scales.append(("the half-space's radius at the depth", hertz, "m"))
        if dgamma > 0.0:
            scales += [(name, dgamma, "J/m²"), (f"the half-space's pull-off radius of {name}", pulled, "m")]
    for name, value, unit in scales:
        if not SCALE_MIN <= abs(value) <= SCALE_MAX:
            raise ValueError(f"{what}: {name} is {value:.3g} {unit} ({contact!r}); allowed: {_SCALES}")


def _checked(contact: Any, depth: float, what: str, points: int, steps_each: float, limits: Limits | None) -> None:
    """A curve's contact checked before it runs: a paraboloid or power law (:func:`layer_material`), the scales it
    computes with at ``depth`` (:func:`check_scales`), and the curve's ``points`` (each ``steps_each`` steps) within
    ``limits``."""
    layer_material(contact)
    check_scales(contact, depth, what)
    check_limits(limits).check(f"{what} ({points} points)", samples=float(points), steps=steps_each * points,
                               memory=CURVE_BYTES_PER_POINT * points)


def _grid(name: str, values, allowed: str, valid) -> np.ndarray:
    """A curve's depths or thicknesses: real numbers on one non-empty axis for which ``valid`` holds (one line)."""
    array = np.atleast_1d(real_array(name, values, allowed)).astype(float)
    if array.ndim != 1 or array.size == 0 or not np.all(valid(array)):
        raise ValueError(f"{name}={shown(values)} is not allowed; allowed: {allowed}, one non-empty axis")
    return array


def thickness_axis(thicknesses) -> np.ndarray:
    """Thicknesses of a curve against ``h``: numbers > 0 (m, ``inf`` the half-space) on one non-empty axis, as
    floats; else the one-line error naming ``thicknesses``.

    Parameters
    ----------
    thicknesses : float or array_like
        The thicknesses in m.

    Returns
    -------
    numpy.ndarray
        One axis of floats.

    Raises
    ------
    ValueError
        Not real numbers > 0, or not one non-empty axis.
    """
    return _grid("thicknesses", thicknesses, "numbers > 0 (m), inf the half-space", lambda values: values > 0.0)


def scan_ceiling(layer: Layer) -> float:
    """The largest radius a scan of the layer's branches takes: the tables' last, ``64 h``, just inside
    (:data:`INSIDE_TABLES`).

    Parameters
    ----------
    layer : Layer
        A layer of finite thickness.

    Returns
    -------
    float
        The radius (m).
    """
    return LAMBDA_MAX * layer.thickness * INSIDE_TABLES


def beyond_tables(depth: float, layer: Layer, ceiling: float) -> ValueError:
    """The error of a depth whose contact radius lies beyond the scan's last radius ``ceiling`` (the tables').

    Parameters
    ----------
    depth : float
        The depth (m).
    layer : Layer
        The layer.
    ceiling : float
        The last radius a scan takes (m).

    Returns
    -------
    ValueError
        Its one line, to raise.
    """
    return ValueError(f"depth={depth!r} m is not allowed on {layer.describe()}: its contact radius exceeds a/h = "
                      f"{LAMBDA_MAX:g}; allowed: depths whose radius is below {ceiling:.6g} m")


def _radius_scale(contact: Contact, dgamma: float, depth: float) -> tuple[float, float]:
    """The scan's range in ``a``: from far below the half-space's pull-off radius to where ``d(a) ≥ depth`` (the
    largest ``a/h`` of the tables at most)."""
    E_star, nu, layer = layer_material(contact)
    pulled, hertz = half_space_radii(contact, dgamma, depth)
    scale = max(pulled, hertz) or _SMALLEST_SCALE
    low, high = _SCAN_BELOW * scale, 2.0 * scale
    ceiling = scan_ceiling(layer)
    while float(branch_depth(min(high, ceiling), contact.indenter, E_star, nu, dgamma, layer)) < depth:
        if high >= ceiling:
            raise beyond_tables(depth, layer, ceiling)
        high *= 2.0
    return low, min(high, ceiling)


def stable_radius(contact: Contact, dgamma: float, depths: np.ndarray) -> np.ndarray:
    """The radius on the stable part of the branch of ``dgamma`` at each depth (``nan`` below the least depth).

    The branch ``d(a) = g(a) − Δl(a)`` (generalised (9)) is scanned in ``ln a`` and each depth bisected on its part
    beyond the least depth (``∂d/∂a ≥ 0``).

    Parameters
    ----------
    contact : Contact
        A contact of a paraboloid or power law on its layer.
    dgamma : float
        The work of adhesion of the branch (J/m², ≥ 0).
    depths : numpy.ndarray
        The depths (m).

    Returns
    -------
    numpy.ndarray
        The contact radii (m), ``nan`` below the branch's least depth; 0 at ``d = 0`` without adhesion.

    Raises
    ------
    ValueError
        A radius beyond the tables (``a/h > 64``).
    """
    E_star, nu, layer = layer_material(contact)
    low, high = _radius_scale(contact, dgamma, float(np.max(depths, initial=0.0)))
    logs = np.linspace(math.log(low), math.log(high), _SCAN_POINTS)

    def depth_of(log_radius: np.ndarray) -> np.ndarray:
        return branch_depth(np.exp(log_radius), contact.indenter, E_star, nu, dgamma, layer)

    scanned = depth_of(logs)
    turn = int(np.argmin(scanned))
    stable, stable_depths = logs[turn:], scanned[turn:]
    if 0 < turn < logs.size - 1:  # (the least depth itself, not the scan's: every depth above it has a bracket)
        least, at_least = _least(depth_of, logs, turn)
        stable = np.concatenate([[at_least], logs[turn + 1:]])
        stable_depths = np.concatenate([[least], scanned[turn + 1:]])
    index = np.clip(np.searchsorted(stable_depths, depths), 1, max(stable.size - 1, 1))
    lower, upper = stable[index - 1], stable[index]
    for _ in range(_BISECTIONS):
        middle = 0.5 * (lower + upper)
        above = depth_of(middle) >= depths
        lower, upper = np.where(above, lower, middle), np.where(above, middle, upper)
    radius = np.exp(0.5 * (lower + upper))
    radius = np.where(depths >= stable_depths[0], radius, np.nan)
    if dgamma == 0.0:  # (without adhesion the branch d = g(a) starts at d = 0 with a = 0: the first touch)
        radius = np.where(depths == 0.0, 0.0, radius)
    return radius


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
        ``contact`` not a Contact, depths not real numbers.
    ValueError
        Another indenter, a non-finite depth, no depth, the contact's scales beyond the double range, a radius beyond
        the tables (``a/h > 64``), or the points beyond ``limits`` (``ResourceLimitError``).
    """
    depth = _grid("depths", depths, "finite numbers (m)", np.isfinite)
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
        ``contact`` not a Contact.
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
    least, _ = branch_jump_off(contact, high)
    pinned = np.linspace(d_max, unpinned, samples)
    shrinking = np.linspace(unpinned, least, samples)
    depth = np.concatenate([loading, pinned, shrinking])
    radius = np.concatenate([stable_radius(contact, low, loading), np.full(samples, a_max),
                             stable_radius(contact, high, shrinking)])
    stage = np.repeat(["loading", "pinned", "shrinking"], samples)
    variables = _variables(contact, depth, radius, ("sample",))
    variables["depth"] = xr.Variable(("sample",), depth, {"units": "m", "long_name": _VARIABLES["depth"][1]})
    dataset = xr.Dataset(variables, coords={"stage": ("sample", stage, {"units": "1", "long_name": "stage"})})
    return _stamped(dataset, contact, d_max, LAYER_CYCLE_CONTENT)


def branch_jump_off(contact: Contact, dgamma: float) -> tuple[float, float]:
    """The least depth of the branch of ``dgamma`` and its radius: the jump-off under depth control (m, m).

    ``∂d/∂a = 0`` on ``d(a) = g(a) − Δl(a)`` (generalised (9)): a scan in ``ln a`` and Brent's method around its
    least node.

    Parameters
    ----------
    contact : Contact
        A contact of a paraboloid or power law on its layer.
    dgamma : float
        The work of adhesion of the branch (J/m², ≥ 0).

    Returns
    -------
    tuple of (float, float)
        The least depth (m, ≤ 0) and the radius there (m); ``(0, 0)`` without adhesion.

    Raises
    ------
    ValueError
        A branch that does not rise back to the depth 0 within the tables (``a/h > 64``).
    """
    E_star, nu, layer = layer_material(contact)
    if dgamma == 0.0:  # (the branch d = g(a) rises from the first touch: its least depth is 0, at a = 0)
        return 0.0, 0.0
    low, high = _radius_scale(contact, dgamma, 0.0)
    logs = np.linspace(math.log(low), math.log(high), _SCAN_POINTS)

    def depth_of(log_radius):
        return branch_depth(np.exp(log_radius), contact.indenter, E_star, nu, dgamma, layer)

    least, at_least = _least(depth_of, logs, int(np.argmin(depth_of(logs))))
    return least, float(np.exp(at_least))


def _least(depth_of, logs: np.ndarray, best: int) -> tuple[float, float]:
    """The least depth near the scan's node ``best`` and its ``ln a`` (Brent's method on the nodes around it)."""
    from scipy.optimize import minimize_scalar

    best = min(max(best, 1), logs.size - 2)
    found = minimize_scalar(lambda value: float(depth_of(value)), bracket=(logs[best - 1], logs[best], logs[best + 1]),
                            method="brent", options={"xtol": 1e-12})
    return float(found.fun), float(found.x)


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
        ``contact`` not a Contact.
    ValueError
        Another indenter, a thickness not > 0, no thickness, the contact's scales beyond the double range, a pull-off
        beyond the tables (``a/h > 64``), or the thicknesses beyond ``limits`` (``ResourceLimitError``).
    """
    E_star, nu, _ = layer_material(contact)
    h = thickness_axis(thicknesses)
    _checked(contact, PAPER_D_MAX, "layer_pull_off_curve", h.size, PULL_OFF_STEPS, limits)
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
