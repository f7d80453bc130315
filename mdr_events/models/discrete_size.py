"""How many springs and samples a discrete run takes, checked before anything is allocated.

The spacing (at least :data:`MIN_SPRINGS_IN_CONTACT` springs per side in contact at the deepest point), the springs
the path's largest contact needs (within a layer's tables), and the time steps, springs and memory of a run against
the :class:`~mdr_events.limits.Limits` (:mod:`mdr_events.models.discrete`).
"""

from __future__ import annotations

import math

import numpy as np

from mdr_events.contact.adhesion import AdhesionLaw
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.io.agreement import ROUND_OFF
from mdr_events.limits import Limits
from mdr_events.models.indenters import SimulatedProfile
from mdr_events.models.paths import Path
from mdr_events.models.spring_media import HalfSpaceSprings, Springs, springs_of
from mdr_events.models.spring_thresholds import spring_thresholds
from mdr_events.parameters import Parameters
from mdr_events.theory.kinds import theory_of
from mdr_events.validation import allowed_bound, check_real

__all__ = ["MIN_SPRINGS_IN_CONTACT"]


#: Fewer springs than this per side at ``d_max`` is too coarse (an error).
MIN_SPRINGS_IN_CONTACT = 10


def _spring_count(springs: Springs, dx: float, max_depth: float, adhesion: AdhesionLaw) -> int:
    """Springs per side needed to hold the largest contact of the path, with margin: the springs probed and kept
    are those the kind's relations know (:meth:`~mdr_events.models.spring_media.LayerSprings.most_springs`: on a
    layer within the tables, whose last radius a contact near it passed by its margin, ``a/h = 64.001`` refused
    by the tables); a contact that needs more is refused in one line."""
    most, count = springs.most_springs(dx), 64
    while True:
        probed = min(count, most)
        positions = (np.arange(probed) + 0.5) * dx
        attach = spring_thresholds(adhesion, springs.profile(positions), positions, springs).attach
        needed = int(attach.count(np.array([max_depth]))[0])
        if needed < probed - 1:
            return needed + 2
        if probed == most:
            raise _beyond_the_tables(springs, dx, max_depth, needed, most)
        count *= 2


#: The springs a finer spacing keeps between the contact's edge and the tables' last radius: the count rounds up by
#: one at the edge, the tables' reach down by one, one spring beyond the edge is needed (3), with one of margin.
SPRINGS_TO_THE_TABLES_EDGE = 4


def _beyond_the_tables(springs: Springs, dx: float, max_depth: float, needed: int, most: int) -> ValueError:
    """The refusal of a contact whose springs, one beyond its edge, pass the layer's tables (``a/h = 64``) at ``dx``,
    naming what applies: a spacing that fits ``SPRINGS_TO_THE_TABLES_EDGE`` springs between the contact's radius and
    ``64 h`` where there is room (none at ``a/h = 64``, round twenty-four: "a smaller dx" was suggested there, which
    cannot help), a shallower depth (a flat punch: a smaller face, whose radius no depth changes), a thicker layer."""
    from mdr_events.theory.layer.compliance import LAMBDA_MAX

    thickness = springs.layer.thickness  # (only a layer's springs are bounded: the half-space's most is sys.maxsize)
    reach, radius = LAMBDA_MAX * thickness, springs.branch_radius(max_depth)
    finer = (reach - radius) / SPRINGS_TO_THE_TABLES_EDGE
    spacing = (f"dx <= {allowed_bound(finer, lambda value: value <= finer, True, 3)} m (the contact radius "
               f"{radius:.6g} m is {reach - radius:.3g} m within the tables' "
               f"64 h = {reach:.6g} m), " if finer > 0 else
               f"no dx (the contact radius {radius:.6g} m reaches the tables' 64 h = {reach:.6g} m), but ")
    smaller = (f"a face's radius below {reach:.6g} m (with a dx that fits {SPRINGS_TO_THE_TABLES_EDGE} springs "
               "between them)" if theory_of(springs.indenter).flat_face else  # (no depth changes a face's radius)
               f"a depth whose contact radius stays below {(most - 1) * dx:.6g} m")
    return ValueError(f"dx={dx!r} m: the contact at the depth {max_depth!r} m takes {needed} springs per side and the "
                      f"layer's tables reach {most} (a/h = 64), too few for one spring beyond its edge; allowed: "
                      f"{spacing}{smaller}, or a layer thicker than h = {thickness!r} m")


def check_spacing(params: Parameters, dx: float, depth: float | None = None, profile: SimulatedProfile = None,
                  layer: Layer = HALF_SPACE) -> float:
    """``dx`` as a float; reject a spring spacing that puts fewer than 10 springs per side in contact at
    the deepest point (``d_max``, or the given ``depth`` of a custom path) of ``profile`` (``None``: the paraboloid)
    on ``layer`` (default the half-space)."""
    dx = check_real("dx", dx, "a finite spring spacing > 0 (m)", lambda value: value > 0)
    depth = params.d_max if depth is None else depth
    radius = springs_of(params, profile, None, layer).branch_radius(depth)
    if not radius / dx >= MIN_SPRINGS_IN_CONTACT:
        most = allowed_bound(radius / MIN_SPRINGS_IN_CONTACT, lambda most: radius / most >= MIN_SPRINGS_IN_CONTACT,
                             True)
        raise ValueError(
            f"dx={dx!r} m puts {int(radius // dx) if radius == radius else 0} springs per side in contact "
            f"at the deepest point d = {depth!r} m; "
            f"allowed: at least {MIN_SPRINGS_IN_CONTACT}, i.e. dx <= "
            f"{most} m"
        )
    return dx


#: Bytes a discrete run allocates per case and time sample (the path, the kernel's output, the dataset),
#: and per spring of the half-space (thresholds, caps, the kernel's groups): measured with tracemalloc, rounded up;
#: each kind of springs counts its own (:attr:`~mdr_events.models.spring_media.HalfSpaceSprings.bytes_per_spring`).
BYTES_PER_SAMPLE = 160

BYTES_PER_SPRING = HalfSpaceSprings.bytes_per_spring


def _time_grid_size(paths: list[Path], dt: float) -> tuple[np.ndarray, np.ndarray, int]:
    """Each path's first contact and its duration from then on (s), and the samples ``k dt`` of the shared
    time grid that covers the longest. A duration that is a whole number of steps to the round-off of the division
    (``dt = duration / n_steps``) takes that number, whichever way another CPU rounds it."""
    starts = np.array([path.first_contact_time() for path in paths])
    durations = np.array([path.duration for path in paths]) - starts
    return starts, durations, int(math.ceil(durations.max() / dt * (1.0 - ROUND_OFF))) + 1


def check_discrete_size(params: Parameters, paths: list[Path], dx: float, dt: float, limits: Limits,
                        profile: SimulatedProfile = None, layer: Layer = HALF_SPACE) -> None:
    """Estimate a discrete run's time steps, springs and memory before anything is allocated, and refuse it
    past ``limits`` (:class:`~mdr_events.limits.ResourceLimitError` saying the estimate and how to raise it)."""
    _, _, n_time = _time_grid_size(paths, dt)
    deepest = max(path.max_depth for path in paths)
    kind = springs_of(params, profile, None, layer)
    springs = kind.branch_radius(deepest) / dx + 2
    limits.check(f"the discrete run (dx={dx!r} m, dt={dt:.6g} s, {len(paths)} case(s))",
                 steps=n_time * len(paths), samples=n_time * len(paths), springs=springs,
                 memory=len(paths) * n_time * BYTES_PER_SAMPLE + springs * kind.bytes_per_spring)
