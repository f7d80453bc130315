"""Which cases of a parametrized grid run in the quick round (``make test``) and which only in ``make test-all`` and CI
(issue 28, item 4).

A grid of several factors (laws × motions × adhesions, ...) checks each claim once per combination; most of its CPU
goes into combinations that exercise the same code as their neighbours. :func:`grid` keeps a chosen covering set in
the quick round and marks the other combinations ``slow`` (they still run in CI, unchanged), and refuses a covering
set that leaves out any value of any factor: every law, every motion, every adhesion is still run in the quick round,
so a gross fault in any one of them fails ``make test``.
"""

from __future__ import annotations

import itertools
import math
import os

import pytest

#: The share of a property test's examples (hypothesis, derandomized) that the quick round draws; ``make test-all`` and
#: CI draw them all, ``HYPOTHESIS_PROFILE=explore`` (conftest.py) five times as many, fresh.
QUICK_EXAMPLES_SHARE = 0.5
#: Whether this run is the quick round (``-m "not slow"``, ``make test``): set by conftest.py's ``pytest_configure``
#: before the test modules are collected.
QUICK = [False]


def examples(count: int) -> int:
    """A property test's ``max_examples``: ``count`` as CI draws them, :data:`QUICK_EXAMPLES_SHARE` of them (at least
    one) in the quick round, five times as many under ``HYPOTHESIS_PROFILE=explore``."""
    if os.environ.get("HYPOTHESIS_PROFILE") == "explore":
        return 5 * count
    return max(1, math.ceil(QUICK_EXAMPLES_SHARE * count)) if QUICK[0] else count


def grid(axes: dict[str, dict[str, object]], quick: set[tuple[str, ...]]) -> list:
    """Every combination of ``axes``' values as a ``pytest.param`` (id ``"a-b-c"``, in the axes' order, as stacked
    ``parametrize`` decorators name them), those whose ids are not in ``quick`` marked ``slow``.

    Parameters
    ----------
    axes : dict
        Each factor's argument name → its values by id (``{"law": {"coulomb": ..., "tau0+coulomb": ...}, ...}``);
        the test takes the argument names in this order.
    quick : set of tuple of str
        The combinations (one id per axis) run in the quick round.

    Raises
    ------
    ValueError
        If a combination of ``quick`` is not in the grid, or a value of some axis appears in none of them.
    """
    names = list(axes)
    ids = [tuple(values) for values in axes.values()]
    unknown = [case for case in quick if len(case) != len(names) or not all(
        value in axis for value, axis in zip(case, ids))]
    if unknown:
        raise ValueError(f"quick={sorted(unknown)!r} is not in the grid; allowed: one id of each of {names}")
    for position, (name, axis) in enumerate(zip(names, ids)):
        missing = set(axis) - {case[position] for case in quick}
        if missing:
            raise ValueError(f"quick leaves {name}={sorted(missing)!r} out of the quick round; allowed: a set that "
                             f"runs every value of every axis")
    return [pytest.param(*(axes[name][value] for name, value in zip(names, case)), id="-".join(case),
                         marks=() if case in quick else pytest.mark.slow)
            for case in itertools.product(*ids)]
