"""Adhesion as data: the works of adhesion of Heß's rule (8).

The paper's law is rate independent with a hysteresis: springs attach on the way in as Heß's rule with the work
of adhesion ``Δγ0`` says, and let go on the way out as it says with ``Δγ1`` (>= or < ``Δγ0``); ``Δγ0 = Δγ1 = 0``
is the non-adhesive (Hertz) contact. A law that depends on the edge's speed goes beside :class:`Adhesion` here,
with the same methods; each method registers the law's kernel by its type (the continuum's edge rule in
:mod:`mdr_events.models.continuum.edges`, the springs' thresholds in :mod:`mdr_events.models.discrete`).

The flat record :class:`~mdr_events.Parameters` holds a law's works at rest (``dgamma0``, ``dgamma1``): what sizes
a run (the springs it needs, the depth a scenario comes out to) is computed from them, and a kernel given a law
checks that it is the one of its parameters (:func:`law_of`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, ClassVar, Mapping

from mdr_events.validation import check_real, reads_attrs, shown

__all__ = ["Adhesion", "RateDependentAdhesion", "NO_ADHESION", "AdhesionLaw", "law_of", "kernel_of",
           "adhesion_from_attrs", "adhesion_attrs"]


@dataclass(frozen=True)
class Adhesion:
    """The paper's rate-independent adhesion: Heß's rule (8) with ``Δγ0`` in and ``Δγ1`` out (J/m², finite, >= 0).

    Parameters
    ----------
    dgamma0 : float, default 0.0
        Work of adhesion ``Δγ0`` (J/m²) of springs attaching while the indenter goes in.
    dgamma1 : float, default 0.0
        Work of adhesion ``Δγ1`` (J/m²) of the detachment criterion while it comes out.

    Raises
    ------
    ValueError
        A work of adhesion that is negative, infinite or NaN.
    """

    dgamma0: float = 0.0
    dgamma1: float = 0.0

    def __post_init__(self) -> None:
        for name in ("dgamma0", "dgamma1"):
            object.__setattr__(self, name, check_real(f"Adhesion.{name}", getattr(self, name),
                                                      "a finite number >= 0 (J m-2)", lambda value: value >= 0.0))

    @property
    def works_at_rest(self) -> tuple[float, float]:
        """``(Δγ0, Δγ1)``: the works of adhesion of an edge at rest, which :class:`~mdr_events.Parameters` holds."""
        return (self.dgamma0, self.dgamma1)

    @property
    def is_adhesive(self) -> bool:
        """Whether either work of adhesion is positive (else the contact is Hertz's)."""
        return self.dgamma0 > 0.0 or self.dgamma1 > 0.0

    @property
    def is_rate_dependent(self) -> bool:
        """Never: the works do not depend on the edge's speed (the closed forms and ``solve_path`` model it)."""
        return False

    def to_attrs(self) -> dict[str, Any]:
        """A result's attributes: ``param_dgamma0``, ``param_dgamma1`` and their units.

        Returns
        -------
        dict of str to object
            ``param_dgamma0``, ``param_dgamma1`` (J/m²) and ``param_dgamma0_units``, ``param_dgamma1_units``.
        """
        return {"param_dgamma0": self.dgamma0, "param_dgamma0_units": "J m-2",
                "param_dgamma1": self.dgamma1, "param_dgamma1_units": "J m-2"}

    @classmethod
    @reads_attrs("an adhesion law")
    def from_attrs(cls, attrs: Mapping[str, Any]) -> "Adhesion":
        """The adhesion a result was computed with (:meth:`to_attrs`).

        Parameters
        ----------
        attrs : mapping of str to object
            A result's attributes holding ``param_dgamma0`` and ``param_dgamma1``.

        Returns
        -------
        Adhesion
            The law of those two works of adhesion.
        """
        return cls(_number_attr(attrs, "param_dgamma0"), _number_attr(attrs, "param_dgamma1"))


def _number_attr(attrs: Mapping[str, Any], key: str) -> float:
    """``attrs[key]`` as a float; else the error naming the key, its value and what is allowed."""
    if key not in attrs:
        raise KeyError(key)
    try:
        return float(attrs[key])
    except (TypeError, ValueError, OverflowError):
        raise ValueError(f"attrs[{key!r}]={shown(attrs[key])} is not allowed; allowed: a number") from None


@dataclass(frozen=True)
class RateDependentAdhesion:
    """Heß's rule (8) with a work of adhesion that depends on the speed ``ȧ`` of the contact's edge.

    A receding edge (the crack opening, ``ȧ < 0``) needs ``Δγ(ȧ) = Δγ1 [1 + (|ȧ|/v_ref)^n]``, an advancing one (the
    crack closing, ``ȧ > 0``) gives ``Δγ(ȧ) = Δγ0 / [1 + (ȧ/v_ref)^n]``; at rest the edge holds while the energy
    release rate lies between ``Δγ0`` and ``Δγ1``. The receding law is Maugis & Barquins' (J. Phys. D 11, 1989,
    1978: ``G − w = w φ(a_T v)``, ``φ ∝ vⁿ``, n ≈ 0.6 for polyurethane on glass); the advancing one is its counterpart
    for a closing crack (Greenwood & Johnson, Phil. Mag. A 43, 697, 1981; Persson & Brener, Phys. Rev. E 71, 036123,
    2005: the energy a closing crack releases falls below the thermodynamic work). Assumptions: the dissipation is
    confined to the edge (small-scale viscoelasticity, the bulk elastic with the relaxed moduli ``E*``, ``G*``); one
    ``v_ref`` and one ``n`` for both directions; the speed is that of the MDR radius ``a``. For ``v_ref → ∞`` it is the
    paper's :class:`Adhesion` (derived in :func:`~mdr_events.theory.symbolic.derive_rate_dependent_adhesion`).

    Parameters
    ----------
    dgamma0 : float
        Work of adhesion of an advancing edge at rest (J/m², finite, > 0).
    dgamma1 : float
        Work of adhesion of a receding edge at rest (J/m², finite, >= ``dgamma0``: the band where the edge rests).
    v_ref : float
        The reference speed of the edge (m/s, finite, > 0).
    n : float
        The exponent of the speed, ``0 < n <= 1``.

    Raises
    ------
    ValueError
        A value outside its range, naming the field and what is allowed.
    """

    dgamma0: float
    dgamma1: float
    v_ref: float
    n: float

    #: where a method without a kernel for this law points its user
    runs_in: ClassVar[str] = ("the discrete method runs it, springs and shifts, and simulate's continuum method under "
                                "every friction law along any path (mdr_events.continuum.solve_rate_shifts under "
                                "tau0, Coulomb's part spring by spring); "
                                "its normal problem also runs in mdr_events.continuum.solve_edge, scenario A's phase "
                                "diagram and critical angle at a speed in mdr_events.phase_diagram_at_speeds and "
                                "critical_angles_at_speeds, scenario B's in critical_angles_B_at_speeds; validate "
                                "referees a run of it against simulate's continuum run")

    def __post_init__(self) -> None:
        checks = {"dgamma0": ("a finite number > 0 (J m-2)", lambda value: value > 0.0),
                  "v_ref": ("a finite number > 0 (m/s, the edge's reference speed)", lambda value: value > 0.0),
                  "n": ("a number with 0 < n <= 1 (the exponent of the speed)", lambda value: 0.0 < value <= 1.0)}
        for name, (allowed, rule) in checks.items():
            object.__setattr__(self, name, check_real(f"RateDependentAdhesion.{name}", getattr(self, name), allowed,
                                                      rule))
        object.__setattr__(self, "dgamma1", check_real(
            "RateDependentAdhesion.dgamma1", self.dgamma1,
            f"a finite number >= dgamma0 = {self.dgamma0!r} J m-2 (an edge at rest holds between the two works; with "
            "dgamma1 < dgamma0 a rate law would advance and recede at once)", lambda value: value >= self.dgamma0))

    @property
    def works_at_rest(self) -> tuple[float, float]:
        """``(Δγ0, Δγ1)``: the works of adhesion of an edge at rest, which :class:`~mdr_events.Parameters` holds."""
        return (self.dgamma0, self.dgamma1)

    @property
    def is_adhesive(self) -> bool:
        """Always: both works at rest are positive."""
        return True

    @property
    def is_rate_dependent(self) -> bool:
        """Always: the works depend on the edge's speed (what models the paper's law alone refuses it by this)."""
        return True

    def to_attrs(self) -> dict[str, Any]:
        """A result's attributes: the works at rest as :class:`Adhesion`'s, and the law's.

        Returns
        -------
        dict of str to object
            ``param_dgamma0``, ``param_dgamma1`` (J/m²) with their units, ``adhesion_law`` (``"rate_dependent"``),
            ``adhesion_v_ref`` (m/s) with its units and ``adhesion_n``.
        """
        return {**Adhesion(self.dgamma0, self.dgamma1).to_attrs(), "adhesion_law": "rate_dependent",
                "adhesion_v_ref": self.v_ref, "adhesion_v_ref_units": "m s-1", "adhesion_n": self.n}

    @classmethod
    @reads_attrs("a rate-dependent adhesion law")
    def from_attrs(cls, attrs: Mapping[str, Any]) -> "RateDependentAdhesion":
        """The law a result was computed with (:meth:`to_attrs`).

        Parameters
        ----------
        attrs : Mapping
            A result's attributes.

        Returns
        -------
        RateDependentAdhesion
            The law.
        """
        return cls(*(_number_attr(attrs, key) for key in ("param_dgamma0", "param_dgamma1", "adhesion_v_ref",
                                                           "adhesion_n")))


def check_rate_law(law: Any, name: str = "law") -> "RateDependentAdhesion":
    """``law`` if it is a :class:`RateDependentAdhesion`; else the ``TypeError`` naming ``name``, its value and what is
    allowed.

    Parameters
    ----------
    law : object
        The value given.
    name : str, optional
        The argument's name in the message.

    Returns
    -------
    RateDependentAdhesion
        ``law``.

    Raises
    ------
    TypeError
        Anything else (the paper's :class:`Adhesion` too: it has no speed).
    """
    if not isinstance(law, RateDependentAdhesion):
        raise TypeError(f"{name}={shown(law)} ({type(law).__name__}) is not allowed; allowed: a "
                        "RateDependentAdhesion(dgamma0, dgamma1, v_ref, n)")
    return law


#: No adhesion: Hertz's contact.
NO_ADHESION = Adhesion()

#: An adhesion law: the paper's, or one whose works depend on the edge's speed.
AdhesionLaw = Adhesion | RateDependentAdhesion


def adhesion_attrs(adhesion: AdhesionLaw) -> dict[str, Any]:
    """The attributes a result of ``adhesion`` carries beyond the works at rest of its
    :class:`~mdr_events.Parameters` (none for the paper's law; ``adhesion_law``, ``adhesion_v_ref``, ``adhesion_n``
    for the rate-dependent one).

    Parameters
    ----------
    adhesion : Adhesion or RateDependentAdhesion
        The law.

    Returns
    -------
    dict of str to object
        The attributes.
    """
    return {key: value for key, value in adhesion.to_attrs().items() if not key.startswith("param_")}


def adhesion_from_attrs(attrs: Mapping[str, Any]) -> AdhesionLaw:
    """The adhesion law a result was computed with: :class:`RateDependentAdhesion` where ``adhesion_law`` says
    ``"rate_dependent"``, else the paper's :class:`Adhesion`.

    Parameters
    ----------
    attrs : Mapping
        A result's attributes (``to_attrs`` of the law).

    Returns
    -------
    Adhesion or RateDependentAdhesion
        The law.
    """
    if attrs.get("adhesion_law") == "rate_dependent":
        return RateDependentAdhesion.from_attrs(attrs)
    return Adhesion.from_attrs(attrs)


def law_of(params: Any, adhesion: AdhesionLaw | None = None) -> AdhesionLaw:
    """The adhesion law a kernel runs: ``adhesion``, whose works at rest must be those of ``params`` (the flat record
    the kernel sizes the run with), or without it the paper's law of ``params.dgamma0`` and ``params.dgamma1``.

    Raises
    ------
    TypeError
        ``adhesion`` that is not an adhesion law.
    ValueError
        A law whose works at rest differ from the parameters' (naming both).
    """
    if adhesion is None:
        return Adhesion(params.dgamma0, params.dgamma1)
    if not isinstance(adhesion, AdhesionLaw):
        raise TypeError(f"adhesion={shown(adhesion)} ({type(adhesion).__name__}) is not allowed; allowed: None (the "
                        "law of the parameters' dgamma0 and dgamma1), an Adhesion or a RateDependentAdhesion")
    if adhesion.works_at_rest != (params.dgamma0, params.dgamma1):
        raise ValueError(f"adhesion={adhesion!r} is not allowed with dgamma0={params.dgamma0!r}, "
                         f"dgamma1={params.dgamma1!r} J/m²; allowed: a law whose works at rest are the parameters' "
                         "(Contact.parameters gives them)")
    return adhesion


def kernel_of(adhesion: Any, kernels: Mapping[type, Callable[..., Any]], method: str) -> Callable[..., Any]:
    """The kernel of ``adhesion`` among a method's ``kernels`` (by the law's type); else the ``TypeError`` naming the
    method and the laws it has kernels for."""
    kernel = kernels.get(type(adhesion))
    if kernel is None:
        elsewhere = getattr(type(adhesion), "runs_in", None)
        raise TypeError(f"adhesion={shown(adhesion)} ({type(adhesion).__name__}) is not allowed in the {method} "
                        f"method; allowed: {', '.join(kind.__name__ for kind in kernels)}"
                        + (f" ({type(adhesion).__name__}: {elsewhere})" if elsewhere else ""))
    return kernel
