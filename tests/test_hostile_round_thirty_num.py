"""The thirtieth hostile round (issue 32), numbers across the model space: each class of what failed, with the cases
that showed it.

The round's cases combine the edges of every accepted range at once (indenters: paraboloids, cones, power laws to
n = 12, flat punches, tables with three points, plateaus, dense ones; every friction law; adhesion off, equal,
reversed, rate-dependent; the half-space and layers, thin and thick, bonded and frictionless, ν = 0 and 0.5; both
methods, the discrete at its stated spacing; scenarios at 0°, 1e-6°, 89.999°, 90°) and are listed with their outcomes
in the issue's closing note; what failed is below.
"""

from __future__ import annotations

import re
import warnings

import numpy as np
import pytest

import mdr_events as me

PAPER = me.Parameters.paper()
SOFT = me.Elastomer(1e3, 0.5)
#: The rate law of the cases (the paper's works, v_ref 1 µm/s, n = 0.5).
RATE = me.RateDependentAdhesion(0.01, 0.15, v_ref=1e-6, n=0.5)


def _every_variable_finite_in_contact(ds) -> None:
    alive = np.isfinite(ds["indentation_depth"].values)
    touching = alive & (ds["contact_area"].values > 0)
    for name, variable in ds.data_vars.items():
        if variable.dims == ds["indentation_depth"].dims and variable.dtype.kind == "f":
            where = touching if name in ("mean_pressure", "mean_shear_stress", "sliding_fraction") else alive
            assert np.all(np.isfinite(variable.values[where])), name


# -- C1: an advancing piece of the rate law's edge overshot its end radius: a spring there matched no attachment ------

@pytest.mark.slow
@pytest.mark.parametrize("indenter, scenario", [
    (me.Paraboloid(0.03), "B+"),
    (me.TabulatedProfile((0.0, 1e-3, 4e-3), (0.0, 1e-5, 1e-3)), "A"),
], ids=["paraboloid-B+", "three-point-table-A"])
@pytest.mark.parametrize("friction", [me.FrictionLaw("coulomb", mu=0.3),
                                      me.FrictionLaw("tau0+coulomb", mu=0.3, tau0=PAPER.tau0)],
                         ids=["coulomb", "tau0+coulomb"])
def test_the_rate_law_s_springs_run_where_the_edge_stops(indenter, scenario, friction):
    """C1: under the rate law with Coulomb's part, a vertical path on a soft elastomer (E = 1 kPa, d_max = 1 µm) ended
    in ``RuntimeError: springs at xi = [...] match no attachment of the radius's history ...: a bug to report``: the
    steps' polynomial of the advancing piece where the edge stops rose 2e-10 of itself above the piece's end radius,
    beyond which no attachment is looked for. A vertical path moves nothing tangentially: ``F_x`` is 0 throughout."""
    contact = me.Contact(SOFT, indenter, RATE, friction)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ds = me.simulate(contact, me.Scenario(scenario, 90.0, 1e-6, 1e-6), method="continuum")
    _every_variable_finite_in_contact(ds)
    force = ds["tangential_force"].values
    assert np.all(force[np.isfinite(force)] == 0.0)
