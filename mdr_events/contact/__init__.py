"""The physical model as data: what is in contact, and how it sticks and slides.

=====================  ==================================================================================
part                   kinds
=====================  ==================================================================================
the elastomer          :class:`Elastomer` (``E``, ``ν``)
the indenter           :class:`Paraboloid` (the paper's), :class:`PowerLaw`, :class:`FlatPunch`,
                       :class:`TabulatedProfile` (:mod:`~mdr_events.contact.indenters`)
the adhesion           :class:`Adhesion` (Heß's rule with ``Δγ0`` in, ``Δγ1`` out;
                       :mod:`~mdr_events.contact.adhesion`)
the friction law       :class:`FrictionLaw` (``τ0``, Coulomb's ``μ``, or both; :mod:`~mdr_events.contact.friction`)
the layer              :class:`Layer` (thickness ``h``, :class:`LayerBase`; :mod:`~mdr_events.contact.layer`;
                       the half-space by default)
the whole              :class:`Contact` (:mod:`~mdr_events.contact.model`)
=====================  ==================================================================================

A new kind of a part goes into its module, as a frozen, validated type with ``to_attrs`` (and the methods the
layers above ask of its part).
"""

from mdr_events.contact.adhesion import NO_ADHESION, Adhesion, RateDependentAdhesion
from mdr_events.contact.elastomer import Elastomer
from mdr_events.contact.friction import FRICTION_LAWS, TAU0, FrictionLaw, as_friction_law, friction_attrs
from mdr_events.contact.indenters import (FlatPunch, Indenter, Paraboloid, PowerLaw, Profile, TabulatedProfile,
                                          indenter_from_attrs, profile_attrs)
from mdr_events.contact.layer import HALF_SPACE, Layer, LayerBase
from mdr_events.contact.model import PARTS, SHORT_NAMES, Contact, check_half_space

__all__ = ["Adhesion", "RateDependentAdhesion", "NO_ADHESION", "Elastomer", "FrictionLaw", "FRICTION_LAWS", "TAU0", "as_friction_law",
           "friction_attrs", "Paraboloid", "PowerLaw", "FlatPunch", "TabulatedProfile", "Profile", "Indenter",
           "indenter_from_attrs", "profile_attrs", "Contact", "PARTS", "SHORT_NAMES", "Layer", "LayerBase", "HALF_SPACE",
           "check_half_space"]
