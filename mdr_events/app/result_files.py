"""Result files: a dataset as netCDF with its figure as PNG, and the event log as CSV.

Shared by the CLI, study files and ``mdr-events reproduce``; every file is written to a temporary
name and renamed into place, the files of one run together (:func:`mdr_events.io.files.atomic_write_all`: an
interrupt or an error leaves the previous run's files as they were, never a new ``.nc`` beside an old ``.png``).
A study plans every job's files (:class:`PlannedFile`: ``*_plans``, :func:`netcdf_plan`, :func:`bytes_plan`) and
writes them all in one commit (:func:`commit_all`); so does ``mdr-events reproduce`` (:func:`dataset_plan`,
:func:`figure_plan`, :func:`text_plan`; :func:`commit_groups`).

With ``keep_agreeing=True`` a file whose content already agrees with what would be written is left
as it is (:attr:`FileStatus.KEPT`): a dataset each of whose quantities agrees within the accuracy of how it is
computed (:func:`mdr_events.io.agreement.result_differences`), a figure with the same pixels, a text with the same
characters (a rounded text: the same words, its numbers within one unit of their last digit; an event log: the same
rows and words, its floats within the tolerances of their variables). The figure and the event log are then drawn
from the dataset on disk, so that a kept dataset keeps its figure and log too. This is what lets
``make reproduce`` leave a clean git tree on a machine whose rounding differs.

:func:`write_phase_diagram` and :func:`write_simulation` check the output directory and the stem first
(:func:`mdr_events.io.files.prepare_output_directory`, :func:`mdr_events.io.files.check_output_stem`) and
draw the figure and the event log before the first file is written: a figure that cannot be drawn leaves
no netCDF file without its figure.
"""

from __future__ import annotations

import csv
import enum
import io
import os
from pathlib import Path
from typing import Callable, NamedTuple

import numpy as np
import xarray as xr
from matplotlib import image
from matplotlib.figure import Figure

from mdr_events.io.agreement import result_differences, rounded_text_differences, tolerance_of
from mdr_events.io.files import (PendingFile, atomic_write_all, check_file_path, check_output_stem, netcdf_writer,
                                 open_result, prepare_output_directory)
from mdr_events.models.motion import case_dimension
from mdr_events.parameters import Parameters
from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.model import Contact
from mdr_events.contact.indenters import Profile
from mdr_events.plotting.figures import figure_png, plot_phase_diagram, plot_simulation
from mdr_events.theory.phase import phase_diagram
from mdr_events.validation import shown

__all__ = ["FileStatus", "FileOutcome", "PlannedFile", "commit", "commit_all", "commit_groups", "netcdf_plan",
           "bytes_plan", "dataset_plan", "figure_plan", "text_plan",
           "write_dataset", "write_figure", "write_text", "write_phase_diagram", "phase_diagram_with",
           "write_phase_diagram_dataset", "write_simulation", "simulation_plans", "phase_diagram_plans",
           "event_log_csv", "event_logs_agree", "describe_outcomes"]


class FileStatus(enum.Enum):
    """What happened to a result file."""

    WRITTEN = "written"
    KEPT = "kept"  #: the file on disk already agreed with the new content and was left untouched


class FileOutcome(NamedTuple):
    """A result file and what happened to it."""

    path: Path
    status: FileStatus


def _agreeing_file(dataset: xr.Dataset, target: Path, keep_agreeing: bool) -> xr.Dataset | None:
    """The dataset in ``target`` if ``keep_agreeing`` and it agrees with ``dataset``; else ``None``."""
    if keep_agreeing and target.exists():
        try:
            existing = open_result(target)
        except ValueError:  # unreadable or foreign: replaced
            return None
        if not result_differences(dataset, existing):
            return existing
    return None


class PlannedFile(NamedTuple):
    """A file of a run as planned, nothing written yet: its path, and what writes it (``None``: the file on disk
    agrees and is kept as it is)."""

    path: Path
    pending: PendingFile | None


def _dataset_plan(dataset: xr.Dataset, target: Path, existing: xr.Dataset | None) -> PlannedFile:
    return PlannedFile(target, None if existing is not None else PendingFile(target, netcdf_writer(dataset), ".nc"))


def netcdf_plan(dataset: xr.Dataset, path: str | os.PathLike) -> PlannedFile:
    """``dataset`` planned as the netCDF file ``path`` (always written), for :func:`commit`."""
    return _dataset_plan(dataset, check_file_path("path", path), None)


def bytes_plan(path: Path, data: bytes, same: Callable[[bytes, bytes], bool] | None = None,
               keep_agreeing: bool = False) -> PlannedFile:
    """``data`` planned as the file ``path``; kept if ``keep_agreeing`` and ``same(on disk, data)``."""
    if keep_agreeing and same is not None and path.exists() and same(path.read_bytes(), data):
        return PlannedFile(path, None)
    return PlannedFile(path, PendingFile(path, lambda temporary: Path(temporary).write_bytes(data), path.suffix))


_bytes_plan = bytes_plan  # (its old name, which a test interrupts)


def commit(plans: list[PlannedFile]) -> list[FileOutcome]:
    """Write the planned files of one run (a command's, a whole study's) together
    (:func:`~mdr_events.io.files.atomic_write_all`: replaced together or not at all) and say what happened to each;
    each file kept because it agrees stays as it is."""
    atomic_write_all([pending for _, pending in plans if pending is not None])
    return [FileOutcome(path, FileStatus.KEPT if pending is None else FileStatus.WRITTEN) for path, pending in plans]


def commit_all(entries: list[PlannedFile | FileOutcome]) -> list[FileOutcome]:
    """:func:`commit` the planned files among ``entries`` (in one commit) and say what became of every entry, in
    order; an entry already a :class:`FileOutcome` (a sweep's store, written as it ran) is said as it is."""
    committed = iter(commit([entry for entry in entries if isinstance(entry, PlannedFile)]))
    return [next(committed) if isinstance(entry, PlannedFile) else entry for entry in entries]


def commit_groups(groups: list[list[PlannedFile]]) -> list[list[FileOutcome]]:
    """:func:`commit` every group's planned files in one commit and say what became of each, group by group."""
    outcomes = iter(commit([plan for group in groups for plan in group]))
    return [[next(outcomes) for _ in group] for group in groups]


def write_dataset(dataset: xr.Dataset, path: str | os.PathLike,
                  keep_agreeing: bool = False) -> tuple[xr.Dataset, FileOutcome]:
    """Write ``dataset`` as netCDF, or keep the file on disk if it agrees (``keep_agreeing``).

    Returns the dataset now in the file (the one on disk if kept) and the outcome.
    """
    on_disk, plan = dataset_plan(dataset, path, keep_agreeing)
    return on_disk, commit([plan])[0]


def dataset_plan(dataset: xr.Dataset, path: str | os.PathLike,
                 keep_agreeing: bool = False) -> tuple[xr.Dataset, PlannedFile]:
    """The file :func:`write_dataset` writes, planned (kept if it agrees), for :func:`commit`; with the dataset the
    file will hold (the one on disk if kept)."""
    if not isinstance(dataset, xr.Dataset):
        raise TypeError(f"dataset={shown(dataset)} ({type(dataset).__name__}) is not allowed; allowed: an "
                        "xarray.Dataset")
    target = check_file_path("path", path)
    existing = _agreeing_file(dataset, target, keep_agreeing)
    return (dataset if existing is None else existing), _dataset_plan(dataset, target, existing)


def _same_pixels(old: bytes, new: bytes) -> bool:
    try:
        before = image.imread(io.BytesIO(old), format="png")
    except (OSError, ValueError, SyntaxError):  # not a PNG we can read: replaced
        return False
    after = image.imread(io.BytesIO(new), format="png")
    return before.shape == after.shape and bool(np.array_equal(before, after))


def write_figure(figure, path: str | os.PathLike, keep_agreeing: bool = False) -> FileOutcome:
    """Write a figure as PNG (:func:`mdr_events.plotting.figure_png`); kept if its pixels are unchanged."""
    return commit([figure_plan(figure, path, keep_agreeing)])[0]


def figure_plan(figure, path: str | os.PathLike, keep_agreeing: bool = False) -> PlannedFile:
    """The file :func:`write_figure` writes, planned (drawn now; kept if its pixels are unchanged)."""
    return _bytes_plan(Path(path), figure_png(figure), _same_pixels, keep_agreeing)


def _same_rounded_text(old: bytes, new: bytes) -> bool:
    try:
        return not rounded_text_differences(new.decode(), old.decode())
    except UnicodeDecodeError:  # not our text: replaced
        return False


def write_text(text: str, path: str | os.PathLike, keep_agreeing: bool = False, rounded: bool = False) -> FileOutcome:
    """Write a text file (UTF-8); kept if it holds the same text (``rounded``: the same words, and its numbers
    within one unit of their last digit, :func:`~mdr_events.io.agreement.rounded_text_differences`)."""
    return commit([text_plan(text, path, keep_agreeing, rounded)])[0]


def text_plan(text: str, path: str | os.PathLike, keep_agreeing: bool = False, rounded: bool = False) -> PlannedFile:
    """The file :func:`write_text` writes, planned (kept if it holds the same text)."""
    same = _same_rounded_text if rounded else (lambda old, new: old == new)
    return _bytes_plan(Path(path), text.encode(), same, keep_agreeing)


def _check_distinct_cases(dataset: xr.Dataset) -> None:
    """Raise ``ValueError`` if a simulation's case labels repeat (its figure and event log need each once)."""
    dimension = case_dimension(dataset)
    labels, counts = np.unique(dataset[dimension].values, return_counts=True)
    if np.any(counts > 1):
        raise ValueError(f"dataset {dimension}={shown(dataset[dimension].values.tolist())} repeats "
                         f"{labels[counts > 1][0].item()!r}; allowed: a simulation whose {dimension} values are "
                         "distinct (each labels one case)")


def write_phase_diagram(params: Parameters | Contact, scenario: str, out: str | os.PathLike, stem: str,
                        keep_agreeing: bool = False, attrs: dict[str, str] | None = None,
                        **diagram: Profile | FrictionLaw | float | None) -> list[FileOutcome]:
    """Compute the phase diagram (Fig. 9a/9b, :func:`~mdr_events.phase_diagram` of ``params`` with the keywords
    ``diagram``: ``profile`` and ``friction`` beside a :class:`~mdr_events.Parameters`, default the paraboloid and the
    paper's law; ``d_max`` beside a :class:`~mdr_events.Contact`, on its layer if it has one) and write ``stem.nc``
    (with the extra ``attrs``) and ``stem.png``.

    The output directory and the stem are checked first (:func:`~mdr_events.io.files.prepare_output_directory`,
    :func:`~mdr_events.io.files.check_output_stem`), and the figure is drawn before any file is written.
    """
    directory = prepare_output_directory(out, "out")
    check_output_stem("stem", stem)
    return write_phase_diagram_dataset(phase_diagram_with(params, scenario, attrs, **diagram), directory, stem,
                                       keep_agreeing)


def phase_diagram_with(params: Parameters | Contact, scenario: str, attrs: dict[str, str] | None = None,
                       **diagram: Profile | FrictionLaw | float | None) -> xr.Dataset:
    """The phase diagram :func:`write_phase_diagram` writes (:func:`~mdr_events.phase_diagram` with ``diagram``),
    with the extra ``attrs``; nothing written."""
    dataset = phase_diagram(params, scenario=scenario, **diagram)
    dataset.attrs.update(attrs or {})
    return dataset


def write_phase_diagram_dataset(dataset: xr.Dataset, out: str | os.PathLike, stem: str,
                                keep_agreeing: bool = False) -> list[FileOutcome]:
    """Write a computed phase diagram (:func:`mdr_events.theory.phase.phase_diagram`) as ``stem.nc`` and its figure
    as ``stem.png``, both together; the directory and the stem are checked and the figure drawn first."""
    return commit(phase_diagram_plans(dataset, out, stem, keep_agreeing))


def phase_diagram_plans(dataset: xr.Dataset, out: str | os.PathLike, stem: str,
                        keep_agreeing: bool = False) -> list[PlannedFile]:
    """The files :func:`write_phase_diagram_dataset` writes, planned (the directory and stem checked, the figure
    drawn), for :func:`commit`."""
    directory = prepare_output_directory(out, "out")
    check_output_stem("stem", stem)
    nc = directory / f"{stem}.nc"
    existing = _agreeing_file(dataset, nc, keep_agreeing)
    png = figure_png(plot_phase_diagram(dataset if existing is None else existing).figure)
    return [_dataset_plan(dataset, nc, existing), _bytes_plan(directory / f"{stem}.png", png, _same_pixels,
                                                              keep_agreeing)]


def write_simulation(dataset: xr.Dataset, out: str | os.PathLike, stem: str, overlay: xr.Dataset | None = None,
                     keep_agreeing: bool = False, plot: Callable[..., Figure] = plot_simulation) -> list[FileOutcome]:
    """Write a simulation as ``stem.nc``, its figure (with ``overlay``) as ``stem.png`` and, for the
    continuum method, its event log as ``stem_events.csv``.

    ``plot(dataset, overlay=overlay)`` draws the figure: :func:`~mdr_events.plotting.plot_simulation` (the
    panels against time) by default, e.g. :func:`~mdr_events.plotting.plot_fretting` for fretting loops.

    Everything is checked and drawn before the first file is written: the output directory, the stem, the
    case labels (distinct), the figure and the event log. A figure that cannot be drawn writes nothing.

    Raises
    ------
    TypeError
        If ``dataset`` is not an ``xarray.Dataset``.
    ValueError
        If ``out`` cannot take the files, ``stem`` is not a plain file-name stem, or the case labels repeat.
    """
    return commit(simulation_plans(dataset, out, stem, overlay, keep_agreeing, plot))


def simulation_plans(dataset: xr.Dataset, out: str | os.PathLike, stem: str, overlay: xr.Dataset | None = None,
                     keep_agreeing: bool = False, plot: Callable[..., Figure] = plot_simulation) -> list[PlannedFile]:
    """The files :func:`write_simulation` writes, planned (everything checked and drawn), for :func:`commit`."""
    if not isinstance(dataset, xr.Dataset):
        raise TypeError(f"dataset={shown(dataset)} ({type(dataset).__name__}) is not allowed; allowed: an "
                        "xarray.Dataset (a simulation)")
    directory = prepare_output_directory(out, "out")
    check_output_stem("stem", stem)
    _check_distinct_cases(dataset)
    nc = directory / f"{stem}.nc"
    existing = _agreeing_file(dataset, nc, keep_agreeing)
    on_disk = dataset if existing is None else existing
    png = figure_png(plot(on_disk, overlay=overlay))
    events = event_log_csv(on_disk) if "event_kind" in on_disk else None
    plans = [_dataset_plan(dataset, nc, existing),
             _bytes_plan(directory / f"{stem}.png", png, _same_pixels, keep_agreeing)]
    if events is not None:
        plans.append(_bytes_plan(directory / f"{stem}_events.csv", events.encode(), event_logs_agree(on_disk),
                                 keep_agreeing))
    return plans


#: The first column of the event log CSV for each case dimension: its header and how a label is written.
EVENT_LOG_CASE_COLUMNS: dict[str, tuple[str, Callable[[object], str]]] = {
    "alpha": ("alpha_degree", lambda angle: f"{float(angle):.17g}"),
    "case": ("case", str),
}


#: The event log's columns of floats and the dataset's variables they are read from (compared within those).
EVENT_LOG_FLOATS = {"time_s": "event_time", "depth_m": "event_depth", "radius_m": "event_radius", "x_m": "event_x"}


def event_logs_agree(dataset: xr.Dataset) -> Callable[[bytes, bytes], bool]:
    """Whether two event logs of ``dataset`` agree: the same rows and words, each float within the tolerance of
    its variable in ``dataset`` (:data:`EVENT_LOG_FLOATS`; the CSV writes all 17 digits, more than the computation
    determines)."""
    def same(old: bytes, new: bytes) -> bool:
        try:
            before, after = (list(csv.DictReader(io.StringIO(text.decode()))) for text in (old, new))
        except (UnicodeDecodeError, csv.Error):  # not our log: replaced
            return False
        if len(before) != len(after) or any(a.keys() != b.keys() for a, b in zip(before, after)):
            return False
        allowed = {column: float(np.max(tolerance_of(dataset, name), initial=0.0))
                   for column, name in EVENT_LOG_FLOATS.items()}
        for a, b in zip(before, after):
            for column in a:
                if column not in allowed:
                    if a[column] != b[column]:
                        return False
                    continue
                try:
                    x, y = float(a[column]), float(b[column])
                except ValueError:
                    return False
                if not (x == y or abs(x - y) <= allowed[column]):
                    return False
        return True
    return same


def event_log_csv(dataset: xr.Dataset) -> str:
    """The continuum event log as CSV text (one row per event per case, full precision).

    The first column is the angle (``alpha_degree``) of a scenario's case or the label (``case``) of a
    custom path's, quoted where it holds a comma or a quote (:mod:`csv`); the last the event's direction
    (+1/-1: the cap of a slip event or the new direction of a tangential reversal; 0 otherwise).
    """
    dimension = case_dimension(dataset)
    header, write_label = EVENT_LOG_CASE_COLUMNS[dimension]
    text = io.StringIO()
    writer = csv.writer(text, lineterminator="\n")
    writer.writerow([header, "event", "time_s", "kind", "depth_m", "radius_m", "x_m", "direction"])
    for label in dataset[dimension].values:
        case = dataset.sel({dimension: label})
        for number in dataset["event"].values:
            kind = str(case["event_kind"].values[number])
            if not kind:
                continue
            values = [float(case[name].values[number]) for name in ("event_time", "event_depth", "event_radius", "event_x")]
            writer.writerow([write_label(label), number, f"{values[0]:.17g}", kind, f"{values[1]:.17g}",
                             f"{values[2]:.17g}", f"{values[3]:.17g}", int(case["event_direction"].values[number])])
    return text.getvalue()


def describe_outcomes(outcomes: list[FileOutcome]) -> str:
    """One line for a progress message: which files were written and which were kept."""
    parts = []
    for status, words in ((FileStatus.WRITTEN, "written"),
                          (FileStatus.KEPT, "agree with a fresh computation (each quantity within the accuracy of how "
                                            "it is computed), not rewritten")):
        names = [outcome.path.name for outcome in outcomes if outcome.status is status]
        if names:
            parts.append(f"{words}: {', '.join(names)}")
    return "; ".join(parts)
