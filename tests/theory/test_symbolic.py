"""SymPy results against quadrature, finite differences and the unreduced statements."""

import math
import re

import numpy as np
import pytest
import sympy as sp
from scipy import integrate, optimize

from mdr_events import Parameters

from mdr_events.theory import symbolic
from mdr_events.theory.symbolic import relation
from mdr_events.theory.symbolic.cache import _cached

R, E_STAR, G_STAR, TAU0, DGAMMA, D_MAX = 0.03, 0.432e6, 0.288e6, 42e3, 0.15, 0.3e-3


def abel_quadrature(df, x):
    """g(x) = x ∫_0^x f'(r)/sqrt(x²−r²) dr with r = x sin φ (no endpoint singularity)."""
    value, _ = integrate.quad(lambda phi: df(x * np.sin(phi)), 0.0, np.pi / 2, epsabs=0, epsrel=1e-13)
    return x * value


@pytest.mark.parametrize("n", [1.0, 1.5, 2.0, 3.0, 4.5])
def test_power_law_abel_transform_against_quadrature(n):
    c, x = 2.7, 0.8
    rel = relation("profile_power_law")
    expected = abel_quadrature(lambda r: c * n * r ** (n - 1), x)
    assert float(rel.numeric(x, c, n)) == pytest.approx(expected, rel=1e-11)


def test_paraboloid_and_cone_are_cases_of_the_power_law():
    power = relation("profile_power_law").rhs
    s = symbolic
    paraboloid = power.subs({s.n: 2, s.c: 1 / (2 * s.R)})
    assert sp.simplify(paraboloid - relation("profile_paraboloid").rhs) == 0
    assert sp.simplify(relation("profile_paraboloid").rhs - s.x**2 / s.R) == 0
    cone = power.subs({s.n: 1, s.c: sp.tan(s.theta)})
    assert sp.simplify(cone - relation("profile_cone").rhs) == 0
    x = 1.3e-3
    assert float(relation("profile_paraboloid").numeric(x, R)) == pytest.approx(
        abel_quadrature(lambda r: r / R, x), rel=1e-12)


def test_jkr_depth_satisfies_hess_rule_at_the_boundary():
    """(9): the boundary spring's elongation −u_z(a) equals Δl_max(a) of (8)."""
    for a in (1e-4, 1e-3, 3e-3):
        d = relation("jkr_depth").numeric(a, R, E_STAR, DGAMMA)
        elongation = -relation("normal_displacement").numeric(d, a, R)
        assert elongation == pytest.approx(math.sqrt(2 * math.pi * a * DGAMMA / E_STAR), rel=1e-13)


def test_normal_force_is_the_integral_of_the_springs():
    """(10): F_N = 2 E* ∫_0^a (d − g(x)) dx, checked by quadrature and by a fine spring sum."""
    for a in (5e-4, 2e-3):
        d = relation("jkr_depth").numeric(a, R, E_STAR, DGAMMA)
        quad, _ = integrate.quad(lambda x: E_STAR * (d - x**2 / R), -a, a, epsrel=1e-13)
        assert relation("jkr_normal_force").numeric(a, R, E_STAR, DGAMMA) == pytest.approx(quad, rel=1e-11)
        n = 200_000
        dx = 2 * a / n
        x = -a + dx * (np.arange(n) + 0.5)
        springs = np.sum(E_STAR * dx * (d - x**2 / R))
        assert springs == pytest.approx(quad, rel=1e-8)


def test_pull_off_force_is_the_minimum_of_the_jkr_force():
    force = lambda a: relation("jkr_normal_force").numeric(a, R, E_STAR, DGAMMA)  # noqa: E731
    res = optimize.minimize_scalar(force, bounds=(1e-5, 1e-2), method="bounded",
                                   options={"xatol": 1e-12})
    assert res.fun == pytest.approx(-1.5 * math.pi * DGAMMA * R, rel=1e-9)
    assert relation("pull_off_force").numeric(R, DGAMMA) == pytest.approx(-1.5 * math.pi * DGAMMA * R, rel=1e-14)
    assert relation("pull_off_radius").numeric(R, E_STAR, DGAMMA) == pytest.approx(res.x, rel=1e-5)


def test_jump_off_radius_zeroes_the_finite_difference_slope():
    a = relation("jump_off_radius").numeric(R, E_STAR, DGAMMA)
    assert a**3 == pytest.approx(math.pi * DGAMMA * R**2 / (8 * E_STAR), rel=1e-13)
    depth = lambda x: relation("jkr_depth").numeric(x, R, E_STAR, DGAMMA)  # noqa: E731
    h = a * 1e-5
    slope = (depth(a + h) - depth(a - h)) / (2 * h)
    scale = abs(depth(a)) / a
    assert abs(slope) < 1e-8 * scale
    assert relation("jump_off_depth").numeric(R, E_STAR, DGAMMA) == pytest.approx(depth(a), rel=1e-13)
    assert relation("jump_off_force").numeric(R, DGAMMA) == pytest.approx(
        relation("jkr_normal_force").numeric(a, R, E_STAR, DGAMMA), rel=1e-12)


def test_jump_in_radius_is_the_zero_depth_radius():
    a0 = relation("jump_in_radius").numeric(R, E_STAR, DGAMMA)
    assert relation("jkr_depth").numeric(a0, R, E_STAR, DGAMMA) == pytest.approx(0.0, abs=1e-15)


def test_hertz_limits_of_the_jkr_relations():
    d = 2e-4
    a = relation("hertz_radius").numeric(d, R)
    assert a == pytest.approx(math.sqrt(R * d), rel=1e-15)
    assert relation("jkr_depth").numeric(a, R, E_STAR, 0.0) == pytest.approx(d, rel=1e-14)
    assert relation("hertz_normal_force").numeric(d, R, E_STAR) == pytest.approx(
        4 * E_STAR * math.sqrt(R) * d**1.5 / 3, rel=1e-14)


# (a, τ0, G*) of different magnitudes, so that a swapped argument or a wrong power shows
SHIFT_POINTS = [(2e-3, TAU0, G_STAR), (7.5e-4, 1.3e3, 4.1e7), (0.11, 9.0e5, 2.2e3), (3.3e-6, 0.42, 0.9)]


@pytest.mark.parametrize("a, tau0, g_star", SHIFT_POINTS)
def test_critical_shift_and_stationary_sliding_against_independent_formulas(a, tau0, g_star):
    """(12), (13) against the formulas written out by hand.

    ``relation("critical_shift")`` must be ``ū = π a τ0 / (2 G*)`` at points where each argument
    has its own magnitude (fails on a changed factor, a wrong power of ``a``, or ``args`` in
    another order than ``(a, tau0, G_star)``); ``relation("stationary_shear_stress")`` must be
    ``τ = 2 G* u / (π a)``, linear in the shift (fails if the derivation of (12) changes a
    factor, e.g. ``n Δx = a`` instead of ``2a``), and must give back ``τ0`` at ``ū(a)`` (fails
    if (12) and (13) disagree).
    """
    u_bar = relation("critical_shift").numeric(a, tau0, g_star)
    assert u_bar == pytest.approx(math.pi * a * tau0 / (2 * g_star), rel=1e-14)
    stress = relation("stationary_shear_stress")
    assert stress.numeric(u_bar, a, g_star) == pytest.approx(tau0, rel=1e-14)
    for u in (0.3 * u_bar, 2.5 * u_bar):
        assert stress.numeric(u, a, g_star) == pytest.approx(2 * g_star * u / (math.pi * a), rel=1e-14)


def test_critical_shift_carries_tau0_by_mindlin_tangential_stiffness():
    """ū(a) is the rigid shift at which a stuck circular contact carries the force τ0 π a².

    Independent of the MDR spring picture: Mindlin's tangential stiffness of a circular contact
    of radius a on an elastic half-space is ``k = 8 G a / (2 − ν)`` (Mindlin 1949; Johnson,
    Contact Mechanics, ch. 7), with ``G = E / (2 (1 + ν))`` from ``E`` and ``ν`` directly. So
    ``k ū(a) = τ0 π a²`` must hold with the package's ``G*``. Fails if the critical shift (13) or the effective
    tangential modulus ``Parameters.G_star`` (eq. (6)) is off by a factor, or if ν enters the
    wrong way (checked at ν = 0.5, 0.3 and −0.2).
    """
    for nu in (0.5, 0.3, -0.2):
        p = Parameters.paper().replace(nu=nu)
        shear = p.E / (2 * (1 + nu))
        for a in (1e-4, 2e-3, 3e-2):
            stiffness = 8 * shear * a / (2 - nu)
            u_bar = relation("critical_shift").numeric(a, p.tau0, p.G_star)
            assert stiffness * u_bar == pytest.approx(p.tau0 * math.pi * a**2, rel=1e-13)


def test_d_crit_17_solves_the_unreduced_statement():
    for tan in (0.1, 0.5, 2.0):
        d = relation("d_crit_A_hertz").numeric(tan, R, TAU0, G_STAR)
        shift = relation("critical_shift").numeric(math.sqrt(R * d), TAU0, G_STAR)
        assert d / tan == pytest.approx(shift, rel=1e-13)


@pytest.mark.parametrize("tan", [0.05, 0.4, 3.0])
def test_cubic_18_roots_solve_the_system(tan):
    rel = relation("slip_A_jkr_cubic")
    coeffs = [complex(c) for c in np.broadcast_arrays(*rel.coefficients(tan, R, TAU0, G_STAR, E_STAR, 0.01))]
    roots = np.roots([c.real for c in coeffs])
    positive = [r.real for r in roots if abs(r.imag) < 1e-12 and r.real > 0]
    assert len(positive) == 1
    a = positive[0] ** 2
    d_path = tan * math.pi * a * TAU0 / (2 * G_STAR)
    d_jkr = a**2 / R - math.sqrt(2 * math.pi * a * 0.01 / E_STAR)
    assert d_path == pytest.approx(d_jkr, rel=1e-10)
    cardano = complex(relation("slip_A_jkr_cardano").numeric(complex(tan), R, TAU0, G_STAR, E_STAR, 0.01))
    assert cardano.real == pytest.approx(positive[0], rel=1e-10)
    assert abs(cardano.imag) < 1e-10 * abs(cardano)


def test_vieta_form_of_the_smaller_root_equals_the_quadratic_formula():
    s = symbolic
    vieta = relation("d_crit_B_hertz_pull_off").rhs
    textbook = relation("d_crit_B_hertz_pull_off_textbook").rhs
    assert sp.simplify(sp.radsimp(vieta - textbook)) == 0
    assert s.d_max in vieta.free_symbols


def test_quadratic_20_roots_and_their_product():
    for k in (1e-3, 1e-2, 0.05):
        lower = relation("d_crit_B_hertz_pull_off").numeric(D_MAX, k)
        upper = relation("d_crit_B_hertz_indentation").numeric(D_MAX, k)
        assert lower * upper == pytest.approx(D_MAX**2, rel=1e-12)
        assert lower <= D_MAX <= upper
        # the paper's form (sqrt(d_max + k²/4) ± k/2)²
        assert lower == pytest.approx((math.sqrt(D_MAX + k**2 / 4) - k / 2) ** 2, rel=1e-10)
        assert upper == pytest.approx((math.sqrt(D_MAX + k**2 / 4) + k / 2) ** 2, rel=1e-12)
        # and the unsquared statement (d_max − d)/tan α = ū(sqrt(R d)) with k = π τ0 sqrt(R) tan α/(2G*)
        tan = k * 2 * G_STAR / (math.pi * TAU0 * math.sqrt(R))
        for d, sign in ((lower, 1), (upper, -1)):
            shift = relation("critical_shift").numeric(math.sqrt(R * d), TAU0, G_STAR)
            assert sign * (D_MAX - d) / tan == pytest.approx(shift, rel=1e-9)


@pytest.mark.parametrize("branch, sign, dgamma", [("pull_off", -1, 0.15), ("indentation", +1, 0.01)])
def test_quartics_21_have_one_positive_root_solving_the_system(branch, sign, dgamma):
    rel = relation(f"slip_B_jkr_quartic_{branch}")
    for tan in (0.1, 0.7, 4.0):
        coeffs = np.array([float(c) for c in rel.coefficients(tan, D_MAX, R, TAU0, G_STAR, E_STAR, dgamma)])
        roots = np.roots(coeffs)
        positive = [r.real for r in roots if abs(r.imag) < 1e-9 * abs(r) and r.real > 0]
        assert len(positive) == 1
        a = positive[0] ** 2
        d_path = D_MAX + sign * tan * math.pi * a * TAU0 / (2 * G_STAR)
        d_jkr = a**2 / R - math.sqrt(2 * math.pi * a * dgamma / E_STAR)
        assert d_path == pytest.approx(d_jkr, rel=1e-8, abs=1e-15)


#: The paper's notation, written out here (not taken from ``symbolic.LATEX_NAMES``).
PAPER_LATEX = {
    "E_star": r"E^{*}", "G_star": r"G^{*}", "tau0": r"\tau_{0}", "dgamma": r"\Delta\gamma",
    "d_max": r"d_{\max}", "u_bar": r"\bar{u}", "tan_alpha": r"\tan\alpha", "Delta_l_max": r"\Delta l_{\max}",
    "v_ref": r"v_{\mathrm{ref}}", "v_a": r"|\dot a|", "Gamma": r"\Gamma", "dgamma0": r"\Delta\gamma_{0}",
    "dgamma1": r"\Delta\gamma_{1}",
}


def _latex_token(text: str) -> str:
    """A regex for a LaTeX fragment standing on its own (not inside a longer name or command)."""
    return r"(?<![A-Za-z\\])" + re.escape(text) + r"(?![A-Za-z])"


def test_relations_print_with_the_papers_symbols():
    """``latex()`` and ``pretty()`` of every relation show the relation, in the paper's notation.

    For each relation: the LaTeX is exactly ``latex(lhs) = latex(rhs)`` with the names of
    ``LATEX_NAMES`` (fails if the sides are swapped or dropped, or ``symbol_names`` is lost);
    ``LATEX_NAMES`` holds the names written out in ``PAPER_LATEX`` (fails if one is lost or
    changed); every argument and every symbol of the relation appears under its paper name
    (``E^{*}``, ``\\Delta\\gamma``, ``d_{\\max}`` ...) and never under SymPy's default name
    (``E_{star}``, ``dgamma``, ``d_{max}``); ``pretty()`` is plain text (no LaTeX) with exactly
    one ``=`` line (``= 0`` for the polynomial reductions) and names every argument. The LaTeX
    of (9) and (13) is also compared with hand-written strings.
    """
    rels = symbolic.relations()
    for key in ("jkr_depth", "slip_A_jkr_cubic", "slip_B_jkr_quartic_pull_off", "profile_power_law"):
        assert key in rels
    names = symbolic.LATEX_NAMES
    assert {sym.name: name for sym, name in names.items() if sym.name in PAPER_LATEX} == PAPER_LATEX
    for key, rel in rels.items():
        text = rel.latex()
        assert text == (sp.latex(rel.lhs, symbol_names=names) + " = "
                        + sp.latex(rel.rhs, symbol_names=names)), key
        symbols = set(rel.args) | rel.lhs.free_symbols | rel.rhs.free_symbols
        for sym in symbols:
            paper_name = PAPER_LATEX.get(sym.name, sp.latex(sym))
            assert re.search(_latex_token(paper_name), text), (key, sym, text)
            default = sp.latex(sym)
            if default != paper_name:
                assert not re.search(_latex_token(default), text), (key, sym, text)
        picture = rel.pretty()
        assert "\\" not in picture and "{" not in picture, key
        equals = [line for line in picture.splitlines() if " = " in line]
        assert len(equals) == 1, (key, picture)
        if rel.variable is not None:
            assert equals[0].rstrip().endswith("= 0"), (key, picture)
        for sym in rel.args:
            assert sp.pretty(sym, use_unicode=True) in picture, (key, sym, picture)
    assert relation("jkr_depth").latex() == (
        r"d = \frac{a^{2}}{R} - \frac{\sqrt{2} \sqrt{\pi} \sqrt{a} \sqrt{\Delta\gamma}}{\sqrt{E^{*}}}")
    assert relation("critical_shift").latex() == r"\bar{u} = \frac{\pi a \tau_{0}}{2 G^{*}}"


def test_numeric_argument_checks():
    """Arguments by name equal arguments by position; a missing argument, ``coefficients`` of a
    relation that is no polynomial and an unknown key each raise their own error."""
    rel = relation("jkr_depth")
    assert rel.numeric(a=1e-3, R=R, E_star=E_STAR, dgamma=DGAMMA) == rel.numeric(1e-3, R, E_STAR, DGAMMA)
    with pytest.raises(TypeError, match="missing"):
        rel.numeric(a=1e-3)
    with pytest.raises(TypeError, match="not a polynomial"):
        rel.coefficients(1.0)
    with pytest.raises(KeyError, match="unknown relation"):
        relation("nope")


def test_the_cache_holds_exactly_what_sympy_derives(tmp_path, monkeypatch):
    """The on-disk cache of derivations returns the very expressions a fresh derivation gives, and a
    damaged cache file is ignored (derived again), never trusted."""
    monkeypatch.setenv("MDR_EVENTS_CACHE_DIR", str(tmp_path))
    path = symbolic.cache_path()
    assert path.parent == tmp_path and not path.exists()
    fresh = symbolic.derive_afresh()
    stored = _cached("model", lambda: list(fresh.values()))
    assert path.exists()
    loaded = _cached("model", lambda: pytest.fail("the cache was not used"))
    for rel, again, original in zip(stored, loaded, fresh.values()):
        assert again.key == original.key and again.equation == original.equation
        assert again.lhs == original.lhs and again.rhs == original.rhs and again.args == original.args
        assert again.variable == original.variable
    assert loaded[0] is not stored[0]  # rebuilt from the file
    path.write_bytes(b"damaged")
    rebuilt = _cached("model", lambda: list(fresh.values()))
    assert [rel.key for rel in rebuilt] == list(fresh)
    monkeypatch.setenv("MDR_EVENTS_NO_CACHE", "1")
    assert symbolic.cache_path() is None


def test_each_module_of_derivations_has_its_own_cache_file_keyed_by_its_source(tmp_path, monkeypatch):
    """The paper's relations and each sibling module's (the layer's three) sit in one directory, each file named by
    its stem and a hash of its own source and SymPy's version: an edited source is never read from an old file."""
    from mdr_events.theory import layer_continuum_symbolic, layer_symbolic, layer_tangential_symbolic
    monkeypatch.setenv("MDR_EVENTS_CACHE_DIR", str(tmp_path))
    paths = {symbolic.cache_path(), layer_symbolic.layer_cache_path(), layer_tangential_symbolic.tangential_cache_path(),
             layer_continuum_symbolic.continuum_cache_path()}
    assert len(paths) == 4 and {path.parent for path in paths} == {tmp_path}
    assert {path.name.rsplit("-", 1)[0] for path in paths} == {
        "relations", "layer-relations", "layer-tangential-relations", "layer-continuum-relations"}
    assert layer_symbolic.layer_cache_path().name == f"layer-relations-{layer_symbolic._SOURCE_DIGEST}.pickle"
    source = tmp_path / "module.py"
    source.write_text("x = 1\n")
    before = symbolic.source_digest(source)
    source.write_text("x = 2\n")
    assert symbolic.source_digest(source) != before and len(before) == 16
    monkeypatch.setenv("MDR_EVENTS_NO_CACHE", "1")
    assert symbolic.sibling_cache_path("layer-relations", before) is None


def test_a_sibling_s_relations_are_read_back_from_its_own_file(tmp_path, monkeypatch):
    """:func:`cached_relations` files what a derivation gives under its name in the file ``where`` names and reads it
    back without deriving again; a failed step of a derivation names the derivation and the step."""
    monkeypatch.setenv("MDR_EVENTS_CACHE_DIR", str(tmp_path))
    fresh = symbolic.derive_afresh()
    where = lambda: symbolic.sibling_cache_path("probe-relations", "0" * 16)  # noqa: E731
    stored = symbolic.cached_relations("probe", lambda: fresh, where)
    assert list(stored) == list(fresh) and where().exists() and not symbolic.cache_path().exists()
    loaded = symbolic.cached_relations("probe", lambda: pytest.fail("the cache was not used"), where)
    assert [rel.rhs for rel in loaded.values()] == [rel.rhs for rel in fresh.values()]
    check = symbolic.derivation_check("probe derivation")
    check(True, "holds")
    with pytest.raises(RuntimeError, match="^probe derivation: the half-space limit$"):
        check(False, "the half-space limit")
