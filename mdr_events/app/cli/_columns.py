"""Your columns: the options of ``validate`` and ``fit`` that say how a measured file's columns are named (``--names``),
in which units (``--units``) and from when its time counts (``--time-origin``), and the command line's words for a file
whose columns are not named as the quantities.

Like :mod:`~mdr_events.app.cli._options`, this module imports only the standard library when imported.
"""

from __future__ import annotations

import argparse
import contextlib
import math
from typing import Iterator, Sequence

from mdr_events.app.cli._options import UsageError


def column_options(parser: argparse.ArgumentParser, whose: str) -> None:
    """Your column names, units and time origin (``validate`` and ``fit``)."""
    from mdr_events.io.candidates import CANDIDATE_QUANTITIES

    parser.add_argument("--names", default=None, metavar="Q=COLUMN,...",
                        help="your column names, e.g. time=t,normal_force=Fn (quantities: "
                             f"{', '.join(CANDIDATE_QUANTITIES)})")
    parser.add_argument("--units", default=None, metavar="Q=UNIT,...",
                        help="your units, e.g. time=ms,normal_force=mN,contact_area=mm2 (default SI)")
    parser.add_argument("--time-origin", default="first_contact", metavar="ORIGIN",
                        help=f"what the {whose} time counts from: first_contact (default), path_start, or the "
                             f"{whose} time of first contact in s")


@contextlib.contextmanager
def names_on_the_command_line() -> Iterator[None]:
    """Say how to name a file's columns with ``--names`` where the columns were not found by their names
    (:class:`~mdr_events.io.candidates.UnnamedColumnError`, whose message says ``names={...}`` as Python writes it):
    ``... (on the command line --names time=<your column>)``, the quantity missing first (round 29: a lab's CSV of
    ``t, Fn`` was told only Python's ``names={'time': <your column>}``, which a command-line user cannot write)."""
    from mdr_events.io.candidates import UnnamedColumnError

    try:
        yield
    except UnnamedColumnError as error:
        more = ",..." if len(error.quantities) > 1 else ""
        raise UnnamedColumnError(f"{error} (on the command line --names {error.quantities[0]}=<your column>{more})",
                                 error.quantities) from None


def pairs(option: str, text: str | None, allowed: Sequence[str]) -> dict[str, str]:
    """``time=t,normal_force=Fn`` -> ``{"time": "t", "normal_force": "Fn"}``; a bad item names the option."""
    if text is None:
        return {}
    found: dict[str, str] = {}
    for item in text.split(","):
        key, equals, value = (part.strip() for part in item.partition("="))
        if not equals or not key or not value:
            raise UsageError(f"{option} {text!r}: {item.strip()!r} is not allowed; allowed: QUANTITY=VALUE pairs "
                             "separated by commas, e.g. time=t,normal_force=Fn")
        if key not in allowed:
            raise UsageError(f"{option} {text!r}: {key!r} is not allowed; allowed: {', '.join(allowed)}")
        if key in found:
            raise UsageError(f"{option} {text!r}: {key!r} is given twice; allowed: each quantity once")
        found[key] = value
    return found


def time_origin(text: str) -> str | float:
    """``--time-origin``: a name of :data:`~mdr_events.analysis.validate.TIME_ORIGINS` or a finite time in s."""
    from mdr_events.analysis.validate import TIME_ORIGINS

    if text in TIME_ORIGINS:
        return text
    from mdr_events.validation import plain_number

    try:
        value = plain_number(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise UsageError(f"--time-origin {text!r} is not allowed; allowed: {', '.join(TIME_ORIGINS)} or the runs' "
                         "time of first contact in s (a finite number, plain decimal: ASCII digits 0-9, an optional "
                         "sign, point and exponent)")
    return value
