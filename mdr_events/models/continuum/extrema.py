"""Exact extrema of a continuum run: the largest and smallest ``F_N``, ``F_x`` and contact area ``A``.

Each comes from the solution's spans (:func:`mdr_events.models.continuum.span_extrema.extremum`: a scan
of every span brackets the extremum, the roots of its derivative refine it, from the span's dense output
and the branch's closed forms, :mod:`~mdr_events.models.continuum.stationary`), not from output samples,
so that it does not depend on the output grid. A run that ends because the contact comes apart (pull-off, or the contact ending
at zero radius) has ``F_N = F_x = A = 0`` just after its end, as the output samples show it
(:func:`~mdr_events.models.continuum.solution.evaluate`); that value counts too, at the run's end.
"""

from __future__ import annotations

from .solution import PathSolution
from .span_extrema import EXTREMUM_TIE, extremum, scan_spans

__all__ = ["EXTREMA_QUANTITIES", "EXTREMA_KINDS", "extremum_names", "solution_extrema"]

#: The quantities whose extrema :func:`solution_extrema` finds (names as in a simulation dataset).
EXTREMA_QUANTITIES = ("normal_force", "tangential_force", "contact_area")
#: Suffix of each extremum -> ``largest`` argument of :func:`extremum`.
EXTREMA_KINDS = {"max": True, "min": False}
#: The value of every quantity of :data:`EXTREMA_QUANTITIES` once the contact has come apart.
VALUE_AFTER_CONTACT = 0.0


def extremum_names(quantity: str, kind: str) -> tuple[str, str]:
    """The keys of :func:`solution_extrema` for ``quantity`` and ``kind`` (``"max"``/``"min"``):
    ``("<quantity>_<kind>", "<quantity>_<kind>_time")``."""
    return f"{quantity}_{kind}", f"{quantity}_{kind}_time"


def solution_extrema(solution: PathSolution) -> dict[str, float]:
    """The exact maximum and minimum of ``F_N``, ``F_x`` and ``A`` along a continuum run, and their times.

    Parameters
    ----------
    solution : PathSolution
        One path's continuum solution (:func:`mdr_events.models.continuum.solve_path`).

    Returns
    -------
    dict of str to float
        For each quantity ``q`` of :data:`EXTREMA_QUANTITIES` (N, N, m²): ``q_max``, ``q_max_time``,
        ``q_min``, ``q_min_time``; times in s from first contact, like a simulation's ``time``. The
        extremum is the one of :func:`~mdr_events.models.continuum.span_extrema.extremum` over the
        spans; if the run ends with the contact coming apart, the value 0 just after its end
        (at ``solution.end_time``) is taken instead where it is larger (max) or smaller (min) by
        more than rounding (``EXTREMUM_TIE`` of the quantity's size); a value within that rounding of
        zero is reported as 0. Where a value is reached more than once, the time is the one ``extremum`` finds
        (the earliest span holding it).
    """
    out: dict[str, float] = {}
    scan = scan_spans(solution)
    scan.prepare(tuple(quantity for quantity in EXTREMA_QUANTITIES  # (all at once)
                       if not (quantity == "tangential_force" and solution.compressed)))
    for quantity in EXTREMA_QUANTITIES:
        # (Coulomb's law alone with adhesion: F_x and its end are the compressed zone's run)
        source = solution.compressed if quantity == "tangential_force" and solution.compressed else solution
        found = {kind: extremum(source, quantity, largest, scan if source is solution else None)
                 for kind, largest in EXTREMA_KINDS.items()}
        size = max(abs(value) for _, value in found.values())
        for kind, largest in EXTREMA_KINDS.items():
            time, value = found[kind]
            # the 0 after the contact only where it is beyond the extremum by more than rounding (else the
            # extremum's earlier time stays, as for every tie)
            beyond = (VALUE_AFTER_CONTACT - value) * (1.0 if largest else -1.0)
            if source.ended_by_contact and beyond > EXTREMUM_TIE * size:
                time, value = source.end_time, VALUE_AFTER_CONTACT
            if abs(value) <= EXTREMUM_TIE * size:
                value = 0.0  # zero to rounding of the run's size (e.g. F_x at first contact): exactly zero
            value_name, time_name = extremum_names(quantity, kind)
            out[value_name], out[time_name] = float(value), float(time)
    return out
