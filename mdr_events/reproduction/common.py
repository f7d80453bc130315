"""What several sections of the reproduction share: the paper's radii and scenarios, the angles of its figures, the
discrete model they overlay, and reading events off a simulation's log."""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from mdr_events.models.motion import case_dimension

__all__ = ["RADII", "SCENARIOS", "FIGURE_NUMBERS", "FIGURE_ANGLES", "OVERLAY_ANGLE", "FIGURE_DX", "FIGURE_STEPS",
           "jobs", "event_times", "first_or_nan"]

#: The paper's two radii (m) by the label of their files.
RADII = {"R30": 0.03, "R100": 0.1}
SCENARIOS = ("A", "B")
#: The paper's figure of each scenario's simulations.
FIGURE_NUMBERS = {"A": "8", "B": "10"}
#: Angles of Fig. 8 and 10 (degrees).
FIGURE_ANGLES = (10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0)
#: The discrete model overlaid on the figures and used in the cross-check: its angle (degrees), spacing (m) and
#: time steps.
OVERLAY_ANGLE = 20.0
FIGURE_DX = 1e-6
FIGURE_STEPS = 10_000


def jobs() -> list[tuple[str, float, str]]:
    """Every (radius label, radius in m, scenario) the report covers."""
    return [(label, radius, scenario) for label, radius in RADII.items() for scenario in SCENARIOS]


def event_times(ds: xr.Dataset, label: float | str, kind: str) -> np.ndarray:
    """The times of every event of ``kind`` in the event log of the case ``label`` (its angle, or a custom
    path's label)."""
    case = ds.sel({case_dimension(ds): label})
    kinds = case["event_kind"].values
    return case["event_time"].values[kinds == kind]


def first_or_nan(values: np.ndarray) -> float:
    """The first of ``values``, nan if there is none."""
    return float(values[0]) if len(values) else math.nan
