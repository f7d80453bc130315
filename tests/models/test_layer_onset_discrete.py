"""Two routes to slip onset on a layer: the discrete model's springs on a 5 mm and a 2 mm layer begin to slide at the
depth the layer's eq. (18) gives (mdr_events.theory.layer.slip_onset), within the springs' resolution."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me

#: The springs' spacing (m) and the samples of the path: the onset depth is resolved to one sample.
DX, STEPS = 5e-7, 40001


@pytest.mark.parametrize("h", [5e-3, 2e-3])
@pytest.mark.parametrize("alpha", [10.0, 20.0])
def test_the_discrete_springs_slide_where_the_layers_onset_says(h, alpha):
    contact = me.Contact.paper().replace(h=h)
    expected = me.d_crit(alpha, contact, "A", True)
    case = me.simulate(contact, me.Scenario("A", alpha=[alpha]), "discrete", dx=DX, n_steps=STEPS).isel(alpha=0)
    depth, sliding = case.indentation_depth.values, np.nan_to_num(case.sliding_fraction.values)
    first = int(np.argmax(sliding > 0.0))
    assert first > 0
    # the cap π a² τ0/K_t of the discrete radius (within Δx of the exact one: ū' ≈ ū/a, so Δd/d ≲ Δx/a, twice for
    # the attached springs' half spacing) and the sample the onset falls in
    radius = float(case.contact_radius[first])
    tolerance = 2.0 * DX / radius * expected + (depth[first] - depth[first - 1])
    assert abs(depth[first] - expected) <= tolerance, (depth[first], expected, tolerance)
