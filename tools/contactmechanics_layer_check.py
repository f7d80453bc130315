"""The outside check of the layer's normal problem (issue 34, item 6): ContactMechanics against the generalized MDR.

ContactMechanics (``pip install contactmechanics``; Pastewka's group) solves the non-adhesive contact of a rigid
surface with an elastic layer on a rigid base by a boundary-element method on a periodic FFT grid:
``PeriodicFFTElasticHalfSpace(..., thickness=h, poisson=ν)`` uses the Green's function of a layer bonded to a rigid
flat with a frictionless top (Carbone & Mangialardi, JMPS 2008, eq. A.30), the case ``LayerBase.BONDED`` of
``mdr_events.theory.layer``. The two routes share nothing but the elasticity: ContactMechanics resolves the contact
pressure on a grid and finds the contact area by a constrained conjugate-gradient minimisation; the MDR solves the
flat punch on the layer once (a Fredholm equation) and reads the paraboloid off it by the generalized MDR.

A non-adhesive paraboloid at depths that put ``a/h`` between 0.4 and 1.1, the paper's elastomer with ``ν = 0.49``
(below 0.5, where the layer's Green's function is regular). ContactMechanics' own errors are estimated, not assumed:
each case on two grids (``a/Δx`` about 16 and 32) and in two periodic boxes (``L`` about 16 and 32 contact radii; the
periodic images press the layer a little more); the finest is the reference and the two changes its uncertainty.
The half-space is not compared this way: in a periodic box its depth has no reference (the mean displacement of a
periodic half-space is set by a chosen stiffness at ``q = 0``), so the layer is compared directly.

Run in an environment that has both packages, e.g.::

    python3 -m venv /tmp/cmvenv && /tmp/cmvenv/bin/pip install contactmechanics -e .
    /tmp/cmvenv/bin/python tools/contactmechanics_layer_check.py \
        --out mdr_events/reproduction/data/layer_contactmechanics_check.csv

It records ContactMechanics' forces in that CSV, which ``mdr-events reproduce`` compares with the MDR computed afresh
(``results/README.md``, section "Layers of finite thickness"; ``tests/reproduction/test_layer_outside_check.py``);
ContactMechanics is not a dependency of the package or its tests. Measured on 2026-11-26 (ContactMechanics 1.8.3,
2 cores): 30 s.
"""

from __future__ import annotations

import argparse
import csv
import io
import math
import time
from pathlib import Path

import numpy as np

#: The paper's elastomer, with ν just below 0.5; the paper's 5 mm layer, bonded to its base.
E, NU, THICKNESS = 0.324e6, 0.49, 5e-3
#: (R in m, depth in m): a/h from 0.4 to 1.1.
CASES = ((0.03, 0.1e-3), (0.03, 0.2e-3), (0.03, 0.3e-3), (0.1, 0.3e-3))
#: Grid points per side of the coarse and the fine grid, and the box in contact radii (small and large).
GRIDS, BOXES = (256, 512), (16.0, 32.0)
#: ContactMechanics' stopping tolerance on the penetration (m): far below the depths' 1e-4 m.
PENETRATION_TOL = 1e-12


def mdr_case(R: float, depth: float) -> tuple[float, float]:
    """The MDR's contact radius and normal force of the non-adhesive paraboloid at ``depth`` on the layer."""
    import mdr_events as me
    from mdr_events.theory import layer

    E_star = E / (1.0 - NU**2)
    on_layer = me.Layer(THICKNESS, me.LayerBase.BONDED)
    radii = np.geomspace(1e-5, 0.5, 20001) * math.sqrt(R * depth) * 4.0
    depths = layer.branch_depth(radii, me.Paraboloid(R), E_star, NU, 0.0, on_layer)
    radius = float(np.interp(depth, depths, radii))
    force = float(layer.normal_force(depth, radius, me.Paraboloid(R), E_star, NU, on_layer))
    return radius, force


def contactmechanics_force(R: float, depth: float, points: int, box: float) -> float:
    """ContactMechanics' normal force (N) of the paraboloid at ``depth`` in a periodic box of side ``box``."""
    from ContactMechanics import PeriodicFFTElasticHalfSpace, make_system
    from SurfaceTopography import Topography

    x = (np.arange(points) - points / 2 + 0.5) * (box / points)
    X, Y = np.meshgrid(x, x, indexing="ij")
    surface = Topography(-(X**2 + Y**2) / (2.0 * R), physical_sizes=(box, box), periodic=True)
    substrate = PeriodicFFTElasticHalfSpace((points, points), E, physical_sizes=(box, box), thickness=THICKNESS,
                                            poisson=NU)
    system = make_system(substrate=substrate, surface=surface)
    result = system.minimize_proxy(offset=depth, pentol=PENETRATION_TOL, maxiter=20000)
    if not result.success:
        raise RuntimeError(f"ContactMechanics did not converge at R={R}, d={depth}, {points}², L={box}")
    return float(system.compute_normal_force())


def rows() -> list[dict[str, object]]:
    """One row per case: the MDR's numbers, ContactMechanics' finest and its two changes."""
    import ContactMechanics

    out = []
    for R, depth in CASES:
        radius, force = mdr_case(R, depth)
        coarse, fine = (contactmechanics_force(R, depth, n, BOXES[0] * radius) for n in GRIDS)
        # the larger box at the same spacing as the fine grid: twice the points
        large = contactmechanics_force(R, depth, 2 * GRIDS[1], BOXES[1] * radius)
        out.append({"R_m": R, "thickness_m": THICKNESS, "nu": NU, "depth_m": depth, "contact_radius_mdr_m": radius,
                    "a_over_h": radius / THICKNESS, "normal_force_mdr_N": force, "normal_force_cm_N": large,
                    "cm_grid_change": abs(fine - coarse) / abs(fine), "cm_box_change": abs(large - fine) / abs(large),
                    "relative_difference": (force - large) / large,
                    "contactmechanics_version": ContactMechanics.__version__})
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, required=True, help="the CSV to write")
    out = parser.parse_args().out
    start = time.perf_counter()
    table = rows()
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=list(table[0]), lineterminator="\n")
    writer.writeheader()
    for row in table:
        writer.writerow({key: (f"{value:.6g}" if isinstance(value, float) else value) for key, value in row.items()})
    out.write_text(text.getvalue())
    print(text.getvalue(), f"({time.perf_counter() - start:.0f} s)")


if __name__ == "__main__":
    main()
