r"""The discrete model's thresholds: the depths at which each spring can be in contact, by the adhesion law.

Heß's rule (8) with hysteresis (:mod:`mdr_events.models.discrete`): a spring attaches where the depth reaches
``g(x_j) − Δl_max(x_j; Δγ0)`` and lets go below ``g(x_j) − Δl_max(x_j; Δγ1)``; the threshold falls to a minimum and
then rises, so the springs in contact stay contiguous from the centre. Each adhesion law's thresholds are looked up
by its type (:data:`THRESHOLD_RULES`); the elongation is the springs' kind's (:mod:`mdr_events.models.spring_media`).
"""

from __future__ import annotations

from typing import Callable, NamedTuple

import numpy as np

from mdr_events.contact.adhesion import Adhesion, AdhesionLaw, RateDependentAdhesion, kernel_of
from mdr_events.models.spring_media import Springs

__all__ = ["Thresholds", "THRESHOLD_RULES", "check_thresholds_known", "spring_thresholds"]


class _Threshold:
    """Depths at which each spring can be in contact: ``g(x_j) − Δl_max(x_j; Δγ)``.

    ``count(d)`` is the number of springs (from the centre) that satisfy
    ``depth >= threshold``; the set is contiguous because the threshold
    falls to its minimum and then rises.
    """

    def __init__(self, g: np.ndarray, elongation: np.ndarray):
        threshold = g - elongation
        self.threshold = np.append(threshold, np.inf)  # a spring beyond the array never qualifies
        self.lowest = int(np.argmin(threshold))
        self.minimum = float(threshold[self.lowest])
        self.rising = threshold[self.lowest + 1:]

    def count(self, depth: np.ndarray) -> np.ndarray:
        above = self.lowest + 1 + np.searchsorted(self.rising, depth, side="right")
        return np.where(depth >= self.minimum, above, 0)

    def grow(self, m: np.ndarray, depth: np.ndarray) -> np.ndarray:
        """Going in: the next spring attaches if ``depth`` reaches its threshold, then all that follow.

        If the next spring is inside the minimum of the threshold, every spring up to
        the minimum has a lower threshold and attaches with it (a jump-in).
        """
        return np.where(depth >= self.threshold[m], np.maximum(m, self.count(depth)), m)

    def shrink(self, m: np.ndarray, depth: np.ndarray) -> np.ndarray:
        """Going out: the boundary spring detaches if ``depth`` falls below its threshold, then
        the next inner one, and so on. On the falling side of the threshold every inner spring
        has a higher threshold, so the whole contact comes off (a jump-off)."""
        boundary = np.maximum(m - 1, 0)
        holds = (m == 0) | (depth >= self.threshold[boundary])
        inner = np.where(boundary > self.lowest, np.minimum(m, self.count(depth)), 0)
        return np.where(holds, m, inner)


class Thresholds(NamedTuple):
    """The springs' thresholds of an adhesion law: attaching on the way in, letting go on the way out."""

    attach: _Threshold
    detach: _Threshold


def hysteresis_thresholds(adhesion: Adhesion, g: np.ndarray, positions: np.ndarray, springs: Springs) -> Thresholds:
    r"""The paper's rate-independent law: Heß's limit (8) with ``Δγ0`` to attach and ``Δγ1`` to let go.

    .. math:: \Delta l_\mathrm{max}(x) = \sqrt{\frac{2 \pi |x| \Delta\gamma}{E^*}} \qquad (8)

    on the half-space; on a layer ``sqrt(4π |x| Δγ / K'(|x|))`` (``springs.elongation``,
    :mod:`mdr_events.models.spring_media`).
    """
    return Thresholds(_Threshold(g, springs.elongation(positions, adhesion.dgamma0)),
                      _Threshold(g, springs.elongation(positions, adhesion.dgamma1)))


def rate_thresholds(adhesion: RateDependentAdhesion, g: np.ndarray, positions: np.ndarray,
                    springs: Springs) -> Thresholds:
    """A rate-dependent law: the thresholds of its works at rest, which size the springs (an advancing edge stays
    inside the ``Δγ0`` branch's radius) and give the first touch; its edge moves by
    :func:`~mdr_events.models.rate_springs.rate_edge_counts`.

    Parameters
    ----------
    adhesion : RateDependentAdhesion
        The law.
    g : numpy.ndarray
        The profile at the springs (m).
    positions : numpy.ndarray
        The springs' centres (m).
    springs : HalfSpaceSprings
        The springs' kind (their Heß elongation).

    Returns
    -------
    Thresholds
        Those of :func:`hysteresis_thresholds` with the works at rest.
    """
    return hysteresis_thresholds(Adhesion(*adhesion.works_at_rest), g, positions, springs)


#: The springs' thresholds of each adhesion law, by its type.
THRESHOLD_RULES: dict[type, Callable[..., Thresholds]] = {Adhesion: hysteresis_thresholds,
                                                          RateDependentAdhesion: rate_thresholds}


def check_thresholds_known(adhesion: AdhesionLaw) -> None:
    """Refuse an adhesion law without thresholds in :data:`THRESHOLD_RULES`, naming those with them."""
    kernel_of(adhesion, THRESHOLD_RULES, "discrete")


def spring_thresholds(adhesion: AdhesionLaw, g: np.ndarray, positions: np.ndarray, springs: Springs) -> Thresholds:
    """The thresholds of ``adhesion`` for springs at ``positions`` on the profile ``g`` of the springs' kind
    (:mod:`~mdr_events.models.spring_media`: its Heß elongation)."""
    return kernel_of(adhesion, THRESHOLD_RULES, "discrete")(adhesion, g, positions, springs)
