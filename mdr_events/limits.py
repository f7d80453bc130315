"""Resource limits, checked before a run starts: nothing silently takes minutes or gigabytes.

Every run estimates what it will need (time steps, springs, output samples, path waypoints, memory)
before it allocates anything; past a limit it raises :class:`ResourceLimitError`, which says the
estimate, the limit and how to raise it: ``limits=Limits(...)`` in Python, ``--limit NAME=VALUE``
on the command line. The defaults keep one run under about a minute and 2 GiB on a laptop.
"""

from __future__ import annotations

import dataclasses
import math
import re
from dataclasses import dataclass

from mdr_events.validation import PLAIN_NUMBER, check_real, plain_number, shown

__all__ = ["Limits", "ResourceLimitError", "DEFAULT_LIMITS", "LIMIT_UNITS", "parse_limit", "check_limits", "values_in",
           "in_study"]

#: What each limit counts, for messages and the CLI help.
LIMIT_UNITS = {
    "memory": "of memory (estimated)",
    "steps": "discrete time steps (all cases)",
    "springs": "springs per side",
    "samples": "output times (all cases)",
    "waypoints": "waypoints in one path (continuum)",
    "spans": "spans of one continuum run",
}

#: Suffixes ``--limit memory=8GiB`` understands.
MEMORY_SUFFIXES = {"KiB": 2**10, "MiB": 2**20, "GiB": 2**30, "TiB": 2**40, "kB": 1e3, "MB": 1e6, "GB": 1e9, "TB": 1e12}


class ResourceLimitError(ValueError):
    """A run would need more than a :class:`Limits` allows (a ``ValueError``: the input asks too much)."""


@dataclass(frozen=True)
class Limits:
    """What one run may use; the defaults keep it under about a minute and 2 GiB here.

    ``float("inf")`` switches a limit off.

    Parameters
    ----------
    memory : float, default 2 GiB
        Bytes of the arrays a run allocates (estimated from its sizes): default 2 GiB.
    steps : float, default 2e7
        Time steps of the discrete model, summed over the cases: default 2e7 (about 30 s here).
    springs : float, default 1e7
        Springs per side of the discrete model: default 1e7.
    samples : float, default 1e7
        Output times of the continuum method, summed over the cases: default 1e7.
    waypoints : float, default 2000
        Waypoints of one path for the continuum method: default 2000. Each growth segment adds a piece
        to the anchor map that every later span's zone layout reads (at a remembered cost per piece):
        2000 waypoints of a monotone path take about 8 s here, 1000 about 3 s.
    spans : float, default 10000
        Spans (closed-form plans integrated between events) of one continuum run: default 10000, some 20 s here at
        the dearest spans (``tau0+coulomb`` with adhesion, ~2 ms a span), 1 s at the paper's ``tau0`` (0.1 ms), where
        the runs of the tests and ``results/`` make at most some 40, and a reciprocating path about three a waypoint
        (100 cycles: 606), so that the waypoints' limit binds first on the paths it bounds. Counted as the run goes (the
        count is not known before): ``tau0+coulomb`` with adhesion on a curved indenter ends a receding span each
        time the edge crosses the annulus ``[x_c, a]``, whose width is ``~√Δγ``, so a small work of adhesion makes
        ``~1/√Δγ`` spans (1e-6 of the paper's: thousands).

    Raises
    ------
    ValueError
        A limit that is not a number > 0.
    """

    memory: float = 2.0 * 2**30
    steps: float = 2e7
    springs: float = 1e7
    samples: float = 1e7
    waypoints: float = 2000
    spans: float = 1e4

    def __post_init__(self) -> None:
        for field in dataclasses.fields(self):
            value = check_real(f"Limits.{field.name}", getattr(self, field.name), "a number > 0 (inf: no limit)",
                               lambda number: number > 0, finite=False)
            object.__setattr__(self, field.name, value)

    def check(self, what: str, **needed: float) -> None:
        """Raise :class:`ResourceLimitError` if any of ``needed`` (limit name → estimate) exceeds its limit.

        Parameters
        ----------
        what : str
            Names the run and the arguments that set its size, e.g. ``"the discrete run (dx=1e-10 m)"``.
        **needed : float
            The run's estimate of each resource by the limit's name (``memory``, ``steps``, ``springs``,
            ``samples``, ``waypoints``, ``spans``).

        Raises
        ------
        ResourceLimitError
            An estimate above its limit (or not a number), naming the run, each limit exceeded and how to raise it.
        """
        over = {name: value for name, value in needed.items() if not value <= getattr(self, name)}
        if over:
            parts = " and ".join(f"{_shown(name, value)} {LIMIT_UNITS[name]} (allowed: at most "
                                 f"{_shown(name, getattr(self, name))})" for name, value in over.items())
            raise ResourceLimitError(f"{what} needs {parts}; {_raising(over)} or make the run smaller")


def _raising(names) -> str:
    """How to raise the limits ``names``, in Python and on the command line (:func:`in_study` says it for a study)."""
    return (f"raise the limit with limits=Limits({', '.join(f'{name}=...' for name in names)}) "
            f"(command line: {' '.join(f'--limit {name}=...' for name in names)})")


#: :func:`_raising`'s advice as it stands in a message, its limits' names the group.
_RAISING = re.compile(r"raise the limit with limits=Limits\(([a-z]+=\.\.\.(?:, [a-z]+=\.\.\.)*)\) "
                      r"\(command line: [^)]*\)")


def in_study(message: str) -> str:
    """``message`` with the advice of a :class:`ResourceLimitError` to raise a limit (``limits=Limits(steps=...)``,
    ``--limit steps=...``) said for a study file, whose limits are its ``[limits]`` table (``mdr-events run`` and
    ``sweep`` take no ``--limit``; round twenty-eight)."""
    def said(match: re.Match) -> str:
        keys = ", ".join(f"{item.partition('=')[0]} = ..." for item in match.group(1).split(", "))
        return f"raise the limit in the study's [limits] table ({keys})"

    return _RAISING.sub(said, message)


def _shown(name: str, value: float) -> str:
    if name == "memory":
        return f"{value / 2**30:.3g} GiB"
    if name == "spans" and math.isfinite(value):  # (a count near its limit: 2001 against 2000, not 2e+03 twice)
        return f"{value:.0f}"
    return f"{value:.3g}"


#: The limits every run uses unless given others.
DEFAULT_LIMITS = Limits()


def values_in(values) -> int:
    """How many values a user's array or sequence holds, counted without reading them: an array's ``size``, a
    sequence's length (its first axis: the caller refuses more axes when it reads them), 1 for anything else.

    A grid given by the user is counted against :class:`Limits` with this before it is converted, checked for
    repeats or evaluated (round twenty-one: the phase diagram of 1e8 angles was refused only after the angles had been
    copied and sorted, 4.9 GB and a minute against the 2 GiB limit).

    Parameters
    ----------
    values : object
        An array, a sequence or one value.

    Returns
    -------
    int
        The count.
    """
    size = getattr(values, "size", None)
    if isinstance(size, int) and not isinstance(size, bool):
        return size
    try:
        return len(values)
    except TypeError:  # (one value, a generator: the caller's reading says what it is)
        return 1


def parse_limit(text: str, limits: Limits = DEFAULT_LIMITS) -> Limits:
    """``limits`` with one limit replaced from ``NAME=VALUE`` (the CLI's ``--limit``; ``memory`` takes
    ``8GiB``, ``500MB``, ... or bytes; ``inf`` switches a limit off)."""
    name, sep, value = text.partition("=")
    name, value = name.strip(), value.strip()
    if not sep or name not in LIMIT_UNITS:
        raise ValueError(f"--limit {shown(text)} is not allowed; allowed: NAME=VALUE with NAME one of "
                         f"{', '.join(LIMIT_UNITS)}")
    factor = 1.0
    if name == "memory":
        for suffix, size in MEMORY_SUFFIXES.items():
            if value.endswith(suffix):
                value, factor = value[: -len(suffix)].strip(), size
                break
    try:
        number = plain_number(value) * factor
    except ValueError:
        raise ValueError(f"--limit {shown(text)} is not allowed; allowed: a number > 0 or inf, {PLAIN_NUMBER}"
                         + (" (memory: with KiB, MiB, GiB, kB, MB, GB)" if name == "memory" else "")) from None
    return dataclasses.replace(limits, **{name: number})


def check_limits(limits) -> "Limits":
    """``limits`` if it is a :class:`Limits` (``None``: the defaults); else ``TypeError`` naming it."""
    if limits is None:
        return DEFAULT_LIMITS
    if not isinstance(limits, Limits):
        raise TypeError(f"limits={shown(limits)} ({type(limits).__name__}) is not allowed; allowed: a mdr_events.Limits")
    return limits
