r"""The critical angles against the layer's thickness: how a layer of finite thickness moves the paper's thresholds.

On a layer bonded to its base the springs' cap (13) is ``ū(a) = π a² τ0 / K_t(a)`` and the radius follows the layer's
branches (:mod:`mdr_events.theory.layer.slip_onset`); each critical angle of :func:`mdr_events.critical_angle`
(scenario A at ``d_max``, B at the jump-off, B+ at ``2 d_max``) is computed at each thickness, the half-space at
``h = inf``. A thin bonded layer shears like a Winkler foundation (``ū → τ0 h/G`` for every radius), so scenario A's
angle tends to ``atan(G d_max / (τ0 h))`` whatever the adhesion (``thin_limit_A``): the thinner the layer, the steeper
a path must be to slide.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from mdr_events.contact.model import Contact
from mdr_events.io.agreement import RootFound, RoundOff, register_accuracy
from mdr_events.io.datasets import register_schema, stamp
from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits
from mdr_events.parameters import PAPER_D_MAX, PAPER_V
from mdr_events.theory.analytic import critical_angle
from mdr_events.theory.layer.curves import thickness_axis
from mdr_events.theory.layer.slip_onset import CRITICAL_ANGLE_STEPS, thin_layer_onset_depth
from mdr_events.validation import check_real, shown

__all__ = ["critical_angles_against_thickness", "LAYER_ANGLES_CONTENT", "LAYER_ANGLE_SCENARIOS",
           "STEPS_PER_THICKNESS", "ANGLE_RTOL"]

#: The ``content`` attribute of :func:`critical_angles_against_thickness`.
LAYER_ANGLES_CONTENT = "critical angles against the layer thickness"
#: The scenarios of the ``scenario`` dimension (:data:`mdr_events.theory.analytic.CRITICAL_ANGLE_SCENARIOS`).
LAYER_ANGLE_SCENARIOS = ("A", "B", "B+")
#: What one thickness counts against :attr:`~mdr_events.Limits.steps`: six critical angles (each
#: :data:`~mdr_events.theory.layer.slip_onset.CRITICAL_ANGLE_STEPS`), checked before the first. (1e4 for all six, a
#: sixth of their 84 ms at the discrete step's 1.5 µs, let 2000 thicknesses pass the default limits: three minutes.)
STEPS_PER_THICKNESS = 6 * CRITICAL_ANGLE_STEPS
register_schema(LAYER_ANGLES_CONTENT, {"critical_angle_jkr": ("scenario", "thickness"),
                                       "critical_angle_hertz": ("scenario", "thickness"),
                                       "thin_limit_A": ("thickness",)})
#: The angles' relative accuracy (the attribute ``angle_rtol``): scenario B's lies at the jump-off, a flat minimum of
#: ``d(a)`` (Brent's method: ``ln a`` to ``sqrt(eps)|ln a|``, ``tan α_c`` to ~1e-7 relative); the others are
#: bisections to round-off.
ANGLE_RTOL = 1e-7
register_accuracy(LAYER_ANGLES_CONTENT, {"critical_angle_jkr": RootFound("angle_rtol"),
                                         "critical_angle_hertz": RootFound("angle_rtol"), "thin_limit_A": RoundOff(),
                                         "thickness": RoundOff()})


def critical_angles_against_thickness(contact: Contact, thicknesses, *, d_max: float | None = None,
                                      limits: Limits = DEFAULT_LIMITS) -> xr.Dataset:
    r"""The critical angles of scenarios A, B and B+ (:func:`mdr_events.critical_angle`) on layers of the given
    thicknesses, with and without adhesion, and scenario A's thin-layer limit.

    .. math:: \tan\alpha_c^{A} \to \frac{G\,d_\mathrm{max}}{\tau_0 h} \quad (h \to 0)

    Parameters
    ----------
    contact : Contact
        A paraboloid or power law under the law (13), on a layer bonded to its base (its thickness is replaced; the
        half-space's contact takes a bonded layer).
    thicknesses : float or array_like
        The thicknesses ``h`` in m (> 0; ``inf`` the half-space), one axis.
    d_max : float, optional
        The motion's depth (m; default the paper's 0.3 mm); B+ goes to ``2 d_max``.
    limits : Limits, optional
        Each thickness counts :data:`STEPS_PER_THICKNESS` steps, checked before the first.

    Returns
    -------
    xarray.Dataset
        Coordinates ``thickness`` (m) and ``scenario`` (:data:`LAYER_ANGLE_SCENARIOS`); ``critical_angle_jkr``
        (Heß's rule with ``Δγ0`` in, ``Δγ1`` out) and ``critical_angle_hertz`` (without adhesion; 90° in B) in
        degrees; ``thin_limit_A`` (degrees; 0 at ``inf``); the contact's attributes.

    Raises
    ------
    TypeError
        ``contact`` not a Contact.
    ValueError
        A thickness not > 0, another law or indenter, a frictionless base, an onset beyond the tables.
    ResourceLimitError
        More thicknesses than ``limits`` allows.
    """
    if not isinstance(contact, Contact):
        raise TypeError(f"contact={shown(contact)} ({type(contact).__name__}) is not allowed; allowed: a "
                        "mdr_events.Contact, e.g. Contact.paper()")
    h = thickness_axis(thicknesses, lambda count: check_limits(limits).check(  # (before they are read)
        f"the critical angles at {count} thicknesses", steps=count * STEPS_PER_THICKNESS))
    depth = PAPER_D_MAX if d_max is None else check_real("d_max", d_max, "a finite number > 0 (m)",
                                                         lambda value: value > 0.0)
    angles = {kind: np.empty((len(LAYER_ANGLE_SCENARIOS), h.size)) for kind in ("jkr", "hertz")}
    thin = np.zeros(h.size)
    for column, thickness in enumerate(h):
        layered = contact.replace(h=float(thickness))
        for row, scenario in enumerate(LAYER_ANGLE_SCENARIOS):
            for kind, adhesion in (("jkr", True), ("hertz", False)):
                angles[kind][row, column] = critical_angle(layered, scenario, adhesion, d_max=depth)
        onset = thin_layer_onset_depth(45.0, layered) if math.isfinite(thickness) else math.inf
        if math.isfinite(onset):  # (without τ0 the onset is at once: 90°, not a ZeroDivisionError)
            thin[column] = math.degrees(math.atan(depth / onset)) if onset > 0.0 else 90.0
    words = {"jkr": "adhesive (Heß's rule, dgamma0 in, dgamma1 out)", "hertz": "non-adhesive"}
    variables = {f"critical_angle_{kind}": (("scenario", "thickness"), values,
                                            {"units": "degree", "long_name": f"critical angle, {words[kind]}"})
                 for kind, values in angles.items()}
    variables["thin_limit_A"] = ("thickness", thin, {"units": "degree",
                                                     "long_name": "scenario A's angle on a thin bonded layer, "
                                                                  "atan(G d_max / (tau0 h))"})
    coords = {"thickness": ("thickness", h, {"units": "m", "long_name": "layer thickness h"}),
              "scenario": ("scenario", np.array(LAYER_ANGLE_SCENARIOS), {"units": "1", "long_name": "scenario"})}
    dataset = stamp(xr.Dataset(variables, coords=coords), contact.parameters(depth, PAPER_V),
                    content=LAYER_ANGLES_CONTENT)
    dataset.attrs.update(contact.to_attrs())
    dataset.attrs.update(param_layer_base=contact.layer.base.value, angle_rtol=ANGLE_RTOL)
    dataset.attrs.pop("param_layer_thickness", None)  # (the thickness is the coordinate)
    dataset.attrs.pop("param_layer_thickness_units", None)
    return dataset
