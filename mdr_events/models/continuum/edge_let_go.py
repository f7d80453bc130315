r"""Where a receding rate-dependent edge lets go: it crosses into the radii whose release rate rises as they shrink.

The paper's contact jumps off where the ``Δγ1`` branch (9) turns (``dd/da = 0``, displacement control). A rate-dependent
edge has no jump: its radius falls to 0 over a finite time. It has let go once its release rate
``Γ(a, d) = E* (g(a) − d)² / (2π a)`` at the present depth rises as the radius shrinks, ``∂Γ/∂a <= 0`` (Griffith's
stability of the edge): from there on, the depth held or falling, the edge recedes ever faster and nothing stops it.
Solved for the depth (:func:`~mdr_events.theory.symbolic.derive_rate_dependent_adhesion`, ``let_go_depth``):

.. math:: d <= g(a) - 2 a\, g'(a)

which on the paraboloid is ``d <= −3 a²/R``: the turning point of every branch (9), so that as ``v_ref → ∞`` (the
edge on the ``Δγ1`` branch) the let-go is the paper's jump-off. On the flat punch (``g = g' = 0`` under the face) it is
the start of the receding: Kendall's detachment, all at once.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from scipy.optimize import brentq

from mdr_events.models.indenters import SimulatedProfile, check_simulated_profile
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters
from mdr_events.theory import symbolic

from .branch import make_branch
from .rate_edge import EdgeRun

__all__ = ["LetGo", "let_go", "LET_GO_XTOL"]

#: Brent's tolerance on the let-go time, as a share of the clock (the radius's ODE is resolved to about 1e-10 of it).
LET_GO_XTOL = 1e-13


class LetGo(NamedTuple):
    """Where the receding edge let go.

    Parameters
    ----------
    time : float
        s on the path's clock.
    depth : float
        The depth then (m).
    radius : float
        The contact radius then (m).
    """

    time: float  #: s on the path's clock
    depth: float  #: m
    radius: float  #: m


def let_go(run: EdgeRun, path: Path, params: Parameters, profile: SimulatedProfile = None) -> LetGo | None:
    """The first point of ``run`` (:func:`~mdr_events.models.continuum.rate_edge.solve_edge` along ``path``) at which
    the receding edge lets go (module docstring), found on the solver's steps and refined by Brent's method.

    Parameters
    ----------
    run : EdgeRun
        The edge along the path.
    path : Path
        The path the run followed.
    params : Parameters
        The material and ``R`` the run was solved with.
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter (``None``: the paraboloid of ``params.R``).

    Returns
    -------
    LetGo or None
        The time, depth and radius; ``None`` where no receding edge lets go on the path.
    """
    profile = check_simulated_profile(profile)
    shape = make_branch(params, 0.0, profile)  # g(a) and g'(a): the branch without adhesion
    depth_at = symbolic.derive_rate_dependent_adhesion()["let_go_depth"].scalar

    def margin(t: float) -> float:  # d − (g − 2 a g'): <= 0 once let go
        radius = float(run.radius(np.array([t]))[0])
        if not radius > 0.0:
            return -np.inf
        return float(path.position(t)[1]) - depth_at(shape.depth(radius), shape.slope(radius), radius)

    for t0, t1, _, solution in run.pieces:
        if not float(solution(t1)[0]) < float(solution(t0)[0]):
            continue  # (only a receding edge lets go)
        knots = np.unique(np.clip(getattr(solution, "ts", np.array([t0, t1])), t0, t1))
        values = [margin(t) for t in knots]
        crossed = [index for index, value in enumerate(values) if value <= 0.0]
        if not crossed:
            continue
        index = crossed[0]
        when = float(knots[0]) if index == 0 else brentq(margin, knots[index - 1], knots[index],
                                                         xtol=LET_GO_XTOL * max(abs(knots[index]), 1e-300))
        return LetGo(when, float(path.position(when)[1]), float(run.radius(np.array([when]))[0]))
    return None
