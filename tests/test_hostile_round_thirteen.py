"""The thirteenth hostile round (issue 32): each class of what failed, with the cases that showed it."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr_events as me

PAPER = me.Parameters.paper()


def _one_line_naming(call, named: str, errors=(ValueError, TypeError)) -> str:
    """The message of what ``call`` raises: one line, naming ``named`` and what is allowed."""
    with pytest.raises(errors) as caught:
        call()
    message = str(caught.value)
    assert named in message and "allowed" in message and "\n" not in message, message
    return message


# --- N1: the caches on disk (the derivations, the layer's tables) were no mere shortcut: the existence of a cache file
# was looked up before the `try` that makes any trouble a missed shortcut, so a cache directory the system refuses to
# look into (a name too long; below a directory without search permission) failed every derivation and every layer
# table with a raw OSError ('mdr-events derive' exited 2, "File name too long"); a store that failed (the cache file's
# name taken by a directory) left its temporary behind. One module reads and stores every cache file ----------------

@pytest.fixture
def unreachable_cache(tmp_path, monkeypatch):
    """A cache directory whose files the system refuses to look at: their names are too long (ENAMETOOLONG)."""
    monkeypatch.setenv("MDR_EVENTS_CACHE_DIR", str(tmp_path / ("x" * 300)))
    monkeypatch.delenv("MDR_EVENTS_NO_CACHE", raising=False)


def test_a_cache_the_system_refuses_is_only_a_missed_shortcut(unreachable_cache):
    from mdr_events.theory.layer import table_store
    from mdr_events.theory.symbolic.cache import _cached

    built = _cached("round-thirteen-probe", lambda: [])  # (derived afresh, not an OSError)
    assert built == []
    grid = np.linspace(0.0, 1.0, 5)
    columns = table_store.stored_columns(table_store.cache_directory() / "probe.npz", ("s", "y"), grid,
                                         lambda: {"s": grid, "y": 2.0 * grid})
    np.testing.assert_array_equal(columns["y"], 2.0 * grid)


def test_a_store_that_fails_leaves_no_temporary(tmp_path):
    from mdr_events.theory.layer import table_store

    grid = np.linspace(0.0, 1.0, 5)
    taken = tmp_path / "table.npz"
    taken.mkdir()  # (the cache file's name is a directory: the store's rename fails)
    table_store.stored_columns(taken, ("s", "y"), grid, lambda: {"s": grid, "y": grid})
    assert sorted(path.name for path in tmp_path.iterdir()) == ["table.npz"]


# --- N2: the tangential layer theory (mdr_events.theory.layer_tangential, new since round twelve) had not been given
# round twelve's checks of the normal one: nan and inf results from G* = nan or 0, a product beyond the double range, a
# depth of nan; negative radii and moduli accepted (negative stiffnesses); Python's words for strings, None, arrays
# that do not broadcast, a missing solution; a direct solve at a/h = 1000 (two minutes) and nodes = 10**6 (MemoryError,
# 7 TiB), the kernel at v = 1e4 (15 s), the coupling's scan of 0 or 1.5 points; a multi-line message naming an array of
# radii (the cases below fail on the code before in seconds: smaller sizes than those that took minutes). Each
# relation checks its arguments by name before it runs and its result after (checks.checked_relation), the
# solve shares the normal one's bounds (punch.solve_size) ----------------------------------------------------------
from mdr_events.theory import layer_tangential as T  # noqa: E402

G_STAR, NU, THIN = 2.88e5, 0.3, me.Layer(1e-3)


def _solution(lam: float) -> T.TangentialPunchSolution:
    """A solution at ``lam`` as a solve would give it (shapes only: what is refused is refused before it is read)."""
    return T.TangentialPunchSolution(lam, NU, np.array([0.5]), np.array([1.0]), np.ones((1, 2)), np.ones(2))


@pytest.mark.parametrize("call, named", [
    (lambda: T.tangential_punch_stiffness(1e-3, math.nan, NU, THIN), "G_star=nan is not allowed"),
    (lambda: T.tangential_punch_stiffness(-1e-3, G_STAR, NU, THIN), "a=-0.001 is not allowed"),
    (lambda: T.tangential_punch_stiffness("x", G_STAR, NU, THIN), "a='x' (of str values) is not allowed"),
    (lambda: T.tangential_punch_stiffness(1e-3, "x", NU, THIN), "G_star='x' (str) is not allowed"),
    (lambda: T.tangential_punch_stiffness(1e308, 1e308, NU, me.Layer()), "tangential_punch_stiffness(a=1e+308"),
    (lambda: T.tangential_punch_stiffness_slope(1e-3, -1.0, NU, THIN), "G_star=-1.0 is not allowed"),
    (lambda: T.tangential_spring_stiffness_density(math.inf, G_STAR, NU, me.Layer()), "x=inf is not allowed"),
    (lambda: T.sliding_cap(1e-3, 4e4, 0.0, NU, THIN), "G_star=0.0 is not allowed"),
    (lambda: T.sliding_cap(1e308, 1e308, 1e-308, NU, me.Layer()), "sliding_cap(a=1e+308, tau0=1e+308"),
    (lambda: T.coulomb_cap(1e-4, math.nan, 0.0, 0.3, 4.3e5, G_STAR, NU, THIN), "depth=nan is not allowed"),
    (lambda: T.coulomb_cap(np.ones(3) * 1e-4, np.ones(2) * 1e-4, 0.0, 0.3, 4.3e5, G_STAR, NU, THIN),
     "which do not broadcast"),
    (lambda: T.tangential_compliance(math.nan, NU, "longitudinal"), "t=nan is not allowed"),
    (lambda: T.tangential_compliance(0.0, NU, "transverse", "frictionless"), "t=0.0 is not allowed"),
    (lambda: T.tangential_compliance(1e-320, NU, "transverse", "frictionless"), "t=1e-320 is not allowed: C_T"),
    (lambda: T.tangential_kernel(math.nan, NU, "longitudinal"), "v=nan is not allowed"),
    (lambda: T.tangential_kernel(1e3, NU, "longitudinal"), "v=1000.0 is not allowed; allowed: finite numbers with"),
    (lambda: T.coupling_ratio(-1.0, NU), "t=-1.0 is not allowed"),
    (lambda: T.coupling_bound(NU, 0), "points=0 is not allowed; allowed: an integer >= 3"),
    (lambda: T.coupling_bound(NU, 1.5), "points=1.5 (float) is not allowed"),
    (lambda: T.coupling_bound(NU, 10**12), "the coupling's scan of 1000000000000 points"),
    (lambda: T.solve_tangential_punch(1000.0, NU, nodes=16), "a/h=1000.0 is not allowed for a direct solve"),
    (lambda: T.solve_tangential_punch(1.0, NU, nodes=10**6), "the layer's Nyström solve with 1000000 nodes"),
    (lambda: T.solve_tangential_punch(0.0, NU).modes_at(math.nan), "tau=nan is not allowed"),
    (lambda: T.contact_displacement(None, 0.5), "solution=None (NoneType) is not allowed"),
    (lambda: T.contact_displacement(_solution(1.0), np.linspace(0.0, 2.0, 100)),
     "rho[50]=1.0101010101010102 is not allowed"),
    (lambda: T.contact_displacement(_solution(2000.0), 0.5), "the tangential displacement at 1 radii (a/h = 2000)"),
    (lambda: T.TangentialTable(NU, {}).stiffness_factor("x"), "lam='x' (of str values) is not allowed"),
])
def test_the_tangential_layer_theory_names_what_it_cannot_compute(call, named):
    _one_line_naming(call, named)


def test_the_tangential_layer_theory_is_unchanged_where_it_computes():
    """The checks are before and after: valid calls give the numbers they gave (the module's own tests cover them)."""
    assert float(T.tangential_punch_stiffness(1e-3, G_STAR, NU, me.Layer())) == 2.0 * G_STAR * 1e-3
    assert float(T.sliding_cap(0.0, 4e4, G_STAR, NU, me.Layer())) == 0.0
    assert float(T.tangential_compliance(0.0, NU, "transverse")) == 0.0  # (C_T = tanh t)


# --- N3: phase_diagram_at_speeds counted one solve of the edge per angle, but a steep angle's onset lies far below
# d_max and the way in doubles up to 40 times to reach it, a solve each (89.9999°: 35 solves, 29 s): 1000 such angles
# passed the default limits (1e7 of 2e7 steps) and ran for hours. The count is that of the doublings up to the
# rate-independent onset (18), which bounds the rate-dependent one (an advancing edge's work is below Δγ0) -----------
RATE_LAW = me.RateDependentAdhesion(PAPER.dgamma0, PAPER.dgamma1, 1e-6, 0.6)


def test_the_rate_phase_diagram_counts_the_doublings_of_its_steep_angles(monkeypatch):
    from mdr_events.analysis import rate_angles

    def never(*args, **kwargs):
        raise AssertionError("the edge was solved: the limits passed")

    monkeypatch.setattr(rate_angles, "solve_edge", never)
    _one_line_naming(lambda: me.phase_diagram_at_speeds(PAPER, RATE_LAW, [1e-6], np.linspace(89.99, 89.9999, 1000)),
                     "the phase diagram at 1 speeds and 1000 angles (31594 solves of the edge)")


def test_the_doublings_counted_bound_those_a_steep_angle_takes(monkeypatch):
    """At 80° the onset lies 170 d_max deep: the way in doubles 8 times, 9 solves, as many as counted."""
    from mdr_events.analysis import rate_angles

    solved = []
    real = rate_angles.solve_edge
    monkeypatch.setattr(rate_angles, "solve_edge", lambda *args, **kwargs: solved.append(1) or real(*args, **kwargs))
    rate_angles.slip_onset_depth_at_speed(PAPER, RATE_LAW, 1e-6, 80.0, method="LSODA")
    assert len(solved) <= rate_angles._onset_solves(PAPER, [80.0], None) == 9


# --- N4: the layer's curves (layer_normal_curve, layer_indentation_cycle, layer_pull_off_curve, new since round
# twelve) computed the half-space's radii of their scan unchecked: R = 1e308 gave a raw ZeroDivisionError, R = 1e-300 or
# a power law's c = 1e300 an OverflowError, E = 1e308 scipy's "Bracketing values ... do not fulfill this requirement";
# no depth numpy's "zero-size array to reduction operation maximum", a layer so thin that no scan point fits on it
# "attempt to get argmin of an empty sequence", and a cycle without adhesion (Hertz on a layer) scipy's bracketing
# error; Layer.relative_radius gave a/h = inf. The curves check the scales they compute with as the simulators do, and
# take the contact without adhesion; a/h is finite or refused ---------------------------------------------------------
LAYERED = me.Contact.paper().replace(h=5e-3)
HERTZ = me.Contact.paper().replace(dgamma0=0.0, dgamma1=0.0)


@pytest.mark.parametrize("call, named", [
    (lambda: me.layer_normal_curve(LAYERED.replace(R=1e308), [1e-5]), "the half-space's radii overflow"),
    (lambda: me.layer_indentation_cycle(LAYERED.replace(R=1e-300), 1e-4, 5), "the half-space's radii overflow"),
    (lambda: me.layer_indentation_cycle(LAYERED.replace(E=1e308), 1e-4, 5), "E* is 1.33e+308 Pa"),
    (lambda: me.layer_pull_off_curve(me.Contact.from_parameters(PAPER, profile=me.PowerLaw(1e300, 1.0)), [1e-3]),
     "layer_pull_off_curve: the half-space's radii overflow"),
    (lambda: me.layer_normal_curve(LAYERED.replace(dgamma0=1e300, dgamma1=1e308), [1e-5]), "Δγ1 is 1e+308 J/m²"),
    (lambda: me.layer_normal_curve(LAYERED, []), "depths=[] is not allowed"),
    (lambda: me.layer_pull_off_curve(LAYERED, []), "thicknesses=[] is not allowed"),
    (lambda: me.layer_pull_off_curve(LAYERED, [1e-9]), "the pull-off radius lies beyond a/h = 64"),
    (lambda: me.Layer(1e-300).relative_radius(1e308), "radius=1e+308 is not allowed on layer h = 1e-300 m"),
])
def test_the_layer_curves_name_what_they_cannot_compute(call, named):
    _one_line_naming(call, named, ValueError)


def test_a_cycle_without_adhesion_is_hertz_s_on_the_half_space():
    """Without adhesion the cycle loads and unloads along d = g(a) from and back to the first touch (d = 0, a = 0):
    on the half-space Hertz's a = sqrt(R d), F = (4/3) E* sqrt(R) d^(3/2), to round-off."""
    cycle = me.layer_indentation_cycle(HERTZ, 1e-4, 5)
    depth, radius, force = (cycle[name].values for name in ("depth", "contact_radius", "normal_force"))
    R, E_star = HERTZ.indenter.R, HERTZ.elastomer.E_star
    np.testing.assert_allclose(radius, np.sqrt(R * depth), rtol=1e-13, atol=0.0)
    np.testing.assert_allclose(force, 4.0 / 3.0 * E_star * np.sqrt(R) * depth**1.5, rtol=1e-12, atol=0.0)
    assert depth[-1] == radius[-1] == force[-1] == 0.0


# --- N5: the layer's sizes were not counted against Limits: a cycle of 10**9 samples was taken (the process was
# killed for its memory), 10**8 depths of a normal curve or 10**6 thicknesses of a pull-off curve (8 ms each: two
# hours) likewise, and equivalent_profile's one direct solve per radius (10**7 radii: hours). Each is counted before
# it runs, with limits= --------------------------------------------------------------------------------------------
from mdr_events.theory import layer as L  # noqa: E402


@pytest.fixture
def no_work(monkeypatch):
    """The curves' and the equivalent profile's work replaced by a failure: what is counted is refused before it."""
    from mdr_events.theory.layer import curves, relations

    def never(*args, **kwargs):
        raise AssertionError("the work began: the sizes were not counted")

    for module, name in ((curves, "stable_radius"), (curves, "pull_off"), (relations, "_solve")):
        monkeypatch.setattr(module, name, never)


@pytest.mark.parametrize("call, named", [
    (lambda: me.layer_indentation_cycle(LAYERED, 1e-4, 10**8), "layer_indentation_cycle to d_max=0.0001 m (300000000"),
    (lambda: me.layer_normal_curve(LAYERED, np.linspace(0.0, 1e-4, 10**7)), "(20000000 points)"),
    (lambda: me.layer_pull_off_curve(LAYERED, np.geomspace(1e-3, 1.0, 10**4)), "layer_pull_off_curve (10000 points)"),
    (lambda: me.layer_pull_off_curve(LAYERED, [1e-3], limits=me.Limits(steps=1.0)), "layer_pull_off_curve (1 points)"),
    (lambda: L.equivalent_profile(np.linspace(0.0, 1e-3, 10**6), lambda r: r / 0.03, 0.5, me.Layer(1e-3)),
     "equivalent_profile at 1000000 radii (1000000 direct solves)"),
    (lambda: L.equivalent_profile([1e-3], lambda r: r / 0.03, 0.5, me.Layer(1e-3), limits=me.Limits(steps=1.0)),
     "equivalent_profile at 1 radii"),
])
def test_the_layer_s_sizes_are_counted_before_they_run(call, named, no_work):
    _one_line_naming(call, named, me.ResourceLimitError)


def test_an_equivalent_profile_beyond_a_direct_solve_is_refused_before_the_first():
    calls = []
    _one_line_naming(lambda: L.equivalent_profile([1e-4, 0.5], lambda r: calls.append(r) or r / 0.03, 0.5,
                                                  me.Layer(1e-3)), "a/h=500.0 is not allowed for a direct solve")
    assert calls == []


# --- N6: layer_pull_off_curve's result could not be written: write_netcdf refused it ("attrs lack the parameter
# attribute(s) ['param_d_max', 'param_v']"), which the curve had dropped. Every layer result reads back identical --
@pytest.mark.parametrize("result", [
    lambda: me.layer_normal_curve(LAYERED, [1e-4, 2e-4]),
    lambda: me.layer_indentation_cycle(LAYERED, 2e-4, 5),
    lambda: me.layer_pull_off_curve(LAYERED, [5e-3]),
    lambda: me.layer_pull_off_curve(me.Contact.paper(), [5e-3, math.inf]),
])
def test_every_layer_result_is_written_and_reads_back_identical(result, tmp_path):
    import xarray as xr

    dataset = result()
    again = me.open_result(me.write_netcdf(dataset, tmp_path / "layer.nc"))
    xr.testing.assert_identical(again, dataset)


# --- N7: two API errors in Python's words: check_half_space (public in mdr_events.contact, every entry point's
# refusal of a layer) took None or a Parameters to an AttributeError ('NoneType' object has no attribute 'layer'); the
# rate-dependent grids read a generator of speeds as one speed ("speeds[0]=<generator ...>; allowed: finite numbers")
@pytest.mark.parametrize("call, named", [
    (lambda: me.contact.check_half_space(None, "simulate"), "contact=None (NoneType) is not allowed in simulate"),
    (lambda: me.contact.check_half_space(PAPER, "simulate"), "(Parameters) is not allowed in simulate"),
    (lambda: me.critical_angles_at_speeds(PAPER, RATE_LAW, (speed for speed in [1e-6])),
     "is not allowed; allowed: a non-empty 1-D sequence of finite numbers > 0 (m/s)"),
])
def test_the_api_names_the_wrong_kind_of_argument(call, named):
    message = _one_line_naming(call, named, TypeError)
    assert "speeds[0]" not in message
