"""Benchmark: the combined law's critical angle of scenario A (issue 28, item 4: the tests' time through the package).

Medians, measured interleaved in one run, of ``mindlin.critical_angle_A`` under ``"tau0+coulomb"`` (μ = 0.3) with the
paper's adhesion for a flat punch (its closed form) and a power law (``combined_onset.critical_angle_A``: a bisection
on the angle, each reading the onset excess on a grid of depths), and of the test that calls them most
(``tests/theory/test_flat_punch.py::test_a_subclass_is_of_its_bases_kind``, both of its cases).

``--against DIR`` measures a checkout of another commit side by side (``_side_by_side.py``: each checkout in a worker
process of its own, the repetitions alternating) and prints each figure's ratio before / now; ``--cpu`` times the
process's CPU time instead of the wall clock (the figure that compares on a shared machine).

Run: ``python benchmarks/bench_critical_angle.py [--repeat N] [--against DIR] [--cpu]``.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

from _side_by_side import clock_name, command_line, measure, print_ratios

#: The tasks timed.
TASKS = ("flat punch", "power law", "subclass test")


def _subclass_test():
    """The subclass test of this checkout (its module loaded from the worker's directory, the checkout's root)."""
    spec = importlib.util.spec_from_file_location("_bench_flat_punch", Path("tests/theory/test_flat_punch.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return lambda: [module.test_a_subclass_is_of_its_bases_kind(base, subclass) for base, subclass in module.SUBCLASSES]


def _tasks() -> dict[str, callable]:
    """Every task of :data:`TASKS` of this checkout, as a function to time (imports the checkout's package)."""
    import mdr_events as me
    from mdr_events.contact.friction import FrictionLaw
    from mdr_events.contact.indenters import FlatPunch, PowerLaw
    from mdr_events.theory import mindlin

    p, law = me.Parameters.paper(), FrictionLaw("tau0+coulomb", mu=0.3)
    tasks = {"flat punch": lambda: mindlin.critical_angle_A(law, p, FlatPunch(1.5e-3), True),
             "power law": lambda: mindlin.critical_angle_A(law, p, PowerLaw(2e3, 1.5), True),
             "subclass test": _subclass_test()}
    for task in tasks.values():
        task()  # once unmeasured: caches, lambdified relations
    return tasks


def main() -> None:
    parsed = command_line(__doc__.splitlines()[0], __file__, _tasks, repeat=5)
    if parsed is None:
        return
    options, roots = parsed
    medians = measure(list(roots.values()), __file__, list(TASKS), options.repeat, options.cpu)
    print(f"critical_angle_A under tau0+coulomb (mu = 0.3, the paper's adhesion), medians of {options.repeat} "
          f"({clock_name(options.cpu)}), interleaved")
    for name, found in zip(roots, medians):
        print(f"  {name}: " + ", ".join(f"{task} {found[task] * 1e3:.1f} ms" for task in TASKS))
    print_ratios(medians, TASKS)


if __name__ == "__main__":
    main()
