"""The factors the layer's relations read at ``|x|/h``: the tables' (``tables.layer_table``) or the half-space's
exactly, and a power law's ``(c, n)`` with its Abel factor ``κₙ``.

Part of :mod:`mdr_events.theory.layer` (the equations (L1)–(L5) are stated there); read by
:mod:`mdr_events.theory.layer.relations` and the modules of the punch's stiffness and the profiles.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from mdr_events.contact.layer import Layer
from mdr_events.theory.layer.compliance import _nu
from mdr_events.theory.layer.tables import layer_table


@dataclass(frozen=True)
class _HalfSpaceFactors:
    """The factors of the half-space (``λ = 0``), exactly: no table is built."""

    exponent: float

    def stiffness_factor(self, lam) -> np.ndarray:
        return np.ones(np.shape(lam))

    edge_factor = profile_factor = stiffness_factor

    def force_factor(self, lam) -> np.ndarray:
        return np.full(np.shape(lam), self.exponent / (self.exponent + 1.0))

    def force_factors(self, lam) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return self.stiffness_factor(lam), self.profile_factor(lam), self.force_factor(lam)


def _factors(nu: float, layer: Layer, exponent: float = 2.0):
    if not isinstance(layer, Layer):
        raise TypeError(f"layer={layer!r} ({type(layer).__name__}) is not allowed; allowed: a Layer")
    if layer.is_half_space:
        _nu(nu)
        return _HalfSpaceFactors(exponent)
    return layer_table(nu, layer.base, exponent)


def _relative(x, layer: Layer) -> np.ndarray:
    """``|x|/h`` (0 for the half-space)."""
    x = np.abs(np.asarray(x, dtype=float))
    return np.zeros(x.shape) if layer.is_half_space else x / layer.thickness


def _power_law(profile) -> tuple[float, float]:
    """``(c, n)`` of a paraboloid (``1/(2R)``, 2) or a power law."""
    from mdr_events.contact.indenters import Paraboloid, PowerLaw

    if isinstance(profile, Paraboloid):
        return 1.0 / (2.0 * profile.R), 2.0
    if isinstance(profile, PowerLaw):
        return profile.c, profile.n
    raise TypeError(f"profile={profile!r} ({type(profile).__name__}) is not allowed; allowed: a Paraboloid or a "
                    "PowerLaw (a general profile: equivalent_profile)")


def _abel_factor(n: float) -> float:
    """``κₙ = √π Γ(n/2 + 1)/Γ(n/2 + 1/2)``: the half-space's ``g∞ = κₙ c xⁿ`` (eq. (3))."""
    return math.exp(0.5 * math.log(math.pi) + math.lgamma(n / 2.0 + 1.0) - math.lgamma(n / 2.0 + 0.5))
