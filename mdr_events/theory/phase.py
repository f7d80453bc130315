"""Phase diagrams of Fig. 9a (scenario A) and Fig. 9b (scenario B) as datasets.

:func:`phase_diagram` takes the physical model as a :class:`~mdr_events.Contact` with the motion's depth ``d_max``,
or as the keywords of before (:class:`~mdr_events.Parameters` with ``profile=`` and ``friction=``); both are read by
:func:`~mdr_events.theory.job.theory_job` and give the same dataset (a contact's with the paper's speed ``v`` in its
stamp, which no closed form uses).
"""

from __future__ import annotations

import math
from typing import Literal

import numpy as np
import xarray as xr

from mdr_events.io.agreement import RoundOff, register_accuracy
from mdr_events.io.datasets import assembled, register_schema, stamp
from mdr_events.limits import DEFAULT_LIMITS, Limits, check_limits, values_in
from mdr_events.parameters import PAPER_D_MAX, PAPER_V, Parameters
from mdr_events.contact.friction import FrictionLaw, as_friction_law, friction_attrs
from mdr_events.contact.indenters import Profile, TabulatedProfile, indenter_kind, profile_attrs
from mdr_events.contact.model import Contact
from mdr_events.theory import analytic, combined_onset, mindlin, power_law, tabulated
from mdr_events.theory.job import ContactLike, contact_alone, on_layer, theory_job
from mdr_events.theory.kinds import theory_of
from mdr_events.theory.scales import check_representable
from mdr_events.validation import check_choice, check_distinct, shown, validate_alpha

__all__ = ["phase_diagram", "default_angles", "PHASE_DIAGRAM_CONTENT", "PHASE_DIAGRAM_VARIABLES"]

#: The ``content`` attribute of a phase diagram.
PHASE_DIAGRAM_CONTENT = "phase diagram of slip onset"
#: The variables every phase diagram holds -> their dimensions (``None``: ``alpha`` in scenario A,
#: ``("branch", "alpha")`` in B); scenario B adds ``jump_off_depth``.
PHASE_DIAGRAM_VARIABLES = {"d_crit_hertz": None, "d_crit_jkr": None, "d_max": (), "critical_angle_hertz": (),
                           "critical_angle_jkr": ()}
register_schema(PHASE_DIAGRAM_CONTENT, PHASE_DIAGRAM_VARIABLES)
#: Bytes a phase diagram allocates per angle at its peak (measured with tracemalloc: 107 for scenario A, 123 for B,
#: 50 for Coulomb's law), rounded up.
BYTES_PER_ANGLE = 160
#: The limits the rows of :func:`~mdr_events.theory.analytic.d_crit_rows` are handed: none of memory, the phase
#: diagram's angles counted against its own limits first (:data:`BYTES_PER_ANGLE` each, the rows' share included).
_COUNTED = Limits(memory=math.inf)
#: Every value of a phase diagram is a closed form or a root converged to round-off (the polynomial root finder,
#: a safeguarded Newton iteration on a table's convex relations), the angles inputs.
register_accuracy(PHASE_DIAGRAM_CONTENT, {name: RoundOff() for name in (*PHASE_DIAGRAM_VARIABLES, "jump_off_depth",
                                                                         "alpha")})


def default_angles(count: int = 901) -> np.ndarray:
    """Evenly spaced angles 0°…90° (0.1° apart by default)."""
    return np.linspace(0.0, 90.0, count)


def phase_diagram(
    contact: ContactLike,
    alpha=None,
    scenario: Literal["A", "B"] = "A",
    profile: Profile | None = None,
    friction: FrictionLaw | str | None = None,
    limits: Limits = DEFAULT_LIMITS,
    *,
    d_max: float | None = None,
) -> xr.Dataset:
    r"""Slip-onset depth against path angle: the phase diagram of Fig. 9a or 9b.

    For the paper's paraboloid and law (13), scenario A (Hertz (17), with adhesion (18)) and scenario B's two
    branches (Hertz (20), with adhesion (21); "−" pull-off with ``Δγ1``, "+" indentation with ``Δγ0``):

    .. math:: d_\mathrm{crit} = \frac{\pi^2 \tau_0^2 R \tan^2\alpha}{4 G^{*2}} \quad (17), \qquad
              \frac{d}{\tan\alpha} = \frac{\pi a \tau_0}{2 G^*},\
              d = \frac{a^2}{R} - \sqrt{\frac{2 \pi a \Delta\gamma_0}{E^*}} \quad (18)

    .. math:: d_\pm = \left(\sqrt{d_\mathrm{max} + k^2/4} \pm k/2\right)^2,\
              k = \frac{\pi \tau_0 \sqrt{R} \tan\alpha}{2 G^*} \quad (20), \qquad
              \pm\frac{d - d_\mathrm{max}}{\tan\alpha} = \frac{\pi a \tau_0}{2 G^*} \quad (21)

    Parameters
    ----------
    contact : Contact or Parameters
        The physical model: a :class:`~mdr_events.Contact` (elastomer, indenter, adhesion, friction law), with the
        depth ``d_max``; or the keywords of before, a :class:`~mdr_events.Parameters` (material, the paraboloid of
        its ``R``, adhesion, ``τ0`` and its own ``d_max``) with ``profile`` and ``friction``. A contact on a layer
        of finite thickness bonded to its base (``Contact.layer``; a paraboloid, power law or flat punch under the law
        (13)): the same curves with the layer's cap and branches (:func:`mdr_events.d_crit`), ``nan`` where an onset lies
        beyond the layer's tables (``a/h > 64``).
    alpha : array_like, optional
        Angles in degrees, in [0, 90]; default 0°, 0.1°, …, 90°.
    scenario : {"A", "B"}
        ``"A"``: Fig. 9a, eqs. (17) and (18). ``"B"``: Fig. 9b, eqs. (20)
        and (21), with a dimension ``branch`` = ``pull-off``, ``indentation``.
    profile : PowerLaw or FlatPunch, optional
        Beside a :class:`~mdr_events.Parameters` only (a contact's is ``Contact.indenter``). Another indenter than
        the paper's paraboloid of ``params.R`` (:mod:`mdr_events.theory.power_law`); the dataset then names it in
        the attribute ``profile`` and is not the paper's figure. The "hertz" variables are then the non-adhesive
        ones, "jkr" the adhesive (Heß's rule). A :class:`TabulatedProfile` has scenario A's
        (:mod:`mdr_events.theory.tabulated`, ``nan`` where the onset lies past the table).
    friction : FrictionLaw or str, optional
        Beside a :class:`~mdr_events.Parameters` only (a contact's is ``Contact.friction``). Another friction law
        than the paper's ``"tau0"`` (:mod:`mdr_events.contact.friction`): scenario A without adhesion
        (:func:`mdr_events.theory.mindlin.d_crit_A`, ``d_crit_B``, ``d_crit_B_indentation``); scenario A's adhesive
        ("jkr") onset is the same for Coulomb's law alone and the flat punch (the compressed zone's,
        :func:`~mdr_events.theory.mindlin.adhesive_onset_A_is_non_adhesive`), that of
        :mod:`~mdr_events.theory.combined_onset` for ``"tau0+coulomb"`` on a curved indenter; scenario B's adhesive
        pull-off onset is (21) (the edge, in tension, holds ``K a`` alone), its indentation branch that of
        :mod:`~mdr_events.theory.combined_onset` for ``"tau0+coulomb"`` (``nan`` beyond its reach).
    limits : Limits, optional
        The angles count as ``samples``, and :data:`BYTES_PER_ANGLE` each as ``memory``: checked before anything
        is computed (``ResourceLimitError``).
    d_max : float, optional
        With a Contact: the maximum indentation depth of the scenario, eqs. (14) and (19) (m; default the paper's
        0.3 mm).

    Returns
    -------
    xarray.Dataset
        Coordinate ``alpha`` (degree); variables ``d_crit_hertz`` and
        ``d_crit_jkr`` in m (``±inf`` where no spring slides, see
        :func:`mdr_events.d_crit`), the scalars ``d_max``,
        ``critical_angle_hertz`` and ``critical_angle_jkr`` (degree) and, for
        scenario B, ``jump_off_depth`` (the displacement-controlled pull-off
        depth on the ``Δγ1`` branch).
    """
    layered = on_layer(contact)
    if layered:
        contact = contact_alone(contact, profile, friction)
    else:
        params, profile, friction = theory_job(contact, d_max, profile, friction, what="phase_diagram")
    scenario = check_choice("scenario", scenario, analytic.SCENARIOS)
    if isinstance(alpha, str) and alpha in ("A", "B"):  # phase_diagram(contact, "B"): the scenario given as alpha
        raise TypeError(f"alpha={shown(alpha)} is not allowed: a scenario's name where the angles go; allowed: angles in "
                        f"degrees, and the scenario by name: phase_diagram(contact, scenario={alpha!r})")
    alpha = default_angles() if alpha is None else alpha
    limits, count = check_limits(limits), values_in(alpha)  # (counted before the angles are read: copies and a sort)
    if layered:  # (the layer's onsets are bisections on its tables: their work and memory per angle are their own)
        from mdr_events.theory.layer.slip_onset import ONSET_BYTES_PER_ANGLE, ONSET_STEPS_PER_ANGLE

        curves = 2 * (1 if scenario == "A" else len(analytic.BRANCHES))  # (with and without adhesion, each branch)
        limits.check(f"the phase diagram of {count} angles on {contact.layer.describe()}", samples=count,
                     steps=curves * ONSET_STEPS_PER_ANGLE * count, memory=ONSET_BYTES_PER_ANGLE * count)
    else:
        working = combined_onset.GRID_WORKING_BYTES if friction.law == "tau0+coulomb" else 0.0
        limits.check(f"the phase diagram of {count} angles", samples=count, memory=BYTES_PER_ANGLE * count + working)
    angles = validate_alpha(alpha)
    if angles.ndim != 1 or angles.size == 0:
        raise ValueError(f"alpha of shape {angles.shape} is not allowed; allowed: a non-empty 1-D array of angles in "
                         "degrees (None: the default grid)")
    check_distinct("alpha", angles, alpha)
    coords = {"alpha": ("alpha", angles, {"units": "degree", "long_name": "path angle to the surface"})}
    if layered:
        return _layer_phase_diagram(contact, angles, scenario, d_max, coords, limits)
    # (the closed forms overflow as the runs would: E = 1e-150 Pa gave d_crit = +inf at 438 angles with warnings)
    check_representable(params, profile, friction)
    if not friction.is_default:
        return _friction_phase_diagram(params, angles, scenario, profile, friction, coords)
    diagram = _PAPER_LAW_PHASE_DIAGRAMS.get(indenter_kind(profile), _profile_phase_diagram)
    return diagram(params, angles, scenario, profile, coords)


def _paper_phase_diagram(params: Parameters, angles: np.ndarray, scenario: str, profile: None,
                         coords: dict) -> xr.Dataset:
    """:func:`phase_diagram` of the paper's paraboloid and friction law: eqs. (17), (18) or (20), (21)
    (:mod:`~mdr_events.theory.analytic`), Fig. 9a or 9b for a paper preset."""
    # (the rows of B's two branches: no stacking; the angles counted by phase_diagram)
    curves = analytic.d_crit_rows(angles, params, scenario, limits=_COUNTED)
    jump_off = analytic.jump_off(params, params.dgamma1)["depth"] if scenario == "B" else None
    variables = _onset_variables(curves, scenario, coords, jump_off, params.d_max,
                                 lambda adhesive: analytic.critical_angle(params, scenario, adhesion=adhesive))
    dataset = assembled(variables, coords)  # (xarray.Dataset(variables, coords=coords) without its merge: 0.1-0.2 ms)
    figure = {} if params.preset_name() is None else {"figure": "9a" if scenario == "A" else "9b"}
    return stamp(dataset, params, scenario=scenario, content=PHASE_DIAGRAM_CONTENT, **figure)


def _layer_phase_diagram(contact: Contact, angles: np.ndarray, scenario: str, d_max: float | None,
                         coords: dict, limits: Limits) -> xr.Dataset:
    """:func:`phase_diagram` of a contact on a layer of finite thickness: eqs. (17)–(21) with the layer's cap
    ``π a² τ0/K_t`` and branches (:mod:`~mdr_events.theory.layer.slip_onset`), ``nan`` where the onset lies beyond
    the layer's tables (``a/h > 64``), the layer's attributes stamped."""
    from mdr_events.theory.layer.slip_onset import critical_angle_on_layer, onset_depths, pull_off_depth

    branches = (None,) if scenario == "A" else analytic.BRANCHES
    found = {(adhesive, branch): onset_depths(angles, contact, scenario, adhesive, branch or "pull-off", d_max,
                                              past_tables=True, limits=limits)
             for branch in branches for adhesive in (False, True)}
    curves = {adhesive: np.stack([found[adhesive, branch] for branch in branches]) for adhesive in (False, True)}
    depth = PAPER_D_MAX if d_max is None else d_max
    jump_off = None
    if scenario == "B":
        jump_off = pull_off_depth(contact)
    variables = _onset_variables(curves, scenario, coords, jump_off, depth,
                                 lambda adhesive: critical_angle_on_layer(contact, scenario, adhesive, None, d_max))
    dataset = stamp(xr.Dataset(variables, coords=coords), contact.parameters(depth, PAPER_V), scenario=scenario,
                    content=PHASE_DIAGRAM_CONTENT)
    dataset.attrs.update(contact.to_attrs())
    return dataset


def _onset_variables(curves: dict, scenario: str, coords: dict, jump_off: float | None, d_max: float,
                     critical_angle) -> dict:
    """The variables of a phase diagram of the law (13) from the curves by adhesion, a row per branch
    (:func:`~mdr_events.theory.analytic.d_crit_rows`), the jump-off depth (scenario B), ``d_max`` and
    ``critical_angle(adhesive)`` (``coords`` gains the branch in B)."""
    variables = {}
    if scenario == "A":
        for key, adhesive, eq in (("hertz", False, "(17)"), ("jkr", True, "(18)")):
            variables[f"d_crit_{key}"] = (
                "alpha",
                curves[adhesive][0],
                {"units": "m", "long_name": f"slip-onset depth, {'adhesive' if adhesive else 'non-adhesive'}, eq. {eq}"},
            )
    else:
        coords["branch"] = ("branch", np.array(analytic.BRANCHES), {"units": "1", "long_name": "motion at angle from d_max"})
        for key, adhesive, eq in (("hertz", False, "(20)"), ("jkr", True, "(21)")):
            variables[f"d_crit_{key}"] = (
                ("branch", "alpha"),
                curves[adhesive],
                {"units": "m", "long_name": f"slip-onset depth, {'adhesive' if adhesive else 'non-adhesive'}, eq. {eq}"},
            )
        variables["jump_off_depth"] = (
            (),
            jump_off,
            {"units": "m", "long_name": "jump-off depth on the pull-off branch (displacement control)"},
        )
    variables["d_max"] = ((), d_max, {"units": "m", "long_name": "maximum indentation depth"})
    for key, adhesive in (("hertz", False), ("jkr", True)):
        meaning = "slip at d_max" if scenario == "A" else "no slip before jump-off above it"
        variables[f"critical_angle_{key}"] = (
            (),
            critical_angle(adhesive),
            {"units": "degree", "long_name": f"critical angle, {'adhesive' if adhesive else 'non-adhesive'} ({meaning})"},
        )
    return variables


def _profile_phase_diagram(params: Parameters, angles: np.ndarray, scenario: str, profile: Profile,
                           coords: dict) -> xr.Dataset:
    """:func:`phase_diagram` of another indenter: the same variables from :mod:`~mdr_events.theory.power_law`, with
    the same encoding of "never slides" (``+inf`` while indenting, ``-inf`` on the pull-off branch)."""
    power_law.check_profile(profile)
    variables = {}
    kinds = (("hertz", False, "non-adhesive"), ("jkr", True, "adhesive (Heß)"))
    if scenario == "A":
        for key, adhesive, words in kinds:
            depth = np.asarray(power_law.d_crit_A(angles, profile, params, adhesive), dtype=float)
            depth = np.where(np.isnan(depth) | (angles >= 90.0), np.inf, depth)  # no onset while indenting
            variables[f"d_crit_{key}"] = ("alpha", depth, {"units": "m", "long_name": f"slip-onset depth, {words}"})
        angle = {key: power_law.critical_angle_A(profile, params, adhesive) for key, adhesive, _ in kinds}
    else:
        coords["branch"] = ("branch", np.array(analytic.BRANCHES), {"units": "1", "long_name": "motion at angle from d_max"})
        for key, adhesive, words in kinds:
            values = np.stack([power_law.d_crit_B(angles, profile, params, adhesive),
                               power_law.d_crit_B_indentation(angles, profile, params, adhesive)])
            variables[f"d_crit_{key}"] = (("branch", "alpha"), values,
                                          {"units": "m", "long_name": f"slip-onset depth, {words}"})
        variables["jump_off_depth"] = ((), power_law.jump_off(profile, params, params.dgamma1)["depth"],
                                       {"units": "m", "long_name": "jump-off depth on the pull-off branch "
                                                                   "(displacement control)"})
        angle = {key: power_law.critical_angle_B(profile, params, adhesive) for key, adhesive, _ in kinds}
    variables["d_max"] = ((), params.d_max, {"units": "m", "long_name": "maximum indentation depth"})
    meaning = "slip at d_max" if scenario == "A" else "no slip before jump-off above it"
    for key, _, words in kinds:
        variables[f"critical_angle_{key}"] = ((), angle[key], {"units": "degree",
                                                               "long_name": f"critical angle, {words} ({meaning})"})
    return stamp(xr.Dataset(variables, coords=coords), params, scenario=scenario, content=PHASE_DIAGRAM_CONTENT,
                 **profile_attrs(profile))


def _tabulated_phase_diagram(params: Parameters, angles: np.ndarray, scenario: str, profile: TabulatedProfile,
                             coords: dict) -> xr.Dataset:
    """:func:`phase_diagram` of scenario A for a tabulated profile (:mod:`~mdr_events.theory.tabulated`); same
    variables and encoding, ``nan`` where the onset lies past what the table reaches (unknown)."""
    if scenario != "A":
        raise ValueError(f"scenario={scenario!r} is not allowed for the phase diagram of a tabulated profile; allowed: "
                         "'A' (scenario B's onset is not derived for it)")
    kinds = {"hertz": ("non-adhesive", tabulated.d_crit_A(angles, profile, params, adhesion=False),
                       tabulated.critical_angle_A(profile, params, adhesion=False)),
             "jkr": ("adhesive (Heß)", tabulated.d_crit_A(angles, profile, params, adhesion=True),
                     tabulated.critical_angle_A(profile, params, adhesion=True))}
    depths = {key: np.where(angles >= 90.0, np.inf, np.asarray(depth, dtype=float))
              for key, (_, depth, _) in kinds.items()}
    return _onset_dataset_A(params, kinds, depths, coords, profile, as_friction_law(None))


#: :func:`phase_diagram` under the paper's friction law, by the indenter's type (any other indenter:
#: :func:`_profile_phase_diagram`, the closed forms of :mod:`~mdr_events.theory.power_law`).
_PAPER_LAW_PHASE_DIAGRAMS = {type(None): _paper_phase_diagram, TabulatedProfile: _tabulated_phase_diagram}


def _friction_phase_diagram(params: Parameters, angles: np.ndarray, scenario: str, profile, friction: FrictionLaw,
                            coords: dict) -> xr.Dataset:
    """:func:`phase_diagram` for another friction law (:mod:`~mdr_events.theory.mindlin`); same variables and
    encoding. Scenario A's adhesive onset is the non-adhesive one for Coulomb's law alone and the flat punch
    (:func:`~mdr_events.theory.mindlin.adhesive_onset_A_is_non_adhesive`), the first depth a spring reaches its cap
    for both parts on a curved indenter (:mod:`~mdr_events.theory.combined_onset`); scenario B's
    (:func:`_friction_phase_diagram_B`)."""
    if not theory_of(profile).friction_closed_forms:
        raise ValueError(f"friction={friction.law!r} is not allowed with a tabulated profile's phase diagram; allowed: "
                         "'tau0'")
    if scenario != "A":
        return _friction_phase_diagram_B(params, angles, profile, friction, coords)
    # with adhesion Coulomb's law alone and the flat punch have the onset without (the compressed zone's, free of Δγ);
    # both parts on a curved indenter the first depth a spring reaches its cap (theory.combined_onset, up to d_max)
    known = mindlin.adhesive_onset_A_is_non_adhesive(friction, profile)
    kinds = {"hertz": (f"non-adhesive, friction law {friction.law!r}", mindlin.d_crit_A(angles, friction, params,
                                                                                        profile),
                       mindlin.critical_angle_A(friction, params, profile)),
             "jkr": (f"adhesive, friction law {friction.law!r}" + (": the non-adhesive onset (free of Δγ)" if known
                                                                   else ""),
                     mindlin.d_crit_A(angles, friction, params, profile, adhesion=True),
                     mindlin.critical_angle_A(friction, params, profile, adhesion=True))}
    onsets = {key: np.asarray(kinds[key][1], dtype=float) for key in kinds}
    depths = {"hertz": np.where(np.isnan(onsets["hertz"]) | (angles >= 90.0), np.inf, onsets["hertz"]),
              "jkr": np.where(np.isnan(onsets["jkr"]) | (angles >= 90.0), np.inf, onsets["jkr"])}
    return _onset_dataset_A(params, kinds, depths, coords, profile, friction)


def _onset_dataset_A(params: Parameters, kinds: dict, depths: dict[str, np.ndarray], coords: dict, profile,
                     friction: FrictionLaw) -> xr.Dataset:
    """Scenario A's phase diagram of the onset ``depths`` and the ``kinds`` (key -> words, depths as computed,
    critical angle), stamped with the indenter and the friction law."""
    variables = {}
    for key, (words, _, _) in kinds.items():
        variables[f"d_crit_{key}"] = ("alpha", depths[key], {"units": "m", "long_name": f"slip-onset depth, {words}"})
    variables["d_max"] = ((), params.d_max, {"units": "m", "long_name": "maximum indentation depth"})
    for key, (words, _, angle) in kinds.items():
        variables[f"critical_angle_{key}"] = ((), float(angle), {"units": "degree",
                                                                  "long_name": f"critical angle, {words} (slip at d_max)"})
    return stamp(xr.Dataset(variables, coords=coords), params, scenario="A", content=PHASE_DIAGRAM_CONTENT,
                 **profile_attrs(profile), **friction_attrs(friction))


def _friction_phase_diagram_B(params: Parameters, angles: np.ndarray, profile, friction: FrictionLaw,
                              coords: dict) -> xr.Dataset:
    """Scenario B's phase diagram of another friction law (:mod:`~mdr_events.theory.mindlin`): without adhesion, and
    with it (the pull-off branch's edge, in tension, holds ``K a`` alone: (21); the indentation branch of both parts on
    a curved indenter by :mod:`~mdr_events.theory.combined_onset`, ``nan`` where its onset lies beyond the reach)."""
    coords["branch"] = ("branch", np.array(analytic.BRANCHES), {"units": "1", "long_name": "motion at angle from d_max"})
    curves = {adhesive: np.stack([mindlin.d_crit_B(angles, friction, params, profile, adhesion=adhesive),
                                  mindlin.d_crit_B_indentation(angles, friction, params, profile, adhesion=adhesive)])
              for adhesive in (False, True)}
    words = f"friction law {friction.law!r}"
    jump_off = theory_of(profile).jump_off(profile, params, params.dgamma1)["depth"] if params.dgamma1 > 0.0 else 0.0
    variables = {"jump_off_depth": ((), jump_off, {"units": "m", "long_name": "jump-off depth on the pull-off branch "
                                                                            "(displacement control)"}),
                 "d_max": ((), params.d_max, {"units": "m", "long_name": "maximum indentation depth"})}
    for key, adhesive, kind in (("hertz", False, "non-adhesive"), ("jkr", True, "adhesive (Heß)")):
        variables[f"d_crit_{key}"] = (("branch", "alpha"), curves[adhesive],
                                      {"units": "m", "long_name": f"slip-onset depth, {kind}, {words}"})
        variables[f"critical_angle_{key}"] = ((), mindlin.critical_angle_B(friction, params, profile, adhesion=adhesive),
                                              {"units": "degree", "long_name": f"critical angle, {kind}, {words} (no "
                                                                               "slip before jump-off above it)"})
    return stamp(xr.Dataset(variables, coords=coords), params, scenario="B", content=PHASE_DIAGRAM_CONTENT,
                 **profile_attrs(profile), **friction_attrs(friction))
