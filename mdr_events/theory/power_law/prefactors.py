"""The power law's scales: the MDR profile's prefactor ``κₙ c`` (3), the cap per radius ``K`` (13) and Heß's
prefactor ``sqrt(2π Δγ / E*)`` (8).
"""

from __future__ import annotations

from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import PowerLaw
from mdr_events.theory.power_law.arguments import _rel, check_work

__all__ = ["prefactor", "cap_per_radius", "hess_prefactor"]


def prefactor(profile: PowerLaw) -> float:
    r"""``κₙ c = g(1)``: the MDR profile is ``g(x) = κₙ c xⁿ`` (3).

    .. math:: \kappa_n = \frac{\sqrt{\pi}\, \Gamma(n/2 + 1)}{\Gamma(n/2 + 1/2)}

    Parameters
    ----------
    profile : PowerLaw
        The power law ``f = c rⁿ``.

    Returns
    -------
    float
        ``κₙ c`` (m^(1−n)).
    """
    return float(_rel("profile_power_law").numeric(1.0, profile.c, profile.n))


def cap_per_radius(params: Parameters) -> float:
    """``K``: the critical shift (13) is ``ū = K a``."""
    return float(_rel("critical_shift").numeric(1.0, params.tau0, params.G_star))


def hess_prefactor(params: Parameters, work_of_adhesion: float) -> float:
    r"""``sqrt(2π Δγ / E*)``: Heß's limit (8) is this times ``√a``.

    .. math:: \Delta l_\mathrm{max}(a) = \sqrt{\frac{2 \pi a \Delta\gamma}{E^*}} \qquad (8)

    Parameters
    ----------
    params : Parameters
        The material (``E*``).
    work_of_adhesion : float
        ``Δγ`` (J/m², >= 0): one number.

    Returns
    -------
    float
        ``sqrt(2π Δγ / E*)`` (m^(1/2)).

    Raises
    ------
    TypeError
        A ``work_of_adhesion`` that is no number (an array or a list of them).
    ValueError
        A negative or non-finite ``work_of_adhesion``.
    """
    return float(_rel("hess_max_elongation").numeric(1.0, check_work(work_of_adhesion), params.E_star))

