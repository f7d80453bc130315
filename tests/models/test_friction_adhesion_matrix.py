"""Issue 26's "done when" matrix: the three friction laws × {paraboloid, cone, n = 3, flat punch, a table of the
paraboloid} × {no adhesion, Δγ0 = Δγ1, Δγ0 < Δγ1, Δγ1 < Δγ0} × {scenario A, scenario B, a fretting path with
re-contact}, every cell run by the continuum and the discrete model, the springs converging to it at first order in
Δx (F_x, and F_N and A, which no friction law changes). Slow (180 cells, three discrete runs each, some 4 minutes of
CPU): run with ``-m slow``; the quick suite keeps cells other files do not check (:data:`QUICK`). It found a table's
level beyond the table's reach taken for the piece's start (tests/models/test_tabulated_models.py)."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.analysis.convergence import history_differences, observed_orders
from mdr_events.contact.friction import FrictionLaw
from mdr_events.models.paths import exit_depth

LAWS = {"tau0": FrictionLaw(), "coulomb": FrictionLaw("coulomb", mu=0.3),
        "tau0+coulomb": FrictionLaw("tau0+coulomb", mu=0.3)}
#: (Δγ0, Δγ1) in J/m²
ADHESIONS = {"none": (0.0, 0.0), "equal": (0.05, 0.05), "paper": (0.01, 0.15), "reversed": (0.15, 0.01)}
_R = np.linspace(0.0, 5e-3, 41)
INDENTERS = {"paraboloid": None, "cone": me.PowerLaw.cone(0.05), "n3": me.PowerLaw(2e5, 3.0),
             "punch": me.FlatPunch(1.5e-3), "table": me.TabulatedProfile(_R, _R**2 / (2 * 0.03))}
SCENARIOS = ("A", "B", "fretting")
#: The springs per contact radius at d_max of the three runs (Δx = a_max / each)
RESOLUTIONS = (100, 200, 400)
#: Observed order of the largest relative difference over the two halvings together: first order is 1; the share of
#: the error where the radius falls between springs need not fall with Δx (tests/models/test_friction_laws.py), so
#: the order is read over the whole range, above this
LEAST_ORDER = 0.7
#: Cells no other test checks against the springs: the cone and the table on scenarios A and B with Δγ1 < Δγ0 (the
#: radius drops onto the Δγ1 branch going out) under Coulomb's part; the quick suite runs these, the rest is slow
QUICK = [(law, indenter, "reversed", scenario) for law in ("coulomb", "tau0+coulomb") for indenter in ("cone", "table")
         for scenario in ("A", "B")]


def _path(scenario, params, profile):
    """Scenario A at 20°, B at 30°, or fretting at 0.6 d_max: in to 0.8 d_max, out to 0.6 d_max, ±0.3 d_max twice,
    out to −2 % d_max (held by adhesion, or off) and in again at 45° to d_max, out beyond the jump-off."""
    if scenario == "A":
        return me.Path.scenario_A(20.0, params, profile)
    if scenario == "B":
        return me.Path.scenario_B(30.0, params, profile=profile)
    d, X = params.d_max, 0.3 * params.d_max
    points = [(0.0, 0.0), (0.0, 0.8 * d), (0.0, 0.6 * d), (X, 0.6 * d), (-X, 0.6 * d), (X, 0.6 * d), (-X, 0.6 * d),
              (-X, -0.02 * d), (-X + d, d), (-X + d, exit_depth(params, profile))]
    return me.Path(np.array(points), params.v)


def _largest_radius(params, profile):
    """The contact radius at d_max on the Δγ0 branch (the punch's own)."""
    if isinstance(profile, me.FlatPunch):
        return profile.radius
    indenter = profile if profile is not None else me.PowerLaw.paraboloid(params.R)
    if isinstance(indenter, me.TabulatedProfile):
        indenter = me.PowerLaw.paraboloid(0.03)
    return float(me.power_law.contact_radius(params.d_max, indenter, params, params.dgamma0))


def _differences(law, indenter, adhesion, scenario):
    params = me.Parameters.paper().replace(dgamma0=ADHESIONS[adhesion][0], dgamma1=ADHESIONS[adhesion][1])
    profile, friction = INDENTERS[indenter], LAWS[law]
    path = _path(scenario, params, profile)
    radius = _largest_radius(params, profile)
    shortest = float(np.min(np.diff(path.corner_times)))
    spacings = [radius / count for count in RESOLUTIONS]
    coarsest = min(0.5 * spacings[0] / params.v, shortest / 10)  # (ten steps at least on every segment)
    found = {}
    for dx in spacings:
        dt = coarsest * dx / spacings[0]  # halved with Δx: first order in both
        discrete = me.simulate(params, path, dx=dx, dt=dt, friction=friction, profile=profile)
        exact = me.simulate(params, path, method="continuum", t=discrete["time"].values, friction=friction,
                            profile=profile)
        for name, values in history_differences(discrete, exact).items():
            found.setdefault(name, []).append(float(np.atleast_1d(values)[0]))
    return spacings, found


def _check(law, indenter, adhesion, scenario):
    spacings, found = _differences(law, indenter, adhesion, scenario)
    for name in ("tangential_force", "normal_force", "contact_area"):
        errors = np.array(found[name])
        if errors[0] == 0.0 or errors[-1] <= 1e-12:  # the same to rounding (no force: a frictionless cell)
            continue
        order = observed_orders(spacings[::2], errors[::2])[0]
        assert order > LEAST_ORDER, (name, errors)


CELLS = [(law, indenter, adhesion, scenario) for law in LAWS for indenter in INDENTERS for adhesion in ADHESIONS
         for scenario in SCENARIOS]


@pytest.mark.slow
@pytest.mark.parametrize("law, indenter, adhesion, scenario", [cell for cell in CELLS if cell not in QUICK],
                         ids=["-".join(cell) for cell in CELLS if cell not in QUICK])
def test_every_cell_converges_at_first_order(law, indenter, adhesion, scenario):
    _check(law, indenter, adhesion, scenario)


@pytest.mark.parametrize("law, indenter, adhesion, scenario", QUICK, ids=["-".join(cell) for cell in QUICK])
def test_the_cells_no_other_test_checks_converge_at_first_order(law, indenter, adhesion, scenario):
    _check(law, indenter, adhesion, scenario)
