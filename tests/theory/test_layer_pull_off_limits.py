"""The pull-off of the paraboloid on a thin layer: the SymPy limits of layer_symbolic (section 6: −2πRΔγ on Winkler's
foundation, −3πRΔγ on the thin incompressible bonded film) against layer_pull_off_curve, with the observed order.

The tables of (ν, base) = (0.5, bonded), (0.3, bonded), (0.5, frictionless) are read from the user's cache (built once).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from mdr_events import Contact
from mdr_events.contact.layer import Layer
from mdr_events.theory import layer_symbolic
from mdr_events.theory.layer import layer_pull_off_curve

#: The limit extrapolated from the numerics (a polynomial of degree 5 in h/a through six thicknesses at a/h ≈ 24–51):
#: within 1.1e-6 of SymPy's on the film, 3e-8 on Winkler's foundation; the tables' 1e-8 and Brent's minimum (the force
#: is flat there) are far below.
EXTRAPOLATION_TOL = 1e-5
#: The observed order of the error in h/a at the thinnest pair: 1 (an edge boundary layer of width ~h), reached from
#: below on the film (0.965 at a/h ≈ 50, the h²/a² term still seen), 0.997 and 1.000 on Winkler's foundation.
ORDER_TOL = 0.05
#: The paper's contact (R = 30 mm, E = 0.324 MPa, Δγ1 = 0.15 J/m²).
CONTACT = Contact.paper(R=0.03)


@pytest.mark.parametrize("nu, base, key", [(0.5, "bonded", "layer_thin_film_pull_off"),
                                           (0.3, "bonded", "layer_winkler_pull_off"),
                                           (0.5, "frictionless", "layer_winkler_pull_off")])
def test_the_thin_layer_pull_off_is_the_symbolic_limit(nu, base, key):
    rels = layer_symbolic.derive_layer_model()
    R, dgamma = CONTACT.indenter.R, CONTACT.adhesion.dgamma1
    limit = float(rels[key].numeric(R, dgamma))
    assert limit / (np.pi * R * dgamma) == pytest.approx(-3.0 if "film" in key else -2.0, rel=1e-15)
    contact = dataclasses.replace(CONTACT.replace(nu=nu), layer=Layer(1.0, base))
    film = "film" in key  # a ∝ h^(1/2) on the film, h^(1/4) on Winkler's foundation: a/h ≈ 24 ... 51
    thicknesses = np.geomspace(7.3e-6, 1.8e-6, 6) if film else np.geomspace(2.3e-5, 8.5e-6, 6)
    curve = layer_pull_off_curve(contact, thicknesses)
    force, eps = curve["pull_off_force"].values, 1.0 / curve["relative_radius"].values
    assert eps.max() < 1 / 20 and eps.min() > 1 / 60
    error = force / limit - 1.0
    order = np.log(error[-1] / error[-2]) / np.log(eps[-1] / eps[-2])
    assert abs(order - 1.0) < ORDER_TOL
    extrapolated = np.linalg.solve(np.vander(eps, 6), force)[-1]
    assert abs(extrapolated / limit - 1.0) < EXTRAPOLATION_TOL
    radius = rels["layer_thin_film_pull_off_radius" if film else "layer_winkler_pull_off_radius"]
    args = (R, dgamma, contact.elastomer.E / 3.0, thicknesses) if film else (
        R, dgamma, 2 * contact.elastomer.E / (2 * (1 + nu)) * (1 - nu) / ((1 - 2 * nu) * thicknesses)
        if base == "bonded" else contact.elastomer.E / (1 - nu**2) / thicknesses)
    ratio = curve["pull_off_radius"].values / radius.numeric(*args)
    assert np.all(np.abs(ratio - 1.0) < 2 * eps)  # first order in h/a too: |error| · a/h ≈ 1.6 (film), 0.2 (Winkler)
