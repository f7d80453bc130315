"""The exact reference of one path under a rate-dependent adhesion law, as a referee reads it: :class:`RateSolution`.

``validate`` compares a candidate with the continuum evaluated at the candidate's own times and with the continuum's
event log. Under the paper's law that is :class:`~mdr_events.models.continuum.solution.PathSolution`; under the
rate-dependent law it is the run ``simulate(method="continuum")`` makes of the path
(:func:`~mdr_events.models.continuum.rate_run.run_rate_continuum`: the radius an ODE state by
:data:`~mdr_events.models.continuum.rate_run.RUN_METHOD` at the tolerances' ``rtol``, the springs' shifts under
``τ0``'s cap on top), with the same quantities (:func:`~mdr_events.models.continuum.rate_run.rate_quantities`) and the
same log (:func:`~mdr_events.models.continuum.rate_run.rate_events`: first contact and re-contact, growth resuming,
detachment starting, the contact's end, corners, reversals, slip onsets, full slip, re-sticks). Both solutions answer
the referee's questions by the same names (:meth:`RateSolution.evaluate_at`, :meth:`RateSolution.normal_force_at`,
``end_time``, ``ended_by_contact``, ``events``, ``params``, ``path``, ``profile``, ``friction``, ``adhesion``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from mdr_events.contact.adhesion import RateDependentAdhesion
from mdr_events.contact.friction import FrictionLaw
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path
from mdr_events.parameters import Parameters

from .rate_run import RUN_METHOD, rate_events, rate_quantities, run_end, scan_run
from .rate_shifts import RateShifts, solve_rate_shifts
from .state import CONTACT_ENDING, Event
from .tolerances import Tolerances

__all__ = ["RateSolution", "solve_rate_reference"]


@dataclass(frozen=True)
class RateSolution:
    """The continuum's run of one path under a rate-dependent adhesion law, read as a referee reads a solution.

    Parameters
    ----------
    shifts : RateShifts
        The run (:func:`~mdr_events.models.continuum.rate_shifts.solve_rate_shifts`).
    params : Parameters
        The parameters solved.
    profile : PowerLaw, FlatPunch, TabulatedProfile or None
        The indenter (``None``: the paraboloid of ``params.R``).
    friction : FrictionLaw
        The friction law (``"tau0"``).
    adhesion : RateDependentAdhesion
        The adhesion law.
    events : list of Event
        The run's log (times from the path's first contact).
    end_time : float
        The run's end (s from first contact): the contact's end, or the path's.
    """

    shifts: RateShifts
    params: Parameters
    profile: SimulatedProfile
    friction: FrictionLaw
    adhesion: RateDependentAdhesion
    events: list[Event] = field(default_factory=list)
    end_time: float = 0.0

    @property
    def path(self) -> Path:
        """The path solved."""
        return self.shifts.path

    @property
    def events_not_timed(self) -> dict[str, str]:
        """The events whose time a sampled run cannot show at the order of its resolution, with why: the receding
        edge starts from rest, ``Δγ1 (ȧ/v_ref)^n = Γ − Δγ1`` growing linearly in time, so ``a`` falls as
        ``(t − t0)^(1 + 1/n)`` and a radius resolved to ``δa`` shows the start ``δa^(n/(n+1))`` late (``n = 0.5``:
        the lag of springs of ``Δx`` halves when ``Δx`` falls eightfold)."""
        return {"detachment_starts": "the rate law's receding edge starts from rest, a(t) flat to order 1 + 1/n: "
                                     "a sampled radius shows it at order n/(n+1) of its resolution"}

    @property
    def ended_by_contact(self) -> bool:
        """The run ended because the contact came apart (not at the end of the path)."""
        return bool(self.events) and self.events[-1].kind in CONTACT_ENDING

    def evaluate_at(self, times: np.ndarray) -> dict[str, np.ndarray]:
        """The quantities at ``times`` (s from first contact) as ``simulate``'s continuum run fills them.

        Parameters
        ----------
        times : numpy.ndarray
            The times (s from first contact, ``>= 0``).

        Returns
        -------
        dict of str to numpy.ndarray
            :func:`~mdr_events.models.continuum.rate_run.rate_quantities` at ``times``.
        """
        return rate_quantities(self.shifts, np.atleast_1d(np.asarray(times, dtype=float)))

    def normal_force_at(self, event: Event) -> float:
        """``F_N`` at ``event`` (its time on the run's clock).

        Parameters
        ----------
        event : Event
            An event of :attr:`events`.

        Returns
        -------
        float
            The normal force (N).
        """
        clock = min(event.time + self.path.first_contact_time(), self.path.duration)
        return float(self.shifts.normal_force(np.array([clock]))[0])


def solve_rate_reference(params: Parameters, path: Path, law: RateDependentAdhesion, tolerances: Tolerances,
                         profile: SimulatedProfile = None, friction: FrictionLaw | None = None) -> RateSolution:
    """The :class:`RateSolution` of ``path``: the run ``simulate(method="continuum")`` makes of it (module docstring).

    Parameters
    ----------
    params : Parameters
        The material, ``τ0`` and the works of adhesion at rest (the law's).
    path : Path
        The path.
    law : RateDependentAdhesion
        The adhesion law.
    tolerances : Tolerances
        Its ``rtol`` is the edge's ODE tolerance.
    profile : PowerLaw, FlatPunch, TabulatedProfile or None, optional
        The indenter (``None``: the paraboloid of ``params.R``).
    friction : FrictionLaw or None, optional
        ``"tau0"`` (``None``: the paper's ``"tau0"`` of ``params.tau0``).

    Returns
    -------
    RateSolution
        The run, its log and its end.

    Raises
    ------
    ValueError
        What :func:`~mdr_events.models.continuum.rate_shifts.solve_rate_shifts` refuses.
    """
    shifts = solve_rate_shifts(params, path, law, profile=profile, friction=friction, rtol=tolerances.rtol,
                               method=RUN_METHOD)
    end, _ = run_end(shifts)
    return RateSolution(shifts, params, profile, friction if friction is not None else FrictionLaw("tau0"), law,
                        rate_events(shifts, scan_run(shifts)), end - path.first_contact_time())
