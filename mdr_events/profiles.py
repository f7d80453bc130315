"""Indenter profiles as data: the power law ``f(r) = c rⁿ`` and the flat punch.

The paper's indenter is the paraboloid ``f = r²/(2R)``, the power law with ``n = 2`` and
``c = 1/(2R)`` (:meth:`PowerLaw.paraboloid`). The MDR maps any axisymmetric profile to the
equivalent profile ``g(x)`` of the springs by the Abel transform (3); for the power law
``g(x) = κₙ c |x|ⁿ`` with ``κₙ = √π Γ(n/2 + 1) / Γ(n/2 + 1/2)`` (2 for the paraboloid, π/2 for the cone;
derived in :mod:`mdr_events.theory.symbolic`, evaluated in :mod:`mdr_events.theory.power_law`).

The closed forms of the theory layer take both; the simulators (continuum and discrete), ``validate``,
``fit``, ``sweep`` and the command line take a power law with ``n >= 1`` (``profile=``), and the paraboloid of
:class:`~mdr_events.Parameters` by default.
"""

from __future__ import annotations

from dataclasses import dataclass

from mdr_events.validation import check_real

__all__ = ["PowerLaw", "FlatPunch", "Profile", "profile_attrs"]


@dataclass(frozen=True)
class PowerLaw:
    """The axisymmetric power-law indenter ``f(r) = c rⁿ``.

    Attributes
    ----------
    c : float
        Prefactor (m^(1−n)), finite and > 0.
    n : float
        Exponent, finite and > 0: 1 the cone, 2 the paraboloid, larger ever flatter punches. With
        adhesion the relations need ``n > 1/2`` (below it the adhesive term ``√a`` outgrows ``aⁿ``
        and no contact is stable).
    """

    c: float
    n: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "c", check_real("PowerLaw.c", self.c, "a finite number > 0 (m^(1-n))",
                                                 lambda value: value > 0.0))
        object.__setattr__(self, "n", check_real("PowerLaw.n", self.n, "a finite number > 0",
                                                 lambda value: value > 0.0))

    @classmethod
    def paraboloid(cls, R: float) -> "PowerLaw":
        """The paper's indenter (4): ``f = r²/(2R)``, ``R`` the radius of curvature (m, > 0)."""
        radius = check_real("R", R, "a finite number > 0 (m)", lambda value: value > 0.0)
        return cls(1.0 / (2.0 * radius), 2.0)

    @classmethod
    def cone(cls, slope: float) -> "PowerLaw":
        """The cone ``f = r tan θ``, ``slope = tan θ`` (θ the angle between its flank and the surface, > 0)."""
        return cls(check_real("slope", slope, "a finite number > 0 (tan of the flank's angle to the surface)",
                              lambda value: value > 0.0), 1.0)

    def describe(self) -> str:
        """The profile in words, for a dataset's ``profile`` attribute."""
        return f"power law f = c r^n, c = {self.c!r} m^(1-n), n = {self.n!r}"


@dataclass(frozen=True)
class FlatPunch:
    """The flat-ended cylindrical punch of radius ``radius``: ``g(x) = 0`` for ``|x| <= radius``.

    In contact the radius is the punch's; adhesion holds it until the edge spring reaches Heß's
    limit (8), and then every spring (all of one length) lets go at once: Kendall's pull-off.
    """

    radius: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", check_real("FlatPunch.radius", self.radius, "a finite number > 0 (m)",
                                                      lambda value: value > 0.0))

    def describe(self) -> str:
        """The profile in words, for a dataset's ``profile`` attribute."""
        return f"flat punch of radius {self.radius!r} m"


#: Any profile the theory layer takes.
Profile = PowerLaw | FlatPunch


def profile_attrs(profile: Profile | None) -> dict[str, object]:
    """A result's attributes naming another indenter than the paraboloid: ``profile`` (in words), ``profile_c`` and
    ``profile_n`` (a power law) or ``profile_radius`` (a flat punch), and ``profile_note`` (``param_R`` is then
    unused); none for the paraboloid (``None``)."""
    if profile is None:
        return {}
    if isinstance(profile, PowerLaw):
        kind, shape = "power law", {"profile_c": float(profile.c), "profile_n": float(profile.n)}
    else:
        kind, shape = "flat punch", {"profile_radius": float(profile.radius)}
    return {"profile": profile.describe(), **shape,
            "profile_note": f"the indenter is this {kind}: param_R (the paraboloid's radius) is not used"}
