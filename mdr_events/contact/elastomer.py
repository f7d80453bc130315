"""The elastomer: a linear-elastic half-space of Young's modulus ``E`` and Poisson's ratio ``ν``."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Mapping

from mdr_events.parameters import effective_normal_modulus, effective_tangential_modulus, shear_modulus
from mdr_events.validation import check_real, reads_attrs

__all__ = ["Elastomer"]


@dataclass(frozen=True)
class Elastomer:
    """A linear-elastic half-space (SI units).

    Parameters
    ----------
    E : float
        Young's modulus in Pa, finite and > 0.
    nu : float
        Poisson's ratio, in (-1, 0.5] (0.5: incompressible, as the paper's elastomer).

    Raises
    ------
    ValueError
        ``E`` or ``nu`` outside its range, infinite or NaN.

    Notes
    -----
    The effective moduli of a rigid indenter on it are ``E* = E / (1 - ν²)`` and ``G* = 4 G / (2 - ν)`` with
    ``G = E / (2 (1 + ν))`` (the definitions next to eqs. (5), (6)): the springs' normal and tangential
    stiffness per width.
    """

    E: float
    nu: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "E", check_real("Elastomer.E", self.E, "a finite number > 0 (Pa)",
                                                 lambda value: value > 0.0))
        object.__setattr__(self, "nu", check_real("Elastomer.nu", self.nu, "a finite number in (-1, 0.5]",
                                                  lambda value: -1.0 < value <= 0.5))

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

    def to_attrs(self) -> dict[str, Any]:
        """A result's attributes: ``param_E``, ``param_nu`` with their units, and ``param_E_star``, ``param_G_star``.

        Returns
        -------
        dict of str to object
            The moduli in Pa and Poisson's ratio, with ``param_E_units`` and ``param_nu_units``.
        """
        return {"param_E": self.E, "param_E_units": "Pa", "param_nu": self.nu, "param_nu_units": "1",
                "param_E_star": self.E_star, "param_G_star": self.G_star}

    @classmethod
    @reads_attrs("an elastomer")
    def from_attrs(cls, attrs: Mapping[str, Any]) -> "Elastomer":
        """The elastomer a result was computed for (:meth:`to_attrs`).

        Parameters
        ----------
        attrs : mapping of str to object
            A result's attributes holding ``param_E`` and ``param_nu`` (the effective moduli are recomputed).

        Returns
        -------
        Elastomer
            The half-space of that modulus and Poisson's ratio.
        """
        return cls(float(attrs["param_E"]), float(attrs["param_nu"]))
