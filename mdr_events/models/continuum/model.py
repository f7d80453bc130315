"""What the continuum method knows of the model: the two branches, the cap per radius, and the path's
segments as linear motions."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import NamedTuple

import numpy as np

from mdr_events.contact.friction import TAU0, FrictionLaw
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.parameters import Parameters
from mdr_events.contact.indenters import FlatPunch, PowerLaw, TabulatedProfile
from mdr_events.models.paths import Path
from mdr_events.contact.adhesion import AdhesionLaw, law_of
from .branch import Branch, make_branch
from .caps import Caps, caps_of, compressed_zone_alone, split_regions
from .media import medium_of
from .state import Regime
from .tolerances import NEGLIGIBLE_SHARE, PIECE_SHARE, SEGMENT_RESOLUTION, Tolerances, force_atol


class ContinuumModel:
    """Parameters, tolerances and the derived pieces every span needs.

    Parameters
    ----------
    params : Parameters
        The material, ``R`` (the paraboloid's), ``τ0`` and the works of adhesion at rest.
    tolerances : Tolerances
        The solver's and the roots' tolerances.
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter (``None``: the paper's paraboloid of ``params.R``).
    friction : FrictionLaw, default TAU0
        The friction law.
    adhesion : Adhesion, optional
        The adhesion law; ``None``: the paper's law of ``params.dgamma0`` and ``params.dgamma1``.
    layer : Layer, default the half-space
        The body (:mod:`.media`: on a layer of finite thickness the springs' stiffness varies with ``ξ``).

    Attributes
    ----------
    solver_tolerances : Tolerances
        The solver's for this run: ``tolerances`` with its ``atol`` capped by the run's force scale
        (:func:`~.tolerances.force_atol`).
    adhesion : Adhesion
        The adhesion law (:func:`~mdr_events.contact.adhesion.law_of`: the paper's law of ``params`` by default).
    grow, shrink : Branch
        The branches its edge follows (:func:`~.edges.edge_of`): for the paper's law the ``Δγ0`` (attach) and
        ``Δγ1`` (detach) branches of (9).
    profile : PowerLaw, FlatPunch or None
        The indenter (``None``: the paper's paraboloid of ``params.R``).
    friction : FrictionLaw
        The cap on the springs' shifts (:mod:`mdr_events.contact.friction`).
    caps : Caps
        Its two parts, ``ū(ξ) = K a + κ (d − g(ξ))``.
    K : float
        Critical shift per contact radius of ``τ0``'s part on the half-space, ``ū(a) = K a`` (13) (0 for
        ``"coulomb"``; on a layer ``ū(a) = K a/Φ_t(a/h)``, :attr:`medium`).
    medium : HalfSpaceMedium
        What the springs are made of (:func:`~.media.medium_of`): their cap, tangential measure, edge and normal
        force.
    split : bool
        Both parts of the cap with adhesion on a curved indenter (:func:`~.caps.split_regions`): the compressed zone and
        the tensile annulus are laid out apart (:mod:`.split_span`).
    hertz : Branch or None
        With :attr:`split`, the branch without adhesion: the profile ``g`` and the compression boundary ``x_c``.
    zone_params : Parameters or None
        Coulomb's law alone with adhesion (:func:`~.caps.compressed_zone_alone`): the parameters of the compressed
        zone, the contact without adhesion whose run gives the tangential force (``solve_path``); this model's own
        springs then hold no shift (``caps`` frictionless). ``None`` otherwise.

    Raises
    ------
    ValueError
        A friction law, indenter and adhesion the continuum does not solve, or an adhesion law whose works at rest
        are not those of ``params``.
    """

    def __init__(self, params: Parameters, tolerances: Tolerances, profile: PowerLaw | FlatPunch | None = None,
                 friction: FrictionLaw = TAU0, adhesion: AdhesionLaw | None = None, layer: Layer = HALF_SPACE):
        self.params = params
        self.tolerances = tolerances
        self.solver_tolerances = replace(tolerances, atol=force_atol(tolerances, params))
        self.profile = profile
        self.friction = friction
        self.adhesion = law_of(params, adhesion)
        self.medium = medium_of(params, friction, profile, layer)
        self.grow, self.shrink = self.medium.edge(self.adhesion, params, profile)
        self.caps = caps_of(friction, params, self.medium)
        self.zone_params = None
        dgammas = (getattr(self.adhesion, "dgamma0", 0.0), getattr(self.adhesion, "dgamma1", 0.0))
        if compressed_zone_alone(self.caps, *dgammas):
            self.zone_params = params.replace(dgamma0=0.0, dgamma1=0.0)
            self.caps = Caps(0.0, 0.0)
        self.K = self.caps.K
        self.split = split_regions(self.caps, *dgammas, profile)
        self.hertz = make_branch(params, 0.0, profile) if self.split else None

    def normal_force(self, depth, radius):
        r"""``F_N`` (10) of the springs in ``|x| < a`` at depth ``d``, vectorised, for the model's profile (the flat
        punch's ``2 E* a d``, ``a`` its radius in contact and 0 out of it; on a layer ``F₀(a) + K(a)(d − g(a))``,
        :meth:`~.media.HalfSpaceMedium.normal_force`).

        .. math:: F_N = 2 E^* \int_0^a \left(d - g(x)\right) \mathrm{d}x \qquad (10)

        Parameters
        ----------
        depth : float or array_like
            The depth ``d`` (m).
        radius : float or array_like
            The contact radius ``a`` (m).

        Returns
        -------
        float or numpy.ndarray
            ``F_N`` (N; negative: tensile).
        """
        return self.medium.normal_force(self.params, self.profile, depth, radius)

    def branch(self, regime: Regime) -> Branch:
        """The branch a moving radius follows in ``regime`` (GROWING or SHRINKING).

        Parameters
        ----------
        regime : Regime
            ``Regime.GROWING`` (the ``Δγ0`` branch of the paper's law) or ``Regime.SHRINKING`` (``Δγ1``).

        Returns
        -------
        Branch
            :attr:`grow` or :attr:`shrink`.
        """
        return self.grow if regime is Regime.GROWING else self.shrink


@dataclass(frozen=True)
class Segment:
    """A straight piece of the path: ``x`` and ``d`` linear in time on ``[t0, t1]``.

    Parameters
    ----------
    t0 : float
        Its start (s on the path's clock).
    t1 : float
        Its end (s).
    xs : float
        ``x`` at ``t0`` (m).
    ds : float
        ``d`` at ``t0`` (m).
    vx : float
        The tangential velocity (m/s).
    vd : float
        The depth's velocity (m/s; positive: into the elastomer).
    """

    t0: float
    t1: float
    xs: float
    ds: float
    vx: float
    vd: float

    def x(self, t):
        """The tangential position ``x(t) = xs + vx (t − t0)``.

        Parameters
        ----------
        t : float or numpy.ndarray
            The time(s) (s on the path's clock).

        Returns
        -------
        float or numpy.ndarray
            The tangential position (m), the shape of ``t``.
        """
        return self.xs + self.vx * (t - self.t0)

    def d(self, t):
        """The depth ``d(t) = ds + vd (t − t0)``.

        Parameters
        ----------
        t : float or numpy.ndarray
            The time(s) (s on the path's clock).

        Returns
        -------
        float or numpy.ndarray
            The depth (m), the shape of ``t``.
        """
        return self.ds + self.vd * (t - self.t0)

    def time_at_depth(self, depth: float) -> float:
        """The time at which the segment's depth is ``depth`` (it needs ``vd != 0``).

        Parameters
        ----------
        depth : float
            The depth (m).

        Returns
        -------
        float
            The time (s on the path's clock), continued beyond the segment.
        """
        return self.t0 + (depth - self.ds) / self.vd


def kinematics(path: Path) -> list[Segment]:
    """The path's straight segments, with their velocities (a component below NEGLIGIBLE_SHARE of the
    speed is zero).

    Parameters
    ----------
    path : Path
        The indenter's path.

    Returns
    -------
    list of Segment
        One per pair of consecutive waypoints.

    Raises
    ------
    ValueError
        Naming the waypoints of a segment too short for the solver to separate its corners: one lasting less
        than :data:`SEGMENT_RESOLUTION` of its end time (the event times' rounding).
    """
    points = path.waypoints
    times = path.corner_times
    durations = np.diff(times)
    unresolved = np.flatnonzero(durations <= SEGMENT_RESOLUTION * times[1:])
    if unresolved.size:
        i = int(unresolved[0])
        raise ValueError(f"waypoints {i} {tuple(points[i].tolist())} and {i + 1} {tuple(points[i + 1].tolist())} are "
                         f"{durations[i]:.3g} s apart at t = {times[i + 1]:.6g} s; allowed for the continuum method: "
                         f"more than {SEGMENT_RESOLUTION:g} of the time (the solver cannot separate closer corners)")
    segments = []
    for i in range(len(points) - 1):
        dt = times[i + 1] - times[i]
        vx, vd = (points[i + 1, 0] - points[i, 0]) / dt, (points[i + 1, 1] - points[i, 1]) / dt
        vx = 0.0 if abs(vx) < NEGLIGIBLE_SHARE * path.speed else vx
        vd = 0.0 if abs(vd) < NEGLIGIBLE_SHARE * path.speed else vd
        segments.append(Segment(times[i], times[i + 1], points[i, 0], points[i, 1], vx, vd))
    return segments


#: The slip criterion classifies the levels ``x − cap ū`` to PIECE_SHARE of the indenter's travel
#: (:func:`~mdr_events.models.continuum.zones.length_scale`); for the critical shift to be known to 1e-3 of
#: itself the travel may be at most this many ``ū``. Below it, what remains of the force's error is the
#: positions' own rounding, ``eps`` times the travel: a few dozen ``eps travel/ū`` of ``τ0 A`` (7e-6 at the
#: limit).
MAX_TRAVEL_PER_CAP = 1e-3 / PIECE_SHARE
#: The other side, Coulomb's part: the centre's cap ``ū = K a + κ d`` is one of the lengths the slip criterion
#: resolves to PIECE_SHARE, while the shifts the springs hold are at most the travel; for those shifts to be
#: classified to 1e-3 of themselves (the standard of :data:`MAX_TRAVEL_PER_CAP`) ``ū`` may be at most this many
#: travels. Beyond it the springs that slide are a band at the compressed zone's edge of width ``~ travel/(κ g')``,
#: and the solver chased it: scenario A at 89° with μ = 1e8 (8.6e9 travels) 30 s, at 45° with μ = 1e9 (1.5e9) 11 s,
#: with μ = 1e10 to 1e13 (1.5e10 to 1.5e13) over a minute each; from about 1e14 travels the band lies within the
#: criterion's tolerance and runs are quick again, an end no bound is derived for, so one bound is stated.
MAX_CAP_PER_TRAVEL = 1e-3 / PIECE_SHARE


class Resolution(NamedTuple):
    """How far a path travels against the critical shift (:func:`resolution`).

    Parameters
    ----------
    travel : float
        The tangential travel (m).
    cap : float
        The critical shift of the centre (m) of the largest contact.
    """

    #: the tangential travel (m): the path's tangential length, or on a segment in the elastomer that
    #: changes the depth ``|v_x / v_d| a²/R``, whichever is larger
    travel: float
    #: the critical shift of the centre, ``ū = K a + κ d`` (m), of the largest contact (at the path's deepest point)
    cap: float

    @property
    def travel_per_cap(self) -> float:
        """``travel / ū``: at most :data:`MAX_TRAVEL_PER_CAP` for the continuum method (``0`` for τ0 = 0)."""
        return self.travel / self.cap if self.cap > 0 else 0.0


def resolution(model: ContinuumModel, path: Path, segments: list[Segment]) -> Resolution:
    """The path's tangential travel and the critical shift the slip criterion resolves it against.

    The travel over which the depth of the largest contact changes by its size, ``|v_x / v_d| a²/R``, is
    the spread of the anchors a growth lays down; the path's tangential length is how far the indenter
    moves. Both are positions the levels ``x − cap ū`` are computed from.

    Parameters
    ----------
    model : ContinuumModel
        The contact's branches and caps.
    path : Path
        The indenter's path.
    segments : list of Segment
        Its segments (:func:`kinematics`).

    Returns
    -------
    Resolution
        The travel and the centre's critical shift at the path's deepest point.
    """
    radius = model.grow.radius(max(path.max_depth, 0.0), model.tolerances.radius_rtol)
    travel = float(np.sum(np.abs(np.diff(path.waypoints[:, 0]))))
    for segment in segments:
        if segment.vd != 0.0 and max(segment.ds, segment.d(segment.t1)) > 0.0:
            travel = max(travel, abs(segment.vx / segment.vd) * model.grow.depth_term(radius))
    return Resolution(travel, model.caps.centre_shift(radius, max(path.max_depth, 0.0)))


def check_resolvable(model: ContinuumModel, path: Path, segments: list[Segment]) -> None:
    """Reject a path whose tangential travel the slip criterion cannot resolve against the critical shift
    (:func:`resolution`): more than :data:`MAX_TRAVEL_PER_CAP` ``ū``.

    In scenario A with the paper's geometry a ``τ0/G*`` below 2e-10 at 20°, or below 4e-6 at 1e-3°, puts
    ``ū`` below what double precision resolves against the positions, and the slip events would be lost:
    ``ValueError`` naming the numbers and what to change.
    """
    params = model.params
    if model.caps.frictionless:  # τ0 = 0 (or μ = 0): no spring holds any shift, nothing to resolve
        return
    travel, cap = resolution(model, path, segments)
    if not travel <= MAX_TRAVEL_PER_CAP * cap and model.caps.kappa > 0.0:
        raise ValueError(
            f"the friction law {model.friction.law!r} with mu={model.friction.mu!r} gives the centre's critical shift "
            f"ū = {cap:.3g} m at the deepest point, and the path travels {travel:.3g} m tangentially; allowed for the "
            f"continuum method: a travel of at most {MAX_TRAVEL_PER_CAP:.0e} ū = {MAX_TRAVEL_PER_CAP * cap:.3g} m "
            "(beyond it the slip events are lost to rounding): a larger mu, a shorter path, or method='discrete'")
    if model.caps.kappa > 0.0 and travel > 0.0 and not cap <= MAX_CAP_PER_TRAVEL * travel:
        raise ValueError(_coulomb_beyond_resolution(model, path, travel, cap))
    if not travel <= MAX_TRAVEL_PER_CAP * cap:
        raise ValueError(
            f"tau0={params.tau0!r} Pa with G*={params.G_star:.4g} Pa (τ0/G* = {params.tau0 / params.G_star:.3g}) gives "
            f"a critical shift ū = πaτ0/(2G*) = {cap:.3g} m at the deepest point, and the path travels "
            f"{travel:.3g} m tangentially; allowed for the continuum method: a travel of at most "
            f"{MAX_TRAVEL_PER_CAP:.0e} ū = {MAX_TRAVEL_PER_CAP * cap:.3g} m (beyond it the slip events are lost "
            "to rounding): a larger τ0/G*, a shorter path, tau0=0 for a frictionless contact, or method='discrete'")


def _coulomb_beyond_resolution(model: ContinuumModel, path: Path, travel: float, cap: float) -> str:
    """The refusal of a Coulomb's cap beyond :data:`MAX_CAP_PER_TRAVEL` travels, with the largest ``μ`` allowed:
    ``ū = K a + κ d`` with ``κ ∝ μ`` (:func:`~mdr_events.theory.mindlin.coulomb_cap_ratio`)."""
    mu, depth = model.friction.mu, max(path.max_depth, 0.0)
    tau0_part = model.caps.centre_shift(model.grow.radius(depth, model.tolerances.radius_rtol), 0.0)
    largest = max(MAX_CAP_PER_TRAVEL * travel - tau0_part, 0.0) / (model.caps.kappa * depth) * mu
    return (f"mu={mu!r} is not allowed for the continuum method on this path: the friction law "
            f"{model.friction.law!r} gives the centre's critical shift ū = {cap:.3g} m at the deepest point, "
            f"{cap / travel:.3g} times the path's tangential travel {travel:.3g} m, and the slip criterion resolves "
            f"the shifts to {PIECE_SHARE:g} ū; allowed: ū at most {MAX_CAP_PER_TRAVEL:.0e} travels, mu <= "
            f"{largest:.3g} on this path, or method='discrete'")
