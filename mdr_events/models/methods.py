"""The method as a value: how a simulation is computed, looked up by name with its options.

=================  ======================================  =====================================================
name               class                                   options
=================  ======================================  =====================================================
``"discrete"``     :class:`Discrete`: the paper's springs  ``dx`` (spacing), ``dt`` or ``n_steps`` (time step)
``"continuum"``    :class:`Continuum`: their Δx → 0 limit  ``tolerances``, ``samples`` or ``t`` (output times)
=================  ======================================  =====================================================

As ``solve_ivp`` maps a method's name to a class and forwards its options, :func:`as_method` makes the class of a
name with the options given beside it; each class checks its own options when made, so that no option is checked
against another method's. A new method is one class here with its options as fields, ``check_model``,
``simulate`` (both take the :class:`~mdr_events.models.job.ModelJob`) and its entry in :data:`METHODS`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any, Callable, ClassVar, Mapping, NamedTuple

import numpy as np
import xarray as xr

from mdr_events.contact.adhesion import RateDependentAdhesion, adhesion_attrs
from mdr_events.contact.friction import FrictionLaw, friction_attrs
from mdr_events.contact.model import Contact
from mdr_events.limits import DEFAULT_LIMITS, Limits, ResourceLimitError, values_in
from mdr_events.models import indenters
from mdr_events.models.continuum import PathSolution, Tolerances, run_continuum, solve_path
from mdr_events.models.continuum.rate_reference import RateSolution, solve_rate_reference
from mdr_events.models.continuum.tolerances import check_output, check_tolerances
from mdr_events.models.continuum.edges import check_edge_known
from mdr_events.models.continuum.play_run import run_play_springs, takes_play_springs
from mdr_events.models.continuum.rate_run import check_rate_layer, run_rate_continuum
from mdr_events.models.continuum.rate_coulomb import check_rate_friction_law, run_rate_coulomb, takes_rate_coulomb
from mdr_events.models.continuum.extrema import solution_extrema
from mdr_events.models.continuum.solve import BYTES_PER_SAMPLE as CONTINUUM_BYTES_PER_SAMPLE
from mdr_events.models.discrete import BYTES_PER_SAMPLE as DISCRETE_BYTES_PER_SAMPLE
from mdr_events.models.kernel_model import KernelModel
from mdr_events.models.discrete import check_spacing, check_thresholds_known, run_discrete
from mdr_events.models.job import ModelJob
from mdr_events.models.motion import Cases
from mdr_events.models.paths import Path
from mdr_events.models.simulation_schema import SIMULATION_CONTENT, continuum_dataset, simulation_dataset
from mdr_events.theory.kinds import theory_of
from mdr_events.theory.layer.punch_onset import check_punch_face
from mdr_events.validation import MAX_COUNT, allowed_bound, as_name, check_count, check_output_times, check_real, shown

__all__ = ["Discrete", "Continuum", "Method", "METHODS", "as_method", "check_counted_first", "check_time_step",
           "DEFAULT_DX", "DEFAULT_STEPS", "DEFAULT_SAMPLES", "MIN_STEPS_PER_SEGMENT", "exact_solution",
           "check_exact_solution"]

DEFAULT_DX = 1e-6
DEFAULT_STEPS = 10_000
DEFAULT_SAMPLES = 2001
#: The discrete model needs at least this many time steps on every path segment it is in contact on.
MIN_STEPS_PER_SEGMENT = 10


@dataclass(frozen=True)
class Discrete:
    """The paper's spring array (:mod:`mdr_events.models.discrete`).

    Parameters
    ----------
    dx : float, default 1e-6
        Spring spacing Δx in m (default 1 µm); at least 10 springs per side must be in contact at ``d_max``.
    dt : float, optional
        Time step in s; or
    n_steps : int, optional
        the number of steps of the longest case (default 10 000); not both. One time grid serves every case.

    Raises
    ------
    ValueError
        ``dt`` and ``n_steps`` both given, a spacing or step that is not > 0, fewer than 10 steps.
    """

    name: ClassVar[str] = "discrete"
    #: Whether the method runs a layer of finite thickness (``Contact.layer``): the springs of the generalized MDR.
    takes_layers: ClassVar[bool] = True
    dx: float = DEFAULT_DX
    dt: float | None = None
    n_steps: int | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "dx", check_real("dx", self.dx, "a spacing > 0 (m)", lambda value: value > 0))
        if self.dt is not None and self.n_steps is not None:
            raise ValueError(f"dt={shown(self.dt)} and n_steps={shown(self.n_steps)} are not allowed together; allowed: "
                             "one of them (give dt or n_steps, not both)")
        if self.dt is not None:
            object.__setattr__(self, "dt", check_real("dt", self.dt, "a finite time step > 0 (s)",
                                                      lambda value: value > 0))
        if self.n_steps is not None:
            object.__setattr__(self, "n_steps", check_count("n_steps", self.n_steps, 10))

    def check_model(self, model: ModelJob) -> None:
        """Refuse an adhesion law the springs have no thresholds for
        (:func:`~mdr_events.models.discrete.spring_thresholds`); they take every indenter and friction law.

        Parameters
        ----------
        model : ModelJob
            The contact along its motion, with the flat values the kernels take.

        Raises
        ------
        TypeError
            An adhesion law without the springs' thresholds.
        """
        check_thresholds_known(model.adhesion)

    def check_layer(self, contact: Contact) -> None:
        """Every friction law runs on a layer (what the springs take:
        :meth:`~mdr_events.models.spring_media.LayerSprings.check`); a flat punch's face within the layer's tables,
        refused beyond them in the continuum's words
        (:func:`~mdr_events.theory.layer.punch_onset.check_punch_face`; round twenty-three: ``--h 1e-9`` under a
        1 mm punch raised numpy's "attempt to get argmin of an empty sequence" from the springs' count, a face just
        beyond the tables was told "a smaller dx", which cannot help).

        Parameters
        ----------
        contact : Contact
            The physical model, on a layer of finite thickness.

        Raises
        ------
        ValueError
            A flat punch whose face exceeds ``a/h = 64``.
        """
        if theory_of(contact.profile).flat_face:  # (its contact radius is the face's from the first touch on)
            check_punch_face(contact.profile, contact.layer, "the discrete method")

    def check_case_count(self, count: int, limits: Limits) -> None:
        """The least a run of ``count`` cases takes, checked before they are built (a million angles were built, for
        minutes and a GiB, before the run's own check): without ``dt``, the shared time grid's ``n_steps + 1``
        samples per case, as ``models.discrete.check_discrete_size`` counts them.

        Parameters
        ----------
        count : int
            The cases of the motion (``case_count`` of a Scenario or Paths).
        limits : Limits
            What the run may use.

        Raises
        ------
        ResourceLimitError
            The steps, the output times or the memory of ``count`` cases beyond ``limits``.
        """
        if self.dt is None:
            n_time = (DEFAULT_STEPS if self.n_steps is None else self.n_steps) + 1
            limits.check(f"the discrete run ({count} case(s) of {n_time} time steps)", steps=count * n_time,
                         samples=count * n_time,  # (each step is an output time)
                         memory=count * n_time * DISCRETE_BYTES_PER_SAMPLE)

    def simulate(self, model: ModelJob, cases: Cases, limits: Limits) -> xr.Dataset:
        """Run the cases with the springs; the dataset of :mod:`~mdr_events.models.simulation_schema` with the
        attributes ``dx``, ``dt`` and ``spring_count_per_side`` (on a layer of finite thickness also
        ``param_layer_thickness`` and ``param_layer_base``).

        Parameters
        ----------
        model : ModelJob
            The contact along its motion, with the flat values the kernels take.
        cases : Cases
            The paths to run, one per case, and their labels.
        limits : Limits
            The most springs, steps and memory a run may take.

        Returns
        -------
        xarray.Dataset
            The time series of every case on one time grid from first contact.

        Raises
        ------
        ValueError
            A path that never touches the surface, a spacing too coarse for 10 springs per side in contact, or a
            time step that gives a path segment in contact fewer than :data:`MIN_STEPS_PER_SEGMENT` steps.
        """
        self.check_model(model)
        params, profile, friction, layer = model.params, model.profile, model.friction, model.contact.layer
        paths = cases.paths
        for path in paths:
            path.first_contact_time()  # a path that never touches the surface is an error first
        dx = check_spacing(params, self.dx, depth=min(params.d_max, max(path.max_depth for path in paths)),
                           profile=profile, layer=layer)
        step = self._time_step(paths)
        check_time_step(paths, step, self.dt, self.n_steps)
        raw = run_discrete(model.kernel, paths, dx, step, limits)
        # (the half-space stamps no layer, as Contact.to_attrs: its results are those of before)
        layer_attrs = {} if layer.is_half_space else layer.to_attrs()
        attrs = dict(method=self.name, scenario=model.scenario, dx=float(dx), dt=step,
                     spring_count_per_side=int(raw["spring_count"]), content=SIMULATION_CONTENT,
                     **indenters.profile_attrs(profile), **friction_attrs(friction), **adhesion_attrs(model.adhesion),
                     **layer_attrs)
        return simulation_dataset(params, cases, raw["time"], raw, **attrs)

    def _time_step(self, paths: list[Path]) -> float:
        if self.dt is not None:
            return self.dt
        longest = max(path.duration - path.first_contact_time() for path in paths)
        return longest / (DEFAULT_STEPS if self.n_steps is None else self.n_steps)


def check_time_step(paths: list[Path], step: float, dt: float | None, n_steps: int | None) -> None:
    """Reject a time step that cannot resolve a path segment after first contact.

    Every segment (from first contact on) must get :data:`MIN_STEPS_PER_SEGMENT`
    steps; otherwise, e.g. for a tiny ``d_max``, the discrete model would jump
    over the whole indentation. The error names the largest ``dt`` (or the
    smallest ``n_steps``) that would do. A ``dt`` so small that the longest case's steps are more than
    :data:`~mdr_events.validation.MAX_COUNT` (``inf`` beyond the doubles) is refused naming the least ``dt``.
    """
    longest = max(path.duration - path.first_contact_time() for path in paths)
    count = longest / step
    if dt is not None and not count <= MAX_COUNT:  # (round twenty-one: dt=5e-324 gave int(inf), an internal error)
        raise ValueError(f"dt={shown(dt)} is not allowed: the longest case's {longest:.6g} s from first contact would "
                         f"take {count:.3g} steps; allowed: a time step in s >= "
                         f"{allowed_bound(longest / MAX_COUNT, lambda least: longest / least <= MAX_COUNT, False, 3)} "
                         "(at most "
                         f"{MAX_COUNT:.0e} steps, which the limits refuse long before: --limit steps)")
    shortest = math.inf
    for path in paths:
        start = path.first_contact_time()
        times = path.corner_times
        for t0, t1 in zip(times[:-1], times[1:]):
            if t1 > start:
                shortest = min(shortest, t1 - max(t0, start))
    largest = shortest / MIN_STEPS_PER_SEGMENT

    def fine_enough(value: float) -> bool:
        return value <= largest * (1 + 1e-12)

    if fine_enough(step):
        return
    most = allowed_bound(largest, fine_enough, True)
    if dt is not None:
        raise ValueError(f"dt={shown(dt)} is too coarse: the shortest path segment in contact lasts {shortest:.6g} s; "
                         f"allowed: dt <= {most} s ({MIN_STEPS_PER_SEGMENT} steps per segment)")
    needed = math.ceil(longest / largest)
    given = DEFAULT_STEPS if n_steps is None else n_steps
    raise ValueError(f"n_steps={shown(given)} is too few: the shortest path segment in contact lasts {shortest:.6g} s of "
                     f"{longest:.6g} s; allowed: n_steps >= {needed} (or dt <= {most} s)")


@dataclass(frozen=True, eq=False)
class Continuum:
    """The springs' Δx → 0 limit integrated between events (:mod:`mdr_events.models.continuum`): exact to its
    tolerances, with the event log and each case's exact extrema.

    Parameters
    ----------
    tolerances : Tolerances, default Tolerances()
        Solver and root-finding tolerances (default ``rtol = 1e-10``, ``atol = 1e-14`` N, ``radius_rtol = 1e-14``).
    samples : int, optional
        Without ``t``: the number of output times to the end of the longest run (default 2001, at least 2).
    t : sequence of float, optional
        The output times in s from first contact (increasing, >= 0), counted first: as many as one case may have
        within the default :class:`~mdr_events.Limits` are read, checked and kept as a read-only copy here (the
        caller's array may change after); more are kept as given and read when a run starts, after their count is
        checked against the run's limits (:meth:`output_times`; round twenty-three:
        ``Continuum(t=np.broadcast_to(0.1, (10**9,)))`` was read here, 16 GB before any limit).

    Raises
    ------
    TypeError
        ``tolerances`` that are not a :class:`~mdr_events.Tolerances`.
    ValueError
        ``t`` and ``samples`` both given, fewer than 2 samples, or times not finite, >= 0 and strictly increasing
        (times beyond the default limits: when a run reads them, :meth:`output_times`).
    """

    name: ClassVar[str] = "continuum"
    #: Whether the method runs a layer of finite thickness (``Contact.layer``): the springs' stiffness varying with
    #: ``ξ`` (:mod:`~mdr_events.models.continuum.media`), Coulomb's part there without adhesion (spring by spring).
    takes_layers: ClassVar[bool] = True
    tolerances: Tolerances = Tolerances()
    samples: int | None = None
    t: np.ndarray | None = None

    def __post_init__(self) -> None:
        check_tolerances(self.tolerances)
        if self.samples is not None and self.t is not None:  # (t was used and samples ignored)
            raise ValueError(f"t={shown(self.t)} and samples={shown(self.samples)} are not allowed together; allowed: "
                             "one of them (give t or samples, not both)")
        object.__setattr__(self, "samples", DEFAULT_SAMPLES if self.samples is None else
                           check_count("samples", self.samples, 2))
        if self.t is not None and self._within_default_limits():  # (a copy: the caller's array may change)
            object.__setattr__(self, "t", check_output_times("t", self.t))

    def _within_default_limits(self) -> bool:
        """Whether one case of the times ``t``, counted (not read), is within :data:`DEFAULT_LIMITS`."""
        try:
            self.check_case_count(1, DEFAULT_LIMITS)
        except ResourceLimitError:
            return False
        return True

    def __repr__(self) -> str:  # (its times as a message shows them: a long list is not written out)
        times = "" if self.t is None else f", t={shown(self.t)}"
        return f"Continuum(tolerances={self.tolerances!r}, samples={self.samples!r}{times})"

    def __eq__(self, other) -> bool:  # (its output times are an array: compared by value)
        if not isinstance(other, Continuum):
            return NotImplemented
        same_times = (self.t is None) == (other.t is None) and (self.t is None or np.array_equal(self.t, other.t))
        return self.tolerances == other.tolerances and self.samples == other.samples and same_times

    __hash__ = None

    def check_model(self, model: ModelJob) -> None:
        """Refuse what the continuum does not take: an adhesion law without a run or an edge rule
        (:func:`continuum_kernel`), and the friction laws its run does not take (the rate-dependent law's takes every
        one: ``"tau0"`` by the closed-form play, Coulomb's part spring by spring,
        :mod:`~mdr_events.models.continuum.rate_coulomb`).

        Parameters
        ----------
        model : ModelJob
            The contact along its motion, with the flat values the kernels take.

        Raises
        ------
        TypeError
            An adhesion law without a run.
        ValueError
            What the layer's check refuses.
        """
        continuum_kernel(model.adhesion).check(model.friction, model.adhesion)
        self.check_layer(model.contact)

    def check_layer(self, contact: Contact) -> None:
        """Every friction law runs on a layer, with or without adhesion: ``"tau0"`` on the spans, Coulomb's part
        spring by spring (:mod:`~mdr_events.models.continuum.play_run`; the flat punch's springs ``g = 0`` under its
        face, ``spring_factors`` of :class:`~mdr_events.models.continuum.layer_normals.PunchNormal`); what the layer's
        springs take (the paraboloid, a power law or the flat punch, its face within the tables) is checked where they
        are made (:mod:`~mdr_events.models.continuum.layer_reach`), so nothing is refused here.

        Parameters
        ----------
        contact : Contact
            The physical model.
        """

    def check_case_count(self, count: int, limits: Limits) -> None:
        """The output a run of ``count`` cases takes, checked before they are built, as
        :func:`~mdr_events.models.continuum.run_continuum` counts it (``samples`` or the times ``t`` per case).

        Parameters
        ----------
        count : int
            The cases of the motion (``case_count`` of a Scenario or Paths).
        limits : Limits
            What the run may use.

        Raises
        ------
        ResourceLimitError
            The output times or the memory of ``count`` cases beyond ``limits``.
        """
        n_time = self.samples if self.t is None else values_in(self.t)  # (counted, not read)
        check_output(limits, count, n_time, CONTINUUM_BYTES_PER_SAMPLE)

    def output_times(self, count: int, limits: Limits) -> np.ndarray | int:
        """The run's output times: ``samples``, or the times ``t`` read (checked: finite, >= 0, strictly increasing)
        once the run of ``count`` cases with as many times is within ``limits`` (:meth:`check_case_count`).

        Parameters
        ----------
        count : int
            The cases of the run.
        limits : Limits
            What the run may use.

        Returns
        -------
        numpy.ndarray or int
            The times (read-only), or the number of samples to the end of the longest run.

        Raises
        ------
        ResourceLimitError
            The output beyond ``limits``.
        ValueError, TypeError
            Times that are not a strictly increasing 1-D grid of finite times >= 0, naming ``t``.
        """
        self.check_case_count(count, limits)
        return self.samples if self.t is None else check_output_times("t", self.t)

    def simulate(self, model: ModelJob, cases: Cases, limits: Limits) -> xr.Dataset:
        """Solve the cases exactly; the dataset of :mod:`~mdr_events.models.simulation_schema` with the event log,
        the extrema and the attributes ``rtol``, ``atol`` and ``radius_rtol``.

        Parameters
        ----------
        model : ModelJob
            The contact along its motion, with the flat values the kernels take.
        cases : Cases
            The paths to solve, one per case, and their labels.
        limits : Limits
            The most waypoints and samples a run may take.

        Returns
        -------
        xarray.Dataset
            The time series of every case at the output times from first contact, the events and the extrema.
        """
        self.check_model(model)
        params, profile, friction = model.params, model.profile, model.friction
        tolerances = self.tolerances
        layer = model.contact.layer
        run = continuum_kernel(model.adhesion).run
        raw = run(model.kernel, cases.paths, self.output_times(len(cases.paths), limits), tolerances, limits)
        # (the half-space stamps no layer, as Contact.to_attrs: its results are those of before)
        layer_attrs = {} if layer.is_half_space else layer.to_attrs()
        attrs = dict(method=self.name, scenario=model.scenario,
                     rtol=tolerances.rtol, atol=tolerances.atol, radius_rtol=tolerances.radius_rtol,
                     content=SIMULATION_CONTENT, **indenters.profile_attrs(profile), **friction_attrs(friction),
                     **adhesion_attrs(model.adhesion), **layer_attrs)
        return continuum_dataset(params, cases, raw["time"], raw, raw["events"], raw["extrema"], **attrs)


def _paper_run(model: KernelModel, paths, times, tolerances, limits) -> dict:
    """The paper's law (:func:`~mdr_events.models.continuum.solve.run_continuum`) with each run's exact extrema, on
    the half-space or the layer."""
    if takes_play_springs(model):  # (Coulomb's part on a layer: each spring its own play operator)
        return run_play_springs(model, paths, times, tolerances, limits)
    raw = run_continuum(model, paths, times, tolerances, limits)
    raw["extrema"] = [solution_extrema(solution) for solution in raw["solutions"]]
    return raw


class ContinuumKernel(NamedTuple):
    """How the continuum runs an adhesion law: the run, the check of the friction law it takes (given the friction
    law and the adhesion law, which a refusal names), the exact solution of one path a referee reads
    (:func:`exact_solution`) and the check of the friction law that solution takes (given the two laws and the
    referee's name: :func:`check_exact_solution`)."""

    run: Callable[..., dict]
    check: Callable[[FrictionLaw, object], None]
    solve: Callable[..., object]
    check_solve: Callable[[FrictionLaw, object, str], None]


def _every_friction_law(friction: FrictionLaw, adhesion: object, caller: str = "") -> None:
    """The paper's edge takes every friction law (in its runs and its exact solution)."""


def _rate_reference_friction(friction: FrictionLaw, adhesion: object, caller: str) -> None:
    """The rate law's exact solution of one path (:func:`_rate_solution`) holds τ0's cap alone: Coulomb's part refused
    in one line naming ``caller``, both laws and what runs them."""
    if takes_rate_coulomb(friction):
        raise ValueError(f"friction={friction!r} is not allowed in {caller} with adhesion={adhesion!r}: its reference, "
                         "the rate law's continuum at the candidate's times, holds tau0's cap alone (Coulomb's part "
                         "gives each spring its own cap); allowed: FrictionLaw('tau0') (Coulomb's part under this law: "
                         "simulate(..., method='continuum') runs it)")


def _rate_run(model: KernelModel, paths, times, tolerances, limits) -> dict:
    """The rate-dependent edge with the springs on top
    (:func:`~mdr_events.models.continuum.rate_run.run_rate_continuum`; Coulomb's part spring by spring,
    :func:`~mdr_events.models.continuum.rate_coulomb.run_rate_coulomb`), on the half-space alone: a layer of finite
    thickness is refused here by name (:func:`~mdr_events.models.continuum.rate_run.check_rate_layer`), as
    ``simulate.check_layer_taken`` refuses it before (the layer's springs take the paper's law)."""
    check_rate_layer(model.layer)
    run = run_rate_coulomb if takes_rate_coulomb(model.friction) else run_rate_continuum
    return run(model.params, paths, times, tolerances, limits, model.profile, model.friction, model.adhesion)


def _paper_solution(model: KernelModel, path: Path, tolerances: Tolerances, limits: Limits) -> PathSolution:
    """The paper's law: :func:`~mdr_events.models.continuum.solve.solve_path` on the contact's body."""
    return solve_path(model.params, path, tolerances, limits, model.profile, model.friction, layer=model.layer)


def _rate_solution(model: KernelModel, path: Path, tolerances: Tolerances, limits: Limits) -> RateSolution:
    """The rate-dependent law: the run of ``simulate``'s continuum method
    (:func:`~mdr_events.models.continuum.rate_reference.solve_rate_reference`), on the half-space alone."""
    check_rate_layer(model.layer)
    return solve_rate_reference(model.params, path, model.adhesion, tolerances, model.profile, model.friction)


#: The runs of the adhesion laws whose radius is not on the branches of an edge rule (the continuum's
#: ``EDGE_RULES``), by their type: the rate-dependent edge an ODE state with the springs on top
#: (:mod:`~mdr_events.models.continuum.rate_run`; Coulomb's part spring by spring,
#: :mod:`~mdr_events.models.continuum.rate_coulomb`), which takes every friction law; its reference for ``validate``
#: (:mod:`~mdr_events.models.continuum.rate_reference`) takes ``"tau0"`` alone.
CONTINUUM_RUNS: dict[type, ContinuumKernel] = {RateDependentAdhesion: ContinuumKernel(_rate_run, check_rate_friction_law,
                                                                                      _rate_solution,
                                                                                      _rate_reference_friction)}


def continuum_kernel(adhesion) -> ContinuumKernel:
    """How the continuum runs ``adhesion``: its own run (:data:`CONTINUUM_RUNS`), else the spans on the branches of
    its edge rule (:func:`~mdr_events.models.continuum.edges.check_edge_known` refuses a law without one, by name).

    Parameters
    ----------
    adhesion : Adhesion or RateDependentAdhesion
        The law.

    Returns
    -------
    ContinuumKernel
        The run and the check of the friction law.

    Raises
    ------
    TypeError
        A law without a run or an edge rule.
    """
    kernel = CONTINUUM_RUNS.get(type(adhesion))
    if kernel is None:
        check_edge_known(adhesion)
        kernel = ContinuumKernel(_paper_run, _every_friction_law, _paper_solution, _every_friction_law)
    return kernel


def exact_solution(model: ModelJob, path: Path, tolerances: Tolerances, limits: Limits) -> PathSolution | RateSolution:
    """The continuum's exact solution of ``path`` for ``model``'s contact, by its adhesion law
    (:func:`continuum_kernel`): the paper's :class:`~mdr_events.models.continuum.solution.PathSolution`, the
    rate-dependent law's :class:`~mdr_events.models.continuum.rate_reference.RateSolution`; both answer a referee by
    the same names (``evaluate_at``, ``normal_force_at``, ``events``, ``end_time``).

    Parameters
    ----------
    model : ModelJob
        The contact along its motion.
    path : Path
        The one path solved.
    tolerances : Tolerances
        The continuum's tolerances.
    limits : Limits
        What the run may use.

    Returns
    -------
    PathSolution or RateSolution
        The solution.

    Raises
    ------
    ValueError, TypeError
        What the law's continuum refuses.
    """
    return continuum_kernel(model.adhesion).solve(model.kernel, path, tolerances, limits)


def check_exact_solution(model: ModelJob, caller: str) -> None:
    """Refuse, before anything is read or solved, a friction law that :func:`exact_solution` does not take for
    ``model``'s adhesion law (under the rate-dependent law, Coulomb's part), in one line naming ``caller``.

    Parameters
    ----------
    model : ModelJob
        The contact along its motion.
    caller : str
        The referee (e.g. ``"validate"``), named in the refusal.

    Raises
    ------
    ValueError
        A friction law the law's exact solution does not take.
    """
    continuum_kernel(model.adhesion).check_solve(model.friction, model.adhesion, caller)


#: A method.
Method = Discrete | Continuum
#: The methods by name.
METHODS: dict[str, type] = {"discrete": Discrete, "continuum": Continuum}


def as_method(method, options: Mapping[str, Any] | None = None) -> Method:
    """``method`` as a method value: a name of :data:`METHODS` made with ``options`` (those given as ``None`` are
    left to the method's defaults), or a method as it is (no options beside it).

    Raises
    ------
    ValueError
        An unknown name, or an option the method does not take (naming the method's own), or options beside a
        method value.
    """
    given = {name: value for name, value in (options or {}).items() if value is not None}
    if isinstance(method, (Discrete, Continuum)):
        if given:
            raise ValueError(f"{', '.join(given)} is not allowed beside method={method!r}; allowed: the method's own "
                             "options")
        return method
    method = as_name(method)
    if not isinstance(method, str) or method not in METHODS:
        raise ValueError(f"method={shown(method)} is not allowed; allowed: {', '.join(map(repr, METHODS))}, or a "
                         "Discrete or Continuum")
    kind = METHODS[method]
    own = [field.name for field in fields(kind)]
    for name in given:
        if name not in own:
            raise ValueError(f"{name} is not allowed with method={method!r}; allowed: {', '.join(own)}")
    return kind(**given)


def check_counted_first(method, options: Mapping[str, Any], count: int, limits: Limits) -> None:
    """The run of ``count`` cases by ``method`` (a name with ``options``, or a method) checked against ``limits``
    before its grids are read: the continuum's output times ``t`` counted (:func:`~mdr_events.limits.values_in`),
    not converted (round twenty-two: 1e8 times were copied ~3 times, 2.4 GB, before the count refused them). The
    caller counts the cases likewise, before the angles are read; ``count`` may be a lower bound (the limits grow
    with it), the exact count checked again once the motion is built (``check_case_count``).

    Parameters
    ----------
    method : str, Discrete or Continuum
        The method, by name or as a value.
    options : mapping of str to object
        The method's options beside its name.
    count : int
        The cases of the run, or fewer.
    limits : Limits
        What the run may use.

    Raises
    ------
    ResourceLimitError
        The output times or the memory of the run beyond ``limits``.
    ValueError
        What :func:`as_method` refuses.
    """
    times = options.get("t")
    if isinstance(method, str) and method == Continuum.name and times is not None:
        check_output(limits, count, values_in(times), CONTINUUM_BYTES_PER_SAMPLE)
    else:
        as_method(method, options).check_case_count(count, limits)
