"""The theory's public functions take a Contact (with the motion's depth ``d_max``) and the keywords of before
(Parameters with ``profile=`` and ``friction=``), read in one place (``theory.job.theory_job``): the same numbers,
and for the paper's paraboloid the same dataset."""

import numpy as np
import pytest
import xarray as xr

import mdr_events as me
from mdr_events.io.datasets import parameters_of
from mdr_events.theory import analytic, combined_onset
from mdr_events.theory.job import paper_parameters, theory_job

PAPER = me.Parameters.paper()
HERTZ = PAPER.replace(dgamma0=0.0, dgamma1=0.0)
#: Attributes only the keyword form stamps beside another indenter: the paraboloid's R it did not use, and the note
#: of the preset that R made the parameters.
KEYWORD_ONLY = {"param_R", "param_R_units", "inferred_parameters", "inferred_parameters_note"}


@pytest.mark.parametrize("R", [0.03, 0.1])
@pytest.mark.parametrize("scenario", ["A", "B"])
def test_a_papers_contact_draws_the_same_dataset_as_its_parameters(R, scenario):
    """Fig. 9a/9b from Contact.paper(R) at the paper's depth is the dataset of Parameters.paper(R): values, every
    attribute (the figure number, the preset's note, param_v) and the encodings."""
    keywords = me.phase_diagram(me.Parameters.paper(R), scenario=scenario)
    contact = me.phase_diagram(me.Contact.paper(R), scenario=scenario)
    xr.testing.assert_identical(contact, keywords)
    assert contact.attrs == keywords.attrs
    assert contact.attrs["figure"] == ("9a" if scenario == "A" else "9b")
    assert parameters_of(contact) == me.Parameters.paper(R)
    assert me.Contact.from_attrs(contact.attrs) == me.Contact.paper(R)


@pytest.mark.parametrize("scenario", ["A", "B"])
def test_a_contact_at_another_depth_is_its_parameters_at_that_depth(scenario):
    alpha = np.linspace(0.0, 90.0, 181)
    params = PAPER.replace(d_max=2e-4, E=1e6, dgamma1=0.2)
    contact = me.Contact.from_parameters(params)
    keywords = me.phase_diagram(params.replace(v=me.Parameters.paper().v), alpha, scenario)
    xr.testing.assert_identical(me.phase_diagram(contact, alpha, scenario, d_max=2e-4), keywords)
    assert float(keywords["d_max"]) == 2e-4


def _same_numbers(contact_ds: xr.Dataset, keyword_ds: xr.Dataset) -> None:
    """The same variables, bit for bit, and the same attributes but those the keyword form adds."""
    xr.testing.assert_equal(contact_ds, keyword_ds)
    for name in keyword_ds.variables:
        np.testing.assert_array_equal(contact_ds[name].values, keyword_ds[name].values)
        assert contact_ds[name].attrs == keyword_ds[name].attrs
    extra = set(keyword_ds.attrs) - set(contact_ds.attrs)
    assert extra <= KEYWORD_ONLY and not set(contact_ds.attrs) - set(keyword_ds.attrs)
    differing = {key for key in contact_ds.attrs if contact_ds.attrs[key] != keyword_ds.attrs[key]}
    assert differing <= {"param_tau0"}  # (Coulomb's law alone: the contact holds no τ0, the parameters an unused one)


@pytest.mark.parametrize("scenario", ["A", "B"])
@pytest.mark.parametrize("profile", [me.PowerLaw(2e3, 3.0), me.PowerLaw.cone(0.1), me.FlatPunch(1.5e-3)],
                         ids=["n=3", "cone", "flat punch"])
def test_a_contact_of_another_indenter_gives_the_numbers_of_profile(scenario, profile):
    keywords = me.phase_diagram(PAPER, scenario=scenario, profile=profile)
    contact = me.phase_diagram(me.Contact.from_parameters(PAPER, profile), scenario=scenario, d_max=PAPER.d_max)
    _same_numbers(contact, keywords)
    assert contact.attrs["profile"] == keywords.attrs["profile"] and "param_R" not in contact.attrs


def test_a_contact_of_a_table_gives_the_numbers_of_profile():
    r = np.linspace(0.0, 4e-3, 81)
    table = me.TabulatedProfile(r, r**2 / (2 * 0.03))
    alpha = np.linspace(1.0, 89.0, 45)
    keywords = me.phase_diagram(PAPER, alpha, profile=table)
    _same_numbers(me.phase_diagram(me.Contact.from_parameters(PAPER, table), alpha), keywords)


@pytest.mark.parametrize("scenario", ["A", "B"])
@pytest.mark.parametrize("law", [me.FrictionLaw("coulomb", mu=0.3), me.FrictionLaw("tau0+coulomb", mu=0.2)],
                         ids=["coulomb", "tau0+coulomb"])
@pytest.mark.parametrize("profile", [None, me.PowerLaw.cone(0.1)], ids=["paraboloid", "cone"])
def test_a_contact_of_another_friction_law_gives_the_numbers_of_friction(scenario, law, profile):
    keywords = me.phase_diagram(HERTZ, scenario=scenario, profile=profile, friction=law)
    contact = me.Contact.from_parameters(HERTZ, profile, law)
    assert contact.friction.law == law.law
    ds = me.phase_diagram(contact, scenario=scenario, d_max=HERTZ.d_max)
    _same_numbers(ds, keywords)
    assert ds.attrs["friction_law"] == law.law and ds.attrs["friction_mu"] == law.mu
    assert np.isfinite(ds["critical_angle_hertz"])
    if law.law == "coulomb" and scenario == "A":  # the compressed zone's onset: the non-adhesive one
        np.testing.assert_array_equal(ds["d_crit_jkr"].values, ds["d_crit_hertz"].values)
    elif scenario == "A":  # both parts: the first depth a spring reaches its cap (theory.combined_onset)
        assert not np.any(np.isnan(ds["d_crit_jkr"]))
    else:  # without adhesion (HERTZ) scenario B's adhesive curves are the non-adhesive ones (the search's rounding),
        # but where the indentation branch's onset lies beyond the search's reach (nan: not known)
        adhesive, plain = ds["d_crit_jkr"].values, ds["d_crit_hertz"].values
        beyond = np.isnan(adhesive)
        assert np.all(plain[beyond] > combined_onset.INDENTATION_REACH * HERTZ.d_max)
        np.testing.assert_allclose(adhesive[~beyond], plain[~beyond], rtol=1e-12)


def test_coulombs_contact_needs_no_tau0():
    """A contact of Coulomb's law alone holds no τ0; its diagram is that of any τ0 beside the law (unused)."""
    contact = me.Contact(me.Elastomer(HERTZ.E, HERTZ.nu), me.Paraboloid(0.03), friction=me.FrictionLaw("coulomb",
                                                                                                       mu=0.3))
    ds = me.phase_diagram(contact, scenario="A")
    assert ds.attrs["param_tau0"] == 0.0 and "friction_note" in ds.attrs
    _same_numbers(ds, me.phase_diagram(HERTZ.replace(tau0=0.0), scenario="A", friction=contact.friction))


PAPER_FUNCTIONS = [
    ("jkr_depth", lambda model: me.jkr_depth(1e-3, model, 0.15)),
    ("jkr_normal_force", lambda model: me.jkr_normal_force(1e-3, model, 0.15)),
    ("jkr_contact_radius", lambda model: me.jkr_contact_radius(np.array([-1e-5, 1e-4, 3e-4]), model, 0.01)),
    ("jump_off", lambda model: me.jump_off(model, 0.15)),
    ("pull_off_force", lambda model: me.pull_off_force(model, 0.15)),
    ("critical_shift", lambda model: me.critical_shift(1e-3, model)),
    ("fretting_dissipated_energy", lambda model: me.fretting_dissipated_energy(1e-3, 5e-5, model)),
    ("normal_force", lambda model: analytic.normal_force(2e-4, 1e-3, model)),
    ("hertz_contact_radius", lambda model: analytic.hertz_contact_radius(2e-4, model)),
    ("jump_in_radius", lambda model: analytic.jump_in_radius(model, 0.01)),
]


@pytest.mark.parametrize("call", [call for _, call in PAPER_FUNCTIONS], ids=[name for name, _ in PAPER_FUNCTIONS])
def test_the_closed_forms_of_a_contact_are_those_of_its_parameters(call):
    for R in (0.03, 0.1):
        params = me.Parameters.paper(R).replace(E=0.5e6, tau0=30e3)
        np.testing.assert_array_equal(call(me.Contact.from_parameters(params)), call(params))


@pytest.mark.parametrize("d_max", [None, 2e-4, 5e-4])
def test_the_depth_of_a_contact_enters_as_d_max(d_max):
    """d_crit, critical_angle and dimensionless_groups read the motion's depth: ``d_max=`` with a Contact (default
    the paper's), the parameters' own with Parameters."""
    contact = me.Contact.paper()
    params = PAPER if d_max is None else PAPER.replace(d_max=d_max)
    alpha = np.linspace(0.0, 90.0, 91)
    for scenario, branch in (("A", None), ("B", "pull-off"), ("B", "indentation")):
        for adhesion in (False, True):
            np.testing.assert_array_equal(me.d_crit(alpha, contact, scenario, adhesion, branch, d_max=d_max),
                                          me.d_crit(alpha, params, scenario, adhesion, branch))
    for scenario in ("A", "B", "B+"):
        for adhesion in (False, True):
            assert me.critical_angle(contact, scenario, adhesion, d_max=d_max) == \
                me.critical_angle(params, scenario, adhesion)
    assert me.critical_angle(contact, "B+", final_depth=1e-3, d_max=d_max) == \
        me.critical_angle(params, "B+", final_depth=1e-3)
    assert analytic.dimensionless_groups(contact, d_max=d_max) == analytic.dimensionless_groups(params)


@pytest.mark.parametrize("contact, refused", [
    (me.Contact.from_parameters(PAPER, me.PowerLaw.cone(0.1)), r"contact.indenter=PowerLaw\(c=0.1, n=1.0\) is not "
                                                               r"allowed here.*mdr_events.power_law"),
    (me.Contact.from_parameters(PAPER, me.FlatPunch(1e-3)), r"FlatPunch.*is not allowed here"),
    (me.Contact.from_parameters(HERTZ, None, me.FrictionLaw("coulomb", mu=0.3)),
     r"contact.friction=FrictionLaw\('coulomb', mu=0.3\) is not allowed here.*mdr_events.mindlin"),
])
def test_the_papers_closed_forms_refuse_another_indenter_or_law(contact, refused):
    """The closed forms of the paraboloid under (13) do not silently compute another contact's numbers."""
    with pytest.raises(ValueError, match=refused):
        me.critical_angle(contact, "A")
    with pytest.raises(ValueError, match=refused):
        me.d_crit(20.0, contact)
    with pytest.raises(ValueError, match=refused):
        me.pull_off_force(contact, 0.15)


def test_one_conversion_refuses_mixed_forms():
    contact = me.Contact.paper()
    with pytest.raises(ValueError, match=r"d_max=0.001 is not allowed beside Parameters.*its own d_max = 0.0003"):
        me.phase_diagram(PAPER, d_max=1e-3)
    with pytest.raises(ValueError, match=r"d_max=0.001 is not allowed beside Parameters"):
        me.critical_angle(PAPER, "A", d_max=1e-3)
    with pytest.raises(ValueError, match=r"profile=PowerLaw.* is not allowed beside a Contact.*Contact.indenter"):
        me.phase_diagram(contact, profile=me.PowerLaw.cone(0.1))
    with pytest.raises(ValueError, match=r"friction='coulomb' is not allowed beside a Contact.*Contact.friction"):
        me.phase_diagram(contact, friction="coulomb")
    for depth in (0.0, -1e-4, float("nan"), float("inf")):
        with pytest.raises(ValueError, match=r"d_max=.* is not allowed; allowed: a finite number > 0"):
            me.phase_diagram(contact, d_max=depth)
    with pytest.raises(TypeError, match=r"d_max=True"):
        me.critical_angle(contact, d_max=True)
    with pytest.raises(TypeError, match=r"contact='paper' \(str\) is not allowed; allowed: a mdr_events.Contact"):
        me.phase_diagram("paper")
    with pytest.raises(TypeError, match=r"contact=None \(NoneType\) is not allowed"):
        me.jump_off(None, 0.15)


def test_the_conversion_passes_the_keywords_on_as_given():
    law = me.FrictionLaw("coulomb", mu=0.3)
    cone = me.PowerLaw.cone(0.1)
    assert theory_job(PAPER, None, cone, law) == (PAPER, cone, law)
    assert theory_job(PAPER) == (PAPER, None, me.FrictionLaw())
    job = theory_job(me.Contact.from_parameters(PAPER, cone, me.FrictionLaw("tau0+coulomb", mu=0.3)), 2e-4)
    assert job.params == PAPER.replace(R=None, d_max=2e-4) and job.profile == cone
    assert job.friction == me.FrictionLaw("tau0+coulomb", mu=0.3)  # (its τ0 in the parameters, as friction= took it)
    assert paper_parameters(me.Contact.paper(0.1), "test") == me.Parameters.paper(0.1)


def test_a_contacts_phase_diagram_round_trips_through_a_file(tmp_path):
    contact = me.Contact.from_parameters(PAPER, me.PowerLaw(2e3, 3.0))
    ds = me.phase_diagram(contact, scenario="B", d_max=2e-4)
    me.write_netcdf(ds, tmp_path / "pd.nc")
    back = me.open_result(tmp_path / "pd.nc")
    xr.testing.assert_identical(back, ds)
    assert me.Contact.from_attrs(back.attrs) == contact
