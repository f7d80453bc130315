"""The paraboloid's slip-onset depths ``d_crit(α)``, (17), (18), (20), (21): one angle or a phase diagram's rows, the
roots of the cubic of (18) and the quartics of (21) vectorised over the angles, block by block.
"""

from __future__ import annotations

from typing import Literal, NamedTuple

import numpy as np

from mdr_events.limits import Limits, check_limits, values_in
from mdr_events.theory.analytic.arguments import _as_output, _rel
from mdr_events.theory.analytic.normal import jump_off
from mdr_events.theory.blocks import blockwise
from mdr_events.theory.roots import positive_polynomial_root
from mdr_events.theory.job import ContactLike, on_layer, paper_parameters
from mdr_events.validation import check_choice, check_flag, shown, validate_alpha

__all__ = ["d_crit", "d_crit_curves", "d_crit_rows", "D_CRIT_BYTES_PER_ANGLE", "D_CRIT_ROWS_BYTES_PER_ANGLE",
           "SCENARIOS", "BRANCHES"]

SCENARIOS = ("A", "B")
BRANCHES = ("pull-off", "indentation")
#: Bytes the half-space's slip onsets allocate per angle at their peak, counted against ``Limits.memory`` before the
#: angles are read (tracemalloc at 1e6 angles: :func:`d_crit` 26 without adhesion, 42 with; :func:`d_crit_rows` 43 in
#: scenario A, 59 in B's two rows), rounded up. Round twenty-five: ``d_crit`` of 1e8 angles (a view of one value, no
#: memory of its own) took 2.4 to 4.2 GB against the default 2 GiB, accepted.
D_CRIT_BYTES_PER_ANGLE = 48
D_CRIT_ROWS_BYTES_PER_ANGLE = 64


#: Degrees to radians: the factor of ``numpy.deg2rad``, whose own loop (one product by it) is ten times slower.
_RADIANS_PER_DEGREE = np.pi / 180.0


class _Tangent(NamedTuple):
    """tan α of validated angles for the closed forms: ``finite`` (1 where α = 90°) and ``vertical`` (α = 90°)."""

    finite: np.ndarray
    vertical: np.ndarray

    @classmethod
    def of(cls, alpha_deg: np.ndarray) -> "_Tangent":
        return cls(*blockwise(_tangent, alpha_deg))


def _tangent(alpha_deg: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The fields of :class:`_Tangent`."""
    vertical = alpha_deg == 90.0
    return np.where(vertical, 1.0, np.tan(alpha_deg * _RADIANS_PER_DEGREE)), vertical


def d_crit(
    alpha,
    contact: ContactLike,
    scenario: Literal["A", "B"] = "A",
    adhesion: bool = False,
    branch: Literal["pull-off", "indentation"] | None = None,
    *,
    d_max: float | None = None,
    limits: Limits | None = None,
):
    """Indentation depth at which the springs start to slide, eqs. (17)–(21).

    Parameters
    ----------
    alpha : float or array_like
        Path angle to the surface in degrees, in [0, 90].
    contact : Contact or Parameters
        Material, indenter (the paraboloid (4)), adhesion and ``τ0`` (13): a :class:`~mdr_events.Contact`, or a
        :class:`~mdr_events.Parameters` (the keywords of before, with its own ``d_max``). A contact on a layer of
        finite thickness bonded to its base (``Contact.layer``; a paraboloid or power law): the same equations with
        the layer's cap ``π a² τ0/K_t(a)`` and branches, solved in ``a``
        (:mod:`mdr_events.theory.layer.slip_onset`; an onset beyond the tables, ``a/h > 64``, is refused); the flat
        punch there: closed forms while its face is held, the root on its receding contact
        (:mod:`mdr_events.theory.layer.punch_onset`).
    scenario : {"A", "B"}
        ``"A"``: indentation at angle α from first contact, eqs. (14), (17),
        (18). ``"B"``: vertical indentation to ``d_max`` then motion at angle α,
        eqs. (19)–(21).
    adhesion : bool
        ``False``: non-adhesive contact radius (16), eqs. (17) and (20).
        ``True``: JKR radius (9), eqs. (18) and (21) with ``Δγ0`` on the way
        in and ``Δγ1`` on the way out.
    branch : {"pull-off", "indentation"}, optional
        Scenario B only (default "pull-off"): from ``d_max`` out at angle α (the "−" sign of (21),
        smaller root of (20)) or further in at angle α (the "+" sign, larger
        root of (20)).
    d_max : float, optional
        With a Contact: the depth of the motion (m; default the paper's 0.3 mm), which scenario B's (20), (21)
        start from.
    limits : Limits, optional
        What the onsets may take, checked before the angles are read (``None``: the defaults). On a layer each angle
        is a bisection on the layer's tables, :data:`~mdr_events.theory.layer.slip_onset.ONSET_STEPS_PER_ANGLE`
        steps; the half-space's closed forms take no steps, :data:`D_CRIT_BYTES_PER_ANGLE` of memory each.

    Returns
    -------
    float or numpy.ndarray
        ``d_crit`` in metres, the same shape as ``alpha``.

    Notes
    -----
    Root choice: each reduced polynomial (the cubic of (18) and the quartics
    of (21) in ``s = sqrt(a)``) has exactly one sign change, hence exactly one
    positive root (Descartes), and that is the one returned. In scenario A it
    lies on the stable JKR branch (``d = K a > 0``). On the pull-off branch of
    scenario B it may lie on the unstable branch ``a < a_jump-off(Δγ1)``: the
    contact then comes apart (jump-off at depth ``d_jump-off < 0``) before any
    spring slides, and ``-inf`` is returned.

    "Never slides" is encoded so that ``d > d_crit`` (indentation) or
    ``d < d_crit`` (pull-off) is the sliding region: α = 90° gives ``+inf``
    for scenario A and the indentation branch, ``-inf`` for the pull-off
    branch. α → 0 gives ``d_crit → 0`` (A) and ``→ d_max`` (B).

    Scenario B (21) assumes the contact radius follows (9) with ``Δγ1`` from
    the start of pull-off; in the model it is pinned first (see
    :mod:`mdr_events` docs on the continuum method).
    """
    params = None if on_layer(contact) else _onset_parameters(contact, "d_crit", d_max)
    scenario = check_choice("scenario", scenario, SCENARIOS)
    if scenario == "A" and branch is not None:
        raise ValueError(f"branch={shown(branch)} is not allowed with scenario 'A'; allowed: None (branch is for scenario B)")
    branch = "pull-off" if branch is None else branch
    branch = check_choice("branch", branch, BRANCHES)
    check_flag("adhesion", adhesion)
    if params is None:
        from mdr_events.theory.layer.slip_onset import check_onset_count, onset_depths

        check_onset_count(values_in(alpha), contact.layer, limits)  # (before the angles are read: a copy each)
        alpha_deg = validate_alpha(alpha)
        return _as_output(onset_depths(alpha_deg, contact, scenario, adhesion, branch, d_max, limits=limits),
                          alpha_deg)
    _check_onset_memory(values_in(alpha), limits, D_CRIT_BYTES_PER_ANGLE)  # (counted before they are read)
    alpha_deg = validate_alpha(alpha)
    return _as_output(_slip_onset(_Tangent.of(alpha_deg), params, scenario, adhesion, branch), alpha_deg)


def _check_onset_memory(count: int, limits: Limits | None, bytes_per_angle: int) -> None:
    """The memory of the half-space's slip onsets at ``count`` angles (``bytes_per_angle`` each: their closed forms
    take no steps) checked against ``limits`` (``None``: the defaults; anything else not a Limits named)."""
    check_limits(limits).check(f"the slip onset at {count} angles", memory=bytes_per_angle * count)


def _onset_parameters(contact: ContactLike, what: str, d_max: float | None) -> "Parameters":
    """:func:`~mdr_events.theory.job.paper_parameters` of a slip onset on the half-space, its scales checked as the
    phase diagram's and the runs' are (:func:`~mdr_events.theory.scales.check_representable`): ``E = 1e300`` gave
    ``d_crit = 0``, ``τ0 = 1e300`` or ``E = 1e-300`` ``inf``, each with NumPy's warning, and the layer's onsets hand
    theirs to :func:`~mdr_events.theory.layer.slip_onset.check_onset_contact`."""
    from mdr_events.theory.scales import check_representable  # (scales imports this module)

    params = paper_parameters(contact, what, d_max)
    check_representable(params)
    return params


def d_crit_curves(alpha, contact: ContactLike, scenario: Literal["A", "B"] = "A", *, d_max: float | None = None,
                  limits: Limits | None = None) -> dict[tuple[bool, str | None], np.ndarray]:
    """Every curve of :func:`d_crit` of a scenario at the same angles, their tangent computed once.

    Parameters
    ----------
    alpha : array_like
        Path angles in degrees, in [0, 90].
    contact : Contact or Parameters
        As for :func:`d_crit`.
    scenario : {"A", "B"}
        As for :func:`d_crit`.
    d_max : float, optional
        As for :func:`d_crit`.
    limits : Limits, optional
        As for :func:`d_crit_rows`.

    Returns
    -------
    dict
        ``(adhesion, branch)`` -> ``d_crit`` (m), an array of the shape of ``alpha``, each equal to
        :func:`d_crit` of those arguments: ``adhesion`` ``False`` and ``True``, ``branch`` ``None`` in scenario A,
        each of :data:`BRANCHES` in B (the rows of :func:`d_crit_rows`).
    """
    rows = d_crit_rows(alpha, contact, scenario, d_max=d_max, limits=limits)
    branches = (None,) if scenario == "A" else BRANCHES
    return {(adhesion, branch): rows[adhesion][row, ...] for row, branch in enumerate(branches)
            for adhesion in (False, True)}


def d_crit_rows(alpha, contact: ContactLike, scenario: Literal["A", "B"] = "A", *,
                d_max: float | None = None, limits: Limits | None = None) -> dict[bool, np.ndarray]:
    """The curves of :func:`d_crit_curves` as one array per adhesion, a row per branch, each computed into its row.

    Parameters
    ----------
    alpha : array_like
        The angles (degrees, 0 to 90) of every row.
    contact : Contact or Parameters
        The paraboloid under the paper's law (:func:`~mdr_events.theory.job.paper_parameters` reads it).
    scenario : {"A", "B"}
        Fig. 9a (one row, (17) and (18)) or 9b (two rows, (20) and (21)).
    d_max : float, optional
        With a Contact: the motion's depth (m).
    limits : Limits, optional
        What the rows may take (``None``: the defaults): :data:`D_CRIT_ROWS_BYTES_PER_ANGLE` of memory per angle,
        counted before the angles are read.

    Returns
    -------
    dict of bool to numpy.ndarray
        ``adhesion`` (``False``, ``True``) -> ``d_crit`` (m) of shape ``(branches, *alpha.shape)``: one row in
        scenario A, the rows of :data:`BRANCHES` in B, each equal to :func:`d_crit` of that branch (a phase diagram's
        variable as it is, without stacking 10⁵ angles' curves afresh).
    """
    params = _onset_parameters(contact, "d_crit", d_max)
    scenario = check_choice("scenario", scenario, SCENARIOS)
    _check_onset_memory(values_in(alpha), limits, D_CRIT_ROWS_BYTES_PER_ANGLE)  # (counted before they are read)
    alpha_deg = validate_alpha(alpha)
    tangent = _Tangent.of(alpha_deg)
    branches = (None,) if scenario == "A" else BRANCHES
    rows = {adhesion: np.empty((len(branches), *alpha_deg.shape)) for adhesion in (False, True)}
    for row, branch in enumerate(branches):
        for adhesion in (False, True):
            _slip_onset(tangent, params, scenario, adhesion, branch or "pull-off", out=rows[adhesion][row, ...])
    return rows


def _unless_vertical(vertical: np.ndarray, value: float, depth: np.ndarray) -> np.ndarray:
    """``np.where(vertical, value, depth)``: ``depth`` itself where no path is vertical (a block of 10⁵ angles holds
    90° at most once: no pass of three arrays for nothing)."""
    return np.where(vertical, value, depth) if vertical.any() else depth


def _slip_onset(tangent: _Tangent, p, scenario: str, adhesion: bool, branch: str,
                out: np.ndarray | None = None) -> np.ndarray:
    """:func:`d_crit` of checked arguments, at the angles of ``tangent`` (written into ``out`` where given)."""
    vertical, tan_finite = tangent.vertical, tangent.finite
    if scenario == "A":
        if not adhesion:
            def onset(tan_finite, vertical):
                depth = _rel("d_crit_A_hertz").numeric(tan_finite, p.R, p.tau0, p.G_star)
                return _unless_vertical(vertical, np.inf, depth)

            return blockwise(onset, tan_finite, vertical, out=out)
        coefficients = blockwise(lambda tan_finite: _rel("slip_A_jkr_cubic").coefficients(
            tan_finite, p.R, p.tau0, p.G_star, p.E_star, p.dgamma0), tan_finite)
        with np.errstate(invalid="ignore", divide="ignore"):  # 0/0 at the double root s = 0 (α = 0, Δγ = 0)
            root = positive_polynomial_root(coefficients, out=out)  # (the onset then replaces it, block by block)

        def onset(root, tan_finite, vertical):
            radius = np.where(np.isfinite(root), root, 0.0) ** 2
            depth = _rel("slip_depth_A").numeric(radius, tan_finite, p.tau0, p.G_star)
            return _unless_vertical(vertical, np.inf, depth)

        return blockwise(onset, root, tan_finite, vertical, out=out)

    pulling = branch == "pull-off"
    never = -np.inf if pulling else np.inf
    key = "pull_off" if pulling else "indentation"
    if not adhesion:
        def onset(tan_finite, vertical):
            k = _rel("slip_B_hertz_k").numeric(tan_finite, p.R, p.tau0, p.G_star)
            depth = _rel(f"d_crit_B_hertz_{key}").numeric(p.d_max, k)
            return _unless_vertical(vertical, never, depth)

        return blockwise(onset, tan_finite, vertical, out=out)
    work = p.dgamma1 if pulling else p.dgamma0
    coefficients = blockwise(lambda tan_finite: _rel(f"slip_B_jkr_quartic_{key}").coefficients(
        tan_finite, p.d_max, p.R, p.tau0, p.G_star, p.E_star, work), tan_finite)
    root = positive_polynomial_root(coefficients, out=out)  # (the onset then replaces it, block by block)
    unstable_below = jump_off(p, work)["contact_radius"] if pulling and work > 0.0 else None

    def onset(root, tan_finite, vertical):
        radius = root ** 2
        depth = _rel(f"slip_depth_B_{key}").numeric(radius, tan_finite, p.d_max, p.tau0, p.G_star)
        if unstable_below is not None:
            depth = np.where(radius < unstable_below, never, depth)
        return _unless_vertical(vertical, never, depth)

    return blockwise(onset, root, tan_finite, vertical, out=out)

