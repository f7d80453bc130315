"""The typed jobs both front ends build: one frozen spec per verb, whose ``run`` calls the library and writes its files.

The command line (:mod:`mdr_events.app.cli`, one module per verb) turns its options into a job, and a study file
(:mod:`mdr_events.app.study`) its tables, through the same parsers (:mod:`mdr_events.app.inputs`); for the same input
both build equal jobs, which differ only in the stem of the files they write. A job holds the package's values
(:class:`~mdr_events.Contact`, :class:`~mdr_events.Scenario` or :class:`~mdr_events.Paths`, :class:`~mdr_events.Discrete`
or :class:`~mdr_events.Continuum`, :class:`~mdr_events.Limits`), checked when it was built.

=================  ===============================  ==========================================================
verb               job                              library
=================  ===============================  ==========================================================
``derive``         :class:`DeriveJob`               :mod:`mdr_events.theory.symbolic`
``phase-diagram``  :class:`PhaseJob`                :func:`~mdr_events.phase_diagram`
``simulate``       :class:`SimulateJob`             :func:`~mdr_events.simulate`
``validate``       :class:`ValidateJob`             :func:`~mdr_events.validate`, ``convergence_study``
``fit``            :class:`FitJob`                  :func:`~mdr_events.fit`
``fit`` (rate)     :class:`RateFitJob`              :func:`~mdr_events.fit_rate_adhesion`
``sweep``          :class:`SweepJob`                :func:`~mdr_events.sweep`
``reproduce``      :class:`ReproduceJob`            :func:`mdr_events.reproduction.reproduce`
``lammps-check``   :class:`LammpsCheckJob`          :func:`mdr_events.dem.lammps_check`
=================  ===============================  ==========================================================

A job that reads measured runs (:class:`ValidateJob`, :class:`FitJob`) computes first (``compute``: everything read
and checked, the files rendered) and writes after (``write``), so that a front end can read every input before it
writes anything; ``run`` does both. A job's ``plans`` are its files planned, not written
(:class:`~mdr_events.app.result_files.PlannedFile`): a study commits every job's at once
(:func:`~mdr_events.app.result_files.commit_all`), so that its files are replaced together or not at all.
"""

from __future__ import annotations

import dataclasses
import importlib
import math
from dataclasses import dataclass, field
from pathlib import Path as FilePath
from typing import TYPE_CHECKING, Any, Callable, Mapping, NamedTuple

from mdr_events.limits import DEFAULT_LIMITS

# What a job computes with is imported when it runs (a verb of the command line loads only what it needs).
if TYPE_CHECKING:
    import xarray as xr

    from mdr_events.analysis.executors import Engine
    from mdr_events.analysis.fit import FitResult
    from mdr_events.analysis.sweep import SweepOutput
    from mdr_events.app.result_files import FileOutcome, PlannedFile
    from mdr_events.contact import Contact
    from mdr_events.limits import Limits
    from mdr_events.models.methods import Method
    from mdr_events.models.motion import Motion
    from mdr_events.app.validation_files import RenderedReport

__all__ = ["DeriveJob", "PhaseJob", "SimulateJob", "ValidateJob", "Convergence", "FitJob", "RateFitJob", "SweepJob", "ReproduceJob",
           "LammpsCheckJob", "Job", "CONVERGENCE_MODULE", "CONVERGENCE_STEM", "DECK_SUFFIX"]

Progress = Callable[[str], None]

#: Where :class:`ValidateJob` finds the convergence study (optional: skipped while the module is missing).
CONVERGENCE_MODULE = "mdr_events.analysis.convergence_study"
#: The file stem of the convergence study.
CONVERGENCE_STEM = "convergence_study"


def _quiet(message: str) -> None:
    """A progress callback that says nothing."""


@dataclass(frozen=True)
class DeriveJob:
    """Print the relations SymPy derives (``mdr-events derive``): each, or the one of ``key``, pretty or LaTeX."""

    latex: bool = False
    key: str | None = None

    def run(self, out: FilePath | None = None, progress: Progress = _quiet) -> None:
        """Print the relations on stdout."""
        from mdr_events.theory import symbolic

        keys = list(symbolic.relations()) if self.key is None else [self.key]
        for key in keys:
            rel = symbolic.relation(key)
            number = f" {rel.equation}" if rel.equation else ""
            print(f"# {rel.key}{number}: {rel.title}")
            print(rel.latex() if self.latex else rel.pretty())
            print()


@dataclass(frozen=True)
class PhaseJob:
    """The phase diagram of a scenario (Fig. 9a/9b) for a contact; written as ``<stem>.nc`` and ``<stem>.png``. Under
    the rate-dependent adhesion law (``speeds`` given) the scenario's critical angle against the speed, ``<stem>.nc``.

    Attributes
    ----------
    contact : Contact
        The physical model.
    scenario : {"A", "B"}
        The scenario.
    d_max, v : float
        The depth and speed the diagram is drawn for (m, m/s).
    provenance : mapping
        Attributes every written result carries (which parameters came from a preset).
    stem : str
        The files' stem.
    speeds : tuple of float, optional
        Under the rate-dependent law, the speeds (m/s) of its critical angles; ``None`` for the paper's law.
    """

    contact: Contact
    scenario: str
    d_max: float
    v: float
    provenance: Mapping[str, str] = field(default_factory=dict)
    stem: str = "phase_diagram"
    speeds: tuple[float, ...] | None = None

    def compute_at_speeds(self) -> xr.Dataset:
        """Under a rate-dependent law: the scenario's critical angle at each of :attr:`speeds`
        (:func:`~mdr_events.critical_angles_at_speeds`, :func:`~mdr_events.critical_angles_B_at_speeds`), stamped
        with the contact (``Contact.from_attrs`` reads the law back)."""
        from mdr_events.analysis.rate_angles import critical_angles_at_speeds
        from mdr_events.analysis.rate_let_go import critical_angles_B_at_speeds
        from mdr_events.io.datasets import stamp

        angles = {"A": critical_angles_at_speeds, "B": critical_angles_B_at_speeds}[self.scenario]
        result = angles(self.contact, list(self.speeds), d_max=self.d_max)
        return stamp(result, self.contact.parameters(self.d_max, self.v), **self.contact.to_attrs(), **self.provenance)

    def compute(self) -> xr.Dataset:
        """The diagram: of the contact's layer where it has one (its slip onset is the layer's, and the paper's speed
        is stamped, as :func:`~mdr_events.phase_diagram` of a contact does); the half-space's of the flat record with
        the study's ``v`` (a study's ``[layer]`` had been dropped here, and the half-space's diagram written); under
        the rate law its angles against the speed (:meth:`compute_at_speeds`)."""
        from mdr_events.app.result_files import phase_diagram_with
        from mdr_events.theory.job import on_layer

        if self.speeds is not None:
            return self.compute_at_speeds()
        if on_layer(self.contact):
            return phase_diagram_with(self.contact, self.scenario, dict(self.provenance), d_max=self.d_max)
        return phase_diagram_with(self.contact.parameters(self.d_max, self.v), self.scenario, dict(self.provenance),
                                  profile=self.contact.profile,
                                  friction=dataclasses.replace(self.contact.friction, tau0=None))

    def plans(self, dataset: xr.Dataset, out: FilePath) -> list[PlannedFile]:
        """The computed diagram's files in ``out``, planned (:func:`~mdr_events.app.result_files.commit` writes
        them): ``<stem>.nc`` and ``<stem>.png``; under the rate law ``<stem>.nc`` alone."""
        from mdr_events.app.result_files import netcdf_plan, phase_diagram_plans

        if self.speeds is not None:
            return [netcdf_plan(dataset, FilePath(out) / f"{self.stem}.nc")]
        return phase_diagram_plans(dataset, out, self.stem)

    def run(self, out: FilePath, progress: Progress = _quiet) -> list[FileOutcome]:
        """Compute the diagram and write its files into ``out``, together."""
        from mdr_events.app.heartbeat import heartbeat
        from mdr_events.app.result_files import commit

        with heartbeat(progress, f"phase-diagram (scenario {self.scenario})"):
            return commit(self.plans(self.compute(), out))


@dataclass(frozen=True)
class SimulateJob:
    """A simulation: ``simulate(contact, motion, method)``; written as ``<stem>.nc``, ``.png`` (and the event log).

    Attributes
    ----------
    contact : Contact
    motion : Scenario or Paths
    method : Discrete or Continuum
    limits : Limits
    provenance : mapping
        Attributes the result carries.
    stem : str
        The files' stem.
    """

    contact: Contact
    motion: Motion
    method: Method
    limits: Limits = DEFAULT_LIMITS
    provenance: Mapping[str, str] = field(default_factory=dict)
    stem: str = "simulation"

    def compute(self) -> xr.Dataset:
        """The simulation, with the provenance attributes."""
        from mdr_events.models.simulate import simulate

        dataset = simulate(self.contact, self.motion, self.method, limits=self.limits)
        dataset.attrs.update(self.provenance)
        return dataset

    def plans(self, dataset: xr.Dataset, out: FilePath) -> list[PlannedFile]:
        """The simulation's files in ``out``, planned (:func:`~mdr_events.app.result_files.simulation_plans`)."""
        from mdr_events.app.result_files import simulation_plans

        return simulation_plans(dataset, out, self.stem)

    def write(self, dataset: xr.Dataset, out: FilePath) -> list[FileOutcome]:
        """Write the simulation into ``out``, its files together."""
        from mdr_events.app.result_files import commit

        return commit(self.plans(dataset, out))

    def run(self, out: FilePath, progress: Progress = _quiet) -> list[FileOutcome]:
        """Simulate and write (``progress`` told that it still runs, :func:`~mdr_events.app.heartbeat.heartbeat`)."""
        from mdr_events.app.heartbeat import heartbeat

        with heartbeat(progress, f"simulate ({self.stem})"):
            dataset = self.compute()
        return self.write(dataset, out)


class Convergence(NamedTuple):
    """A convergence study computed and drawn but not written, and the lines to print about it."""

    dataset: xr.Dataset | None
    png: bytes | None
    lines: list[str]


class Validated(NamedTuple):
    """What :meth:`ValidateJob.compute` gives: each run (as given) with its rendered report, and the convergence
    study (``None``: none was asked for)."""

    reports: list[tuple[str, RenderedReport]]
    convergence: Convergence | None


@dataclass(frozen=True)
class ValidateJob:
    """Runs of a simulator against the exact continuum: each written as ``<stem>.nc``, ``.md`` and ``.png``; with
    ``spacings`` also the convergence study over them.

    Attributes
    ----------
    runs : tuple of str
        The runs as given (their names in messages).
    files : tuple of pathlib.Path
        The files of the runs.
    stems : tuple of str
        The stem each run's report is written with.
    contact, motion
        The contact and the motion of the one path the runs took (a Scenario of one angle, or Paths of one path).
    description : str
        The path, for the report.
    tolerance : float
        The verdict's bound on each quantity's max error relative to its range.
    names, units, time_origin
        How to read the runs (:func:`~mdr_events.validate`).
    spacings : tuple of float, optional
        One spacing per run (m) for a convergence study.
    """

    runs: tuple[str, ...]
    files: tuple[FilePath, ...]
    stems: tuple[str, ...]
    contact: Contact
    motion: Motion
    description: str
    tolerance: float = 1e-3
    names: Mapping[str, str] = field(default_factory=dict)
    units: Mapping[str, str] = field(default_factory=dict)
    time_origin: str | float = "first_contact"
    limits: Limits = DEFAULT_LIMITS
    provenance: Mapping[str, str] = field(default_factory=dict)
    spacings: tuple[float, ...] | None = None

    def _options(self) -> dict[str, Any]:
        return dict(names=dict(self.names), units=dict(self.units), time_origin=self.time_origin, limits=self.limits)

    def compute(self, progress: Progress | None = None) -> Validated:
        """Validate every run, then render the files (no figure is drawn before every run is judged, so that a bad run
        is refused without the others' figures), and the convergence study; nothing is written."""
        from mdr_events.analysis.validate import validate
        from mdr_events.app.validation_files import render_validation

        reports = []
        for file in self.files:
            report = validate(file, self.contact, self.motion, tolerance=self.tolerance, progress=progress,
                              **self._options())
            report.attrs.update(self.provenance, path_description=self.description)
            reports.append(report)
        rendered = [(run, render_validation(report, stem)) for run, report, stem in zip(self.runs, reports, self.stems)]
        return Validated(rendered, None if self.spacings is None else self._convergence())

    def _convergence(self) -> Convergence:
        """The convergence study of the runs by spacing, computed and drawn."""
        try:
            study = importlib.import_module(CONVERGENCE_MODULE).convergence_study
        except (ModuleNotFoundError, AttributeError) as error:
            if isinstance(error, ModuleNotFoundError) and error.name != CONVERGENCE_MODULE:
                raise
            return Convergence(None, None, [f"convergence study skipped ({CONVERGENCE_MODULE}.convergence_study is "
                                            "not available)"])
        # every option of validate, the tolerance too: each spacing's verdict is its run's (the study's own verdict
        # is the observed order)
        dataset = study(dict(zip(self.spacings, self.files)), self.contact, self.motion, tolerance=self.tolerance,
                        **self._options())
        try:
            from mdr_events.plotting.convergence import plot_convergence_study
            from mdr_events.plotting.figures import figure_png
            png = figure_png(plot_convergence_study(dataset))
        except ImportError:
            png = None
        lines = [f"convergence study ({len(self.spacings)} spacings): {dataset.attrs.get('verdict', '?')}"]
        if "max_error_order" in dataset:
            orders = dataset["max_error_order"]
            spreads = dataset.get("max_error_order_spread", orders * math.nan)
            # (the finest step's order beside: an error that stops falling there does not converge)
            finest = dataset.get("max_error_finest_order", orders * math.nan)
            lines.append("  observed order of the max error (and between the two finest spacings): " + ", ".join(
                f"{name} {float(orders.sel(quantity=name)):.2f} ± {float(spreads.sel(quantity=name)):.2f} "
                f"({float(finest.sel(quantity=name)):.2f})" for name in orders["quantity"].values)
                + (f" (expected {float(dataset['expected_order']):g})" if "expected_order" in dataset else ""))
        return Convergence(dataset, png, lines)

    @staticmethod
    def write_convergence(convergence: Convergence, out: FilePath) -> list[FilePath]:
        """Write the convergence study's ``.nc`` and ``.png`` into ``out``, together or not at all."""
        from mdr_events.io.files import PendingFile, atomic_write_all, netcdf_writer

        png = convergence.png
        files = [PendingFile(out / f"{CONVERGENCE_STEM}.nc", netcdf_writer(convergence.dataset), ".nc")]
        if png is not None:
            files.append(PendingFile(out / f"{CONVERGENCE_STEM}.png",
                                     lambda temporary: FilePath(temporary).write_bytes(png), ".png"))
        return atomic_write_all(files)


@dataclass(frozen=True)
class FitJob:
    """A fit of the continuum to a measurement (:func:`~mdr_events.fit`): written as ``<stem>.nc``, ``.md``, ``.png``.

    Attributes
    ----------
    data : str
        The measurement as given (its name in messages).
    file : pathlib.Path
        Its file.
    stem : str
        The stem of the fit's files.
    contact, motion
        The fit's start and the one path of the experiment.
    description : str
        The path, for the report.
    free : tuple of str
        The parameters to fit.
    bounds, noise, names, units, time_origin
        As :func:`~mdr_events.fit` takes them (SI units).
    """

    data: str
    file: FilePath
    stem: str
    contact: Contact
    motion: Motion
    description: str
    free: tuple[str, ...]
    bounds: Mapping[str, tuple[float, float]] = field(default_factory=dict)
    noise: Mapping[str, float] = field(default_factory=dict)
    names: Mapping[str, str] = field(default_factory=dict)
    units: Mapping[str, str] = field(default_factory=dict)
    time_origin: str | float = "first_contact"
    limits: Limits = DEFAULT_LIMITS
    provenance: Mapping[str, str] = field(default_factory=dict)

    def compute(self, progress: Progress | None = None) -> tuple[FitResult, RenderedReport]:
        """Fit and render the files; nothing is written."""
        from mdr_events.analysis.fit import fit
        from mdr_events.app.fit_files import render_fit

        result = fit(self.file, self.contact, self.motion, free=list(self.free), limits=self.limits,
                     progress=progress, bounds=dict(self.bounds), noise=dict(self.noise), names=dict(self.names),
                     units=dict(self.units), time_origin=self.time_origin)
        result.dataset.attrs.update(self.provenance, path_description=self.description)
        return result, render_fit(result.dataset, self.stem)


@dataclass(frozen=True)
class RateFitJob:
    """The joint fit of the rate-dependent adhesion law to normal-force curves measured at several speeds
    (:func:`~mdr_events.fit_rate_adhesion`): one result, written as ``<stem>.nc``.

    Attributes
    ----------
    data : tuple of str
        The measurements as given (their names in messages and in the result).
    files : tuple of pathlib.Path
        Their files.
    stem : str
        The stem of the fit's file.
    contact : Contact
        The fit's start: its adhesion a :class:`~mdr_events.RateDependentAdhesion`, on the half-space.
    paths : tuple of Path
        The path of each measurement (its speed the measurement's).
    description : str
        The path, for the result.
    free : tuple of str
        The law's values to fit (:data:`~mdr_events.analysis.rate_fit.RATE_FREE_NAMES`).
    offsets : bool
        A free force offset per measurement.
    noise : float or None
        The normal force's noise (N, every measurement's), ``None``: estimated from the residuals.
    names, units, time_origin
        How to read the measurements (:func:`~mdr_events.validate`'s).
    d_max : float
        The depth the contact's flat record takes (m).
    """

    data: tuple[str, ...]
    files: tuple[FilePath, ...]
    stem: str
    contact: Contact
    paths: tuple[Any, ...]
    description: str
    free: tuple[str, ...] = ("v_ref", "n")
    offsets: bool = False
    noise: float | None = None
    names: Mapping[str, str] = field(default_factory=dict)
    units: Mapping[str, str] = field(default_factory=dict)
    time_origin: str | float = "first_contact"
    d_max: float = 3e-4
    limits: Limits = DEFAULT_LIMITS
    provenance: Mapping[str, str] = field(default_factory=dict)

    def measurements(self) -> list:
        """Each measurement's normal force read (names, units) on its path's clock (the time origin), the samples
        without a force left out (``nan``: a missing sample)."""
        import numpy as np

        from mdr_events.analysis.rate_fit import RateMeasurement
        from mdr_events.analysis.validate import times_from_contact
        from mdr_events.io.candidates import read_candidate

        found = []
        for data, file, path in zip(self.data, self.files, self.paths):
            read = read_candidate(file, dict(self.names), dict(self.units), self.limits)
            if "normal_force" not in read.quantities:
                raise ValueError(f"{data}: no normal_force column; allowed: a measurement of the normal force (the "
                                 "rate law's joint fit reads F_N alone; --names normal_force=COLUMN names yours)")
            force = read.quantities["normal_force"]
            kept = np.isfinite(force)
            clock = times_from_contact(read, path, self.time_origin) + path.first_contact_time()
            found.append(RateMeasurement(path, clock[kept], force[kept], self.noise))
        return found

    def compute(self, progress: Progress | None = None) -> xr.Dataset:
        """Read the measurements and fit; nothing is written."""
        from mdr_events.analysis.rate_fit import fit_rate_adhesion

        measurements = self.measurements()
        params = self.contact.parameters(self.d_max, self.paths[0].speed)
        try:
            result = fit_rate_adhesion(measurements, params, self.contact.adhesion, list(self.free), self.offsets,
                                       self.contact.profile, limits=self.limits)
        except (TypeError, ValueError) as error:
            raise type(error)(self.named(str(error))) from None
        from mdr_events.io.datasets import stamp

        # the start's contact stamped (Contact.from_attrs reads it back), the fitted values in the variables
        return stamp(result, params, **self.contact.to_attrs(), **self.provenance, path_description=self.description,
                     measurements=", ".join(self.data), speeds=", ".join(f"{path.speed!r}" for path in self.paths),
                     speeds_units="m s-1")

    def named(self, message: str) -> str:
        """``message`` of :func:`~mdr_events.analysis.rate_fit.fit_rate_adhesion` with each ``measurements[i]`` named
        by its file (round nineteen: "measurements[1].times=307.9 s is not allowed" named the second DATA by the API's
        argument; the noise, one for all, is ``--noise``'s, and what it allows without the API's ``None``: round twenty,
        "allowed: None or a finite number ..." where the command line has no ``None``, only the option left out)."""
        import re

        if re.search(r"measurements\[\d+\]\.noise=", message):
            message = re.sub(r"measurements\[\d+\]\.noise=", "the noise of normal_force (--noise, [fit] noise) ", message)
            message = message.replace("allowed: None or ", "allowed: ")
        message = re.sub(r"(measurements\[\d+\])\.path\.speed=", r"\1its speed (--speeds, [fit] speeds) ", message)
        return re.sub(r"measurements\[(\d+)\]\.?", lambda found: f"{self.data[int(found.group(1))]}: ", message)

    @staticmethod
    def determined(result: xr.Dataset) -> bool:
        """Whether every value of the fit ``result`` is determined: the solver converged (``status > 0``: not stopped at
        its evaluation limit), every standard error and interval finite, ``n`` (if free) inside its bounds
        (:data:`~mdr_events.analysis.rate_fit.N_BOUNDS`: at a bound the linearised interval ignores it) and every
        value's ``identifiability`` "determined" (fit's rule: a law's value whose scaled standard error exceeds
        :data:`~mdr_events.analysis.fit_diagnostics.POOR_STANDARD_ERROR` is poorly determined; a result written
        before it was recorded is judged without it), and the law describes every curve (:meth:`misfits`)."""
        import numpy as np

        from mdr_events.analysis.rate_fit import N_BOUNDS

        finite = all(np.all(np.isfinite(result[name].values))
                     for name in ("standard_error", "interval_lower", "interval_upper"))
        names = [str(name) for name in result["parameter"].values]
        inside = "n" not in names or N_BOUNDS[0] < float(result["estimate"].values[names.index("n")]) < N_BOUNDS[1]
        verdicts = result["identifiability"].values if "identifiability" in result else ()
        judged = all(str(verdict) == "determined" for verdict in verdicts)
        return bool(finite and int(result.attrs["status"]) > 0 and inside and judged and not RateFitJob.misfits(result))

    @staticmethod
    def misfits(result: xr.Dataset) -> list[int]:
        """The measurements the fit ``result`` does not describe: their ``misfit`` (the residuals' RMS over the noise)
        above :data:`~mdr_events.analysis.fit_diagnostics.MISFIT_RMS`, as fit warns (none in a result written
        before it was recorded)."""
        from mdr_events.analysis.fit_diagnostics import MISFIT_RMS

        if "misfit" not in result:
            return []
        return [index for index, value in enumerate(result["misfit"].values) if not value <= MISFIT_RMS]

    def plans(self, result: xr.Dataset, out: FilePath) -> list[PlannedFile]:
        """``<stem>.nc`` in ``out``, planned."""
        from mdr_events.app.result_files import netcdf_plan

        return [netcdf_plan(result, FilePath(out) / f"{self.stem}.nc")]

    def write(self, result: xr.Dataset, out: FilePath) -> list[FileOutcome]:
        """Write ``<stem>.nc`` into ``out``."""
        from mdr_events.app.result_files import commit

        return commit(self.plans(result, out))

    def run(self, out: FilePath, progress: Progress = _quiet) -> list[FileOutcome]:
        """Fit and write."""
        return self.write(self.compute(), out)


@dataclass(frozen=True)
class SweepJob:
    """A parameter sweep (:func:`~mdr_events.sweep`), written chunk by chunk to its store and as ``<stem>.nc``.

    Attributes
    ----------
    grid : mapping or list of mappings
        Names to values (the outer product), or sets of values (:func:`~mdr_events.sweep`).
    contact : Contact
        The model of every run before the grid's values are put in.
    motion : Scenario or Paths
        A scenario of one angle (any, if the grid sweeps ``alpha``), or the one custom path.
    method : Discrete or Continuum
        The method with its options.
    output : SweepOutput
        The quantities, the histories and the Zarr store (``resume`` is set when it runs).
    engine : Engine
        Where the chunks run: scheduler, workers, chunk size (the progress is set when it runs).
    stem : str
        The stem of the labelled result's file.
    limits : Limits
        What each run may use.
    provenance : mapping
        Attributes every written result carries.
    """

    grid: Any
    contact: Contact
    motion: Motion
    method: Method
    output: SweepOutput
    engine: Engine
    stem: str
    limits: Limits = DEFAULT_LIMITS
    provenance: Mapping[str, str] = field(default_factory=dict)

    @property
    def store(self) -> FilePath:
        """The Zarr store the sweep writes as it goes."""
        return FilePath(self.output.store)

    def compute(self, progress: Progress = _quiet, resume: bool = False) -> xr.Dataset:
        """Run the sweep (the store written chunk by chunk; ``resume``: an interrupted one continued)."""
        from mdr_events.analysis.sweep import sweep

        def report(done: int, total: int) -> None:
            progress(f"sweep: {done}/{total} runs")

        result = sweep(self.grid, self.contact, self.motion, None, self.method,
                       output=dataclasses.replace(self.output, resume=resume),
                       engine=dataclasses.replace(self.engine, progress=report), limits=self.limits)
        result.attrs.update(self.provenance)
        return result

    def plans(self, result: xr.Dataset, out: FilePath, progress: Progress = _quiet) -> list[PlannedFile | FileOutcome]:
        """Say how many runs failed; the store (written as the sweep ran, chunk by chunk: what ``resume`` continues)
        and ``<stem>.nc`` in ``out``, planned."""
        from mdr_events.app.result_files import FileOutcome, FileStatus, netcdf_plan

        progress(f"sweep: {result.attrs['runs']} runs, {result.attrs['failed_runs']} failed")
        return [FileOutcome(self.store, FileStatus.WRITTEN), netcdf_plan(result, out / f"{self.stem}.nc")]

    def write(self, result: xr.Dataset, out: FilePath, progress: Progress = _quiet) -> list[FileOutcome]:
        """Say how many runs failed and write ``<stem>.nc`` into ``out``; the store and the file written."""
        from mdr_events.app.result_files import commit_all

        return commit_all(self.plans(result, out, progress))

    def run(self, out: FilePath, progress: Progress = _quiet, resume: bool = False) -> list[FileOutcome]:
        """Run the sweep and write its result."""
        return self.write(self.compute(progress, resume), out, progress)


@dataclass(frozen=True)
class ReproduceJob:
    """Everything in ``results/`` (:func:`mdr_events.reproduction.reproduce`); ``rewrite``: also the files that agree."""

    rewrite: bool = False

    def run(self, out: FilePath, progress: Progress = _quiet) -> None:
        """Recompute and write the results into ``out``."""
        from mdr_events.reproduction import reproduce

        reproduce(out, progress=progress, keep_agreeing=not self.rewrite)


#: The suffix of the LAMMPS input deck :class:`LammpsCheckJob` writes beside the report.
DECK_SUFFIX = ".lmp"


@dataclass(frozen=True)
class LammpsCheckJob:
    """A LAMMPS granular model run along one path and validated against the exact continuum
    (:func:`~mdr_events.dem.lammps_check`): written as ``<stem>.nc``, ``.md``, ``.png`` (the report, as
    ``validate`` writes it) and ``<stem>.lmp`` (the input deck, to rerun it with ``lmp -in <stem>.lmp``).

    Attributes
    ----------
    contact, motion
        The contact and the motion of one path.
    description : str
        The path, for the report.
    normal, tangential : str
        LAMMPS's models.
    steps, dt
        LAMMPS's number of steps or time step (``None``: the default).
    tolerance : float
        The verdict's bound.
    """

    contact: Contact
    motion: Motion
    description: str
    normal: str
    tangential: str = "none"
    steps: int | None = None
    dt: float | None = None
    tolerance: float = 1e-3
    limits: Limits = DEFAULT_LIMITS
    provenance: Mapping[str, str] = field(default_factory=dict)
    stem: str = "lammps_check"

    def compute(self) -> RenderedReport:
        """Run LAMMPS, validate and render the files; nothing is written."""
        from mdr_events.app.validation_files import render_validation
        from mdr_events.dem import LammpsModel, lammps_check

        _, report = lammps_check(self.contact, self.motion, model=LammpsModel(self.normal, self.tangential),
                                 steps=self.steps, dt=self.dt, tolerance=self.tolerance, limits=self.limits)
        report.attrs.update(self.provenance, path_description=self.description)
        return render_validation(report, self.stem)

    @staticmethod
    def plans(rendered: RenderedReport, out: FilePath) -> list[PlannedFile]:
        """The report's three files and the deck in ``out``, planned."""
        from mdr_events.app.result_files import bytes_plan
        from mdr_events.app.validation_files import rendered_plans

        deck = rendered.report.attrs["lammps_input_deck"]
        return [*rendered_plans(rendered, out),
                bytes_plan(FilePath(out) / f"{rendered.stem}{DECK_SUFFIX}", deck.encode("utf-8"))]

    @staticmethod
    def write(rendered: RenderedReport, out: FilePath) -> list[FilePath]:
        """Write the report's three files and the deck into ``out``, together or not at all."""
        from mdr_events.app.result_files import commit

        return [outcome.path for outcome in commit(LammpsCheckJob.plans(rendered, out))]

    def run(self, out: FilePath, progress: Progress = _quiet) -> list[FilePath]:
        """Compute and write."""
        return self.write(self.compute(), out)


#: A job.
Job = DeriveJob | PhaseJob | SimulateJob | ValidateJob | FitJob | RateFitJob | SweepJob | ReproduceJob | LammpsCheckJob
