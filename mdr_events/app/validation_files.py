"""Validation files: a report of :func:`mdr_events.validate` written as ``<stem>.nc``, ``<stem>.md``, ``<stem>.png``.

- ``<stem>.nc``: the report itself (:func:`mdr_events.io.files.write_netcdf`; ``open_result`` reads it back);
- ``<stem>.md``: a Markdown summary: the verdict, the tolerance, the candidate's source, the path, the
  samples compared and left out, the norms per quantity and the events;
- ``<stem>.png``: :func:`mdr_events.plotting.validation.plot_validation`.

Everything is computed first (:func:`render_validation`: the text and the PNG bytes), then written
(:func:`write_rendered`; a study plans them, :func:`rendered_plans`, and writes them with its other files), each
file to a temporary name renamed into place, together (:func:`mdr_events.io.files.atomic_write_all`): a run that
fails while being computed writes nothing, and no file is ever seen half-written. Used by ``mdr-events validate``
and by the ``[validate]`` table of study files.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import NamedTuple

import numpy as np
import xarray as xr

from mdr_events.analysis.reports import ValidationReport, Verdict
from mdr_events.analysis.validate import LEFT_OUT_CODES
from mdr_events.app.result_files import FileOutcome, PlannedFile, bytes_plan, commit, netcdf_plan
from mdr_events.io.files import check_output_stem, prepare_output_directory
from mdr_events.parameters import PARAMETER_UNITS
from mdr_events.plotting.figures import figure_png
from mdr_events.plotting.validation import plot_validation

__all__ = ["RenderedReport", "VALIDATION_SUFFIXES", "render_validation", "write_rendered", "rendered_plans",
           "write_validation", "validation_markdown", "console_summary"]

#: The files of one validated run, by suffix.
VALIDATION_SUFFIXES = (".nc", ".md", ".png")
#: How the report's events are named in the summaries.
EVENT_NAMES = {"first_contact": "first contact", "slip_onset": "slip onset", "full_slip": "full slip",
               "detachment_starts": "start of detachment", "pull_off": "pull-off", "re_contact": "re-contact"}


class RenderedReport(NamedTuple):
    """A report ready to be written (a validated run, a fit): the dataset, its Markdown summary and its figure
    (PNG bytes)."""

    stem: str
    report: xr.Dataset
    markdown: str
    png: bytes

    def paths(self, out: str | os.PathLike) -> list[Path]:
        """Where :func:`write_rendered` puts the files in ``out``."""
        return [Path(out) / f"{self.stem}{suffix}" for suffix in VALIDATION_SUFFIXES]


def _number(value, digits: int = 4, signed: bool = False) -> str:
    """A number for a table; ``—`` where it is not a number (an event not found)."""
    value = float(value)
    if not math.isfinite(value):
        return "—"
    return f"{value:+.{digits}g}" if signed else f"{value:.{digits}g}"


def _left_out_counts(report: xr.Dataset) -> dict[int, int]:
    codes = report["left_out"].values
    return {code: int(np.count_nonzero(codes == code)) for code in LEFT_OUT_CODES if code}


def validation_markdown(report: xr.Dataset, stem: str | None = None) -> str:
    """The Markdown summary of a validation report (``<stem>.md``; ``stem`` names the figure beside it)."""
    typed = ValidationReport.from_dataset(report)
    verdict, tolerance = typed.verdict, typed.tolerance
    source = str(report.attrs.get("candidate_source", "candidate"))
    counts = _left_out_counts(report)
    lines = [f"# Validation of `{os.path.basename(source)}` against the exact continuum", "",
             f"**Verdict: {verdict}** — "
             + ("every quantity's max error, the contact and every event compared are" if verdict is Verdict.PASS
                else "not everything is")
             + f" within the tolerance {tolerance:g} (errors relative to the exact quantity's range, event times to "
             "the path's duration).", ""]
    failures = typed.failures
    if failures:
        lines += ["## Failing", ""] + [f"- **{text}**" for text in failures] + [""]
    lines += [f"- Candidate: `{source}`",
             f"- Events not compared: {report.attrs.get('events_not_compared', 'none')}",
             f"- Not compared: {report.attrs.get('quantities_not_compared', 'none')}; columns not read: "
             f"{report.attrs.get('unused_columns', 'none')} (name them with --names to check them)",
             f"- Tolerance: {tolerance:g} (max error relative to the range of the exact quantity over the compared "
             "samples)"]
    if "path_description" in report.attrs:
        lines.append(f"- Path: {report.attrs['path_description']}")
    lines += [f"- Waypoints (x, d) in m: {report.attrs.get('path_waypoints', '?')}; speed "
              f"{float(report.attrs.get('path_speed', math.nan)):g} m/s",
              f"- Time origin of the candidate: {report.attrs.get('time_origin', '?')}",
              f"- Samples compared: {int(report['samples_compared'])}; left out: {int(report['samples_left_out'])} "
              f"({LEFT_OUT_CODES[2]}: {counts[2]}, {LEFT_OUT_CODES[3]}: {counts[3]}); "
              f"{LEFT_OUT_CODES[1]} (not counted): {counts[1]}",
              "- Parameters: " + ", ".join(
                  f"{name} = {report.attrs[f'param_{name}']:g}" + (f" {unit}" if unit != "1" else "")
                  for name, unit in PARAMETER_UNITS.items() if f"param_{name}" in report.attrs)]
    if "parameters_preset" in report.attrs:
        lines.append(f"- Preset: {report.attrs['parameters_preset']} (from it: "
                     f"{report.attrs.get('parameters_from_preset') or 'none'})")
    lines += _norm_rows(report) + _event_rows(report)
    exact_force, candidate_force = float(report["pull_off_force_exact"]), float(report["pull_off_force_candidate"])
    lines += ["", f"Pull-off force (mN): exact {_number(exact_force * 1e3, 6)}, candidate (last sample in contact) "
                  f"{_number(candidate_force * 1e3, 6)}, "
                  f"error {_number((candidate_force - exact_force) * 1e3, 3, True)}."]
    if stem is not None:
        lines += ["", f"![candidate and exact against time, the difference below]({stem}.png)",
                  "", f"The whole report: `{stem}.nc` (`mdr_events.open_result`)."]
    return "\n".join(lines) + "\n"


def _norm_rows(report: xr.Dataset) -> list[str]:
    """The Markdown section of a validation report's norms, one row per quantity."""
    lines = ["", "## Norms", "",
             "Over the samples compared in contact, each relative to the exact quantity's range there.", "",
             "| quantity | max | RMS | L1 | within tolerance |", "|---|---:|---:|---:|:---:|"]
    for name in report["quantity"].values:
        row = report.sel(quantity=name)
        lines.append(f"| {name} | {_number(row['max_error'], 3)} | {_number(row['rms_error'], 3)} | "
                     f"{_number(row['l1_error'], 3)} | {'yes' if int(row['within_tolerance']) else '**no**'} |")
    return lines


def _event_rows(report: xr.Dataset) -> list[str]:
    """The Markdown section of a validation report's events, one row per event."""
    lines = ["", "## Events", "",
             "Found in the candidate by the rules of `mdr_events.analysis.validate`; compared with the first event of "
             "each kind in the continuum's log (times from first contact; — where not found).", "",
             "| event | exact time (s) | candidate time (s) | time error (s) | / duration | exact depth (µm) "
             "| candidate depth (µm) | depth error (µm) |", "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for event in report["event"].values:
        row = report.sel(event=event)
        relative = row["event_time_relative_error"] if "event_time_relative_error" in row else math.nan
        cells = [EVENT_NAMES.get(str(event), str(event)), _number(row["event_time_exact"], 6),
                 _number(row["event_time_candidate"], 6), _number(row["event_time_error"], 3, True),
                 _number(relative, 3),
                 _number(row["event_depth_exact"] * 1e6, 6), _number(row["event_depth_candidate"] * 1e6, 6),
                 _number(row["event_depth_error"] * 1e6, 3, True)]
        lines.append(f"| {' | '.join(cells)} |")
    return lines


def console_summary(report: xr.Dataset, name: str) -> list[str]:
    """A few lines for the terminal: the verdict, the max errors, the event time errors, the samples."""
    tolerance = float(report.attrs["tolerance"])
    errors = ", ".join(f"{quantity} {float(report['max_error'].sel(quantity=quantity)):.2e}"
                       + ("" if int(report["within_tolerance"].sel(quantity=quantity)) else " (!)")
                       for quantity in report["quantity"].values)
    events = ", ".join(f"{EVENT_NAMES.get(str(event), str(event))} "
                       f"{_number(report['event_time_error'].sel(event=event), 3, True)}"
                       for event in report["event"].values)
    typed = ValidationReport.from_dataset(report)
    return [f"{name}: {str(typed.verdict).upper()} (tolerance {tolerance:g}; "
            f"{int(report['samples_compared'])} samples compared, {int(report['samples_left_out'])} left out)",
            *[f"  failing: {text}" for text in typed.failures],
            f"  max error / range: {errors}",
            f"  event time error (s): {events}",
            f"  not compared: {report.attrs.get('quantities_not_compared', 'none')}; columns not read: "
            f"{report.attrs.get('unused_columns', 'none')}"]


def render_validation(report: xr.Dataset, stem: str) -> RenderedReport:
    """The files of a report, computed but not written: the Markdown text and the figure's PNG bytes."""
    return RenderedReport(stem, report, validation_markdown(report, stem), figure_png(plot_validation(report)))


def write_rendered(rendered: RenderedReport, out: str | os.PathLike) -> list[FileOutcome]:
    """Write ``<stem>.nc``, ``<stem>.md`` and ``<stem>.png`` into ``out`` together (:func:`rendered_plans`)."""
    return commit(rendered_plans(rendered, out))


def rendered_plans(rendered: RenderedReport, out: str | os.PathLike) -> list[PlannedFile]:
    """``<stem>.nc``, ``<stem>.md`` and ``<stem>.png`` planned in ``out``, for
    :func:`~mdr_events.app.result_files.commit`, after checking ``out``
    (:func:`~mdr_events.io.files.prepare_output_directory`) and the stem
    (:func:`~mdr_events.io.files.check_output_stem`)."""
    prepare_output_directory(out, "out")
    check_output_stem("stem", rendered.stem)
    nc, md, png = rendered.paths(out)
    return [netcdf_plan(rendered.report, nc), bytes_plan(md, rendered.markdown.encode("utf-8")),
            bytes_plan(png, rendered.png)]


def write_validation(report: xr.Dataset, out: str | os.PathLike, stem: str) -> list[FileOutcome]:
    """Render a report (:func:`render_validation`), then write its three files (:func:`write_rendered`)."""
    return write_rendered(render_validation(report, stem), out)
