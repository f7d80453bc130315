"""Friction laws as data: the cap on each spring's tangential shift, chosen by name.

The MDR springs of width ``Δx`` have the normal stiffness ``E* Δx`` (5) and the tangential stiffness
``G* Δx`` (6). A spring slides once its shift ``u`` reaches its cap ``ū``:

- ``"tau0"`` (the paper's, the default): ``ū(a) = π a τ0 / (2G*)`` (13), the same for every spring
  in contact, set by the critical mean shear stress ``τ0``;
- ``"coulomb"``: the local Coulomb rule of the MDR (Popov & Heß 2015, ch. 5): a spring holds a tangential
  force up to ``μ`` times its normal force, ``G* Δx |u| <= μ E* Δx w`` with ``w = d − g(ξ)`` its
  compression, so ``ū(ξ) = μ (E*/G*) max(w, 0)``: largest at the centre, zero at the edge of a contact
  without adhesion and in every spring in tension (adhesion);
- ``"tau0+coulomb"``: the sum of both caps, ``ū = π a τ0/(2G*) + μ (E*/G*) max(w, 0)``. The assumption:
  the shear strength of the interface is an adhesive part ``τ0`` that needs no pressure plus a Coulomb
  part proportional to the pressure (Derjaguin's two-term law, applied spring by spring).

Under a constant normal load the ``"coulomb"`` law gives the Cattaneo–Mindlin solution exactly
(:mod:`mdr_events.theory.mindlin`).
"""

from __future__ import annotations

from dataclasses import dataclass

from mdr_events.validation import check_choice, check_real, reads_attrs, shown

__all__ = ["FrictionLaw", "FRICTION_LAWS", "TAU0", "friction_attrs", "as_friction_law"]

#: The friction laws by name: whether each uses ``τ0`` and whether it uses ``μ``.
FRICTION_LAWS: dict[str, tuple[bool, bool]] = {
    "tau0": (True, False),
    "coulomb": (False, True),
    "tau0+coulomb": (True, True),
}


@dataclass(frozen=True, repr=False)
class FrictionLaw:
    r"""A friction law by name (:data:`FRICTION_LAWS`) and its coefficient of friction.

    Parameters
    ----------
    law : {"tau0", "coulomb", "tau0+coulomb"}, default "tau0"
        ``"tau0"`` (the paper's cap (13)), ``"coulomb"`` or ``"tau0+coulomb"`` (module docstring).
    mu : float or None, optional
        The coefficient of friction ``μ`` (finite, >= 0): required by the laws with Coulomb's part, not
        allowed with ``"tau0"`` (it would be silently unused).
    tau0 : float or None, optional
        The critical mean shear stress ``τ0`` in Pa (finite, >= 0) of the laws with its part, not allowed with
        ``"coulomb"``. A :class:`~mdr_events.Contact` needs it; ``None``: ``Parameters.tau0`` (the keyword
        form ``friction=`` beside :class:`~mdr_events.Parameters`).

    Raises
    ------
    ValueError
        An unknown ``law``; ``mu`` missing for a law with Coulomb's part or given to ``"tau0"``; ``tau0`` given to
        ``"coulomb"``; a negative, infinite or NaN coefficient.

    Notes
    -----
    The caps on a spring's shift, with :math:`w = d - g(\xi)` its compression:

    .. math::

        \bar u_{\tau_0} = \frac{\pi a \tau_0}{2 G^*} \quad (13), \qquad
        \bar u_{\mathrm{coulomb}} = \mu \frac{E^*}{G^*} \max(w, 0), \qquad
        \bar u_{\tau_0 + \mathrm{coulomb}} = \bar u_{\tau_0} + \bar u_{\mathrm{coulomb}}.
    """

    law: str = "tau0"
    mu: float | None = None
    tau0: float | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "law", check_choice("FrictionLaw.law", self.law, FRICTION_LAWS))
        if self.tau0 is not None:
            if not self.uses_tau0:
                raise ValueError(f"tau0={shown(self.tau0)} is not allowed with the friction law {self.law!r} (it has no "
                                 "τ0 part); allowed: None, or the law 'tau0' or 'tau0+coulomb'")
            object.__setattr__(self, "tau0", check_real("tau0", self.tau0, "a finite number >= 0 (Pa, the critical "
                                                        "mean shear stress)", lambda value: value >= 0.0))
        if self.uses_mu:
            if self.mu is None:
                raise ValueError(f"mu=None is not allowed with the friction law {self.law!r}; "
                                 "allowed: a finite number >= 0 (the coefficient of friction)")
            object.__setattr__(self, "mu", check_real("mu", self.mu, "a finite number >= 0 (the coefficient "
                                                      "of friction)", lambda value: value >= 0.0))
        elif self.mu is not None:
            raise ValueError(f"mu={shown(self.mu)} is not allowed with the friction law {self.law!r} (it has no "
                             f"Coulomb part); allowed: None, or the law 'coulomb' or 'tau0+coulomb'")

    def __repr__(self) -> str:
        values = "".join(f", {name}={getattr(self, name)!r}" for name in ("mu", "tau0") if getattr(self, name) is not None)
        return f"FrictionLaw({self.law!r}{values})"

    @property
    def uses_tau0(self) -> bool:
        """Whether the cap has the part ``π a τ0 / (2G*)`` of (13)."""
        return FRICTION_LAWS[self.law][0]

    @property
    def uses_mu(self) -> bool:
        """Whether the cap has the Coulomb part ``μ (E*/G*) max(w, 0)``."""
        return FRICTION_LAWS[self.law][1]

    @property
    def is_default(self) -> bool:
        """The paper's law ``"tau0"``."""
        return self.law == "tau0"

    @property
    def coulomb_mu(self) -> float:
        """``μ`` of the Coulomb part (0 for ``"tau0"``)."""
        return float(self.mu) if self.uses_mu else 0.0

    @property
    def is_complete(self) -> bool:
        """Whether every part the law uses has its value (``τ0`` given where the law uses it)."""
        return not self.uses_tau0 or self.tau0 is not None

    def to_attrs(self) -> dict[str, object]:
        """A result's attributes: ``param_tau0`` and its unit where the law uses ``τ0``; for another law than the
        paper's also ``friction_law``, ``friction_mu`` and ``friction_cap`` (the cap in words).

        Returns
        -------
        dict of str to object
            Empty for the paper's law without its ``τ0`` given.
        """
        attrs: dict[str, object] = {} if self.tau0 is None else {"param_tau0": self.tau0, "param_tau0_units": "Pa"}
        if not self.is_default:
            attrs.update(friction_law=self.law, friction_mu=float(self.mu), friction_cap=self.describe())
        return attrs

    @classmethod
    @reads_attrs("a friction law")
    def from_attrs(cls, attrs) -> "FrictionLaw":
        """The law a result was computed with (:meth:`to_attrs`; ``friction_law`` absent: the paper's).

        Parameters
        ----------
        attrs : mapping of str to object
            A result's attributes: ``friction_law``, ``friction_mu``, ``param_tau0`` where the law uses them.

        Returns
        -------
        FrictionLaw
            The law, with its ``μ`` and ``τ0``.

        Raises
        ------
        ValueError
            A ``friction_mu`` beside a law without Coulomb's part, or an unknown law.
        """
        law = str(attrs.get("friction_law", "tau0"))
        if "friction_mu" in attrs and not FRICTION_LAWS.get(law, (0, 0))[1]:  # (its μ was dropped silently)
            raise ValueError(f"the attribute friction_mu={shown(attrs['friction_mu'])} beside the law {law!r} is not "
                             "allowed; allowed: friction_mu with friction_law 'coulomb' or 'tau0+coulomb'")
        mu = float(attrs["friction_mu"]) if FRICTION_LAWS.get(law, (0, 0))[1] else None
        tau0 = float(attrs["param_tau0"]) if FRICTION_LAWS.get(law, (0, 0))[0] else None
        return cls(law, mu=mu, tau0=tau0)

    def describe(self) -> str:
        """The law in words, for a dataset's ``friction_law`` attribute.

        Returns
        -------
        str
            The cap as a formula in ASCII, e.g. ``"u_cap = pi a tau0 / (2 G*) (13)"``, with ``μ``'s value.
        """
        caps = {"tau0": "u_cap = pi a tau0 / (2 G*) (13)",
                "coulomb": f"u_cap = mu (E*/G*) max(d - g, 0), mu = {self.mu!r}",
                "tau0+coulomb": f"u_cap = pi a tau0 / (2 G*) + mu (E*/G*) max(d - g, 0), mu = {self.mu!r}"}
        return caps[self.law]


#: The paper's law, the default everywhere.
TAU0 = FrictionLaw()


def as_friction_law(friction: "FrictionLaw | str | None", name: str = "friction") -> FrictionLaw:
    """``friction`` as a :class:`FrictionLaw`: ``None`` is the paper's, a name without ``μ`` only ``"tau0"``."""
    if friction is None:
        return TAU0
    if isinstance(friction, FrictionLaw):
        return friction
    if isinstance(friction, str):
        return FrictionLaw(friction)
    raise TypeError(f"{name}={shown(friction)} ({type(friction).__name__}) is not allowed; allowed: a FrictionLaw "
                    f"(e.g. FrictionLaw('coulomb', mu=0.3)) or one of {', '.join(map(repr, FRICTION_LAWS))}")


def friction_attrs(friction: FrictionLaw) -> dict[str, object]:
    """A result's attributes naming another friction law than the paper's: ``friction_law``, ``friction_mu``,
    ``friction_cap`` (the cap in words) and, for ``"coulomb"``, ``friction_note`` (``param_tau0`` is then unused);
    none for ``"tau0"`` (a result of the paper's law is as before)."""
    if friction.is_default:
        return {}
    attrs: dict[str, object] = {"friction_law": friction.law, "friction_mu": float(friction.mu),
                                "friction_cap": friction.describe()}
    if not friction.uses_tau0:
        attrs["friction_note"] = "the friction law is Coulomb's: param_tau0 is not used"
    return attrs
