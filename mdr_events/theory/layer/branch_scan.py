r"""The scan of a branch on a layer: a depth inverted on its stable part (:func:`stable_radius`) and its least depth,
the jump-off under depth control (:func:`branch_jump_off`), with what a contact must be to be scanned
(:func:`layer_material`, :func:`check_scales`) and where a scan ends (:func:`scan_ceiling`).

Part of :mod:`mdr_events.theory.layer` (the relations (L1)–(L5) are stated there). The depth of the branch of radius
``a`` is ``d(a) = g(a) − Δl(a)`` (generalised (9)); its stable part is ``a ≥ a_jo`` (``∂d/∂a ≥ 0``, ``a_jo`` the
radius of the jump-off under depth control, the least depth). A depth is inverted on it by bisection in ``ln a``
inside the bracket of a logarithmic scan, for all depths at once. The curves (:mod:`.curves`), the slip onset
(:mod:`.slip_onset`) and the branch points (:mod:`.branch_points`) scan with it.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from mdr_events.contact.indenters import Paraboloid, PowerLaw
from mdr_events.contact.layer import Layer
from mdr_events.contact.model import Contact
from mdr_events.parameters import PAPER_D_MAX, PAPER_V
from mdr_events.theory.layer.compliance import LAMBDA_MAX
from mdr_events.theory.layer.branch_slopes import depth_slope, flat_least
from mdr_events.theory.layer.relations import _abel_factor, _power_law, branch_depth
from mdr_events.validation import SCALE_MAX, SCALE_MIN, shown

__all__ = ["layer_material", "half_space_radii", "check_scales", "scan_ceiling", "beyond_tables", "stable_radius",
           "branch_jump_off", "INSIDE_TABLES"]

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

#: What the scales of a curve's contact must be (:func:`check_scales`).
_SCALES = (f"a contact whose scales lie within {SCALE_MIN:.2g} to {SCALE_MAX:.2g} in SI units, so that their products "
           "stay finite in double precision")


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


def branch_jump_off(contact: Contact, dgamma: float) -> tuple[float, float]:
    """The least depth of the branch of ``dgamma`` and its radius: the jump-off under depth control (m, m).

    ``∂d/∂a = 0`` on ``d(a) = g(a) − Δl(a)`` (generalised (9)): a scan in ``ln a`` and the root of the slope
    (:func:`~.branch_slopes.flat_least`) around its least node.

    Parameters
    ----------
    contact : Contact
        The indenter (a paraboloid or power law), its elastomer and layer.
    dgamma : float
        ``Δγ`` of the branch whose least depth is sought (J/m², ≥ 0).

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
    if layer.is_half_space:  # (the closed form: Brent's minimum of a flat least depth has its radius to ~sqrt(eps))
        from mdr_events.theory.branches import jump_off

        found = jump_off(contact.parameters(PAPER_D_MAX, PAPER_V), dgamma, contact.profile)
        return float(found["depth"]), float(found["contact_radius"])
    low, high = _radius_scale(contact, dgamma, 0.0)
    logs = np.linspace(math.log(low), math.log(high), _SCAN_POINTS)

    def depth_of(log_radius):
        return branch_depth(np.exp(log_radius), contact.indenter, E_star, nu, dgamma, layer)

    def slope_of(log_radius):
        return depth_slope(math.exp(log_radius), contact.indenter, E_star, nu, dgamma, layer)

    least, at_least = flat_least(depth_of, slope_of, logs, int(np.argmin(depth_of(logs))))
    return least, float(np.exp(at_least))


def _least(depth_of, logs: np.ndarray, best: int) -> tuple[float, float]:
    """The least depth near the scan's node ``best`` and its ``ln a`` (Brent's method on the nodes around it)."""
    from scipy.optimize import minimize_scalar

    best = min(max(best, 1), logs.size - 2)
    found = minimize_scalar(lambda value: float(depth_of(value)), bracket=(logs[best - 1], logs[best], logs[best + 1]),
                            method="brent", options={"xtol": 1e-12})
    return float(found.fun), float(found.x)
