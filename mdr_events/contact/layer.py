"""The elastomer as a layer of finite thickness ``h`` on a rigid base (issue 34); ``h = inf`` is the half-space.

The layer's top is in frictionless contact with the indenter in the normal problem; its base is either bonded to the
rigid support (no displacement there) or resting on it without friction (no normal displacement, no shear
stress). The theory of a punch on such a layer, the generalized MDR built on it, is
:mod:`mdr_events.theory.layer`.
"""

from __future__ import annotations

import enum
import math
import sys
from dataclasses import dataclass
from typing import Any, Mapping

from mdr_events.validation import as_name, check_real, reads_attrs, shown

__all__ = ["Layer", "LayerBase", "HALF_SPACE", "NU_RANGE"]

#: The Poisson's ratios a layer of finite thickness takes, ``[0, 0.5]``: the range of its compliance and tables
#: (:mod:`mdr_events.theory.layer`); the half-space takes ``(-1, 0.5]``.
NU_RANGE = (0.0, 0.5)


class LayerBase(enum.Enum):
    """How the layer rests on its rigid base.

    ``BONDED``: the base is glued (``u_r = u_z = 0`` at ``z = h``); ``FRICTIONLESS``: it slides freely on the base
    (``u_z = 0``, ``σ_rz = 0`` at ``z = h``). Looked up by value too: ``LayerBase("bonded")``.
    """

    #: Glued to the rigid base: no displacement at ``z = h``.
    BONDED = "bonded"
    #: Resting on the rigid base without friction: ``u_z = 0`` and no shear stress at ``z = h``.
    FRICTIONLESS = "frictionless"

    @classmethod
    def _missing_(cls, value: object) -> "LayerBase":
        """A value that names no base: the package's one line (Enum's own names no allowed values)."""
        raise ValueError(f"LayerBase({shown(value)}) is not allowed; allowed: "
                         + ", ".join(repr(member.value) for member in cls))


#: What ``Layer.base`` may be, in a message.
_BASES_ALLOWED = "one of " + ", ".join(f"LayerBase.{member.name} ({member.value!r})" for member in LayerBase)


def _as_base(value: Any) -> LayerBase:
    """``value`` as a :class:`LayerBase` (a member or its value's string), else a one-line ``ValueError``."""
    if isinstance(value, LayerBase):
        return value
    if isinstance(as_name(value), str):
        for member in LayerBase:
            if as_name(value) == member.value:
                return member
    raise ValueError(f"Layer.base={shown(value)} is not allowed; allowed: {_BASES_ALLOWED}")


@dataclass(frozen=True)
class Layer:
    """An elastic layer of thickness ``h`` on a rigid base (SI units); ``h = inf`` is the half-space.

    Parameters
    ----------
    thickness : float, default inf
        The layer's thickness ``h`` in m: a number > 0, finite or ``+inf`` (the half-space of the paper).
    base : LayerBase or str, default LayerBase.BONDED
        How the layer rests on its rigid base: ``LayerBase.BONDED`` (``"bonded"``) or ``LayerBase.FRICTIONLESS``
        (``"frictionless"``). Irrelevant for the half-space (kept as given).

    Raises
    ------
    TypeError
        ``thickness`` not a real number (a bool, a string, a complex number).
    ValueError
        ``thickness`` ≤ 0, NaN or ``-inf``; ``base`` not one of the two (the message names the field, the value and
        what is allowed).

    Notes
    -----
    The contact at the layer's top is frictionless in the normal problem (the indenter presses without shear);
    the layer's moduli are the elastomer's (:class:`~mdr_events.contact.elastomer.Elastomer`).
    """

    thickness: float = math.inf
    base: LayerBase = LayerBase.BONDED

    def __post_init__(self) -> None:
        object.__setattr__(self, "thickness", check_real(
            "Layer.thickness", self.thickness, "a number > 0 (m), finite or inf (the half-space)",
            lambda value: value > 0.0, finite=False))
        object.__setattr__(self, "base", _as_base(self.base))

    def __repr__(self) -> str:
        return f"Layer(thickness={self.thickness!r}, base={self.base.value!r})"

    @property
    def is_half_space(self) -> bool:
        """Whether the layer is infinitely thick (``thickness = inf``): the paper's half-space."""
        return math.isinf(self.thickness)

    def relative_radius(self, radius: float) -> float:
        """The contact radius in the layer's thickness, ``a / h`` (0 for the half-space).

        Parameters
        ----------
        radius : float
            A contact radius ``a`` in m.

        Returns
        -------
        float
            ``a / h``.

        Raises
        ------
        TypeError, ValueError
            ``radius`` not a finite number >= 0, or one whose ``a/h`` overflows (``inf`` before).
        """
        radius = check_real("radius", radius, "a finite number >= 0 (m)", lambda value: value >= 0.0)
        relative = radius / self.thickness
        if not math.isfinite(relative):
            raise ValueError(f"radius={shown(radius)} is not allowed on {self.describe()}: a/h overflows; allowed: a radius "
                             f"whose a/h is a finite double (at most {self.thickness * sys.float_info.max:.3g} m)")
        return relative

    def check_poisson_ratio(self, nu: float) -> None:
        """Refuse a Poisson's ratio ``nu`` this layer has no compliance for, in one line naming the layer.

        The half-space takes any ``nu`` in ``(-1, 0.5]`` (``Elastomer``'s range); a layer of finite thickness takes
        ``[0, 0.5]``, the range of its compliance and tables (:data:`NU_RANGE`; Lebedev & Ufliand's kernel, the
        tangential ones). Checked when a ``Contact`` is made (round twenty: ``--nu -0.99 --h 5e-3`` ran until the
        layer's tables refused ``nu=-0.99`` with the range ``[0, 0.5]``, not saying it is the layer's).

        Parameters
        ----------
        nu : float
            The elastomer's Poisson's ratio.

        Raises
        ------
        ValueError
            A layer of finite thickness and ``nu`` outside :data:`NU_RANGE`.
        """
        low, high = NU_RANGE
        if not self.is_half_space and not low <= nu <= high:
            raise ValueError(f"nu={shown(nu)} is not allowed on {self.describe()}; allowed: a Poisson's ratio in [{low:g}, "
                             f"{high:g}] on a layer of finite thickness (its compliance's range; the half-space, "
                             "h = inf, takes (-1, 0.5])")

    def describe(self) -> str:
        """The layer in words.

        Returns
        -------
        str
            ``"half-space"`` or e.g. ``"layer h = 0.005 m, bonded base"``.
        """
        if self.is_half_space:
            return "half-space"
        return f"layer h = {self.thickness:.9g} m, {self.base.value} base"

    def to_attrs(self) -> dict[str, Any]:
        """A result's attributes: ``param_layer_thickness`` (m, ``inf`` for the half-space) and ``param_layer_base``.

        Returns
        -------
        dict of str to object
            The thickness with its units and the base's name.
        """
        return {"param_layer_thickness": self.thickness, "param_layer_thickness_units": "m",
                "param_layer_base": self.base.value}

    @classmethod
    @reads_attrs("a layer")
    def from_attrs(cls, attrs: Mapping[str, Any]) -> "Layer":
        """The layer a result was computed for (:meth:`to_attrs`); the half-space if the attributes name none.

        Parameters
        ----------
        attrs : mapping of str to object
            A result's attributes, with ``param_layer_thickness`` and ``param_layer_base`` or without (a result
            written before layers existed: the half-space).

        Returns
        -------
        Layer
            The layer of that thickness and base.
        """
        if "param_layer_thickness" not in attrs:
            return HALF_SPACE
        return cls(float(attrs["param_layer_thickness"]), str(attrs.get("param_layer_base", "bonded")))


#: The paper's elastomer: a half-space (``Layer()``).
HALF_SPACE = Layer()
