"""The cases of "LAMMPS granular models against the exact MDR": which LAMMPS models along which paths, each run
refereed by :func:`~mdr_events.dem.lammps_check`, and how the stored reports agree with a fresh computation.

Each case's validation report is stored with ``study="lammps_granular"``, two variables of the LAMMPS run beside it
(:data:`RUN_VARIABLES`: its depth and contact flag, what the section's measurements read) and the continuum's
tolerances as attributes; this module registers the schema and the accuracy of every variable of such a report
(:func:`register_report_accuracy`). The input deck is not stored (it prints the path's corner times to 17 digits,
which another CPU's ``tan`` may round otherwise): ``me.dem.run_lammps`` gives it.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.analysis.validate import VALIDATION_CONTENT
from mdr_events.contact import Adhesion, Contact, FrictionLaw, Paraboloid
from mdr_events.dem.check import lammps_check
from mdr_events.dem.mapping import LammpsModel
from mdr_events.dem.runner import LammpsUnavailable, load_lammps
from mdr_events.io.agreement import ROUND_OFF, Accuracy, Integrated, RootFound, RoundOff, register_accuracy
from mdr_events.io.agreement import tolerance_of
from mdr_events.io.datasets import register_schema
from mdr_events.models.continuum import Tolerances
from mdr_events.models.paths import Path, exit_depth
from mdr_events.parameters import Parameters
from mdr_events.reproduction.common import RADII

__all__ = ["LAMMPS_STUDY", "LAMMPS_STEPS", "LAMMPS_MU", "LAMMPS_DGAMMA", "LAMMPS_RADIUS", "PATH_LABELS",
           "LammpsCase", "CASES", "TANGENTIAL_MODELS_RUN", "case_contact", "case_path", "run_case", "run_cases",
           "lammps_unavailable",
           "RUN_VARIABLES", "StepSum", "SumOf", "OneSample", "NormAccuracy"]

#: The ``study`` attribute of the section's reports (it selects their accuracies).
LAMMPS_STUDY = "lammps_granular"
#: LAMMPS's time steps over each path: a step moves the indenter by about 1/2000 of the path (0.5 µm on the
#: vertical path), each segment gets far more than the 20 steps it needs, and a case runs in about 0.2 s.
LAMMPS_STEPS = 2000
#: Coulomb's μ of the cases with a tangential model, and the work of adhesion of the adhesive ones (both ways: LAMMPS
#: has one γ = Δγ/2), J/m².
LAMMPS_MU = 0.5
LAMMPS_DGAMMA = 0.15
#: The sphere's radius: the paper's R = 30 mm.
LAMMPS_RADIUS = RADII["R30"]
#: The scenarios' angles (degrees) and the fretting loop: in vertically to d_max, x through these multiples of the
#: full-slip shift μ E* d_max / G* (beyond it: the loop slides), out vertically to below the jump-off.
ANGLE_A = 20.0
ANGLE_B = 30.0
FRETTING_TURNS = (1.5, -1.5, 1.5, 0.0)
#: The paths by label.
PATH_LABELS = ("vertical", f"A {ANGLE_A:g}°", f"B {ANGLE_B:g}°", "fretting")


class LammpsCase(NamedTuple):
    """One case: LAMMPS's normal and tangential model along the path of ``path`` (a :data:`PATH_LABELS` entry)."""

    normal: str
    tangential: str
    path: str

    @property
    def label(self) -> str:
        """E.g. ``jkr + mindlin, B 30°``."""
        return f"{self.normal} + {self.tangential}, {self.path}"

    @property
    def stem(self) -> str:
        """Its files' stem in ``results/``: ``lammps_jkr_mindlin_B30``."""
        path = self.path.replace("°", "").replace(" ", "")
        return "lammps_" + "_".join(part.replace("/", "-") for part in (self.normal, self.tangential, path))


#: The tangential models run with Hertz and JKR: every one LAMMPS offers with a Coulomb cap (dmt: mindlin alone).
TANGENTIAL_MODELS_RUN = ("mindlin", "linear_history", "mindlin_rescale", "mindlin/force", "mindlin_rescale/force")


def _cases() -> tuple[LammpsCase, ...]:
    """The vertical path without friction for each normal model; along A, B and the fretting loop each tangential
    model of :data:`TANGENTIAL_MODELS_RUN` with Hertz (no adhesion) and JKR (adhesion), and DMT with mindlin."""
    cases = [LammpsCase(normal, "none", "vertical") for normal in ("hertz/material", "jkr", "dmt")]
    for normal, tangentials in (("hertz/material", TANGENTIAL_MODELS_RUN), ("jkr", TANGENTIAL_MODELS_RUN),
                                ("dmt", ("mindlin",))):
        cases += [LammpsCase(normal, tangential, path) for tangential in tangentials for path in PATH_LABELS[1:]]
    return tuple(cases)


#: The section's cases, in the table's order.
CASES = _cases()


def case_contact(case: LammpsCase) -> Contact:
    """The paper's elastomer against R = 30 mm; Δγ0 = Δγ1 = :data:`LAMMPS_DGAMMA` for an adhesive normal model;
    Coulomb's law with :data:`LAMMPS_MU` with a tangential model, no friction without."""
    adhesive = LammpsModel(case.normal, case.tangential).adhesive
    dgamma = LAMMPS_DGAMMA if adhesive else 0.0
    friction = FrictionLaw("tau0", tau0=0.0) if case.tangential == "none" else FrictionLaw("coulomb", mu=LAMMPS_MU)
    return Contact(Contact.paper().elastomer, Paraboloid(LAMMPS_RADIUS), Adhesion(dgamma, dgamma), friction)


def case_path(case: LammpsCase) -> Path:
    """The case's path for its contact (the way out ends below the contact's own jump-off)."""
    params = case_contact(case).parameters(Parameters.paper().d_max, Parameters.paper().v)
    if case.path == "vertical":
        return Path.scenario_A(90.0, params)
    if case.path == PATH_LABELS[1]:
        return Path.scenario_A(ANGLE_A, params)
    if case.path == PATH_LABELS[2]:
        return Path.scenario_B(ANGLE_B, params)
    shift = LAMMPS_MU * params.E_star / params.G_star * params.d_max
    points = [(0.0, 0.0), (0.0, params.d_max)] + [(turn * shift, params.d_max) for turn in FRETTING_TURNS]
    return Path(points + [(0.0, exit_depth(params))], params.v)


#: The LAMMPS run's variables kept in the report: name -> (run's name, units, long name).
RUN_VARIABLES = {"lammps_depth": ("depth", "m", "overlap d = R - z of the sphere (LAMMPS)"),
                 "lammps_contact": ("lammps_contact", "1", "1: the wall holds a contact (LAMMPS)")}


def run_case(case: LammpsCase) -> xr.Dataset:
    """LAMMPS along the case's path (:data:`LAMMPS_STEPS` steps), validated against the exact continuum: the report
    with :data:`RUN_VARIABLES`, the case and the continuum's tolerances as attributes, without the input deck."""
    run, report = lammps_check(case_contact(case), case_path(case), model=LammpsModel(case.normal, case.tangential),
                               steps=LAMMPS_STEPS)
    del report.attrs["lammps_input_deck"]
    # (an array among a variable's attributes cannot be compared by io.agreement, which compares attributes with
    # ``!=``: the codes of ``left_out`` as text, their meanings beside them as before)
    codes = report["left_out"].attrs.pop("flag_values")
    report["left_out"].attrs["flag_codes"] = " ".join(str(int(code)) for code in codes)
    for name, (source, units, long_name) in RUN_VARIABLES.items():
        report[name] = ("time", run[source].values, {"units": units, "long_name": long_name})
    tolerances = Tolerances()
    report.attrs.update(study=LAMMPS_STUDY, lammps_case=case.label, lammps_path=case.path, rtol=tolerances.rtol,
                        radius_rtol=tolerances.radius_rtol)
    return report


def lammps_unavailable() -> str | None:
    """Why LAMMPS cannot run here (one line), or ``None`` if it can."""
    try:
        load_lammps()
    except LammpsUnavailable as error:
        return str(error)
    return None


def run_cases(normal: str) -> dict[LammpsCase, xr.Dataset] | str:
    """Every case of the normal model ``normal`` run and validated; the reason in one line if LAMMPS cannot run."""
    why = lammps_unavailable()
    if why is not None:
        return why
    return {case: run_case(case) for case in CASES if case.normal == normal}


# --- how the stored reports agree with a fresh computation ---------------------------------------------------------
def _largest(values: np.ndarray) -> float:
    finite = np.abs(values[np.isfinite(values)])
    return float(finite.max()) if finite.size else 0.0


class StepSum(Accuracy):
    """LAMMPS's arithmetic: its closed forms (the normal force of the overlap, the position of the time) to
    :class:`~mdr_events.io.agreement.RoundOff`, and the tangential history, a sum of one increment per step (each
    rounded at most once, by ε of the largest magnitude), so ``lammps_steps`` ε more; of ``scale_of``'s largest
    magnitude (default the quantity's own)."""

    def __init__(self, scale_of: str | None = None) -> None:
        self.scale_of = scale_of

    def tolerance(self, dataset, name):
        scale = _largest(np.asarray(dataset[self.scale_of or name].values, dtype=float))
        steps = float(dataset.attrs["lammps_steps"])
        return RoundOff(self.scale_of).tolerance(dataset, name) + steps * float(np.finfo(float).eps) * scale

    def describe(self):
        return "LAMMPS's arithmetic: round-off, and one ε per step of its tangential history"


class SumOf(Accuracy):
    """A difference or sum of two variables: the sum of their tolerances' largest values."""

    def __init__(self, *names: str) -> None:
        self.names = names

    def tolerance(self, dataset, name):
        return sum(float(np.max(tolerance_of(dataset, part))) for part in self.names)

    def describe(self):
        return f"the sum of the tolerances of {', '.join(self.names)}"


class OneSample(Accuracy):
    """A time read off LAMMPS's samples (an event, a contact's end): a rounding that tips a sample across a threshold
    moves it by one sample spacing, times ``factor`` (1 for a time, the path's speed for a depth, 1/duration for a
    share of it), plus the exact side's :class:`~mdr_events.io.agreement.Integrated` tolerance where it has one."""

    def __init__(self, factor: str = "time", exact: str | None = None) -> None:
        self.factor, self.exact = factor, exact

    def tolerance(self, dataset, name):
        times = np.asarray(dataset["time"].values, dtype=float)
        spacing = float(np.max(np.diff(times))) if times.size > 1 else 0.0
        scale = {"time": 1.0, "depth": float(dataset.attrs["path_speed"]),
                 "share": 1.0 / float(times[-1] - times[0]) if times.size > 1 else 0.0}[self.factor]
        exact = float(np.max(tolerance_of(dataset, self.exact))) if self.exact else 0.0
        return 2.0 * spacing * scale + exact * (scale if self.factor == "share" else 1.0)

    def describe(self):
        return "one sample spacing either way (a sample tipped across a threshold)"


class NormAccuracy(Accuracy):
    """A norm along ``quantity`` relative to the exact quantity's range: the candidate's and the exact value's
    tolerances over the range, one per quantity."""

    def tolerance(self, dataset, name):
        out = []
        for quantity in dataset["quantity"].values:
            exact = np.asarray(dataset[f"exact_{quantity}"].values, dtype=float)
            span = float(np.nanmax(exact) - np.nanmin(exact)) if np.any(np.isfinite(exact)) else 0.0
            total = sum(float(np.max(tolerance_of(dataset, f"{kind}_{quantity}"))) for kind in ("candidate", "exact"))
            out.append(total / span if span > 0.0 else ROUND_OFF)
        return np.array(out)

    def describe(self):
        return "the candidate's and the exact quantity's tolerances over the exact range"


def register_report_accuracy() -> None:
    """Declare the schema of the section's reports (:data:`RUN_VARIABLES`) and how each of their variables is
    computed: LAMMPS's samples :class:`StepSum`, the continuum's normal force a root (``radius_rtol``, F ∝ a³) and its
    tangential force integrated (``rtol``), differences and norms from both, event times to one sample."""
    exact_force = RootFound("radius_rtol", sensitivity=3.0)
    variables: dict[str, Accuracy] = {
        "time": RoundOff(), "lammps_depth": RoundOff(), "lammps_contact": RoundOff(),
        "candidate_normal_force": StepSum(), "candidate_tangential_force": StepSum(),
        "exact_normal_force": exact_force, "exact_tangential_force": Integrated("rtol"),
        "difference_normal_force": SumOf("candidate_normal_force", "exact_normal_force"),
        "difference_tangential_force": SumOf("candidate_tangential_force", "exact_tangential_force"),
        **{name: NormAccuracy() for name in ("max_error", "rms_error", "l1_error", "left_out_max_error",
                                             "corner_max_excess", "contact_change_max_excess")},
        "contact_differs_share": OneSample("share"),
        "event_time_exact": Integrated("rtol"), "event_time_candidate": OneSample("time"),
        "event_time_error": OneSample("time", "event_time_exact"),
        "event_depth_exact": Integrated("rtol"), "event_depth_candidate": OneSample("depth"),
        "event_depth_error": OneSample("depth", "event_depth_exact"),
        "event_time_relative_error": OneSample("share", "event_time_exact"),
        "pull_off_force_exact": RootFound("radius_rtol", sensitivity=3.0, scale_of="exact_normal_force"),
        "pull_off_force_candidate": StepSum("candidate_normal_force"),
        "pull_off_force_exact_at_last_sample": RootFound("radius_rtol", sensitivity=3.0,
                                                         scale_of="exact_normal_force"),
    }
    register_schema(VALIDATION_CONTENT, {name: ("time",) for name in RUN_VARIABLES}, when=("study", LAMMPS_STUDY))
    register_accuracy(VALIDATION_CONTENT, variables, when=("study", LAMMPS_STUDY))


register_report_accuracy()
