"""What every method runs: a contact along a motion, with the flat values the layers below read.

:func:`mdr_events.models.simulate.model_job` makes it, from a :class:`~mdr_events.Contact` or from the keywords of
before; a method (:mod:`mdr_events.models.methods`) takes it whole and hands each kernel what it reads.
"""

from __future__ import annotations

from typing import NamedTuple

from mdr_events.contact import Contact
from mdr_events.contact.adhesion import AdhesionLaw
from mdr_events.contact.friction import FrictionLaw
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.kernel_model import KernelModel
from mdr_events.models.motion import Motion
from mdr_events.parameters import Parameters

__all__ = ["ModelJob"]


class ModelJob(NamedTuple):
    """A contact along a motion, and the flat values the kernels take.

    Attributes
    ----------
    contact : Contact
        The physical model.
    motion : Scenario or Paths
        Where the indenter goes.
    params : Parameters
        The contact's values with the motion's ``d_max`` and ``v`` (the works of adhesion at rest, ``τ0`` of the
        friction law or 0).
    profile : PowerLaw, FlatPunch, TabulatedProfile or None
        The indenter as the kernels take it (``None``: the paraboloid of ``params.R``).
    friction : FrictionLaw
        The friction law without ``τ0``, which ``params`` holds.
    """

    contact: Contact
    motion: Motion
    params: Parameters
    profile: SimulatedProfile
    friction: FrictionLaw

    @property
    def kernel(self) -> KernelModel:
        """The flat values the kernels read (:class:`~mdr_events.models.kernel_model.KernelModel`)."""
        return KernelModel(self.params, self.profile, self.friction, self.contact.adhesion, self.contact.layer)

    @property
    def adhesion(self) -> AdhesionLaw:
        """The contact's adhesion law, whose kernel each method looks up by its type."""
        return self.contact.adhesion

    @property
    def scenario(self) -> str:
        """The motion's name as results carry it (``"A"``, ``"B"``, ``"B+"`` or ``"custom"``)."""
        return self.motion.to_attrs()["scenario"]
