"""One parser per input, shared by both front ends: the command line (:mod:`mdr_events.app.cli`) and study files
(:mod:`mdr_events.app.study`).

Each turns the values a front end read (from ``argparse`` or from a TOML table) into the package's value, and
raises ``ValueError`` or ``TypeError`` with the library's own message; the front end prefixes it with where the
value came from (``--power-law 2000 0.5: ...``, ``study.toml: [profile] ...``) and turns it into its error.

=============  ==========================================  ===============================================
input          parser                                      value
=============  ==========================================  ===============================================
parameters     :func:`parameters`                          :class:`~mdr_events.Parameters` and provenance
indenter       :func:`indenter`                            ``None`` (the paraboloid of ``R``) or an indenter
friction       :func:`friction`                            :class:`~mdr_events.FrictionLaw`
adhesion       :func:`adhesion`                            :class:`~mdr_events.Adhesion` or :class:`~mdr_events.RateDependentAdhesion`
layer          :func:`layer`                               :class:`~mdr_events.Layer`
limits         :func:`limits`                              :class:`~mdr_events.Limits`
a path         :func:`path`                                :class:`~mdr_events.Path`
the contact    :func:`contact`                             :class:`~mdr_events.Contact`
the motion     :func:`scenario`, :func:`paths`             :class:`~mdr_events.Scenario`, :class:`~mdr_events.Paths`
the method     :func:`method`                              :class:`~mdr_events.Discrete`, :class:`~mdr_events.Continuum`
=============  ==========================================  ===============================================
"""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING, Any, Iterable, Mapping, Sequence

from mdr_events.validation import as_float, shown
from mdr_events.contact import Contact
from mdr_events.contact.adhesion import Adhesion, AdhesionLaw, RateDependentAdhesion
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import FlatPunch, PowerLaw
from mdr_events.limits import DEFAULT_LIMITS, Limits, parse_limit
from mdr_events.parameters import PARAMETER_UNITS, PRESETS, Parameters, from_preset

if TYPE_CHECKING:  # (the models and the table reader are imported where used: a verb's --help loads none of them)
    from mdr_events.models.indenters import SimulatedProfile
    from mdr_events.models.methods import Method
    from mdr_events.models.motion import Paths, Scenario
    from mdr_events.models.paths import Path

__all__ = ["parameters", "indenter", "friction", "adhesion", "ADHESION_LAWS", "check_rate_run", "check_reference_run", "check_reference_law", "angle_speeds", "layer", "limits", "path", "contact", "scenario", "paths", "method",
           "DEFAULT_PRESET"]

#: The preset of the paper both front ends start from when none is named.
DEFAULT_PRESET = "paper-R30"


def parameters(preset: str | None, values: Mapping[str, float], overrides: Mapping[str, float] | None = None,
               complete: bool = False) -> tuple[Parameters, dict[str, str]]:
    """The parameters of ``preset`` (default :data:`DEFAULT_PRESET`) with ``values`` on top, and the attributes saying
    which came from the preset (:func:`~mdr_events.parameters.from_preset`).

    Parameters
    ----------
    preset : str, optional
        A preset of :data:`~mdr_events.parameters.PRESETS`.
    values : mapping of str to float
        Parameter values in SI units.
    overrides : mapping of str to float, optional
        Values on top of ``values`` (``--E`` beside ``--params FILE``).
    complete : bool
        Without a preset: ``values`` must name all eight parameters (a study's ``[parameters]`` table without a
        preset), which are then the parameters, with no provenance.

    Raises
    ------
    ValueError
        A missing parameter (``complete``), an unknown preset or a value :class:`~mdr_events.Parameters` refuses.
    """
    if preset is None and complete:
        missing = [name for name in PARAMETER_UNITS if name not in values]
        if missing:
            raise ValueError(f"without a preset lacks {', '.join(missing)}; allowed: all eight of "
                             f"{', '.join(PARAMETER_UNITS)}, or preset = " + " or ".join(map(repr, PRESETS))
                             + " and any of them as overrides")
    values = {key: as_float(value) for key, value in {**values, **(overrides or {})}.items()}
    if preset is None and complete:
        return Parameters(**values), {}
    return from_preset(DEFAULT_PRESET if preset is None else preset, **values)


def indenter(power_law: Sequence[float] | None = None, radius: float | None = None, table: Any = None,
             simulated: bool = True) -> SimulatedProfile:
    """The indenter of one of ``power_law`` (``(c, n)``: ``f = c rⁿ``), ``radius`` (the flat punch) or ``table`` (a CSV
    file with the columns ``r`` and ``f``); ``None`` without any: the paraboloid of the parameters' ``R``.

    ``simulated``: one the simulators take (a power law from the cone on), else any the closed forms take (the
    phase diagram's).

    Raises
    ------
    ValueError, TypeError
        The indenter's own message (a value it refuses, a table that cannot be read).
    """
    from mdr_events.models.indenters import check_simulated_profile

    if table is not None:
        from mdr_events.io.candidates import read_profile_table

        profile = read_profile_table(table)
    elif radius is not None:
        profile = FlatPunch(radius)
    elif power_law is not None:
        profile = PowerLaw(*power_law)
    else:
        return None
    return check_simulated_profile(profile) if simulated else profile


def friction(law: str | None = None, mu: float | None = None) -> FrictionLaw:
    """The friction law ``law`` (default the paper's ``"tau0"``) with ``mu`` for a law with Coulomb's part.

    Raises
    ------
    ValueError, TypeError
        The law's own message (an unknown law, ``mu`` missing or given to a law without Coulomb's part).
    """
    return FrictionLaw(law or "tau0", mu=mu)


#: The adhesion laws both front ends name (``--adhesion-law``, ``[adhesion] law``): the paper's rate-independent
#: :class:`~mdr_events.Adhesion` (the default) and the rate-dependent :class:`~mdr_events.RateDependentAdhesion`, each
#: with the values it takes beyond the works at rest of the parameters.
ADHESION_LAWS: dict[str, tuple[str, ...]] = {"paper": (), "rate": ("v_ref", "n")}


def adhesion(law: str | None, params: Parameters, v_ref: float | None = None, n: float | None = None) -> AdhesionLaw:
    """The adhesion law ``law`` (default ``"paper"``: Heß's rule (8) with the parameters' ``Δγ0``, ``Δγ1``; ``"rate"``:
    :class:`~mdr_events.RateDependentAdhesion` of those works at rest with ``v_ref`` (m/s) and the exponent ``n``).

    Raises
    ------
    ValueError, TypeError
        An unknown law, ``v_ref`` or ``n`` missing from the rate law or given to the paper's, or the law's own message
        (``v_ref <= 0``, ``n`` outside ``(0, 1]``, a value that is not finite, works at rest it refuses).
    """
    name = "paper" if law is None else law
    if name not in ADHESION_LAWS:
        raise ValueError(f"law={shown(law)} is not allowed; allowed: " + " or ".join(map(repr, ADHESION_LAWS))
                         + " (the paper's rate-independent law, or the rate-dependent one with v_ref and n)")
    given = {"v_ref": v_ref, "n": n}
    extra = [key for key, value in given.items() if value is not None and key not in ADHESION_LAWS[name]]
    if extra:
        raise ValueError(f"{extra[0]}={shown(given[extra[0]])} is not allowed with the adhesion law {name!r}; allowed: "
                         "v_ref and n with the law 'rate' alone")
    missing = [key for key in ADHESION_LAWS[name] if given[key] is None]
    if missing:
        raise ValueError(f"the adhesion law {name!r} lacks {' and '.join(missing)}; allowed: the law 'rate' with both "
                         "v_ref (m/s, > 0) and n (0 < n <= 1)")
    if name == "paper":
        return Adhesion(params.dgamma0, params.dgamma1)
    return RateDependentAdhesion(params.dgamma0, params.dgamma1, as_float(v_ref), as_float(n))


def check_rate_run(contact: Contact, motion: Scenario | Paths, method: Method, where: str) -> None:
    """Refuse the rate-dependent law where ``method`` does not run it with the contact's other parts (a friction law,
    an indenter, a layer) along ``motion``: ``simulate``'s own checks (``Method.check_model``,
    :func:`~mdr_events.models.simulate.check_layer_taken`), made before anything runs; the paper's law passes.

    Raises
    ------
    ValueError, TypeError
        What the method refuses, in its own words.
    """
    if not contact.adhesion.is_rate_dependent:
        return
    from mdr_events.models.simulate import check_layer_taken, model_job

    method.check_model(model_job(contact, motion, None, {}))
    check_layer_taken(contact, motion, method, where=where)


def check_reference_run(contact: Contact, motion: Scenario | Paths, where: str) -> None:
    """Refuse the rate-dependent law where the referee ``where`` (``validate``) cannot take its reference, the law's
    own continuum: what the continuum does not run (:func:`check_rate_run`) and what its exact solution of one path
    does not take (:func:`~mdr_events.models.methods.check_exact_solution`: Coulomb's part); the paper's law passes.

    Raises
    ------
    ValueError, TypeError
        What the reference refuses, in its own words.
    """
    if not contact.adhesion.is_rate_dependent:
        return
    from mdr_events.models.methods import Continuum, check_exact_solution
    from mdr_events.models.simulate import model_job

    check_rate_run(contact, motion, Continuum(), where)
    check_exact_solution(model_job(contact, motion, None, {}), where)


def check_reference_law(contact: Contact, where: str) -> None:
    """Refuse the rate-dependent law where the model compared is rate independent (``lammps-check``: LAMMPS's
    granular models): the one-line ``TypeError`` naming the law and what runs it (``validate`` referees the law
    against its own continuum: :func:`check_rate_run` with the continuum).

    Raises
    ------
    TypeError
        A contact whose adhesion law is rate dependent.
    """
    if contact.adhesion.is_rate_dependent:
        raise TypeError(f"adhesion={contact.adhesion!r} is not allowed in {where}: LAMMPS's granular models hold a work "
                        "of adhesion independent of the edge's speed; allowed: the paper's law (a run of the rate law "
                        "is refereed by validate against its own continuum)")


def angle_speeds(contact: Contact, speeds: Sequence[float] | None, params: Parameters) -> tuple[float, ...] | None:
    """The speeds (m/s) of a phase diagram's critical angles under the rate-dependent law (default the parameters'
    ``v`` alone), checked with what the angles take of the contact
    (:func:`~mdr_events.analysis.rate_job.rate_job`: the friction law ``"tau0"``, the half-space); ``None`` for the
    paper's law (its closed forms, Fig. 9).

    Raises
    ------
    ValueError, TypeError
        Speeds with the paper's law, a speed that is not a finite number > 0, or a contact the angles refuse.
    """
    if not contact.adhesion.is_rate_dependent:
        if speeds is not None:
            raise ValueError(f"speeds={list(speeds)!r} are not allowed with the adhesion law 'paper'; allowed: speeds "
                             "with the law 'rate' (its critical angles against the speed)")
        return None
    from mdr_events.analysis.rate_job import rate_job
    from mdr_events.validation import check_real

    found = tuple(check_real("speed", speed, "a finite number > 0 (m/s)", lambda value: value > 0.0)
                  for speed in ([params.v] if speeds is None else speeds))
    rate_job(contact, found, (), d_max=params.d_max, what="the critical angles against the speed")
    return found


def layer(h: float | None = None, base: str | None = None) -> Layer:
    """The elastomer's layer of thickness ``h`` (m; default ``inf``: the half-space) on ``base`` (``"bonded"``, the
    default, or ``"frictionless"``).

    Raises
    ------
    ValueError, TypeError
        The layer's own message (a thickness not > 0, a base not among the two).
    """
    return Layer(float("inf") if h is None else h, "bonded" if base is None else base)


def limits(items: Iterable[str]) -> Limits:
    """The resource limits of ``NAME=VALUE`` items (``--limit``, a ``[limits]`` table) over the defaults.

    Raises
    ------
    ValueError
        An unknown name or a value that is not a number (:func:`~mdr_events.limits.parse_limit`), or a name given
        twice.
    """
    found, given = DEFAULT_LIMITS, set()
    for text in items:
        found = parse_limit(text, found)
        name = text.partition("=")[0].strip()
        if name in given:
            raise ValueError(f"--limit {shown(text)}: {name} is given twice; allowed: each limit once (e.g. --limit "
                             "memory=8GiB --limit steps=1e8)")
        given.add(name)
    return found


def path(waypoints: Sequence[Sequence[float]], speed: float | None, params: Parameters) -> Path:
    """The path through ``waypoints`` (x, d) in m at ``speed`` (m/s, default the parameters' ``v``).

    Raises
    ------
    ValueError, TypeError
        The path's own message.
    """
    from mdr_events.models.paths import Path

    return Path(waypoints, params.v if speed is None else speed)


def contact(params: Parameters, profile: SimulatedProfile = None, law: FrictionLaw | None = None,
            body: Layer = HALF_SPACE, adhesion_law: AdhesionLaw | None = None) -> Contact:
    """The :class:`~mdr_events.Contact` of ``params`` with ``profile`` (``None``: its paraboloid), the friction
    law ``law`` (default the paper's, ``τ0`` from ``params``), the layer ``body`` (default the half-space) and the
    adhesion law ``adhesion_law`` (default the paper's of ``params``' works: :func:`adhesion`)."""
    made = dataclasses.replace(Contact.from_parameters(params, profile, law), layer=body)
    return made if adhesion_law is None else dataclasses.replace(made, adhesion=adhesion_law)


def scenario(name: str, alpha: float | Sequence[float] | None, params: Parameters) -> Scenario:
    """The paper's scenario ``name`` at the angles ``alpha`` (degrees; default those of Fig. 8 and 10), to the
    parameters' ``d_max`` at their ``v``.

    Raises
    ------
    ValueError, TypeError
        An unknown scenario, or angles :class:`~mdr_events.Scenario` refuses.
    """
    from mdr_events.models.motion import FIGURE_ANGLES, Scenario

    return Scenario(name, FIGURE_ANGLES if alpha is None else alpha, params.d_max, params.v)


def paths(custom: Path, params: Parameters) -> Paths:
    """One custom path, labelled ``"path 1"``, whose run the parameters' ``d_max`` and ``v`` name (its checks and
    ``param_d_max``, ``param_v``), as they always did (:meth:`~mdr_events.Paths.named_by`)."""
    from mdr_events.models.motion import Paths

    return Paths.named_by(custom, params.d_max, params.v)


def method(name: str, options: Mapping[str, Any]) -> Method:
    """The method ``name`` (``"discrete"``, ``"continuum"``) with its options; those given as ``None`` take the
    method's defaults (:func:`~mdr_events.models.methods.as_method`).

    Raises
    ------
    ValueError, TypeError
        An unknown method, an option of another method or a value the method refuses.
    """
    from mdr_events.models.methods import as_method

    return as_method(name, options)
