"""Adhesion as data: the works of adhesion of Heß's rule (8).

The paper's law is rate independent with a hysteresis: springs attach on the way in as Heß's rule with the work
of adhesion ``Δγ0`` says, and let go on the way out as it says with ``Δγ1`` (>= or < ``Δγ0``); ``Δγ0 = Δγ1 = 0``
is the non-adhesive (Hertz) contact. A law that depends on the edge's speed goes beside :class:`Adhesion` here,
with the same methods.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Mapping

from mdr_events.validation import check_real

__all__ = ["Adhesion", "NO_ADHESION"]


@dataclass(frozen=True)
class Adhesion:
    """The paper's rate-independent adhesion: Heß's rule (8) with ``Δγ0`` in and ``Δγ1`` out (J/m², finite, >= 0).

    Attributes
    ----------
    dgamma0 : float
        Work of adhesion of springs attaching while the indenter goes in.
    dgamma1 : float
        Work of adhesion of the detachment criterion while it comes out.
    """

    dgamma0: float = 0.0
    dgamma1: float = 0.0

    def __post_init__(self) -> None:
        for name in ("dgamma0", "dgamma1"):
            object.__setattr__(self, name, check_real(f"Adhesion.{name}", getattr(self, name),
                                                      "a finite number >= 0 (J m-2)", lambda value: value >= 0.0))

    @property
    def is_adhesive(self) -> bool:
        """Whether either work of adhesion is positive (else the contact is Hertz's)."""
        return self.dgamma0 > 0.0 or self.dgamma1 > 0.0

    def to_attrs(self) -> dict[str, Any]:
        """A result's attributes: ``param_dgamma0``, ``param_dgamma1`` and their units."""
        return {"param_dgamma0": self.dgamma0, "param_dgamma0_units": "J m-2",
                "param_dgamma1": self.dgamma1, "param_dgamma1_units": "J m-2"}

    @classmethod
    def from_attrs(cls, attrs: Mapping[str, Any]) -> "Adhesion":
        """The adhesion a result was computed with (:meth:`to_attrs`)."""
        return cls(float(attrs["param_dgamma0"]), float(attrs["param_dgamma1"]))


#: No adhesion: Hertz's contact.
NO_ADHESION = Adhesion()
