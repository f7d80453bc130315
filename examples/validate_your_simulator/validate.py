"""Validate my_simulator.py (your stand-in) against the exact continuum of mdr_events.

    .venv/bin/python examples/validate_your_simulator/validate.py [OUT_DIR]

Scenario A at 20°, the paper's parameters. The right simulator at four spacings: max errors,
verdicts, event errors and the observed order of convergence (first order expected); then the
three wrong variants (and the right one beside them) at three spacings, and what flags each.
The CSVs go to OUT_DIR (default: a temporary directory, removed at the end).
"""
import functools
import sys
import tempfile
import types
from pathlib import Path

import numpy as np

import mdr_events as me
from mdr_events.analysis.convergence import slip_onset_delay_bound
from mdr_events.models.continuum import solve_path

sys.path.insert(0, str(Path(__file__).resolve().parent))  # my_simulator.py sits beside this script
import my_simulator as sim  # noqa: E402

ALPHA = 20.0  # degrees
#: The motion: scenario A at ALPHA to the paper's depth d_max = 0.3 mm at its speed v = 1 µm/s.
SCENARIO = me.Scenario("A", ALPHA)
SPACINGS = (8e-6, 4e-6, 2e-6, 1e-6)  # m
WRONG_SPACINGS = (4e-6, 2e-6, 1e-6)  # m: does an error shrink with Δx?
QUANTITIES = ("normal_force", "tangential_force", "contact_area")
SYMBOLS = {"normal_force": "F_N", "tangential_force": "F_x", "contact_area": "A"}


def time_step(dx, motion=SCENARIO):
    """dt = 0.5 Δx / v: each step moves the indenter half a spring spacing (``v`` the motion's speed)."""
    return 0.5 * dx / motion.v


def tolerance(dx, contact):
    """What a spring model at Δx (dt = time_step(Δx)) is judged at: the larger of

    - the resolution of the springs: one spring row per side, 2 Δx / a(d_max) of the contact area (and of the
      full-slip F_x = π a² τ0), a = JKR radius at d_max: the norms;
    - the lag of its slip onset beyond one step, relative to the path's duration: the oldest springs attach at the
      end of the step that touches (a step's travel short) and their cap is that of a radius rounded to Δx/2,
      amplified by |ẋ|/(|ẋ| − K ȧ) (mdr_events.analysis.convergence.slip_onset_delay_bound): 1.5 times the first.
    """
    springs = 2 * dx / float(me.jkr_contact_radius(SCENARIO.d_max, contact, contact.adhesion.dgamma0))
    params = contact.parameters(SCENARIO.d_max, SCENARIO.v)
    solution = exact_solution(params)
    return max(springs, slip_onset_delay_bound(solution, params, dx, time_step(dx)) / solution.path.duration)


@functools.lru_cache(maxsize=None)
def exact_solution(params):
    """The exact continuum along the scenario's path (solved once)."""
    return solve_path(params, me.Path.scenario_A(ALPHA, params))


def run_and_validate(contact, dx, out_dir, variant="right"):
    """Simulate, write the CSV and validate it: the report (xarray.Dataset) and the CSV's path."""
    result = sim.simulate(sim.PAPER, ALPHA, dx, time_step(dx), variant)
    csv_path = Path(out_dir) / f"{variant}_dx{dx * 1e6:g}um.csv"
    sim.write_csv(result, csv_path)
    return me.validate(csv_path, contact, SCENARIO, tolerance=tolerance(dx, contact)), csv_path


def observed_order(spacings, errors):
    """Least-squares slope of log(error) against log(Δx)."""
    return float(np.polyfit(np.log(spacings), np.log(errors), 1)[0])


def flags(coarse, fine, dx_fine):
    """What a wrong model shows and a right one does not, from reports at two spacings (Δx and Δx/2):
    a quantity outside the tolerance whose error does not shrink with Δx (order < 0.4), and an event
    more than 4 time steps off at the finer spacing that does not shrink either."""
    shrink = 0.75  # 2**-0.4: an error that halving Δx takes below this share is converging
    out = []
    for q in QUANTITIES:
        e_coarse, e_fine = (float(report.max_error.sel(quantity=q)) for report in (coarse, fine))
        if e_fine > fine.attrs["tolerance"] and e_fine > shrink * e_coarse:
            out.append(f"{SYMBOLS[q]} (max error {e_fine:.1e}, order {np.log2(e_coarse / e_fine):.2f})")
    for event in fine.event.values:
        e_coarse, e_fine = (float(report.event_time_error.sel(event=event)) for report in (coarse, fine))
        if abs(e_fine) > 4 * time_step(dx_fine) and abs(e_fine) > shrink * abs(e_coarse):
            out.append(f"{event} ({e_fine:+.1f} s)")
    return out


def validate_right(contact, out_dir):
    """The right simulator at SPACINGS: reports by spacing, the CSVs by spacing."""
    print(f"right simulator, scenario A at {ALPHA:g}°, dt = 0.5 Δx / v; tolerance max(2 Δx / a(d_max), slip onset "
          "lag bound / duration); "
          "max errors relative to each quantity's range:")
    print("  Δx/µm  dt/s  samples    max F_N    max F_x      max A  tolerance  verdict")
    reports, csvs = {}, {}
    for dx in SPACINGS:
        report, csvs[dx] = run_and_validate(contact, dx, out_dir)
        reports[dx] = report
        errors = "".join(f"{float(report.max_error.sel(quantity=q)):11.2e}" for q in QUANTITIES)
        print(f"  {dx * 1e6:5g} {time_step(dx):5g} {report.time.size:8d}{errors}"
              f"{report.attrs['tolerance']:11.2e}  {report.attrs['verdict']}")
    print("  event time errors / s (candidate − exact; exact times in s from first contact):")
    print("  Δx/µm" + "".join(f"{e:>19}" for e in reports[SPACINGS[0]].event.values))
    print("  exact" + "".join(f"{float(t):19.1f}" for t in reports[SPACINGS[0]].event_time_exact.values))
    for dx, report in reports.items():
        print(f"  {dx * 1e6:5g}" + "".join(f"{float(e):+19.2f}" for e in report.event_time_error.values))
    print("  pull-off force / N: exact at the jump, candidate's last sample in contact, exact at that sample")
    for dx, report in reports.items():
        last = np.flatnonzero(report.candidate_contact_area.values > 0)[-1]
        print(f"  {dx * 1e6:5g}{float(report.pull_off_force_exact):12.5f}{float(report.pull_off_force_candidate):12.5f}"
              f"{float(report.exact_normal_force[last]):12.5f}")
    print("observed order (least-squares slope in log-log over the four spacings; expected: 1):")
    for norm in ("max_error", "l1_error"):
        orders = [observed_order(SPACINGS, [float(reports[dx][norm].sel(quantity=q)) for dx in SPACINGS])
                  for q in QUANTITIES]
        print(f"  {norm:10s}" + "".join(f"  {SYMBOLS[q]} {o:.2f}" for q, o in zip(QUANTITIES, orders)))
    return reports, csvs


def find_convergence_study():
    """mdr_events' own convergence study (``convergence_study(candidates_by_dx, contact, motion)``),
    or None where this version of mdr_events has none."""
    convergence_study = getattr(me, "convergence_study", None)
    if convergence_study is None:
        try:
            from mdr_events.analysis import convergence_study
        except ImportError:
            return None
    if isinstance(convergence_study, types.ModuleType):  # the module of that name, not yet re-exported
        convergence_study = getattr(convergence_study, "convergence_study", None)
    return convergence_study if callable(convergence_study) else None


def package_convergence_study(contact, csvs):
    """The observed orders by mdr_events.analysis.convergence_study of the same CSVs, if it exists."""
    convergence_study = find_convergence_study()
    if convergence_study is None:
        print("mdr_events.analysis.convergence_study is not in this version of mdr_events: skipped")
        return None
    study = convergence_study(csvs, contact, SCENARIO)
    print(f"mdr_events.analysis.convergence_study: verdict {study.attrs.get('verdict')!r}; observed orders ± spread:")
    for name in [name for name in study.data_vars if name.endswith("_order") and name != "expected_order"]:
        order, spread = study[name], study.get(f"{name}_spread", study[name] * np.nan)
        if order.ndim == 0:
            print(f"  {name}: {float(order):.2f} ± {float(spread):.2f}")
        else:
            label = order.dims[0]
            print(f"  {name}: " + ", ".join(f"{SYMBOLS.get(str(k), str(k))} {float(o):.2f} ± {float(s):.2f}" for k, o, s
                                            in zip(order[label].values, order.values, spread.values)))
    return study


def validate_wrong(contact, out_dir):
    """Each variant at WRONG_SPACINGS: its max errors, event errors, what flags it (from the two finest)
    and, if mdr_events has it, the verdict of convergence_study."""
    convergence_study = find_convergence_study()
    print(f"\nthe four variants at Δx = {' → '.join(f'{dx * 1e6:g}' for dx in WRONG_SPACINGS)} µm. Flagged: a quantity "
          "outside the tolerance whose error does not shrink with Δx, an event > 4 steps off that does not shrink")
    found = {}
    for variant, what in sim.VARIANTS.items():
        runs = [run_and_validate(contact, dx, out_dir, variant) for dx in WRONG_SPACINGS]
        reports = [report for report, _ in runs]
        found[variant] = flags(reports[-2], reports[-1], WRONG_SPACINGS[-1])
        print(f"  {variant} ({what}): verdicts {', '.join(r.attrs['verdict'] for r in reports)}")
        print("    max errors: " + "; ".join(f"{SYMBOLS[q]} " + " → ".join(
            f"{float(r.max_error.sel(quantity=q)):.1e}" for r in reports) for q in QUANTITIES))
        print("    event time errors / s: " + "; ".join(f"{e} " + " → ".join(
            f"{float(r.event_time_error.sel(event=e)):+.1f}" for r in reports) for e in reports[0].event.values))
        print(f"    pull-off force {float(reports[-1].pull_off_force_candidate):.5f} N "
              f"(exact {float(reports[-1].pull_off_force_exact):.5f} N)")
        if convergence_study is not None:
            study = convergence_study({dx: csv for dx, (_, csv) in zip(WRONG_SPACINGS, runs)}, contact, SCENARIO)
            print(f"    convergence_study verdict: {study.attrs.get('verdict')}")
        print(f"    flagged by: {', '.join(found[variant]) or 'nothing'}")
    return found


def main(out_dir=None):
    """Everything above, printed; returns the right simulator's reports by Δx and each variant's flags."""
    contact = me.Contact.paper()
    print(f"mdr_events.Contact.paper(): {contact}; {SCENARIO}")
    if contact.parameters(SCENARIO.d_max, SCENARIO.v).as_dict() != sim.PAPER:
        raise SystemExit(f"my_simulator.PAPER differs from Contact.paper() and {SCENARIO}: {sim.PAPER}")
    with tempfile.TemporaryDirectory() as scratch:
        out = Path(out_dir or scratch)
        out.mkdir(parents=True, exist_ok=True)
        reports, csvs = validate_right(contact, out)
        package_convergence_study(contact, csvs)
        return reports, validate_wrong(contact, out)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else None)
