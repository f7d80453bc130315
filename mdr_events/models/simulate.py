"""``simulate``: one entry point for every simulation method, one result schema.

``simulate(contact, motion, method)`` runs a :class:`~mdr_events.Contact` along a motion
(:class:`~mdr_events.models.motion.Scenario` or :class:`~mdr_events.models.motion.Paths`) with a method
(:mod:`mdr_events.models.methods`, by name with its options or as a value). The keywords of before,
``simulate(params, scenario, alpha, method=..., dx=..., profile=..., friction=...)``, are read by
:func:`simulation_job`, the one place that converts them; a run of either form gives the same numbers.
"""

from __future__ import annotations

import dataclasses
from typing import Any, Mapping, NamedTuple, Sequence

import xarray as xr

from mdr_events.contact import Contact
from mdr_events.contact.model import check_half_space
from mdr_events.contact.friction import as_friction_law
from mdr_events.limits import Limits, check_limits, values_in
from mdr_events.memo import kept
from mdr_events.models import indenters
from mdr_events.models.job import ModelJob
from mdr_events.models.methods import METHODS, Continuum, Discrete, Method, as_method, check_counted_first
from mdr_events.models.motion import Motion, Paths, Scenario, angles_within, as_motion
from mdr_events.models.paths import Path
from mdr_events.models.spring_media import springs_of
from mdr_events.parameters import Parameters
from mdr_events.theory.job import contact_alone
from mdr_events.theory.scales import check_representable
from mdr_events.validation import shown

#: The keywords of before that ``model_job`` takes out of the options beside a :class:`~mdr_events.Parameters`.
MODEL_OPTIONS = ("profile", "friction")
#: The method of simulate unless given: the paper's springs.
DEFAULT_METHOD = "discrete"

__all__ = ["simulate", "simulation_job", "SimulationJob", "model_job", "METHODS", "check_layer_taken"]

#: How many contacts of the keywords of before :func:`model_job` keeps (:func:`_contact_of`).
CONTACTS_KEPT = 16


@kept(CONTACTS_KEPT)
def _contact_of(params: Parameters, profile, friction) -> Contact:
    """:meth:`Contact.from_parameters <mdr_events.Contact.from_parameters>`, kept by the exact values of its frozen
    arguments (:func:`~mdr_events.memo.kept`; a ``Contact`` is frozen: the same value, made and validated once)."""
    return Contact.from_parameters(params, profile, friction)


class SimulationJob(NamedTuple):
    """What a simulation runs: the contact along the motion (:class:`ModelJob`) with the method."""

    model: ModelJob
    method: Method


def model_job(contact, motion, alpha, options: dict[str, Any]) -> ModelJob:
    """The contact and motion of ``contact``, ``motion`` and ``alpha`` (a scenario's name with its angles): a
    :class:`~mdr_events.Contact` with a motion; or the keywords of before, a :class:`~mdr_events.Parameters` (its
    ``d_max`` and ``v`` the motion's) with ``profile`` and ``friction`` taken out of ``options``, whose results keep
    its attributes as they were (``param_R`` beside a profile). The one place the keywords are converted."""
    indenter, law = (options.pop(name, None) for name in MODEL_OPTIONS)
    if isinstance(contact, Parameters):
        if isinstance(motion, (Scenario, Paths)):  # (the Parameters' d_max and v were named as if given beside it)
            raise ValueError(f"motion={motion!r} is not allowed beside a Parameters, whose d_max and v are a motion of "
                             "its own; allowed: Contact.from_parameters(params) with the motion, or the scenario's name "
                             "with alpha beside the Parameters")
        params, profile = contact, indenters.check_simulated_profile(indenter)
        friction = as_friction_law(law)
        return ModelJob(_contact_of(params, profile, friction), as_motion(motion, alpha, params.d_max, params.v),
                        params, profile, friction)
    contact = contact_alone(contact, indenter, law)
    motion = as_motion(motion, alpha)
    return ModelJob(contact, motion, contact.parameters(motion.d_max, motion.v),
                    indenters.check_simulated_profile(contact.profile), dataclasses.replace(contact.friction, tau0=None))


def simulation_job(contact, motion, alpha, method, options: Mapping[str, Any], limits: Limits) -> SimulationJob:
    """The job of ``simulate(contact, motion, alpha, method, **options)``: :func:`model_job`, and the method by name
    with the remaining options (:func:`~mdr_events.models.methods.as_method`), its cases counted against ``limits``
    before the layer's check builds them (round twenty-two: 1e6 angles on a layer were built, minutes and a GiB,
    before the count refused them), and before the angles ``alpha`` and the continuum's times ``t`` are read: counted
    (:func:`~mdr_events.limits.values_in`) first (round twenty-two: 1e8 angles were copied ~7 times, 5 GB, before the
    count refused them)."""
    options = dict(options)
    if isinstance(alpha, (Discrete, Continuum)) or (isinstance(alpha, str) and alpha in METHODS):
        if method is not None:  # simulate(contact, motion, method): the third argument is the method
            raise ValueError(f"method={shown(method)} is not allowed beside the method {shown(alpha)} given third; "
                             "allowed: one method")
        alpha, method = None, alpha
    unread = values_in(alpha) if alpha is not None else getattr(motion, "case_count", 1)  # (a lower bound, unread)
    own = {name: value for name, value in options.items() if name not in MODEL_OPTIONS}
    check_counted_first(DEFAULT_METHOD if method is None else method, own, unread, limits)
    with angles_within(limits):  # (the angles counted against the run's limits above)
        model = model_job(contact, motion, alpha, options)
    the_method = as_method(DEFAULT_METHOD if method is None else method, options)
    the_method.check_case_count(model.motion.case_count, limits)  # (before the cases are built: each takes its theory)
    check_layer_taken(model.contact, model.motion, the_method)
    return SimulationJob(model, the_method)


def check_layer_taken(contact: Contact, motion: Motion, method: Method, where: str | None = None) -> Contact:
    """``contact`` if ``method`` runs its body along ``motion``: the half-space always; a layer of finite thickness
    with a method that takes layers (both do; one that does not is refused by
    :func:`~mdr_events.contact.model.check_half_space`), and there what its springs take
    (:meth:`~mdr_events.models.spring_media.LayerSprings.check`: the paraboloid or a power law, the paper's adhesion
    law; on a frictionless base no tangential motion) and what the method takes (``method.check_layer``: both run every
    friction law there, the continuum Coulomb's part spring by spring). The front ends call it before they write anything.

    Parameters
    ----------
    contact : Contact
        The physical model.
    motion : Scenario or Paths
        Where the indenter goes.
    method : Discrete or Continuum
        The method.
    where : str, optional
        The entry point named where a method without layers refuses one (default ``"simulate(method=...)"``;
        :func:`~mdr_events.sweep` names itself).

    Returns
    -------
    Contact
        ``contact`` itself.

    Raises
    ------
    ValueError, TypeError
        A layer of finite thickness with a method, indenter, adhesion law or motion that does not take it; scales
        beyond double precision (:func:`~mdr_events.theory.scales.check_representable`, checked first: the springs'
        check builds the motion's paths from them); a contact, motion or method of another kind (an
        ``AttributeError`` before).
    """
    if not isinstance(contact, Contact):
        raise TypeError(f"contact={shown(contact)} ({type(contact).__name__}) is not allowed in check_layer_taken; "
                        "allowed: a mdr_events.Contact")
    motion, method = as_motion(motion), as_method(method)
    if contact.layer.is_half_space:
        return contact
    if not method.takes_layers:
        check_half_space(contact, f"simulate(method={method.name!r})" if where is None else where)
    params, profile = contact.parameters(motion.d_max, motion.v), indenters.check_simulated_profile(contact.profile)
    # (the scales before the paths: PowerLaw(1e3, 1e6) on a layer was an OverflowError, R = 1e308 a path's jump-off)
    check_representable(params, profile, dataclasses.replace(contact.friction, tau0=None))
    springs = springs_of(params, profile, None, contact.layer)
    springs.check(contact.adhesion, motion.cases(params, profile, contact.friction).paths)
    method.check_layer(contact)
    return contact


def simulate(
    contact: Contact | Parameters,
    motion: Motion | str | Path | Sequence[Path] | Mapping[str, Path] = "A",
    alpha: float | Sequence[float] | None = None,
    method: str | Method | None = None,
    *,
    limits: Limits | None = None,
    **options: Any,
) -> xr.Dataset:
    """Simulate indentation and detachment along straight paths.

    Parameters
    ----------
    contact : Contact or Parameters
        The physical model (:class:`~mdr_events.Contact`: elastomer, indenter, adhesion, friction law). A
        :class:`~mdr_events.Parameters` is read as before: its paraboloid (or ``profile=``), its ``τ0`` (with
        ``friction=``) and its ``d_max`` and ``v`` for a scenario.
    motion : Scenario, Paths, {"A", "B", "B+"}, Path, list of Path or mapping of str to Path
        A :class:`~mdr_events.Scenario` (one case per angle) or :class:`~mdr_events.Paths` (one case per path);
        or a scenario's name with ``alpha`` (``"A"``: eq. (14); ``"B"``: eq. (19); ``"B+"``: the "+" branch of
        Fig. 9b, :meth:`~mdr_events.Path.scenario_B_indentation`), or custom paths: a :class:`Path`, a non-empty list of
        them (labelled ``"path 1"``, ``"path 2"``, ...) or a mapping ``{label: Path}``; the paths may have
        different speeds.
    alpha : float or sequence of float, optional
        With a scenario's name: angles in degrees (default 10°, 20°, …, 80°, as in Fig. 8 and 10).
    method : {"discrete", "continuum"}, Discrete or Continuum
        ``"discrete"`` (the default): the paper's spring array (:mod:`mdr_events.models.discrete`).
        ``"continuum"``: its Δx → 0 limit integrated between events
        (:mod:`mdr_events.models.continuum`); adds the event log along
        ``event`` and each case's exact extrema (:data:`EXTREMA_VARIABLES`).
        By name, its options are given beside it (:mod:`mdr_events.models.methods`): ``dx``, ``dt`` or
        ``n_steps`` for the discrete model; ``tolerances``, ``samples`` or ``t`` for the continuum.
    limits : Limits, optional
        What the run may use (default ``Limits()``: 2 GiB, 2e7 discrete steps, 1e7 springs per side, 1e7
        output samples, 2000 waypoints per path for the continuum); a larger run is refused before it
        starts with :class:`~mdr_events.limits.ResourceLimitError` giving the estimate.
    **options
        The method's options; beside a :class:`~mdr_events.Parameters` also ``profile`` (a
        :class:`~mdr_events.PowerLaw` with ``n >= 1``, a :class:`~mdr_events.FlatPunch` or a
        :class:`~mdr_events.TabulatedProfile`; default its paraboloid) and ``friction`` (a
        :class:`~mdr_events.FrictionLaw` or a law's name; default the paper's ``"tau0"``). The discrete method
        takes every law; the continuum takes Coulomb's part for a contact without adhesion.

    Returns
    -------
    xarray.Dataset
        Dims ``("alpha", "time")`` for a scenario (coordinate: the angles in
        degrees), ``("case", "time")`` for custom paths (coordinate: the
        labels; per case ``path_waypoints`` and ``path_speed``); variables of
        :data:`SIMULATION_VARIABLES`, ``nan`` after a case has ended (pull-off,
        or the end of its path); time from first contact.

    Raises
    ------
    ValueError, TypeError
        Naming the argument, its value and what is allowed: e.g. an unknown
        scenario, an empty list of paths, an element that is not a Path, a
        label that is not a non-empty string or is repeated, ``alpha`` with
        custom paths.
    """
    limits = check_limits(limits)
    model, method = simulation_job(contact, motion, alpha, method, options, limits)
    check_representable(model.params, model.profile, model.friction)
    cases = model.motion.cases(model.params, model.profile, model.friction)
    return method.simulate(model, cases, limits)
