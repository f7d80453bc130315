"""What a run of either method reads of the physical model, as one value.

The kernels of the two methods (:func:`~mdr_events.models.discrete.run_discrete`,
:func:`~mdr_events.models.continuum.solve.run_continuum`) and the fit's model curves
(:func:`~mdr_events.analysis.fit_data.model_curves`) read the material, the indenter, the friction law, the adhesion
law and the body; a :class:`KernelModel` carries them together, as a method's
:class:`~mdr_events.models.job.ModelJob` hands them on (:attr:`~mdr_events.models.job.ModelJob.kernel`). A plain
:class:`~mdr_events.Parameters` stands for the paper's model of its values (:func:`as_kernel_model`).
"""

from __future__ import annotations

from typing import NamedTuple

from mdr_events.contact.adhesion import AdhesionLaw
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.limits import Limits, check_limits
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.validation import shown

__all__ = ["KernelModel", "as_kernel_model", "check_kernel_run"]


class KernelModel(NamedTuple):
    """The physical model as the kernels read it: the flat values of a contact with its motion's depth and speed.

    Attributes
    ----------
    params : Parameters
        The material, ``R``, ``τ0``, the works of adhesion, ``d_max`` and ``v``.
    profile : PowerLaw, FlatPunch, TabulatedProfile, callable or None
        The indenter (``None``: the paraboloid of ``params.R``; the discrete method also takes the springs' profile
        ``g(x)`` as a vectorised function).
    friction : FrictionLaw, str or None
        The friction law (``None``: the paper's ``"tau0"``).
    adhesion : Adhesion, RateDependentAdhesion or None
        The adhesion law (``None``: the paper's, of ``params.dgamma0`` and ``params.dgamma1``).
    layer : Layer
        The body (default the half-space).
    """

    params: Parameters
    profile: SimulatedProfile = None
    friction: FrictionLaw | str | None = None
    adhesion: AdhesionLaw | None = None
    layer: Layer = HALF_SPACE


def as_kernel_model(model: KernelModel | Parameters) -> KernelModel:
    """``model`` as a :class:`KernelModel`: itself, or the paper's model of a :class:`~mdr_events.Parameters`.

    Parameters
    ----------
    model : KernelModel or Parameters
        The model, or the values of the paper's paraboloid with ``"tau0"`` and the paper's adhesion law.

    Returns
    -------
    KernelModel
        The model.

    Raises
    ------
    TypeError
        Anything else, named with what is allowed.
    """
    if isinstance(model, KernelModel):
        if not isinstance(model.params, Parameters):
            raise TypeError(f"model.params={shown(model.params)} ({type(model.params).__name__}) is not allowed; "
                            "allowed: a mdr_events.Parameters")
        return model
    if isinstance(model, Parameters):
        return KernelModel(model)
    raise TypeError(f"model={shown(model)} is not allowed; allowed: a KernelModel, or Parameters for the paper's model")


def check_kernel_run(paths, limits) -> tuple[list[Path], Limits]:
    """What a kernel (:func:`~mdr_events.models.discrete.run_discrete`,
    :func:`~mdr_events.models.continuum.solve.run_continuum`) runs along and within, checked before anything is
    computed: they were read as they came, and a path that was not one, or limits that were not, failed deep inside
    (``AttributeError``, ``ZeroDivisionError``, NumPy's "zero-size array").

    Parameters
    ----------
    paths : list of Path
        One case per path: a non-empty list or tuple of :class:`~mdr_events.models.paths.Path`.
    limits : Limits
        The resource limits.

    Returns
    -------
    tuple of (list of Path, Limits)
        The paths as a list, and the limits.

    Raises
    ------
    TypeError
        ``paths`` not a list or tuple of paths (a single path among them), ``limits`` not a ``Limits``.
    ValueError
        No path.
    """
    allowed = "a non-empty list of mdr_events.Path (one case each)"
    if not isinstance(paths, (list, tuple)):
        raise TypeError(f"paths={shown(paths)} ({type(paths).__name__}) is not allowed; allowed: {allowed}")
    if not paths:
        raise ValueError(f"paths={shown(paths)} is not allowed; allowed: {allowed}")
    for index, path in enumerate(paths):
        if not isinstance(path, Path):
            raise TypeError(f"paths[{index}]={shown(path)} ({type(path).__name__}) is not allowed; allowed: {allowed}")
    return list(paths), check_limits(limits)
