"""The runs of a sweep: what every run shares (:class:`SweepSpec`), a run's scalar quantities and history per method,
and a chunk of runs as one task (:func:`run_chunk`, a plain function of picklable arguments).

A run is the sweep's contact, motion and method with the swept names' values put in (:meth:`SweepSpec.job`). Its
quantities (:data:`QUANTITIES`) are exact for the continuum (the solution's extrema and event log,
:mod:`mdr_events.models.continuum`); for the discrete method they are read off its samples by the rules of
:mod:`mdr_events.analysis.validate` (first sample sliding, first sample out of contact, ...). What a method gives is
looked up by its name (:data:`METHOD_QUANTITIES`): a new method is one function there.

On a layer of finite thickness (``Contact.layer``, swept as ``h``) a run takes the model where its method takes a
layer (:attr:`Method.takes_layers <mdr_events.models.methods.Discrete.takes_layers>`, checked by
:func:`~mdr_events.models.simulate.check_layer_taken`); the closed-form quantities (:data:`CLOSED_FORM_QUANTITIES`)
are :func:`~mdr_events.critical_angle` of the run's contact, which hands a layer to
:mod:`mdr_events.theory.layer.slip_onset`, so a sweep of them alone takes a layer with any method
(:func:`check_layer_run`). The half-space's are those of :func:`mdr_events.models.indenters.critical_angle`, as
before.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Callable, NamedTuple, Sequence

import numpy as np

from mdr_events.analysis.fit import curves_of
from mdr_events.analysis.play_sweep import play_continuum_quantities
from mdr_events.analysis.rate_sweep import check_rate_sweep_run, rate_continuum_quantities
from mdr_events.analysis.samples import candidate_events, sliding as sliding_samples
from mdr_events.analysis.sweep_events import deepest_time, event_quantities, first_events
from mdr_events.contact import Contact
from mdr_events.contact.adhesion import RateDependentAdhesion
from mdr_events.limits import DEFAULT_LIMITS, Limits
from mdr_events.models import indenters
from mdr_events.models.continuum import extremum, solve_path, tangential_work
from mdr_events.models.continuum.edges import check_edge_known
from mdr_events.models.continuum.play_run import takes_play_springs
from mdr_events.models.continuum.span_extrema import scan_spans
from mdr_events.models.methods import Continuum, Discrete, Method
from mdr_events.models.motion import Motion, Paths
from mdr_events.models.paths import Path
from mdr_events.models.job import ModelJob
from mdr_events.models.simulate import check_layer_taken, model_job, simulate
from mdr_events.theory.analytic import critical_angle
from mdr_events.theory.scales import check_representable

__all__ = ["SweepSpec", "run_chunk", "ChunkResult", "QUANTITIES", "HISTORY_QUANTITIES", "CLOSED_FORM_QUANTITIES",
           "MOTION_NAMES", "METHOD_NAMES", "METHOD_QUANTITIES", "DISCRETE_STEP_PER_SPACING", "ERROR_CHARACTERS",
           "runs_model", "check_layer_run", "closed_form_angle", "CONTINUUM_QUANTITIES"]

#: Scalar quantities of each run: name -> (unit, long name).
QUANTITIES: dict[str, tuple[str, str]] = {
    "normal_force_min": ("N", "smallest normal force (largest adhesive pull)"),
    "tangential_force_max": ("N", "largest |F_x|"),
    "contact_area_max": ("m2", "largest contact area"),
    "slip_onset_in_time": ("s", "first slip onset before the path's deepest point (s from the path's start)"),
    "slip_onset_in_depth": ("m", "depth at the first slip onset before the path's deepest point"),
    "slip_onset_out_time": ("s", "first slip onset after the path's deepest point (s from the path's start)"),
    "slip_onset_out_depth": ("m", "depth at the first slip onset after the path's deepest point"),
    "full_slip_time": ("s", "first full slip (s from the path's start)"),
    "pull_off_time": ("s", "pull-off (s from the path's start)"),
    "pull_off_depth": ("m", "depth at the pull-off"),
    "pull_off_force": ("N", "normal force at the pull-off"),
    "tangential_work": ("J", "work of the tangential force over the run, ∫ F_x dx: all of it dissipated where the "
                             "run ends out of contact (the springs detach and forget their shift)"),
    "event_count": ("1", "events logged (continuum) / found (discrete)"),
    "critical_angle_A": ("degree", "critical angle of scenario A (eq. 18; closed form)"),
    "critical_angle_B": ("degree", "angle of scenario B above which the contact comes apart before sliding "
                                   "(eq. 21; closed form)"),
}
#: Quantities of a run's history (``history_samples``), at times spread evenly over its path.
HISTORY_QUANTITIES: dict[str, tuple[str, str]] = {
    "normal_force": ("N", "normal force"), "tangential_force": ("N", "tangential force"),
    "contact_area": ("m2", "contact area")}
#: Quantities of the closed forms alone: a sweep asking only for these runs no model.
CLOSED_FORM_QUANTITIES = ("critical_angle_A", "critical_angle_B")
#: Names a grid may sweep that are the motion's (with their units): the angle of a scenario, its depth and speed.
MOTION_NAMES = {"alpha": "degree", "d_max": "m", "v": "m s-1"}
#: Names a grid may sweep that are the method's: the discrete spacing.
METHOD_NAMES = {"dx": "m"}
#: Characters of a failed run's error kept in the result.
ERROR_CHARACTERS = 200
#: The discrete model's time step per spring spacing of travel when its method gives neither ``dt`` nor ``n_steps``:
#: the time step is refined with the spacing (both are first order; a fixed step would stop the convergence).
DISCRETE_STEP_PER_SPACING = 0.5


@dataclass(frozen=True)
class SweepSpec:
    """What every run of a sweep shares (picklable: sent to the workers once per chunk).

    Attributes
    ----------
    contact, motion, method
        The run before the grid's values are put in: a :class:`~mdr_events.Contact`, a
        :class:`~mdr_events.Scenario` of one angle (any, if the grid sweeps ``alpha``) or
        :class:`~mdr_events.Paths` of one path, and a method value.
    names : tuple of str
        The swept names: the contact's (dotted or short), :data:`MOTION_NAMES` and :data:`METHOD_NAMES`.
    quantities : tuple of str
        Which of :data:`QUANTITIES` each run keeps.
    history_samples : int, optional
        Each run's F_N, F_x and A at this many times spread evenly over its path.
    limits : Limits
        What each run may use.
    """

    contact: Contact
    motion: Motion
    method: Method
    names: tuple[str, ...]
    quantities: tuple[str, ...] = tuple(QUANTITIES)
    history_samples: int | None = None
    limits: Limits = DEFAULT_LIMITS

    def job(self, values: Sequence[float]) -> tuple[ModelJob, Method]:
        """The model and method of the run at ``values`` (one per swept name), each value validated where it goes."""
        settings = dict(zip(self.names, (float(value) for value in values)))
        changes = {name: value for name, value in settings.items()
                   if name not in MOTION_NAMES and name not in METHOD_NAMES}
        contact = self.contact.replace(**changes) if changes else self.contact
        method = dataclasses.replace(self.method, dx=settings["dx"]) if "dx" in settings else self.method
        return model_job(contact, _motion_at(self.motion, settings), None, {}), method

    @property
    def runs_model(self) -> bool:
        """Whether a run runs the model (:func:`runs_model`): not for :data:`CLOSED_FORM_QUANTITIES` alone."""
        return runs_model(self.quantities, self.history_samples)

    def check(self, values: Sequence[float]) -> None:
        """Refuse the run at ``values`` before anything runs: its scales, what its method takes, and a layer of
        finite thickness where the run cannot take it (:func:`check_layer_run`; the closed forms alone on a layer:
        what they refuse, :func:`~mdr_events.theory.layer.slip_onset.check_onset_contact`, a few branch evaluations.
        Computing them here, about 0.04 s a run, had checked a grid of 1e5 thicknesses for over an hour before its
        first run, with no progress, and again on every resume)."""
        model, method = self.job(values)
        check_representable(model.params, model.profile, model.friction)  # (E = 1e300 was a failed run)
        method.check_model(model)
        if self.runs_model and method.name in METHOD_CHECKS:
            METHOD_CHECKS[method.name](model)
        check_layer_run(model.contact, model.motion, method, self.quantities, self.history_samples)
        if not self.runs_model and model.adhesion.is_rate_dependent:
            raise ValueError(f"quantities={self.quantities!r} are not allowed with adhesion={model.adhesion!r}: the "
                             "closed forms are rate independent; allowed: the model's quantities (its angles at a speed: "
                             "mdr_events.critical_angles_at_speeds, critical_angles_B_at_speeds)")
        if not self.runs_model and not model.contact.layer.is_half_space:
            from mdr_events.theory.layer.slip_onset import check_onset_contact  # (the layer's theory, when asked)

            check_onset_contact(model.contact, "critical_angle", model.motion.d_max)

    def _closed_forms(self, model: ModelJob) -> dict[str, float]:
        return {f"critical_angle_{scenario}": closed_form_angle(model, scenario) for scenario in ("A", "B")
                if f"critical_angle_{scenario}" in self.quantities}

    def run(self, values: Sequence[float]) -> tuple[dict[str, float], np.ndarray | None]:
        """The :attr:`quantities` of the run at ``values``, and its history (rows :data:`HISTORY_QUANTITIES`,
        ``history_samples`` columns over the path's duration) if asked for; the model runs only if one of them
        needs it (not for :data:`CLOSED_FORM_QUANTITIES` alone)."""
        model, method = self.job(values)
        out, history = {}, None
        if self.runs_model:
            path = model.motion.cases(model.params, model.profile, model.friction).paths[0]
            times = None if not self.history_samples else np.linspace(0.0, path.duration, self.history_samples)
            out, history = METHOD_QUANTITIES[method.name](model, path, method, self.limits, times)
        out.update(self._closed_forms(model))
        return {name: out[name] for name in self.quantities}, history


def runs_model(quantities: Sequence[str], history_samples: int | None) -> bool:
    """Whether a sweep of ``quantities`` (and histories) runs the model: not for :data:`CLOSED_FORM_QUANTITIES`
    alone.

    Parameters
    ----------
    quantities : sequence of str
        Names of :data:`QUANTITIES`.
    history_samples : int or None
        Each run's history at this many times (``None``: none).

    Returns
    -------
    bool
        ``True`` if a quantity or the history needs the model.
    """
    return bool(set(quantities) - set(CLOSED_FORM_QUANTITIES) or history_samples)


def check_layer_run(contact: Contact, motion: Motion, method: Method, quantities: Sequence[str],
                    history_samples: int | None) -> None:
    """Refuse a sweep's run of a contact on a layer of finite thickness that runs the model (:func:`runs_model`)
    with a method that does not take the layer, or where the layer's springs do not take the contact or the motion
    (:func:`~mdr_events.models.simulate.check_layer_taken`, naming ``sweep(method=...)``); in the continuum
    Coulomb's part on a layer runs spring by spring (:mod:`~mdr_events.analysis.play_sweep`, ``simulate``'s run). The
    half-space and the closed-form quantities alone pass (those check themselves: :func:`closed_form_angle`).

    Parameters
    ----------
    contact : Contact
        The run's physical model.
    motion : Scenario or Paths
        The run's motion.
    method : Discrete or Continuum
        The sweep's method.
    quantities : sequence of str
        What the sweep keeps of each run.
    history_samples : int or None
        Each run's history at this many times (``None``: none).

    Raises
    ------
    ValueError, TypeError
        In one line, naming the layer, the sweep's method and what runs a layer.
    """
    if runs_model(quantities, history_samples):
        check_layer_taken(contact, motion, method, where=f"sweep(method={method.name!r}) of the model's quantities")


def closed_form_angle(model: ModelJob, scenario: str) -> float:
    """A run's closed-form critical angle of scenario ``"A"`` (18) or ``"B"`` (21), in degrees: on the half-space
    :func:`mdr_events.models.indenters.critical_angle` (any indenter; ``nan`` where a friction law has none); on a
    layer :func:`mdr_events.critical_angle` of the run's contact at the motion's ``d_max``, which hands it to
    :func:`~mdr_events.theory.layer.critical_angle_on_layer` (the layer's ``K_t`` and branches).

    Parameters
    ----------
    model : ModelJob
        The run's contact along its motion.
    scenario : {"A", "B"}
        The scenario of the angle.

    Returns
    -------
    float
        The angle in degrees.

    Raises
    ------
    ValueError, TypeError
        On a layer, what the layer's closed forms refuse (a radius beyond the tables). Where they have none (a
        frictionless base, another law: :func:`~mdr_events.theory.layer.slip_onset.has_closed_forms`) the angle is
        ``nan``, as the half-space's where a friction law has none (a sweep of the model's quantities on such a layer
        had failed every run); a sweep of the angles alone is refused before it runs. Under the rate-dependent law
        (closed forms of the rate-independent law alone) ``nan`` too: its angles at a speed are
        :func:`~mdr_events.critical_angles_at_speeds` and :func:`~mdr_events.critical_angles_B_at_speeds`.
    """
    if model.adhesion.is_rate_dependent:  # (the closed forms are rate independent)
        return math.nan
    if model.contact.layer.is_half_space:
        return indenters.critical_angle(model.params, scenario, model.profile, model.friction)
    from mdr_events.theory.layer.slip_onset import has_closed_forms  # (the layer's theory, when asked)

    if not has_closed_forms(model.contact):
        return math.nan
    return critical_angle(model.contact, scenario, d_max=model.motion.d_max)


def _motion_at(motion: Motion, settings: dict[str, float]) -> Motion:
    """The motion with the swept angle, depth and speed of a run put in."""
    changes = {name: settings[name] for name in ("d_max", "v") if name in settings}
    if isinstance(motion, Paths):
        return Paths.named_by(motion.paths, changes.get("d_max", motion.d_max), changes.get("v", motion.v)) \
            if changes else motion
    if "alpha" in settings:
        changes["alpha"] = (settings["alpha"],)
    return dataclasses.replace(motion, **changes) if changes else motion


#: The continuum's quantities of the adhesion laws that ``simulate``'s continuum runs by a run of their own (not on the
#: spans of ``solve_path``), by the law's type: the rate-dependent law's (:mod:`~mdr_events.analysis.rate_sweep`).
CONTINUUM_QUANTITIES: dict[type, Callable[..., tuple[dict[str, float], np.ndarray | None]]] = {
    RateDependentAdhesion: rate_continuum_quantities}


def continuum_quantities(model: ModelJob, path: Path, method: Continuum, limits: Limits,
                         times: np.ndarray | None) -> tuple[dict[str, float], np.ndarray | None]:
    """A run's quantities from the exact solution (its extrema and event log), and its history at ``times``; a law
    of :data:`CONTINUUM_QUANTITIES` by its own run, Coulomb's part on a layer by the per-spring run
    (:mod:`~mdr_events.analysis.play_sweep`)."""
    own = CONTINUUM_QUANTITIES.get(type(model.adhesion))
    if own is not None:
        return own(model, path, method, limits, times)
    if takes_play_springs(model.kernel):  # (Coulomb's part on a layer: simulate's per-spring run, not the spans)
        return play_continuum_quantities(model, path, method, limits, times)
    solution = solve_path(model.params, path, method.tolerances, limits, model.profile, model.friction,
                          layer=model.contact.layer)
    scan = scan_spans(solution)  # one scan serves every extremum, its quantities reduced at once
    scan.prepare(("normal_force", "contact_area") + (() if solution.compressed else ("tangential_force",)))
    out = {"normal_force_min": extremum(solution, "normal_force", largest=False, scan=scan)[1],
           "tangential_force_max": max(abs(extremum(solution, "tangential_force", largest=True, scan=scan)[1]),
                                       abs(extremum(solution, "tangential_force", largest=False, scan=scan)[1])),
           "contact_area_max": extremum(solution, "contact_area", largest=True, scan=scan)[1],
           "tangential_work": tangential_work(solution), "event_count": float(len(solution.events))}
    first = first_events(solution.events, path)
    out.update(event_quantities(first))
    pull = first.get("pull_off")
    out["pull_off_force"] = float(solution.model.normal_force(pull.depth, pull.radius)) if pull else math.nan
    if times is None:
        return out, None
    curves = curves_of(solution, path, times, tuple(HISTORY_QUANTITIES)).values
    return out, np.array([curves[name] for name in HISTORY_QUANTITIES])


def _discrete_run(model: ModelJob, path: Path, method: Discrete, limits: Limits):
    """The discrete model along ``path`` (its time step refined with the spacing unless the method gives one)."""
    if method.dt is None and method.n_steps is None:
        method = dataclasses.replace(method, dt=DISCRETE_STEP_PER_SPACING * method.dx / path.speed)
    paths = Paths.named_by([path], model.motion.d_max, model.motion.v)
    return simulate(model.contact, paths, method, limits=limits).isel(case=0)


def discrete_quantities(model: ModelJob, path: Path, method: Discrete, limits: Limits,
                        history_times: np.ndarray | None) -> tuple[dict[str, float], np.ndarray | None]:
    """A run's quantities read off the discrete model's samples, and its history at ``history_times``."""
    run = _discrete_run(model, path, method, limits)
    times = run["time"].values
    quantities = {name: run[name].values for name in ("normal_force", "tangential_force", "contact_area",
                                                      "sliding_fraction")}
    contact = np.nan_to_num(quantities["contact_area"]) > 0
    found = candidate_events(times, quantities, contact, model.params)
    start = path.first_contact_time()
    depth = run["indentation_depth"].values
    deepest = deepest_time(path)
    sliding_now = sliding_samples(quantities["sliding_fraction"]).partly
    sliding = np.flatnonzero(sliding_now & ~np.concatenate([[False], sliding_now[:-1]]))  # onsets: sliding, not before
    path_times = times + start
    onset_in = sliding[path_times[sliding] <= deepest]
    onset_out = sliding[path_times[sliding] > deepest]
    lost = found["last_in_contact"] + 1 if found["last_in_contact"] >= 0 else -1
    x = run["tangential_displacement"].values
    finite = np.isfinite(quantities["tangential_force"]) & np.isfinite(x)
    history = None if history_times is None else np.array(
        [np.interp(history_times, path_times, np.nan_to_num(run[name].values), left=0.0, right=math.nan)
         for name in HISTORY_QUANTITIES])
    return {
        "normal_force_min": float(np.nanmin(quantities["normal_force"])),
        "tangential_force_max": float(np.nanmax(np.abs(quantities["tangential_force"]))),
        "contact_area_max": float(np.nanmax(quantities["contact_area"])),
        "slip_onset_in_time": float(path_times[onset_in[0]]) if onset_in.size else math.nan,
        "slip_onset_in_depth": float(depth[onset_in[0]]) if onset_in.size else math.nan,
        "slip_onset_out_time": float(path_times[onset_out[0]]) if onset_out.size else math.nan,
        "slip_onset_out_depth": float(depth[onset_out[0]]) if onset_out.size else math.nan,
        "full_slip_time": found["full_slip"] + start if math.isfinite(found["full_slip"]) else math.nan,
        "pull_off_time": found["pull_off"] + start if math.isfinite(found["pull_off"]) else math.nan,
        "pull_off_depth": float(depth[lost]) if lost >= 0 else math.nan,
        "pull_off_force": found["pull_off_force"],
        "tangential_work": float(np.trapezoid(quantities["tangential_force"][finite], x[finite])),
        "event_count": float(sum(math.isfinite(found[k]) for k in ("slip_onset", "full_slip", "detachment_starts",
                                                                    "pull_off"))),
    }, history


#: A run's quantities and history by the method's name.
#: What a method's quantities take beyond what the method does, by its name: the continuum's read the spans of
#: ``solve_path`` (the branches of an edge rule) or a law's own run (:data:`CONTINUUM_QUANTITIES`, the rate-dependent
#: law's, which takes ``τ0``'s cap alone: ``rate_sweep.check_rate_sweep_run``), so a law with neither is refused
#: before the sweep runs.
METHOD_CHECKS: dict[str, Callable[[ModelJob], None]] = {
    "continuum": lambda model: (check_rate_sweep_run(model) if type(model.adhesion) in CONTINUUM_QUANTITIES
                                else check_edge_known(model.adhesion))}

METHOD_QUANTITIES: dict[str, Callable[..., tuple[dict[str, float], np.ndarray | None]]] = {
    Continuum.name: continuum_quantities, Discrete.name: discrete_quantities}


class ChunkResult(NamedTuple):
    """The quantities of a chunk's runs (runs × :data:`QUANTITIES`, ``nan`` where a run failed) and each run's
    error (``""``: it ran)."""

    values: np.ndarray
    errors: list[str]
    histories: np.ndarray | None = None  #: runs × :data:`HISTORY_QUANTITIES` × samples (``history_samples``)


def run_chunk(spec: SweepSpec, rows: np.ndarray) -> ChunkResult:
    """Run every row (the swept names' values) of a chunk; a run that raises is recorded, not raised."""
    values = np.full((len(rows), len(spec.quantities)), np.nan)
    histories = None if not spec.history_samples else \
        np.full((len(rows), len(HISTORY_QUANTITIES), spec.history_samples), np.nan)
    errors = []
    for i, row in enumerate(rows):
        try:
            out, history = spec.run(row)
            values[i] = list(out.values())
            if histories is not None:
                histories[i] = history
            errors.append("")
        except Exception as error:  # noqa: BLE001 - a failed run is a result of the sweep, recorded with its error
            errors.append(f"{type(error).__name__}: {error}"[:ERROR_CHARACTERS])
    return ChunkResult(values, errors, histories)
