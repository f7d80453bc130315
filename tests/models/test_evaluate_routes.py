"""``simulate``'s evaluate, dataset and front end (issue 28: ``simulate`` of A or B under 2 ms): each shortcut against
the route it replaced, kept here as the reference, bit for bit on every kind of continuum run (scenarios A and B, a
zigzag, fretting cycles, a table, a layer, a power law, the rate law, Coulomb's law with and without adhesion), on a
run of one sample and before the first contact.

- ``sample_radii._iterated_radii``: the paraboloid's iterated radius at one depth (a run's first sample, at first contact)
  kept by value; the reference is ``Branch.radii`` called each time;
- ``solution._kinematics``: the spans' numbers repeated over their times in one call; the reference repeats each
  number alone;
- ``io.datasets._dimensions``: the dataset's sizes read off its variables; the reference is ``xarray.Dataset``'s
  (its refusals too).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import mdr_events as me
from mdr_events.models.continuum import sample_radii
from mdr_events.models.continuum import solution as solution_module
from mdr_events.models.continuum import solve_path
from mdr_events.models.continuum.branch import Branch

PAPER = me.Parameters.paper()
#: Samples of the runs compared (the shortcuts do not depend on the count; a few hundred keep the file cheap).
SAMPLES = 301


def _contact(**changes) -> me.Contact:
    """The paper's contact with its parts ``changes`` (``indenter=``, ``layer=``, ...)."""
    return dataclasses.replace(me.Contact.paper(), **changes)


def _reciprocating() -> me.Path:
    """In at 20° to ``(x_c, d_max)``, ten fretting cycles of ``±20 µm``, out vertically."""
    x_c = PAPER.d_max / math.tan(math.radians(20.0))
    turns = [(x_c + 2e-5 * (1 if i % 2 == 0 else -1), PAPER.d_max) for i in range(20)]
    return me.Path([(0.0, 0.0), (x_c, PAPER.d_max), *turns, (x_c, PAPER.d_max), (x_c, -1e-4)], PAPER.v)


def _table() -> me.TabulatedProfile:
    """A 41-point table of the paper's paraboloid."""
    r = np.linspace(0.0, 4e-3, 41)
    return me.TabulatedProfile(r, r**2 / (2 * PAPER.R))


ZIGZAG = me.Path([(0, 0), (2e-4, 1.2e-4), (-1e-4, 2.1e-4), (1e-4, 3e-4), (-1e-4, 3e-4), (2e-4, -1e-4)], PAPER.v)
#: Every kind of continuum run: label -> (contact, motion).
RUNS = {
    "A 20°": lambda: (_contact(), me.Scenario("A", 20.0)),
    "B 30°": lambda: (_contact(), me.Scenario("B", 30.0)),
    "zigzag": lambda: (_contact(), me.Paths([ZIGZAG])),
    "reciprocating": lambda: (_contact(), me.Paths([_reciprocating()])),
    "table": lambda: (_contact(indenter=_table()), me.Scenario("A", 20.0)),
    "layer": lambda: (_contact(layer=me.Layer(5e-3)), me.Scenario("B", 30.0)),
    "power law": lambda: (_contact(indenter=me.PowerLaw(2.0e3, 3.0)), me.Scenario("A", 30.0)),
    "rate law": lambda: (_contact(adhesion=me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)),
                         me.Scenario("B", 30.0)),
    "Coulomb": lambda: (_contact(friction=me.FrictionLaw("tau0+coulomb", tau0=PAPER.tau0, mu=0.3)),
                        me.Scenario("A", 20.0)),
    "Coulomb with adhesion": lambda: (_contact(friction=me.FrictionLaw("coulomb", mu=0.3)), me.Scenario("B", 20.0)),
    "from above the surface": lambda: (_contact(), me.Paths([me.Path([(0.0, -1e-4), (1e-4, 2e-4), (2e-4, -1e-4)],
                                                                      PAPER.v)])),
}


def _reference_iterated_radii(branch, depth: np.ndarray) -> np.ndarray:
    """The route ``_iterated_radii`` replaced: the branch's iteration, called each time."""
    return branch.radii(depth)


def _reference_kinematics(solution, members, parts):
    """The route ``_kinematics`` replaced: each span's number repeated over its times by a call of its own."""
    lengths = [len(part) for part in parts]
    t = solution.t_contact + (np.concatenate(parts) if len(parts) > 1 else parts[0])
    segments = [span.segment for span in members]

    def each(values: list[float]) -> np.ndarray:
        return np.repeat(np.array(values, dtype=float), lengths)

    elapsed = t - each([segment.t0 for segment in segments])
    d = each([segment.ds for segment in segments]) + each([segment.vd for segment in segments]) * elapsed
    x = each([segment.xs for segment in segments]) + each([segment.vx for segment in segments]) * elapsed
    return t, d, x, each([span.pinned_radius for span in members]), lengths


#: Each replaced route by its name: the module it is looked up in when called (where a test patches it), and its
#: reference.
REFERENCES = {"_iterated_radii": (sample_radii, _reference_iterated_radii),
              "_kinematics": (solution_module, _reference_kinematics)}


def assert_same_bits(left, right) -> None:
    """Two datasets with the same variables, attributes and values, bit for bit (``nan`` where the other has it)."""
    assert list(left.variables) == list(right.variables) and left.attrs == right.attrs
    for name, variable in left.variables.items():
        assert variable.dims == right[name].dims and variable.attrs == right[name].attrs, name
        mine, theirs = np.asarray(variable.values), np.asarray(right[name].values)
        if mine.dtype.kind == "f":
            assert mine.tobytes() == theirs.tobytes(), name
        else:
            np.testing.assert_array_equal(mine, theirs, err_msg=name)


@pytest.mark.parametrize("replaced", [*REFERENCES, "all"])
@pytest.mark.parametrize("label", list(RUNS))
def test_each_route_is_its_reference_bit_for_bit(label, replaced, monkeypatch):
    """A run (cold, and warm: the second run of the same values, its first radius kept) is the run with the replaced
    route's reference (or every reference at once), bit for bit."""
    contact, motion = RUNS[label]()
    sample_radii._paraboloid_radius.cache_clear()
    cold = me.simulate(contact, motion, "continuum", samples=SAMPLES)
    warm = me.simulate(contact, motion, "continuum", samples=SAMPLES)
    with monkeypatch.context() as patched:
        for name, (module, reference) in REFERENCES.items():
            if replaced in (name, "all"):
                patched.setattr(module, name, reference)
        reference = me.simulate(contact, motion, "continuum", samples=SAMPLES)
    assert_same_bits(cold, reference)
    assert_same_bits(warm, reference)


@pytest.mark.parametrize("name", list(REFERENCES))
def test_each_patched_route_is_the_one_called(name, monkeypatch):
    """The module :data:`REFERENCES` patches each route in is the one its callers look it up in: a run with the route
    patched (the route itself, counted) calls the patch, so that the comparisons above replace the route and are not
    the run compared with itself (a route moved to another module, a stale name left where the tests patch it)."""
    module, _ = REFERENCES[name]
    route, calls = getattr(module, name), []

    def counted(*args):
        calls.append(args)
        return route(*args)

    sample_radii._paraboloid_radius.cache_clear()
    with monkeypatch.context() as patched:
        patched.setattr(module, name, counted)
        me.simulate(*RUNS["B 30°"](), "continuum", samples=SAMPLES)
    assert calls, name


def test_kept_iterated_radius_is_kept_and_taken_at_first_contact():
    """The paraboloid's first sample (at first contact, depth 0) is read from what is kept: the kept value is the
    iteration's, by depth (``0.0`` and ``-0.0`` apart, each the iteration's own), and other depths are not taken for
    it."""
    sample_radii._paraboloid_radius.cache_clear()
    path = me.Path.scenario_B(30.0, PAPER)
    solution = solve_path(PAPER, path)
    times = np.linspace(0.0, solution.end_time, 11)
    first = solution.evaluate_at(times)
    misses = sample_radii._paraboloid_radius.cache_info().misses
    assert misses >= 1  # (the first sample's; the last one, at the pull-off on the fold, is also a span's end)
    again = solution.evaluate_at(times)
    assert sample_radii._paraboloid_radius.cache_info().hits == misses
    np.testing.assert_array_equal(first["contact_radius"], again["contact_radius"])
    branch = Branch(PAPER, PAPER.dgamma0)
    for depth in (0.0, -0.0, 1e-6, 2e-4, branch.jump_off_depth):
        kept = sample_radii._iterated_radii(branch, np.array([depth]))
        assert kept.tobytes() == branch.radii(np.array([depth])).tobytes(), depth
    assert first["contact_radius"][0] == branch.radii(np.array([0.0]))[0]


def test_one_sample_evaluated_is_the_reference_bit_for_bit(monkeypatch):
    """``evaluate`` at one time (before the first contact, at it, inside a span, at the pull-off) as its reference."""
    path = me.Path([(0.0, -1e-4), (1e-4, 2e-4), (2e-4, -1e-4)], PAPER.v)
    solution = solve_path(PAPER, path)
    for time in (-solution.t_contact / 2.0, 0.0, solution.end_time / 3.0, solution.end_time):
        found = solution.evaluate_at(np.array([time]))
        with monkeypatch.context() as patched:
            for name, (module, route) in REFERENCES.items():
                patched.setattr(module, name, route)
            reference = solution.evaluate_at(np.array([time]))
        for name, values in found.items():
            assert values.tobytes() == reference[name].tobytes(), (time, name)


@pytest.mark.parametrize("label", ["A 20°", "zigzag", "Coulomb with adhesion"])
def test_assembled_dimensions_are_xarrays(label):
    """``io.datasets._dimensions`` (the sizes read off the variables) is the sizes ``xarray.Dataset`` gives the same
    variables, its order too, on a run's dataset; and where a size disagrees or a variable has no dimensions, both
    refuse it in the same words."""
    import xarray as xr

    from mdr_events.io.datasets import _dimensions, assembled

    contact, motion = RUNS[label]()
    run = me.simulate(contact, motion, "continuum", samples=SAMPLES)
    reference = xr.Dataset({name: run[name].variable for name in run.data_vars},
                           coords={name: run[name].variable for name in run.coords})
    assert list(_dimensions(dict(run.variables)).items()) == list(reference.sizes.items())
    scalar = assembled({"x": ((), 1.0, {}), "y": (("time",), [1.0, 2.0], {})}, {"time": ("time", np.arange(2.0), {})})
    assert dict(scalar.sizes) == {"time": 2} and scalar["y"].shape == (2,)
    refused = {"conflicting sizes for dimension 'time'": ({"x": (("time",), np.zeros(2), {}),
                                                           "y": (("time",), np.zeros(3), {})}, {}),
               "dimension 's' already exists as a scalar variable": ({"x": (("s",), np.zeros(2), {})},
                                                                     {"s": ((), 0.0, {})})}
    for words, (data, coords) in refused.items():
        for route in (assembled, xr.Dataset):
            with pytest.raises(ValueError, match=words):
                route(data, coords)


def test_assembled_sizes_are_the_variables_not_the_arrays_given(monkeypatch):
    """The sizes are read off each variable, not off the array the caller gave: a variable made transposed (its
    dimensions and values both) is sized as it is, as ``xarray.Dataset`` sizes it."""
    import xarray as xr

    from mdr_events.io import datasets

    def transposed(dims, values, attrs):
        return xr.Variable(tuple(reversed(dims)), np.asarray(values).T, attrs)

    monkeypatch.setattr(datasets, "_variable", transposed)
    made = datasets.assembled({"x": (("a", "b"), np.zeros((2, 3)), {})}, {})
    assert dict(made.sizes) == {"b": 3, "a": 2} == dict(xr.Dataset({"x": made["x"].variable}).sizes)


def test_a_numpy_work_finds_the_kept_radius():
    """A branch whose work of adhesion is a NumPy number (no key of its own, :func:`~mdr_events.memo.exact_key`) finds
    the radius kept for the same work as a float, and is its iteration's bit for bit."""
    sample_radii._paraboloid_radius.cache_clear()
    depth = np.array([0.0])
    kept = sample_radii._iterated_radii(Branch(PAPER, float(PAPER.dgamma0)), depth)
    numpy_branch = Branch(PAPER, np.float64(PAPER.dgamma0))
    found = sample_radii._iterated_radii(numpy_branch, depth)
    info = sample_radii._paraboloid_radius.cache_info()
    assert (info.misses, info.hits) == (1, 1)
    assert found.tobytes() == kept.tobytes() == numpy_branch.radii(depth).tobytes()


@pytest.mark.parametrize("dtype", ["float64", "float32", "int64", "int32", "uint8"])
def test_a_long_numeric_coordinate_is_the_one_xarray_makes(dtype):
    """A numeric coordinate longer than the shared ones (a run's times) is wrapped at once in its ``pandas.Index``:
    the dataset, its index (type, dtype, name, values) and the coordinate's variable (type, dtype, attributes,
    encoding) are those of ``xarray.Dataset``, the reference."""
    import xarray as xr

    from mdr_events.io.datasets import SHARED_INDEX_SIZE, assembled

    values = (np.arange(SHARED_INDEX_SIZE + 45) % 250).astype(dtype)
    data = {"y": (("time",), np.linspace(0.0, 1.0, values.size), {"units": "1"})}
    coords = {"time": ("time", values, {"units": "s", "long_name": "time"})}
    made, reference = assembled(data, coords), xr.Dataset(data, coords=coords)
    xr.testing.assert_identical(made, reference)
    index, expected = made.xindexes["time"], reference.xindexes["time"]
    assert (type(index), index.coord_dtype, type(index.index), index.index.dtype, index.index.name) == \
        (type(expected), expected.coord_dtype, type(expected.index), expected.index.dtype, expected.index.name)
    assert index.index.equals(expected.index)
    variable, wanted = made["time"].variable, reference["time"].variable
    assert (type(variable), variable.dtype, variable.attrs, variable.encoding) == \
        (type(wanted), wanted.dtype, wanted.attrs, wanted.encoding)


@pytest.mark.parametrize("profile, friction", [
    (None, None), (_table(), None), (me.PowerLaw(2.0e3, 3.0), me.FrictionLaw("tau0+coulomb", tau0=PAPER.tau0, mu=0.3)),
    (None, "tau0"), (me.FlatPunch(1e-3), None)])
def test_the_kept_contact_of_parameters_is_contact_from_parameters(profile, friction):
    """``simulate``'s front end keeps the contact of the keywords of before by value (``_contact_of``): the contact
    ``Contact.from_parameters`` makes, equal in every part, for equal values of another identity; a bad part refused
    with the same message each time (never kept)."""
    from mdr_events.models.simulate import _contact_of

    reference = me.Contact.from_parameters(PAPER, profile, friction)
    kept_contact = _contact_of(PAPER, profile, friction)
    again = _contact_of(dataclasses.replace(PAPER), profile, friction)
    assert kept_contact == reference and again is kept_contact and repr(kept_contact) == repr(reference)
    assert kept_contact.to_attrs() == reference.to_attrs()
    assert _contact_of(PAPER.replace(E=4e5), profile, friction).parameters(PAPER.d_max, PAPER.v).E == 4e5
    for _ in range(2):
        with pytest.raises(TypeError, match="profile=.* is not allowed"):
            _contact_of(PAPER, "cone", friction)
