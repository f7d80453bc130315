"""The physical model as one value: the elastomer, the indenter, the adhesion and the friction law.

A :class:`Contact` is immutable and validated once, when it is made; every layer takes it whole. It says what it
is in a short ``repr`` and in the attributes it stamps on results (:meth:`Contact.to_attrs`, read back by
:meth:`Contact.from_attrs`, which also reads the files written with :class:`~mdr_events.Parameters`). A value inside
is changed by its dotted name (``contact.replace(**{"friction.mu": 0.4})``) or by its short name
(``contact.replace(mu=0.4)``), as fits and sweeps do (:data:`SHORT_NAMES`).

What the indenter moves along (depth, angle, speed) is not part of the contact: it is the motion's.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any, Mapping

from mdr_events.contact.adhesion import NO_ADHESION, Adhesion, RateDependentAdhesion, adhesion_from_attrs
from mdr_events.contact.elastomer import Elastomer
from mdr_events.contact.friction import FrictionLaw, as_friction_law
from mdr_events.contact.indenters import FlatPunch, Indenter, Paraboloid, PowerLaw, TabulatedProfile, \
    indenter_from_attrs
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.parameters import Parameters, check_parameters
from mdr_events.validation import PLAIN_NUMBER, number_of, shown

__all__ = ["Contact", "SHORT_NAMES", "PARTS", "UNITS", "check_half_space"]

#: The parts of a contact and the types each may be.
PARTS: dict[str, tuple[type, ...]] = {
    "elastomer": (Elastomer,),
    "indenter": (Paraboloid, PowerLaw, FlatPunch, TabulatedProfile),
    "adhesion": (Adhesion, RateDependentAdhesion),
    "friction": (FrictionLaw,),
    "layer": (Layer,),
}
#: Short names of the values inside a contact (those of :class:`~mdr_events.Parameters` and ``mu``) → dotted names.
SHORT_NAMES: dict[str, str] = {
    "E": "elastomer.E", "nu": "elastomer.nu", "R": "indenter.R", "c": "indenter.c", "n": "indenter.n",
    "radius": "indenter.radius", "dgamma0": "adhesion.dgamma0", "dgamma1": "adhesion.dgamma1",
    "tau0": "friction.tau0", "mu": "friction.mu", "h": "layer.thickness", "v_ref": "adhesion.v_ref",
}
#: The unit of each value inside a contact, by dotted name (``c`` of ``f = c rⁿ`` is in m^(1-n)).
UNITS: dict[str, str] = {
    "elastomer.E": "Pa", "elastomer.nu": "1", "indenter.R": "m", "indenter.c": "m^(1-n)", "indenter.n": "1",
    "indenter.radius": "m", "adhesion.dgamma0": "J m-2", "adhesion.dgamma1": "J m-2",
    "adhesion.v_ref": "m s-1", "adhesion.n": "1", "friction.tau0": "Pa",
    "friction.mu": "1", "layer.thickness": "m",
}
#: Values inside a contact that are a choice, not a number (no unit; :meth:`Contact.value` and
#: :meth:`Contact.replace` take them, :meth:`Contact.names` lists the numbers).
CHOICES = ("layer.base",)


#: The attributes of a contact that hold numbers.
NUMERIC_ATTRIBUTES = ("param_E", "param_nu", "param_R", "param_dgamma0", "param_dgamma1", "param_tau0", "friction_mu",
                      "profile_c", "profile_n", "profile_radius", "param_layer_thickness")


@dataclass(frozen=True, repr=False)
class Contact:
    """A rigid indenter on an elastomer, with adhesion and friction: the physical model of section 4.

    Parameters
    ----------
    elastomer : Elastomer
        ``E`` and ``ν``: the springs' stiffness per width ``E*`` (5) and ``G*`` (6).
    indenter : Paraboloid, PowerLaw, FlatPunch or TabulatedProfile
        The indenter's profile ``f(r)``; the springs see its Abel transform ``g(x)`` (3).
    adhesion : Adhesion, default NO_ADHESION
        Heß's rule (8) with ``Δγ0`` in and ``Δγ1`` out; default none (Hertz).
    friction : FrictionLaw, default FrictionLaw("tau0", tau0=0.0)
        The cap on the springs' shifts (:mod:`mdr_events.contact.friction`) with every value it uses: ``τ0`` for the
        paper's law (13), ``μ`` for Coulomb's, both for their sum.
    layer : Layer, default HALF_SPACE
        The elastomer's thickness ``h`` and base (:class:`~mdr_events.contact.layer.Layer`): the paper's half-space
        (``h = inf``) by default. A finite layer is taken by the normal problem of :mod:`mdr_events.theory.layer`
        (:func:`~mdr_events.layer_normal_curve`) and by the discrete method of :func:`~mdr_events.simulate` (the
        springs of the generalized MDR); the continuum and the closed forms of the half-space refuse it
        (:func:`check_half_space`).

    Raises
    ------
    TypeError
        A part of another type, naming it and what is allowed.
    ValueError
        A friction law without a value it uses (``FrictionLaw("tau0")`` without ``tau0``).
    """

    elastomer: Elastomer
    indenter: Indenter
    adhesion: Adhesion = NO_ADHESION
    friction: FrictionLaw = FrictionLaw("tau0", tau0=0.0)
    layer: Layer = HALF_SPACE

    def __post_init__(self) -> None:
        for name, kinds in PARTS.items():
            part = getattr(self, name)
            if not isinstance(part, kinds):
                raise TypeError(f"Contact.{name}={shown(part)} ({type(part).__name__}) is not allowed; allowed: "
                                f"{' or '.join(kind.__name__ for kind in kinds)}")
        if not self.friction.is_complete:
            raise ValueError(f"Contact.friction={self.friction!r} is not allowed: the law {self.friction.law!r} uses "
                             "tau0; allowed: a law with its values, e.g. FrictionLaw('tau0', tau0=42e3)")
        self.layer.check_poisson_ratio(self.elastomer.nu)

    def __repr__(self) -> str:
        layer = "" if self.layer.is_half_space else f", {self.layer!r}"  # (the half-space: the paper's, unnamed)
        return f"Contact({self.elastomer!r}, {self.indenter!r}, {self.adhesion!r}, {self.friction!r}{layer})"

    # --- construction ---------------------------------------------------------------------------------------------
    @classmethod
    def paper(cls, R: float = 0.03) -> "Contact":
        """The contact of section 4 (:meth:`Parameters.paper <mdr_events.Parameters.paper>`: ``E``, ``ν``
        inferred; ``R`` 30 mm or 100 mm, ``τ0``, ``Δγ0``, ``Δγ1`` quoted).

        Parameters
        ----------
        R : float, default 0.03
            The paraboloid's radius (m): 0.03 in the paper's section 4, 0.1 in its supplementary material.

        Returns
        -------
        Contact
            The paraboloid on the paper's elastomer, with its adhesion and the friction law ``"tau0"``.
        """
        return cls.from_parameters(Parameters.paper(R))

    @classmethod
    def from_parameters(cls, params: Parameters, profile: Indenter | None = None,
                        friction: FrictionLaw | str | None = None) -> "Contact":
        """The contact of ``params`` (its ``d_max`` and ``v`` are the motion's), with ``profile`` instead of its
        paraboloid and ``friction`` instead of the paper's law (``τ0`` from ``params`` where the law uses it).

        Parameters
        ----------
        params : Parameters
            The flat record: ``E``, ``ν``, ``R``, ``τ0``, ``Δγ0``, ``Δγ1`` (its ``d_max`` and ``v`` are not used).
        profile : PowerLaw, FlatPunch, TabulatedProfile or Paraboloid, optional
            The indenter; ``None``: the paraboloid of ``params.R``.
        friction : FrictionLaw or str, optional
            The friction law or its name; ``None``: the paper's ``"tau0"``. A law that uses ``τ0`` without its
            value takes ``params.tau0``.

        Returns
        -------
        Contact
            The contact of those parts.

        Raises
        ------
        TypeError
            A ``profile`` or ``friction`` of another type.
        """
        check_parameters(params)
        if profile is not None and not isinstance(profile, PARTS["indenter"]):
            raise TypeError(f"profile={shown(profile)} ({type(profile).__name__}) is not allowed; allowed: None (the "
                            "paraboloid of params.R), a PowerLaw, a FlatPunch or a TabulatedProfile")
        law = as_friction_law(friction)
        if law.uses_tau0 and law.tau0 is None:
            law = dataclasses.replace(law, tau0=params.tau0)
        return cls(Elastomer(params.E, params.nu), Paraboloid(params.R) if profile is None else profile,
                   Adhesion(params.dgamma0, params.dgamma1), law)

    @classmethod
    def from_attrs(cls, attrs: Mapping[str, Any]) -> "Contact":
        """The contact a result was computed for (:meth:`to_attrs`, or the attributes of
        :meth:`Parameters.to_attrs <mdr_events.Parameters.to_attrs>` with ``profile_*`` and ``friction_*``).

        Parameters
        ----------
        attrs : mapping of str to object
            A result's attributes (``dataset.attrs``, not the dataset itself).

        Returns
        -------
        Contact
            The contact they describe.

        Raises
        ------
        TypeError
            ``attrs`` that is not a mapping, or a dataset.
        ValueError
            A missing attribute, a number that is not one, or attributes that describe no valid contact.
        """
        if not isinstance(attrs, Mapping) or hasattr(attrs, "data_vars"):  # (a Dataset is a mapping of variables)
            raise TypeError(f"attrs of type {type(attrs).__name__} are not allowed; allowed: a mapping of a result's "
                            "attributes (dataset.attrs)")
        for key in NUMERIC_ATTRIBUTES:
            if key in attrs:
                try:
                    number_of(attrs[key])
                except (TypeError, ValueError, OverflowError):
                    raise ValueError(f"the attribute {key}={shown(attrs[key])} is not allowed; allowed: a number "
                                     f"(in text: {PLAIN_NUMBER})") from None
        try:
            return cls(Elastomer.from_attrs(attrs), indenter_from_attrs(attrs), adhesion_from_attrs(attrs),
                       FrictionLaw.from_attrs(attrs), Layer.from_attrs(attrs))
        except KeyError as error:
            raise ValueError(f"attrs lack the attribute {error.args[0]!r}; allowed: a result's attributes "
                             "(Contact.to_attrs)") from None
        except (TypeError, ValueError, OverflowError) as error:
            raise ValueError(f"attrs do not describe a contact: {error}") from None

    # --- the simulators' keywords -----------------------------------------------------------------------------
    @property
    def profile(self) -> PowerLaw | FlatPunch | TabulatedProfile | None:
        """The indenter as the keyword ``profile=`` of the layers below takes it: ``None`` for the paraboloid
        (theirs of ``Parameters.R``, the paper's functions bit for bit), else the indenter."""
        return None if isinstance(self.indenter, Paraboloid) else self.indenter

    def parameters(self, d_max: float, v: float) -> Parameters:
        """The flat record the layers below take, with the motion's ``d_max`` and ``v``: ``R`` of the paraboloid
        (``None`` for another indenter, which :attr:`profile` gives), ``τ0`` of the friction law (0 for
        Coulomb's, which has none).

        Parameters
        ----------
        d_max : float
            The motion's largest depth (m).
        v : float
            The motion's speed (m/s).

        Returns
        -------
        Parameters
            The record of this contact's values with ``d_max`` and ``v``.
        """
        R = self.indenter.R if isinstance(self.indenter, Paraboloid) else None
        return Parameters(E=self.elastomer.E, nu=self.elastomer.nu, R=R, tau0=self.friction.tau0 or 0.0,
                          dgamma0=self.adhesion.dgamma0, dgamma1=self.adhesion.dgamma1, d_max=d_max, v=v)

    # --- reading and changing values ------------------------------------------------------------------------------
    def value(self, name: str) -> float:
        """The value of a dotted (``"friction.mu"``) or short (``"mu"``) name of this contact (:meth:`names`).

        Parameters
        ----------
        name : str
            A dotted name of :meth:`names` or its short name (:data:`SHORT_NAMES`).

        Returns
        -------
        float or LayerBase
            The value, in the unit :meth:`unit` gives (``layer.base``: the :class:`~mdr_events.contact.layer.LayerBase`).

        Raises
        ------
        ValueError
            A name this contact does not hold (listing those it does).
        """
        part, field = self._path(name)
        if not self.holds(name) and SHORT_NAMES.get(name, name) not in CHOICES:  # (a law's unused mu or tau0)
            raise ValueError(f"{name!r} is not a value of this contact; allowed: {', '.join(self.names())}")
        return getattr(getattr(self, part), field)

    def replace(self, **changes: float) -> "Contact":
        """A copy with values changed by dotted or short name (validated again), e.g.
        ``contact.replace(**{"elastomer.E": 1e6}, mu=0.4)``.

        Parameters
        ----------
        **changes : float
            New values by dotted or short name, each value once.

        Returns
        -------
        Contact
            The copy, validated as a new contact is.

        Raises
        ------
        ValueError
            A name this contact does not hold, a value changed under two names, or a value out of its range.
        """
        parts: dict[str, dict[str, float]] = {}
        for name, value in changes.items():
            part, field = self._path(name)
            if field in parts.get(part, {}):  # (E= and **{"elastomer.E": ...}: one would silently win)
                raise ValueError(f"{name!r} changes {part}.{field}, which another name changes too; allowed: each "
                                 "value once")
            parts.setdefault(part, {})[field] = value
        return dataclasses.replace(self, **{part: dataclasses.replace(getattr(self, part), **fields)
                                            for part, fields in parts.items()})

    def holds(self, name: str) -> bool:
        """Whether ``name`` (dotted or short) is a value of this contact.

        Parameters
        ----------
        name : str
            A dotted or short name (any other object: ``False``).

        Returns
        -------
        bool
            ``True`` if :meth:`names` lists it.
        """
        return isinstance(name, str) and SHORT_NAMES.get(name, name) in self.names()

    def unit(self, name: str) -> str:
        """The unit of a dotted or short name of this contact (:data:`UNITS`).

        Parameters
        ----------
        name : str
            A dotted name of :meth:`names` or its short name.

        Returns
        -------
        str
            The unit, e.g. ``"Pa"``, ``"J m-2"``, ``"1"``.

        Raises
        ------
        ValueError
            A name this contact does not hold.
        """
        part, field = self._path(name)
        if not self.holds(name):  # (a law's mu or tau0 that it does not use)
            raise ValueError(f"{name!r} is not a value of this contact; allowed: {', '.join(self.names())}")
        return UNITS[f"{part}.{field}"]

    def _path(self, name: str) -> tuple[str, str]:
        """``(part, field)`` of a dotted or short name that this contact holds; else an error listing those it does."""
        if not isinstance(name, str):
            raise TypeError(f"name={shown(name)} ({type(name).__name__}) is not allowed; allowed: a dotted or short name "
                            f"({', '.join(self.names())})")
        dotted = SHORT_NAMES.get(name, name)
        part, _, field = dotted.partition(".")
        held = getattr(self, part, None) if part in PARTS else None
        if held is None or field not in {f.name for f in dataclasses.fields(held)} or field == "law":
            raise ValueError(f"{name!r} is not a value of this contact; allowed: {', '.join(self.names())} (or their "
                           "short names: " + ", ".join(short for short, full in SHORT_NAMES.items()
                                                       if full in self.names()) + ")")
        return part, field

    def names(self) -> list[str]:
        """The dotted names of the numbers this contact holds (``friction.mu`` only for a law with Coulomb's part;
        ``layer.base``, a choice, is read and changed by name but not listed: :data:`CHOICES`).

        Returns
        -------
        list of str
            E.g. ``["elastomer.E", "elastomer.nu", "indenter.R", ..., "friction.tau0"]``.
        """
        return [f"{part}.{field.name}" for part in PARTS for field in dataclasses.fields(getattr(self, part))
                if field.name != "law" and getattr(getattr(self, part), field.name) is not None
                and f"{part}.{field.name}" not in CHOICES]

    # --- results --------------------------------------------------------------------------------------------------
    def to_attrs(self) -> dict[str, Any]:
        """The attributes a result of this contact carries: each part's (``param_E``, ``param_nu``, ``param_E_star``,
        ``param_G_star``; ``param_R`` or ``profile_*``; ``param_dgamma0``, ``param_dgamma1``; ``param_tau0`` where
        the law uses it, ``friction_*`` for another law than the paper's; ``param_layer_thickness`` and
        ``param_layer_base`` for a layer of finite thickness: the half-space stamps none, so that its results are
        those written before layers existed, and :meth:`from_attrs` reads a result without them as the half-space).

        Returns
        -------
        dict of str to object
            The attributes, read back by :meth:`from_attrs`.
        """
        layer = {} if self.layer.is_half_space else self.layer.to_attrs()
        return {**self.elastomer.to_attrs(), **self.indenter.to_attrs(), **self.adhesion.to_attrs(),
                **self.friction.to_attrs(), **layer}


def check_half_space(contact: Contact, where: str) -> Contact:
    """``contact`` if its elastomer is the half-space (``Contact.layer``, ``h = inf``); else the one-line
    ``ValueError`` naming the layer, ``where`` (the entry point that does not take a layer yet) and what runs it.

    Parameters
    ----------
    contact : Contact
        The physical model.
    where : str
        The entry point asked, e.g. ``"simulate(method='continuum')"``.

    Returns
    -------
    Contact
        ``contact`` itself.

    Raises
    ------
    TypeError
        ``contact`` not a Contact (an ``AttributeError`` before).
    ValueError
        A layer of finite thickness.
    """
    if not isinstance(contact, Contact):
        raise TypeError(f"contact={shown(contact)} ({type(contact).__name__}) is not allowed in {where}; allowed: a "
                        "mdr_events.Contact")
    if contact.layer.is_half_space:
        return contact
    raise ValueError(f"Contact.layer={contact.layer!r} is not allowed in {where} yet; allowed: the half-space (h = "
                     "inf, Layer()) — a layer runs in simulate(...) and sweep(...) with either method (a continuum "
                     "sweep with the friction law 'tau0'), validate and fit, its slip onset in d_crit, critical_angle, "
                     "phase_diagram and a sweep of the closed-form quantities alone (quantities=('critical_angle_A', "
                     "'critical_angle_B')), and its normal problem in mdr_events.layer_normal_curve, "
                     "mdr_events.layer_pull_off_curve, jump_off, jump_in_radius and pull_off_force "
                     "(mdr_events.theory.layer)")
