"""Model parameters of section 4: one immutable object, validated once.

Every other layer of :mod:`mdr_events` takes a :class:`Parameters` instead of
loose numbers, so that a dataset or a figure can always say exactly which
material, indenter and adhesion it was computed for.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import numbers
from dataclasses import dataclass
from typing import Any, Mapping

from mdr_events.validation import PLAIN_NUMBER, as_float, check_choice, number_of, reads_attrs, shown

__all__ = ["Parameters", "PARAMETER_UNITS", "PARAMETER_LONG_NAMES", "PRESETS", "PAPER_D_MAX", "PAPER_V", "from_preset",
           "check_parameters"]

#: SI unit of every field, used for dataset attributes and the CLI help.
PARAMETER_UNITS: dict[str, str] = {
    "E": "Pa",
    "nu": "1",
    "R": "m",
    "tau0": "Pa",
    "dgamma0": "J m-2",
    "dgamma1": "J m-2",
    "d_max": "m",
    "v": "m s-1",
}

#: Human-readable name of every field.
PARAMETER_LONG_NAMES: dict[str, str] = {
    "E": "Young's modulus of the elastomer",
    "nu": "Poisson's ratio of the elastomer",
    "R": "radius of the (paraboloidal) indenter",
    "tau0": "critical mean shear stress in stationary sliding",
    "dgamma0": "work of adhesion of springs attaching on the way in",
    "dgamma1": "work of adhesion used for detachment on the way out",
    "d_max": "maximum indentation depth",
    "v": "speed of the indenter along its path",
}

#: Allowed ranges, in words, for the error messages.
_ALLOWED: dict[str, str] = {
    "E": "a finite number > 0",
    "nu": "a finite number in (-1, 0.5]",
    "R": "a finite number > 0",
    "tau0": "a finite number >= 0",
    "dgamma0": "a finite number >= 0",
    "dgamma1": "a finite number >= 0",
    "d_max": "a finite number > 0",
    "v": "a finite number > 0",
}


def shear_modulus(E: float, nu: float) -> float:
    """``G = E / (2 (1 + ν))`` (Pa)."""
    return E / (2.0 * (1.0 + nu))


def effective_normal_modulus(E: float, nu: float) -> float:
    """``E* = E / (1 - ν²)`` of a rigid indenter on an elastic half-space (Pa, eq. (5))."""
    return E / (1.0 - nu**2)


def effective_tangential_modulus(E: float, nu: float) -> float:
    """``G* = 4 G / (2 - ν)`` of a rigid indenter on an elastic half-space (Pa, eq. (6))."""
    return 4.0 * shear_modulus(E, nu) / (2.0 - nu)


def _is_allowed(name: str, value: float) -> bool:
    if name == "nu":
        return -1.0 < value <= 0.5
    if name in ("tau0", "dgamma0", "dgamma1"):
        return value >= 0.0
    return value > 0.0


#: Named parameter sets of the paper (CLI ``--preset``, study files): the radius of ``Parameters.paper``.
PRESETS = {"paper-R30": 0.03, "paper-R100": 0.1}
#: The paper's depth ``d_max`` (m, quoted) and speed ``v`` (m/s, inferred) of :meth:`Parameters.paper`: the defaults of
#: a motion (``Scenario``) and of the closed forms of a :class:`~mdr_events.Contact` (which holds neither).
PAPER_D_MAX, PAPER_V = 0.3e-3, 1e-6


@dataclass(frozen=True)
class Parameters:
    """Material, indenter, adhesion and kinematics of the model (SI units).

    Parameters
    ----------
    E : float
        Young's modulus of the elastomer in Pa.
    nu : float
        Poisson's ratio of the elastomer, in (-1, 0.5].
    R : float or None
        Radius of the indenter in m; the sphere is replaced by the paraboloid
        ``f(r) = r**2 / (2 R)``, eq. (4). ``None`` for another indenter (the simulators' ``profile=``; what
        :meth:`Contact.parameters <mdr_events.Contact.parameters>` gives for one).
    tau0 : float
        Critical mean shear stress of stationary sliding in Pa; fixes the
        critical spring shift ``ū(a) = π a τ0 / (2 G*)``, eq. (13).
    dgamma0 : float
        Work of adhesion ``Δγ0`` (J/m²) of springs attaching while the indenter
        goes in (Heß's rule, eq. (8)).
    dgamma1 : float
        Work of adhesion ``Δγ1`` (J/m²) of the detachment criterion while the
        indenter comes out.
    d_max : float
        Maximum indentation depth in m (turning point of both scenarios).
    v : float
        Speed of the indenter along its path in m/s, eqs. (14) and (19).

    Notes
    -----
    The effective moduli of a rigid indenter on an elastic half-space are
    ``E* = E / (1 - ν²)`` and ``G* = 4 G / (2 - ν)`` with
    ``G = E / (2 (1 + ν))`` (the definitions next to eqs. (5), (6)).

    Invalid values raise :class:`ValueError` naming the field, the value and
    the allowed range.
    """

    E: float
    nu: float
    R: float | None
    tau0: float
    dgamma0: float
    dgamma1: float
    d_max: float
    v: float

    def __post_init__(self) -> None:
        for field in dataclasses.fields(self):
            value = getattr(self, field.name)
            if field.name == "R" and value is None:  # (another indenter than the paraboloid: Contact.parameters)
                continue
            if isinstance(value, bool) or not isinstance(value, numbers.Real):
                raise TypeError(
                    f"Parameters.{field.name}={shown(value)} has type "
                    f"{type(value).__name__}; allowed: {_ALLOWED[field.name]}"
                )
            given, value = value, as_float(value)
            if not math.isfinite(value) or not _is_allowed(field.name, value):
                raise ValueError(
                    f"Parameters.{field.name}={shown(given)} is not allowed; "
                    f"allowed: {_ALLOWED[field.name]} ({PARAMETER_UNITS[field.name]})"
                )
            object.__setattr__(self, field.name, value)

    # ------------------------------------------------------------------
    # derived elastic constants
    @property
    def G(self) -> float:
        """Shear modulus ``G = E / (2 (1 + ν))`` in Pa."""
        return shear_modulus(self.E, self.nu)

    @property
    def E_star(self) -> float:
        """Effective normal modulus ``E* = E / (1 - ν²)`` in Pa (eq. (5))."""
        return effective_normal_modulus(self.E, self.nu)

    @property
    def G_star(self) -> float:
        """Effective tangential modulus ``G* = 4 G / (2 - ν)`` in Pa (eq. (6))."""
        return effective_tangential_modulus(self.E, self.nu)

    # ------------------------------------------------------------------
    # construction helpers
    @classmethod
    def paper(cls, R: float = 0.03) -> "Parameters":
        """The parameter set of section 4 (Lyashenko, Popov & Borysiuk 2023).

        Quoted in the section: ``R`` = 30 mm (100 mm in the supplementary
        material), ``d_max`` = 0.3 mm, ``τ0`` = 42 kPa, ``Δγ0`` = 0.01 J/m²,
        ``Δγ1`` = 0.15 J/m².

        **Inferred, not quoted** (the section's text does not state them; they
        were in a figure caption): ``ν = 0.5`` and ``E = 0.324 MPa``, which
        reproduce both stated critical angles α_c(Hertz) ≈ 23.59° and
        α_c(JKR) ≈ 22.87° to within 0.01°, and ``v = 1 µm/s``. The model is
        rate independent, so ``v`` only sets the time axis.

        Parameters
        ----------
        R : float
            Indenter radius in m: 0.03 or 0.1 (the two radii of the paper).
            For another radius use ``Parameters.paper().replace(R=...)``.
        """
        if isinstance(R, bool) or not isinstance(R, numbers.Real) or \
                not any(math.isclose(as_float(R), allowed, rel_tol=1e-12) for allowed in (0.03, 0.1)):
            raise ValueError(
                f"Parameters.paper(R={R!r}): the paper uses R = 0.03 m or 0.1 m; "
                "for another radius use Parameters.paper().replace(R=...)"
            )
        return cls(
            E=0.324e6,
            nu=0.5,
            R=R,
            tau0=42e3,
            dgamma0=0.01,
            dgamma1=0.15,
            d_max=PAPER_D_MAX,
            v=PAPER_V,
        )

    #: Fields of :meth:`paper` that are inferred rather than quoted.
    INFERRED_FIELDS = ("E", "nu", "v")

    def preset_name(self) -> str | None:
        """The name in :data:`PRESETS` of the paper's parameter set these are exactly, else ``None``.

        Figures and datasets use it to number themselves as the paper does (Fig. 8, 9a, ...) and to
        say that ``E``, ``ν`` and ``v`` of a preset are inferred, not quoted.

        Returns
        -------
        str or None
            A key of :data:`PRESETS` (``Parameters.paper(R)`` equal to these field by field), or ``None``.
        """
        for name, preset in _presets(tuple(PRESETS.items())):
            if self == preset:
                return name
        return None

    def replace(self, **changes: float) -> "Parameters":
        """A copy with some fields changed (validated again).

        Parameters
        ----------
        **changes : float
            New values of fields by name (``E``, ``nu``, ``R``, ``tau0``, ``dgamma0``, ``dgamma1``, ``d_max``,
            ``v``), in SI units.

        Returns
        -------
        Parameters
            The copy.

        Raises
        ------
        TypeError
            A name that is not a field.
        ValueError
            A value out of its field's range.
        """
        unknown = set(changes) - {f.name for f in dataclasses.fields(self)}
        if unknown:
            raise TypeError(
                f"Parameters.replace got unknown field(s) {sorted(unknown)}; "
                f"allowed: {[f.name for f in dataclasses.fields(self)]}"
            )
        return dataclasses.replace(self, **changes)

    def as_dict(self) -> dict[str, float]:
        """The eight fields as a plain ``dict`` (SI units).

        Returns
        -------
        dict of str to float
            Field name to value, in the fields' order (``R`` is ``None`` beside another indenter).
        """
        return {f.name: getattr(self, f.name) for f in dataclasses.fields(self)}

    def to_attrs(self) -> dict[str, Any]:
        """netCDF-safe attributes: ``param_<name>`` (float) and its units.

        Returns
        -------
        dict of str to object
            ``param_<name>`` and ``param_<name>_units`` for each field that has a value, and the effective moduli
            ``param_E_star``, ``param_G_star`` (Pa).
        """
        attrs: dict[str, Any] = {}
        for name, value in self.as_dict().items():
            if value is None:  # (R of another indenter: it names itself)
                continue
            attrs[f"param_{name}"] = float(value)
            attrs[f"param_{name}_units"] = PARAMETER_UNITS[name]
        attrs["param_E_star"] = self.E_star
        attrs["param_G_star"] = self.G_star
        return attrs

    @classmethod
    @reads_attrs("parameters")
    def from_attrs(cls, attrs: Mapping[str, Any]) -> "Parameters":
        """Rebuild the parameters from :meth:`to_attrs` output (e.g. a file).

        Parameters
        ----------
        attrs : mapping of str to object
            A result's attributes with ``param_<name>`` for every field (``param_R`` may be absent beside
            ``profile``: another indenter).

        Returns
        -------
        Parameters
            The record those attributes hold.

        Raises
        ------
        ValueError
            An attribute missing.
        """
        names = [f.name for f in dataclasses.fields(cls)]
        missing = [f"param_{n}" for n in names if f"param_{n}" not in attrs and not (n == "R" and "profile" in attrs)]
        if missing:
            raise ValueError(f"attrs lack the parameter attribute(s) {missing}")
        values = {}
        for n in names:
            if f"param_{n}" not in attrs:
                values[n] = None
                continue
            try:
                values[n] = number_of(attrs[f"param_{n}"])
            except (TypeError, ValueError, OverflowError):
                raise ValueError(f"the attribute param_{n}={shown(attrs[f'param_{n}'])} is not allowed; allowed: a "
                                 f"number ({PARAMETER_UNITS[n]}; in text: {PLAIN_NUMBER})") from None
        return cls(**values)


def from_preset(preset: str, **overrides: float) -> tuple[Parameters, dict[str, str]]:
    """A preset of the paper (:data:`PRESETS`) with some fields replaced, and attributes saying so.

    Returns the parameters and netCDF-safe attributes for the results computed with them:
    ``parameters_preset`` (the preset's name) and ``parameters_from_preset`` (the fields whose values
    came from the preset rather than from the user, comma-separated; "" if the user gave all).
    """
    preset = check_choice("preset", preset, PRESETS)
    params = Parameters.paper(R=PRESETS[preset])
    params = params.replace(**overrides) if overrides else params
    taken = [name for name in PARAMETER_UNITS if name not in overrides]
    return params, {"parameters_preset": preset, "parameters_from_preset": ", ".join(taken)}


def check_parameters(params: Any, name: str = "params") -> Parameters:
    """``params`` if it is a :class:`Parameters`; else ``TypeError`` naming it and what is allowed."""
    if not isinstance(params, Parameters):
        raise TypeError(f"{name}={shown(params)} ({type(params).__name__}) is not allowed; allowed: a "
                        "mdr_events.Parameters (e.g. Parameters.paper())")
    return params


@functools.lru_cache(maxsize=4)
def _presets(presets: tuple[tuple[str, float], ...]) -> tuple[tuple[str, Parameters], ...]:
    """Each preset's name and its ``Parameters.paper(R)``, made once (every result's stamp asks
    :meth:`Parameters.preset_name`, twice)."""
    return tuple((name, Parameters.paper(R=radius)) for name, radius in presets)

