"""How far a layer of finite thickness reaches in the continuum: the contact radius at a path's deepest depth within the
layer's tables, and not so far below its thickness that the layer is the half-space to the doubles' rounding."""

from __future__ import annotations

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.parameters import Parameters
from mdr_events.theory.kinds import theory_of
from mdr_events.theory.layer.punch_onset import check_punch_face

__all__ = ["THINNEST_LAYER_SHARE", "check_layer_reach"]

#: The least ``a/h`` at the deepest depth the continuum takes on a layer of finite thickness: the layer's factors are
#: the half-space's plus ``O(a/h)`` (the tables' series below ``LAMBDA_MIN``), so below the doubles' epsilon the layer
#: is the half-space to their rounding, and its branch (``d`` the difference of terms in ``h``) loses every digit
#: further on (``h = 1e60`` on the paper's contact: no root found; ``1e160``: an overflow).
THINNEST_LAYER_SHARE = float(np.finfo(float).eps)


def check_layer_reach(params: Parameters, depth: float, profile: SimulatedProfile, layer: Layer) -> None:
    """Refuse, before the continuum builds its branches, a layer whose contact radius at ``depth`` lies beyond the
    layer's tables (``a/h > 64``: ``h = 1e-20`` divided by zero; a flat punch's face,
    :func:`~mdr_events.theory.layer.punch_onset.check_punch_face`) or below :data:`THINNEST_LAYER_SHARE` of its
    thickness (the half-space to the doubles' rounding); the half-space passes.

    Parameters
    ----------
    params : Parameters
        The material and the works of adhesion.
    depth : float
        The deepest depth of the path (m).
    profile : PowerLaw, FlatPunch, TabulatedProfile or None
        The indenter (``None``: the paraboloid of ``params.R``).
    layer : Layer
        The body.

    Raises
    ------
    ValueError
        Naming the depth, the punch or the layer, the radius and what is allowed.
    """
    if layer.is_half_space or depth <= 0.0:
        return
    from mdr_events.models.spring_media import springs_of  # (the discrete's springs: the layer's branch, checked)

    if theory_of(profile).flat_face:  # (its radius is the face's from the first touch on: within the tables, or no run)
        check_punch_face(profile, layer, "the continuum method")
        # (at a depth > 0, above the face's jump-off (Kendall's depth, <= 0), the branch's radius is the face's: what
        # ``branch_radius`` gives, without its jump-off's relations read again every run)
        radius = float(profile.radius)
    else:
        radius = springs_of(params, profile, None, layer).branch_radius(depth)  # (beyond the tables: refused there)
    if radius < THINNEST_LAYER_SHARE * layer.thickness:
        raise ValueError(f"contact.layer={layer!r} is not allowed in the continuum method: the contact radius "
                         f"{radius:.6g} m at the depth {depth!r} m is below {THINNEST_LAYER_SHARE:.3g} of the "
                         f"thickness, where the layer is the half-space to the doubles' rounding; allowed: h <= "
                         f"{radius / THINNEST_LAYER_SHARE:.6g} m, or h = inf (the half-space)")
