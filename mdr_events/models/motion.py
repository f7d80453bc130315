"""The motion as a value: the paper's scenarios at their angles, or custom paths; and the cases they give.

A :class:`Scenario` is one of the paper's motions (A: eq. (14), B: eq. (19), B+: the "+" branch of Fig. 9b) at one
or several angles, to the depth ``d_max`` at the speed ``v``; :class:`Paths` are paths of any shape
(:class:`~mdr_events.Path`), labelled. Either gives the :class:`Cases` of a run (one path each, along ``alpha`` or
``case``) for a contact (:meth:`Scenario.cases`: the way out ends below the contact's jump-off). :func:`as_motion`
reads what ``simulate`` and the other entry points are given: a motion, a scenario's name with ``alpha``, or paths.
"""

from __future__ import annotations

import collections
import contextlib
from contextvars import ContextVar
from dataclasses import dataclass, field
from typing import Iterator, Mapping, NamedTuple, Sequence

import numpy as np
import xarray as xr

from mdr_events.contact.friction import TAU0, FrictionLaw
from mdr_events.limits import DEFAULT_LIMITS, Limits, ResourceLimitError, values_in
from mdr_events.memo import kept
from mdr_events.models import indenters
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path
from mdr_events.parameters import PAPER_D_MAX, PAPER_V, Parameters  # (the paper's depth and speed: a scenario's defaults)
from mdr_events.theory import analytic
from mdr_events.theory.scales import check_representable
from mdr_events.validation import SCALE_MAX, as_name, check_real, shown, validate_alpha

__all__ = ["Scenario", "Paths", "Motion", "as_motion", "Cases", "simulation_cases", "scenario_paths",
           "case_dimension", "case_text", "check_path_extent", "check_path_representable", "FIGURE_ANGLES", "SCENARIO_NAMES",
           "ANGLE_DIMENSION", "CUSTOM_DIMENSION", "CASE_DIMENSIONS", "CUSTOM_SCENARIO", "SLIP_DIGITS",
           "TIMES_PER_CASE_MIN", "angles_within"]


#: The angles of Fig. 8 and Fig. 10.
FIGURE_ANGLES = (10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0)
SCENARIO_NAMES = ("A", "B", "B+")
#: The dimension of a simulation's cases: ``alpha`` (path angle, degrees) for the paper's scenarios,
#: ``case`` (a name) for custom paths.
ANGLE_DIMENSION, CUSTOM_DIMENSION = "alpha", "case"
CASE_DIMENSIONS = (ANGLE_DIMENSION, CUSTOM_DIMENSION)
#: The ``scenario`` attribute of a simulation of custom paths.
CUSTOM_SCENARIO = "custom"

#: How many of the scenarios' paths are kept (:func:`_scenario_path`): a figure's angles for a few contacts.
PATHS_KEPT = 256

#: Relative accuracy the slip criterion needs: x − X(ξ) against ū(a) must keep this many digits.
SLIP_DIGITS = 1e-9


def check_path_extent(params: Parameters, path: Path, label: str, profile: SimulatedProfile = None) -> None:
    """Reject a path so long that ``x − X(ξ)`` cannot be compared with ``ū(a)`` in double precision.

    The positions along the path are rounded to ``eps · |x|``; the slip
    criterion compares differences of them with ``ū(a)`` (at ``d_max``) or,
    without friction, with ``d_max``. A path whose tangential extent exceeds
    ``SLIP_DIGITS · max(ū, d_max) / eps`` (about 3 km for the paper's
    parameters: a path angle of a few 1e-6 degrees) is an error, not a
    silently wrong result.
    """
    indenters.check_reach(params, path.max_depth, profile, label)
    reference, limit = _slip_reference(params, profile)
    extent = float(np.max(np.abs(path.waypoints[:, 0])))
    if extent > limit:
        raise ValueError(f"{label}: the path reaches x = {extent:.3g} m; allowed: |x| <= {limit:.3g} m, beyond "
                         f"which double precision cannot resolve the slip criterion (shift vs {reference:.3g} m)")


@kept(PATHS_KEPT)
def _path_parameters(params: Parameters, depth: float, speed: float) -> Parameters:
    """``params`` with a path's deepest point as ``d_max`` (if it goes in) and its speed as ``v``, kept
    (:func:`~mdr_events.memo.kept`: each run of the same paths makes the same)."""
    return params.replace(d_max=depth, v=speed) if depth > 0.0 else params.replace(v=speed)


@kept(PATHS_KEPT)
def _slip_reference(params: Parameters, profile: SimulatedProfile) -> tuple[float, float]:
    """The shift the slip criterion resolves, ``max(ū(a(d_max)), d_max)``, and the largest tangential extent that
    keeps it resolved (:func:`check_path_extent`), kept per contact (:func:`~mdr_events.memo.kept`)."""
    radius = float(indenters.branch_radius(params.d_max, params, params.dgamma0, profile))
    reference = max(float(analytic.critical_shift(radius, params)), params.d_max)
    return reference, SLIP_DIGITS * reference / np.finfo(float).eps


def check_path_representable(params: Parameters, path: Path, label: str, profile: SimulatedProfile = None,
                             friction: FrictionLaw = TAU0) -> None:
    """Refuse a path whose own scales do not fit in double precision: its coordinates and duration within
    :data:`~mdr_events.validation.SCALE_MAX`, and the run's scales (:func:`~mdr_events.theory.scales.check_representable`)
    with its deepest point as ``d_max`` and its speed as ``v`` (a path to 1e300 m gave nan forces)."""
    largest = float(np.max(np.abs(path.waypoints)))
    for what, value, unit in (("its largest coordinate", largest, "m"), ("its duration", path.duration, "s")):
        if not value <= SCALE_MAX:
            raise ValueError(f"{label}: {what} is {value:.3g} {unit}; allowed: at most {SCALE_MAX:.2g} {unit}, so that "
                             "products stay finite in double precision")
    try:
        check_representable(_path_parameters(params, path.max_depth, path.speed), profile, friction)
    except ValueError as error:
        raise ValueError(f"{label} (its deepest point as d_max, its speed as v): {error}") from None


class Cases(NamedTuple):
    """The cases of a simulation: one path each, labelled along ``dimension`` by ``labels``."""

    paths: list[Path]
    #: ``"alpha"`` (the paper's scenarios) or ``"case"`` (custom paths)
    dimension: str
    #: the angles in degrees (float) or the case names (str), one per path
    labels: np.ndarray

    @property
    def custom(self) -> bool:
        return self.dimension == CUSTOM_DIMENSION


#: What ``scenario`` may be, for messages.
SCENARIO_ALLOWED = ("'A', 'B', 'B+', a Path, a non-empty list of Paths, or a non-empty mapping "
                    "{label (non-empty str): Path}")


def _custom_paths(scenario: Path | Sequence[Path] | Mapping[str, Path]) -> dict[str, Path]:
    """The custom paths of ``scenario`` by label; a single path or a list is labelled ``"path 1"``, ...

    Raises ``ValueError`` for an empty list or mapping or repeated labels and ``TypeError`` for an
    element that is not a :class:`Path` or a label that is not a non-empty string.
    """
    if isinstance(scenario, Path):
        return {"path 1": scenario}
    if not isinstance(scenario, (Mapping, list, tuple)):
        raise TypeError(f"paths={shown(scenario)} ({type(scenario).__name__}) is not allowed; allowed: "
                        f"{SCENARIO_ALLOWED}")
    if isinstance(scenario, Mapping):
        labels, paths = list(scenario.keys()), [scenario[label] for label in scenario.keys()]
        where = [f"scenario[{shown(label)}]" for label in labels]
    else:
        paths = list(scenario)
        labels = [f"path {number}" for number in range(1, len(paths) + 1)]
        where = [f"scenario[{index}]" for index in range(len(paths))]
    if not paths:
        raise ValueError(f"scenario={shown(scenario)} is not allowed: it holds no path; allowed: {SCENARIO_ALLOWED}")
    for label in labels:
        if not isinstance(label, str) or not label:
            raise TypeError(f"scenario has the label {shown(label)} ({type(label).__name__}); allowed: labels that are "
                            "non-empty strings")
    repeated = sorted(label for label, count in collections.Counter(labels).items() if count > 1)  # (not n² counts)
    if repeated:
        raise ValueError(f"scenario has the label(s) {shown(repeated)} more than once; allowed: distinct labels")
    for name, path in zip(where, paths):
        if not isinstance(path, Path):
            raise TypeError(f"{name}={shown(path)} ({type(path).__name__}) is not allowed; allowed: a "
                            "mdr_events.Path")
    return dict(zip(labels, paths))


def _scenario_cases(params: Parameters, name: str, angles: np.ndarray, profile: SimulatedProfile = None,
                    final_depth: float | None = None) -> Cases:
    """One path of scenario ``name`` per angle (:func:`_scenario_path`), labelled by the angles."""
    paths = [_scenario_path(name, float(angle), params, profile, final_depth) for angle in angles]
    return Cases(paths, ANGLE_DIMENSION, np.asarray(angles, dtype=float))


@kept(PATHS_KEPT)
def _scenario_path(name: str, angle: float, params: Parameters, profile: SimulatedProfile,
                   final_depth: float | None) -> Path:
    """The path of scenario ``name`` at ``angle``, checked by :func:`check_path_extent` (it ends below the jump-off
    of ``profile``'s ``Δγ1`` branch); kept for the last :data:`PATHS_KEPT` (:func:`~mdr_events.memo.kept`: a path
    is immutable, and a run's set-up builds the same ones again, some 60 µs each)."""
    label = f"alpha={angle!r} (degrees) in scenario {name}"
    try:  # (an angle of 1e-300° makes waypoints 1e298 m apart: the path refuses them, the angle is named)
        if name == "A":
            path = Path.scenario_A(angle, params, profile=profile)
        elif name == "B":
            path = Path.scenario_B(angle, params, profile=profile)
        else:
            path = Path.scenario_B_indentation(angle, params, final_depth, profile=profile)
    except ValueError as error:
        if str(error).startswith("alpha="):  # (the path names the angle itself)
            raise
        raise ValueError(f"{label}: {error}") from None
    check_path_extent(params, path, label, profile)
    return path


def simulation_cases(params: Parameters, scenario, alpha, profile: SimulatedProfile = None) -> Cases:
    """The cases of ``simulate(params, scenario, alpha)`` (:func:`as_motion` of the three, then its cases)."""
    return as_motion(scenario, alpha, params.d_max, params.v).cases(params, profile)


def scenario_paths(params: Parameters, scenario, alpha, profile: SimulatedProfile = None) -> tuple[list[Path], np.ndarray]:
    """The paths of :func:`simulation_cases` and their labels (angles in degrees, or case names)."""
    cases = simulation_cases(params, scenario, alpha, profile)
    return cases.paths, cases.labels


def case_dimension(dataset: xr.Dataset) -> str:
    """The dimension along which a simulation's cases lie: ``"case"`` (custom paths) or ``"alpha"``."""
    found = [name for name in CASE_DIMENSIONS if name in dataset.dims]
    if len(found) != 1:
        raise ValueError(f"a simulation with the dimensions {tuple(dataset.dims)} is not allowed; allowed: "
                         f"exactly one of {CASE_DIMENSIONS}")
    return found[0]


def case_text(dimension: str, label) -> str:
    """How a case is named in messages and legends: ``α = 20°`` or its label."""
    return f"α = {float(label):g}°" if dimension == ANGLE_DIMENSION else str(label)



#: The fewest output times any run makes per case (its start and end: the discrete's steps + 1, the continuum's
#: samples, counted as 2001 at least): a run within ``Limits.samples`` takes at most ``samples / 2`` cases.
TIMES_PER_CASE_MIN = 2
#: The most angles a Scenario made now reads: what a run within the default limits, or those of the run that makes
#: it (:func:`angles_within`), could take.
_ANGLES_MAX: ContextVar[float] = ContextVar("angles_max", default=DEFAULT_LIMITS.samples / TIMES_PER_CASE_MIN)


@contextlib.contextmanager
def angles_within(limits: Limits) -> Iterator[None]:
    """Scenarios made in this block read as many angles as a run within ``limits`` could take (``simulate`` by name
    with its ``limits``: its count checked against them first), not only the default limits' number.

    Parameters
    ----------
    limits : Limits
        The run's limits.

    Yields
    ------
    None
        The block, with the bound raised or lowered to ``limits``.
    """
    token = _ANGLES_MAX.set(limits.samples / TIMES_PER_CASE_MIN)
    try:
        yield
    finally:
        _ANGLES_MAX.reset(token)


def _angles(alpha) -> tuple[float, ...]:
    """The angles of a scenario: one or a 1-D list, distinct, each in [0, 90] degrees; counted before they are read
    (round twenty-four: a million angles took 54 MB and 0.8 s when the Scenario was made, before any limit), then
    :func:`_plain_angles` as they are; anything else, or what that refuses, read and named by
    :func:`~mdr_events.validation.validate_alpha`."""
    count, most = values_in(alpha), _ANGLES_MAX.get()
    if not count <= most:
        raise ResourceLimitError(
            f"alpha of {count} angles is not allowed in a Scenario; allowed: at most {most:.3g} (a run within "
            f"Limits.samples = {most * TIMES_PER_CASE_MIN:.3g} output times, {TIMES_PER_CASE_MIN} at least per "
            "case); more by name with larger limits: simulate(contact, 'A', alpha=..., limits=Limits(samples=...))")
    plain = _plain_angles(alpha)
    if plain is not None:
        return plain
    angles = np.atleast_1d(validate_alpha(alpha))
    if angles.ndim != 1 or angles.size == 0:
        raise ValueError(f"alpha of shape {angles.shape} is not allowed; allowed: one angle or a 1-D list")
    values, counts = np.unique(angles, return_counts=True)
    if np.any(counts > 1):
        raise ValueError(f"alpha={shown(alpha)} repeats {float(values[counts > 1][0])!r}; allowed: distinct "
                         "angles (each labels one case)")
    return tuple(float(angle) for angle in angles)


def _plain_angles(alpha) -> tuple[float, ...] | None:
    """The angles of a Python float or a non-empty list or tuple of them, distinct and each in [0, 90], as they are
    (what :func:`_angles` reads of them through NumPy, without its arrays: some 15 µs a run); ``None`` for anything
    else, which :func:`_angles` reads and, if it must, refuses by name."""
    values = (alpha,) if type(alpha) is float else tuple(alpha) if type(alpha) in (list, tuple) else ()
    if values and all(type(value) is float and 0.0 <= value <= 90.0 for value in values) and \
            len(set(values)) == len(values):
        return values
    return None


@dataclass(frozen=True)
class Scenario:
    """One of the paper's scenarios at one or several path angles.

    Parameters
    ----------
    name : {"A", "B", "B+"}, default "A"
        ``"A"``: in at angle α to ``d_max``, out vertically (14); ``"B"``: in vertically, out at angle α (19);
        ``"B+"``: in vertically to ``d_max``, further in at α to ``final_depth``, out vertically (Fig. 9b, "+").
    alpha : float or sequence of float
        Path angles to the surface in degrees, distinct, in [0, 90] (default 10°, 20°, …, 80°: Fig. 8 and 10);
        one case each.
    d_max : float, optional
        The turning depth in m (default the paper's 0.3 mm).
    v : float, optional
        The speed along the path in m/s (default the paper's 1 µm/s; the model is rate independent, so ``v``
        only sets the time axis).
    final_depth : float, optional
        ``"B+"`` only: the deepest point, > ``d_max`` (default ``2 d_max``).

    Raises
    ------
    ValueError
        An unknown name, an angle out of range or repeated, a depth or speed not > 0, a ``final_depth`` not
        beyond ``d_max`` or with another scenario than ``"B+"``.
    ResourceLimitError
        More angles than a run within the default :class:`~mdr_events.Limits` could take (``Limits.samples / 2``),
        counted before they are read; more are taken by name with larger limits (``simulate(contact, "A",
        alpha=..., limits=...)``).
    """

    name: str = "A"
    alpha: tuple[float, ...] = FIGURE_ANGLES
    d_max: float = PAPER_D_MAX
    v: float = PAPER_V
    final_depth: float | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "name", as_name(self.name))  # (np.array("A"), np.str_: the plain name)
        if not isinstance(self.name, str) or self.name not in SCENARIO_NAMES:
            raise ValueError(f"scenario={shown(self.name)} is not allowed; allowed: {SCENARIO_ALLOWED}")
        object.__setattr__(self, "alpha", _angles(self.alpha))
        object.__setattr__(self, "d_max", check_real("d_max", self.d_max, "a finite number > 0 (m)",
                                                     lambda value: value > 0.0))
        object.__setattr__(self, "v", check_real("v", self.v, "a finite number > 0 (m/s)", lambda value: value > 0.0))
        if self.final_depth is not None:
            if self.name != "B+":
                raise ValueError(f"final_depth={shown(self.final_depth)} is not allowed with scenario {self.name!r}; "
                                 "allowed: with 'B+'")
            object.__setattr__(self, "final_depth", check_real(
                "final_depth", self.final_depth, f"a finite number > d_max = {self.d_max!r} (m)",
                lambda value: value > self.d_max))

    @property
    def dimension(self) -> str:
        """The dimension the cases are labelled along: ``"alpha"`` (the path angles in degrees)."""
        return ANGLE_DIMENSION

    @property
    def case_count(self) -> int:
        """How many cases :meth:`cases` builds: one per angle (counted before they are built)."""
        return len(self.alpha)

    def cases(self, params: Parameters, profile: SimulatedProfile = None, friction: FrictionLaw = TAU0) -> Cases:
        """One path per angle for the contact of ``params`` and ``profile`` (its ``d_max`` and ``v`` this
        scenario's).

        Parameters
        ----------
        params : Parameters
            The contact's values with this scenario's ``d_max`` and ``v``.
        profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
            The indenter; ``None``: the paraboloid of ``params.R``. The paths end below the jump-off of its
            ``Δγ1`` branch.
        friction : FrictionLaw, optional
            Not used by the scenarios' paths (the parameter of :meth:`Paths.cases`, whose checks need it).

        Returns
        -------
        Cases
            The paths labelled along ``"alpha"`` by their angles.

        Raises
        ------
        ValueError
            A path that cannot be computed or compared in double precision, naming its angle.
        """
        return _scenario_cases(params, self.name, np.array(self.alpha), profile, self.final_depth)

    def to_attrs(self) -> dict[str, object]:
        """A result's attributes: ``scenario`` and ``param_d_max``, ``param_v`` with their units.

        Returns
        -------
        dict of str to object
            ``scenario`` (``"A"``, ``"B"`` or ``"B+"``), ``param_d_max`` (m), ``param_v`` (m/s) and their units.
        """
        return {"scenario": self.name, "param_d_max": self.d_max, "param_d_max_units": "m", "param_v": self.v,
                "param_v_units": "m s-1"}


@dataclass(frozen=True, repr=False)
class Paths:
    """Custom paths, one case each, labelled along ``case``.

    The depth and speed the run's checks measure against and its result names (``param_d_max``, ``param_v``) are
    the paths' own: :attr:`d_max` their deepest point, :attr:`v` the slowest speed.

    Parameters
    ----------
    paths : Path, sequence of Path or mapping of str to Path
        A path, a non-empty list of them (labelled ``"path 1"``, ``"path 2"``, ...) or a mapping
        ``{label: Path}`` (its keys, non-empty strings, the labels); the paths may have different speeds. Kept as
        the mapping.

    Raises
    ------
    ValueError
        No path, a label that is not a non-empty string, or a path that never enters the elastomer.
    """

    paths: Mapping[str, Path]
    d_max: float = field(init=False)
    v: float = field(init=False)

    def __post_init__(self) -> None:
        paths = _custom_paths(self.paths)
        object.__setattr__(self, "paths", paths)
        for label, path in paths.items():
            if not path.max_depth > 0.0:
                raise ValueError(f"scenario path {label!r} never enters the elastomer (d > 0); allowed: paths that "
                                 "make contact")
        object.__setattr__(self, "d_max", max(path.max_depth for path in paths.values()))
        object.__setattr__(self, "v", min(path.speed for path in paths.values()))

    @classmethod
    def named_by(cls, paths, d_max: float, v: float) -> "Paths":
        """The keywords of before: paths whose run a :class:`~mdr_events.Parameters`' ``d_max`` and ``v`` name (its
        checks and its ``param_d_max``, ``param_v``), as they did (:func:`as_motion` beside a Parameters).

        Parameters
        ----------
        paths : Path, sequence of Path or mapping of str to Path
            The paths, labelled as :class:`Paths` labels them.
        d_max : float
            The depth the run's checks measure against and its ``param_d_max`` (m), > 0.
        v : float
            The speed its result names (``param_v``, m/s), > 0.

        Returns
        -------
        Paths
            The paths with that ``d_max`` and ``v`` instead of their own.
        """
        motion = object.__new__(cls)
        object.__setattr__(motion, "paths", _custom_paths(paths))
        object.__setattr__(motion, "d_max", check_real("d_max", d_max, "a finite number > 0 (m)",
                                                       lambda value: value > 0.0))
        object.__setattr__(motion, "v", check_real("v", v, "a finite number > 0 (m/s)", lambda value: value > 0.0))
        return motion

    def __repr__(self) -> str:  # (a path's waypoints may be thousands: the labels say which)
        return f"Paths(<{len(self.paths)} path{'s' * (len(self.paths) > 1)}: {', '.join(map(repr, self.paths))}>)"

    @property
    def dimension(self) -> str:
        """The dimension the cases are labelled along: ``"case"`` (the paths' labels)."""
        return CUSTOM_DIMENSION

    @property
    def case_count(self) -> int:
        """How many cases :meth:`cases` builds: one per path (counted before they are built)."""
        return len(self.paths)

    def cases(self, params: Parameters, profile: SimulatedProfile = None, friction: FrictionLaw = TAU0) -> Cases:
        """The paths, each checked by :func:`check_path_representable` and :func:`check_path_extent`.

        Parameters
        ----------
        params : Parameters
            The contact's values (its ``d_max`` and ``v`` replaced by each path's own in the checks).
        profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
            The indenter; ``None``: the paraboloid of ``params.R``.
        friction : FrictionLaw, optional
            The friction law, whose scales the check of double precision includes (default the paper's).

        Returns
        -------
        Cases
            The paths labelled along ``"case"`` by their labels.

        Raises
        ------
        ValueError
            A path that never touches the surface, or too long or large for double precision, naming its label.
        """
        for label, path in self.paths.items():
            try:
                path.first_contact_time()
            except ValueError as error:
                raise ValueError(f"scenario path {label!r}: {error}") from None
            check_path_representable(params, path, f"scenario path {label!r}", profile, friction)
            check_path_extent(params, path, f"scenario path {label!r}", profile)
        return Cases(list(self.paths.values()), CUSTOM_DIMENSION, np.array(list(self.paths), dtype=str))

    def to_attrs(self) -> dict[str, object]:
        """A result's attributes: ``scenario`` (``"custom"``) and ``param_d_max``, ``param_v`` with their units.

        Returns
        -------
        dict of str to object
            ``scenario``, ``param_d_max`` (m), ``param_v`` (m/s) and their units.
        """
        return {"scenario": CUSTOM_SCENARIO, "param_d_max": self.d_max, "param_d_max_units": "m",
                "param_v": self.v, "param_v_units": "m s-1"}


#: A motion.
Motion = Scenario | Paths


def as_motion(motion, alpha=None, d_max: float | None = None, v: float | None = None) -> Motion:
    """``motion`` as a :class:`Scenario` or :class:`Paths`: a motion as it is (``alpha``, ``d_max`` and ``v`` must
    then be ``None``), a scenario's name with ``alpha`` (default Fig. 8's angles) or paths (a :class:`Path`, a list,
    a mapping; ``alpha`` must be ``None``); ``d_max`` and ``v`` default to the paper's for a scenario and to the
    paths' own for paths."""
    if isinstance(motion, (Scenario, Paths)):
        given = [f"{name}={shown(value)}" for name, value in (("alpha", alpha), ("d_max", d_max), ("v", v))
                 if value is not None]
        if given:
            raise ValueError(f"{', '.join(given)} is not allowed beside motion={motion!r}; allowed: the motion's own "
                             "(a method is simulate's fourth argument, or method=)")
        return motion
    motion = as_name(motion)
    if isinstance(motion, str):
        return Scenario(motion, FIGURE_ANGLES if alpha is None else alpha, PAPER_D_MAX if d_max is None else d_max,
                        PAPER_V if v is None else v)
    if not isinstance(motion, (Path, Mapping, list, tuple)):
        raise TypeError(f"scenario={shown(motion)} ({type(motion).__name__}) is not allowed; allowed: "
                        f"{SCENARIO_ALLOWED}, a Scenario or Paths")
    if alpha is not None:
        raise ValueError(f"alpha={shown(alpha)} is not allowed with custom paths (their waypoints fix the motion); "
                         "allowed: alpha=None")
    return Paths(motion) if d_max is None and v is None else Paths.named_by(motion, d_max, v)
