"""The paths of ``benchmarks/bench_simulate.py`` that the routes' tests in tests/models/ run (imported by their
modules, written once): the paper's parameters and their non-adhesive twin, the zigzag, the reciprocating path and
the 41-point table of the paper's paraboloid."""

from __future__ import annotations

import math

import numpy as np

import mdr_events as me
from mdr_events.models.paths import exit_depth
from mdr_events.theory import analytic

PAPER = me.Parameters.paper()
#: The paper's parameters without adhesion (Hertz's branch).
HERTZ = PAPER.replace(dgamma0=0.0, dgamma1=0.0)
#: In with tangential reversals, a pinned zigzag, out (``bench_discrete.py``'s).
ZIGZAG = ((0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4), (-1e-4, 3e-4), (2e-4, -1e-4))


def paper_table() -> me.TabulatedProfile:
    """A 41-point table of the paper's paraboloid (``bench_simulate.py``'s)."""
    radii = np.linspace(0.0, 4e-3, 41)
    return me.TabulatedProfile(radii, radii**2 / (2 * PAPER.R))


def reciprocating() -> me.Path:
    """In at 20° to ``(x_c, d_max)``, ten cycles ``x_c ± 3 ū(a_max)``, out vertically (``bench_simulate.py``'s)."""
    amplitude = 3.0 * float(analytic.critical_shift(float(analytic.jkr_contact_radius(PAPER.d_max, PAPER,
                                                                                     PAPER.dgamma0)), PAPER))
    x_c = PAPER.d_max / math.tan(math.radians(20.0))
    turns = [(x_c + amplitude * (1 if i % 2 == 0 else -1), PAPER.d_max) for i in range(20)]
    return me.Path([(0.0, 0.0), (x_c, PAPER.d_max), *turns, (x_c, PAPER.d_max), (x_c, exit_depth(PAPER))], PAPER.v)
