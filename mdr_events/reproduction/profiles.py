"""Other indenters: the cone, the paraboloid, a quartic and the flat punch in scenario A, each against its closed
forms (Heß's rule; Kendall's punch), with the discrete model's gap to the continuum (``profiles_A20``)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import NamedTuple

import numpy as np

from mdr_events.app.result_files import PlannedFile, dataset_plan, figure_plan
from mdr_events.contact.indenters import FlatPunch, PowerLaw
from mdr_events.models.simulate import simulate
from mdr_events.parameters import Parameters
from mdr_events.plotting.profiles import plot_profile_comparison
from mdr_events.reproduction.common import FIGURE_DX, FIGURE_STEPS, event_times, first_or_nan
from mdr_events.reproduction.markdown import INTEGRATED_ACCURACY, markdown_table
from mdr_events.reproduction.section import Section, Step
from mdr_events.theory import power_law
from mdr_events.theory.kinds import theory_of

__all__ = ["PROFILES", "PROFILE_STEM", "PROFILE_ANGLE", "ProfileComparison", "ProfileRow", "matching_power_law",
           "profile_comparison", "profile_rows", "profile_lines"]

#: The power laws compared with the paper's paraboloid (scenario A at :data:`PROFILE_ANGLE`, R = 30 mm): each
#: with the paraboloid's non-adhesive contact radius at d_max; and the flat punch of that radius.
PROFILE_EXPONENTS = {"cone": 1.0, "paraboloid": 2.0, "quartic": 4.0}
PROFILE_PUNCH = "flat_punch"
PROFILE_ANGLE = 20.0


class ProfileComparison(NamedTuple):
    """Scenario A at :data:`PROFILE_ANGLE` for the indenters of :data:`PROFILE_EXPONENTS`, by name."""

    profiles: dict  #: name → PowerLaw or FlatPunch
    continuum: dict  #: name → simulation (continuum)
    discrete: dict  #: name → simulation (discrete, Δx = FIGURE_DX, FIGURE_STEPS steps)


def matching_power_law(n: float, params: Parameters) -> PowerLaw:
    """The power law ``f = c rⁿ`` whose non-adhesive contact radius at ``d_max`` is the paraboloid's, ``√(R d_max)``
    (the paraboloid itself for ``n = 2``)."""
    if n == 2.0:
        return PowerLaw.paraboloid(params.R)
    return power_law.with_radius_at(n, math.sqrt(params.R * params.d_max), params.d_max)


def profile_comparison(params: Parameters) -> ProfileComparison:
    """Continuum and discrete runs of scenario A at :data:`PROFILE_ANGLE` for each of :data:`PROFILE_EXPONENTS` and the
    flat punch of the paraboloid's radius at d_max (:data:`PROFILE_PUNCH`)."""
    profiles = {name: matching_power_law(n, params) for name, n in PROFILE_EXPONENTS.items()}
    profiles[PROFILE_PUNCH] = FlatPunch(math.sqrt(params.R * params.d_max))
    continuum = {name: simulate(params, "A", alpha=[PROFILE_ANGLE], method="continuum", profile=profile)
                 for name, profile in profiles.items()}
    discrete = {name: simulate(params, "A", alpha=[PROFILE_ANGLE], dx=FIGURE_DX, n_steps=FIGURE_STEPS, profile=profile)
                for name, profile in profiles.items()}
    return ProfileComparison(profiles, continuum, discrete)


class ProfileRow(NamedTuple):
    """One indenter of the comparison: its closed forms against the continuum's, and the discrete model's gap."""

    name: str
    profile: PowerLaw | FlatPunch
    pull_off_closed_form: float  #: pull-off force under force control (N)
    pull_off_continuum: float  #: the continuum's least normal force (N)
    onset_closed_form: float  #: slip-onset depth (18) (m; nan: none before d_max)
    onset_continuum: float  #: the continuum's first slip onset while indenting (m; nan: none)
    tangential_force_max: float  #: the continuum's largest F_x (N)
    discrete_difference: float  #: max_t ``|discrete − continuum|`` of F_x over its largest value


def profile_rows(comparison: ProfileComparison, params: Parameters) -> list[ProfileRow]:
    """The rows of the report's table of :func:`profile_comparison`."""
    rows = []
    for name, profile in comparison.profiles.items():
        exact, springs = comparison.continuum[name], comparison.discrete[name]
        onset = float(power_law.d_crit_A(PROFILE_ANGLE, profile, params, adhesion=True))
        found = event_times(exact, PROFILE_ANGLE, "slip_onset")
        corner = first_or_nan(event_times(exact, PROFILE_ANGLE, "corner"))
        kinds = list(exact["event_kind"].values[0])
        onset_continuum = float(exact["event_depth"].values[0, kinds.index("slip_onset")]) \
            if len(found) and found[0] < corner else math.nan
        on_grid = exact if np.array_equal(exact["time"].values, springs["time"].values) else simulate(
            params, "A", alpha=[PROFILE_ANGLE], method="continuum", t=springs["time"].values, profile=profile)
        largest = float(exact["tangential_force_max"].values[0])
        difference = float(np.nanmax(np.abs(springs["tangential_force"].values - on_grid["tangential_force"].values)))
        rows.append(ProfileRow(name, profile, power_law.pull_off_force(profile, params, params.dgamma1),
                               float(exact["normal_force_min"].values[0]), onset if onset < params.d_max else math.nan,
                               onset_continuum, largest, difference / largest))
    return rows



#: The stem of the comparison's files in ``results/``.
PROFILE_STEM = f"profiles_A{PROFILE_ANGLE:g}"


def _gap_text(value: float) -> str:
    """A discrete model's gap to the continuum's F_x as the tables print it: three digits, or ``< 1e-10`` below the
    accuracy of the continuum's F_x (the punch's springs are the continuum: their digits there differ between
    machines)."""
    return f"< {INTEGRATED_ACCURACY:g}" if abs(value) < INTEGRATED_ACCURACY else f"{value:.2e}"


def _profile_cells(row: ProfileRow) -> list[str]:
    onset = "none before d_max" if math.isnan(row.onset_closed_form) else f"{row.onset_closed_form * 1e3:.6f} mm"
    found = "none" if math.isnan(row.onset_continuum) else f"{row.onset_continuum * 1e3:.6f} mm"
    if theory_of(row.profile).flat_face:
        shape = [f"radius {row.profile.radius * 1e3:g} mm", "—"]
    else:
        shape = [f"{row.profile.c:#.6g}", f"{row.profile.n:g}"]
    return [row.name.replace("_", " "), *shape, f"{row.pull_off_closed_form:#.9g} N",
            f"{row.pull_off_continuum:#.9g} N", onset, found, f"{row.tangential_force_max:#.6g} N",
            _gap_text(row.discrete_difference)]


def profile_lines(comparison: ProfileComparison) -> list[str]:
    """The comparison of indenters: the closed forms of each power law against the continuum, and the discrete
    model's gap (:func:`profile_rows`)."""
    lines = [
        "## Other indenters: cone, paraboloid, quartic, flat punch",
        "",
        f"Scenario A at {PROFILE_ANGLE:g}° with the paper's material and adhesion for power laws `f = c rⁿ` that reach "
        "the paraboloid's (R = 30 mm) non-adhesive contact radius at d_max (`simulate(..., profile=PowerLaw(c, n))`), "
        "and the flat punch of that radius (`profile=FlatPunch(radius)`; "
        f"`{PROFILE_STEM}_<name>.nc`, `{PROFILE_STEM}_<name>_discrete.nc`, `{PROFILE_STEM}.png`). The closed forms are "
        "Heß's rule for the power law (`mdr_events.power_law`): the pull-off force under force control, which the "
        "least normal force of the displacement-controlled run equals, and the slip onset (18) while indenting; for "
        "the punch Kendall's pull-off force `−sqrt(8π a³ E* Δγ1)` and the onset `d = tan α K a` (full slip at once). "
        f"Discrete: Δx = {FIGURE_DX * 1e6:g} µm, {FIGURE_STEPS} steps; its largest gap to the continuum in F_x over the "
        "largest F_x.",
        "",
    ]
    lines += markdown_table(
        ["indenter", "c", "n", "pull-off force, closed form", "continuum F_N,min", "slip onset (18)", "continuum onset",
         "F_x,max", "discrete gap"],
        [_profile_cells(row) for row in profile_rows(comparison, Parameters.paper())])
    return lines + [""]


def _plans(comparison: ProfileComparison, out: Path, keep_agreeing: bool) -> list[list[PlannedFile]]:
    written, kept, plans = {}, {}, []
    for name in comparison.profiles:
        written[name], plan = dataset_plan(comparison.continuum[name], out / f"{PROFILE_STEM}_{name}.nc",
                                           keep_agreeing)
        kept[name], discrete_plan = dataset_plan(comparison.discrete[name],
                                                 out / f"{PROFILE_STEM}_{name}_discrete.nc", keep_agreeing)
        plans += [plan, discrete_plan]
    figure = plot_profile_comparison(written, kept)
    return [plans + [figure_plan(figure, out / f"{PROFILE_STEM}.png", keep_agreeing)]]


PROFILES = Section(
    name="profiles",
    steps=(Step(f"other indenters: cone, paraboloid, quartic and flat punch, scenario A at {PROFILE_ANGLE:g}° "
                f"(continuum; discrete at Δx = {FIGURE_DX * 1e6:g} µm)",
                lambda: profile_comparison(Parameters.paper())),),
    collect=lambda results: results[0],
    render=profile_lines,
    plan=_plans,
    writing="writing the other indenters (.nc, .png)",
    files=(f"- `{PROFILE_STEM}.png`, `{PROFILE_STEM}_<cone|paraboloid|quartic|flat_punch>.nc` (continuum) and "
           "`..._discrete.nc`:",
           "  other indenters in scenario A."),
)
