"""Text tables another program writes (a CSV file, or columns separated by semicolons, tabs or blanks, of any name
but ``.nc``): their columns read as float64 with the file's own line numbers in every error, their rows counted
against the limits before they are read, a long read's progress; a tabulated indenter from such a file
(:func:`read_profile_table`). :mod:`mdr_events.io.candidates` reads a simulator's run through them.
"""

from __future__ import annotations

import csv
import itertools
import math
import os
from array import array
from pathlib import Path
from typing import Callable, Collection

import numpy as np

from mdr_events.contact.indenters import TabulatedProfile
from mdr_events.io.files import HDF5_MAGIC, NETCDF3_MAGIC, input_file_problem
from mdr_events.limits import DEFAULT_LIMITS, Limits
from mdr_events.validation import PLAIN_NUMBER, cut_text, plain_number, shown_path, shown_text

__all__ = ["read_csv", "is_text", "read_profile_table", "columns_listed", "LISTED_CHARACTERS", "BYTES_PER_CSV_VALUE",
           "PROGRESS_ROWS", "LAMMPS_DUMP_HEADER", "UTF16_MARKS"]

#: Characters of the list of a file's columns shown in a message (a CSV of 100 000 columns, or one header cell of
#: 100 000 characters, is listed by its first columns and their count, not written out whole).
LISTED_CHARACTERS = 200


def columns_listed(columns) -> str:
    """The names of ``columns`` for a message, joined by commas on one line (control characters as in ``repr``) and cut
    to :data:`LISTED_CHARACTERS` characters with the count of them all; ``none`` if there are none."""
    names = [shown_text(name, math.inf) for name in columns]
    text = ", ".join(names)
    if len(text) <= LISTED_CHARACTERS:
        return text or "none"
    return f"{cut_text(text, LISTED_CHARACTERS)} ({len(names)} columns)"


#: Bytes a CSV file's value takes while it is read and afterwards (its float64 in a column, the arrays the validation
#: and the fit derive from it: about six copies), rounded up.
BYTES_PER_CSV_VALUE = 64
#: Bytes of a CSV file read at a time while its lines are counted.
_COUNT_CHUNK = 1 << 20


def _line_count(path: Path) -> int:
    """The number of lines of a file (newlines, and a last line without one), counted in chunks of bytes."""
    lines, last = 0, b"\n"
    with open(path, "rb") as handle:
        while chunk := handle.read(_COUNT_CHUNK):
            lines += chunk.count(b"\n")
            last = chunk[-1:]
    return lines + (last != b"\n")


#: A CSV file read reports its progress every this many rows (a long read says how far it is).
PROGRESS_ROWS = 1_000_000


def read_csv(path: Path, limits: Limits = DEFAULT_LIMITS,
             progress: Callable[[str], None] | None = None,
             read: Collection[str] | None = None) -> dict[str, np.ndarray]:
    """A CSV file's columns (a header row, its fields separated by commas, or by semicolons or tabs where the header
    holds no comma (:func:`_delimiter`); ``#`` lines are comments and blank lines are skipped, as spreadsheets and
    editors leave them at the end; a UTF-8 byte-order mark is read, as spreadsheets write it), each as float64; its
    rows are checked against ``limits`` before they are read, ``progress`` hears every :data:`PROGRESS_ROWS` of them,
    and errors name the file's own line number. A column not in ``read`` (default: every column is read) is named
    with an empty array and its fields are not parsed: any text (a DEM's column of particle labels was refused whole,
    round 28)."""
    where = shown_path(path)  # (named in its messages: one line, a long path cut)
    rows = max(_line_count(path) - 1, 0)
    line = [0]  # the file's line the reader is at (comments and blank lines counted)

    def data_lines(handle):
        for line[0], text in enumerate(handle, start=1):
            if text.strip() and not text.lstrip().startswith("#"):
                yield text

    try:
        with open(path, newline="", encoding="utf-8-sig") as handle:
            lines = data_lines(handle)
            first = next(lines, "")
            mark = _delimiter(first)
            if mark == " ":  # (columns aligned by any run of blanks, spaces or tabs: fields are the line's words)
                first, lines = " ".join(first.split()), (" ".join(text.split()) for text in lines)
            reader = csv.reader(itertools.chain([first], lines), delimiter=mark)
            header = [name.strip() for name in next(reader, [])]
            _check_header(where, line[0], header)
            limits.check(f"reading {where} ({rows} rows of {len(header)} columns)", samples=rows,
                         memory=BYTES_PER_CSV_VALUE * rows * len(header))
            columns = {name: array("d") for name in header}
            parsed = [index for index, name in enumerate(header) if read is None or name in read]
            for count, row in enumerate(reader, start=1):
                if progress is not None and count % PROGRESS_ROWS == 0:
                    progress(f"reading {where}: {count} of {rows} rows")
                _read_row(where, line[0], header, row, columns, parsed)
    except UnicodeDecodeError as error:
        raise ValueError(f"{where}: not UTF-8 text (byte {error.start}: {error.reason}); allowed: a CSV file with a "
                         "header row (UTF-8 text)") from None
    except csv.Error as error:
        raise ValueError(f"{where}: not a readable CSV file (line {line[0]}: {error}); allowed: a CSV file with a "
                         "header row") from None
    return {name: np.frombuffer(values, dtype=float).copy() for name, values in columns.items()}


def _delimiter(header: str) -> str:
    """What separates the fields of a CSV file whose header row is ``header``: a comma, or where the header holds
    none, a semicolon or a tab in it (a spreadsheet's "CSV" where the decimal mark is a comma; a tab-separated file:
    round 29 read either as one column ``'t;Fn;Ft;A'`` and refused it, not naming why), or else blanks between its
    words (``' '``: columns aligned with spaces, as LAMMPS's ``fix print`` and Fortran codes write them; round 30
    read ``'t_ms Fz_mN'`` as one column)."""
    if "," in header:
        return ","
    return next((mark for mark in (";", "\t") if mark in header), " " if len(header.split()) > 1 else ",")


#: The first word of a LAMMPS dump file (``ITEM: TIMESTEP``), which holds atoms' snapshots, not a run's table.
LAMMPS_DUMP_HEADER = "ITEM:"


def _check_header(where: str, number: int, header: list[str]) -> None:
    """``ValueError`` naming the file and its line ``number`` where the header row is missing (an empty file), is a
    LAMMPS dump's (``ITEM: TIMESTEP``), holds numbers only (a file without a header: its first row of data was read
    as the names) or names a column twice."""
    if not header:
        raise ValueError(f"{where}: the file is empty; allowed: a CSV file with a header row")
    if header[0] == LAMMPS_DUMP_HEADER:
        shown_header = cut_text(" ".join(header), LISTED_CHARACTERS)
        raise ValueError(f"{where}: line {number} ({shown_header}) starts a LAMMPS dump (atoms' snapshots), not a "
                         "table of the run; allowed: a header row and a row per time, as "
                         "LAMMPS's fix print writes it (title \"t Fn Ft\" and one line per step)")
    if all(_is_number(name) for name in header):
        raise ValueError(f"{where}: line {number} ({cut_text(', '.join(header), LISTED_CHARACTERS)}) holds numbers, "
                         "not the columns' names; allowed: a header row naming the columns before the data (a header "
                         "written as a comment, '# t Fn', as LAMMPS's fix ave/time writes it, is a comment: remove "
                         "its '#')")
    repeated = sorted({name for name in header if header.count(name) > 1})
    if repeated:
        raise ValueError(f"{where}: the header names {', '.join(map(repr, repeated))} more than once; allowed: "
                         "each column's name once")


def _is_number(text: str) -> bool:
    """Whether ``text`` reads as a number (:func:`~mdr_events.validation.plain_number`)."""
    try:
        plain_number(text)
    except ValueError:
        return False
    return True


def _read_row(where: str, number: int, header: list[str], row: list[str], columns: dict[str, array],
              parsed: list[int]) -> None:
    """Append a CSV row's numbers (an empty field: ``nan``) in the columns ``parsed`` (their indices) to ``columns``;
    ``ValueError`` naming the file's line ``number`` where the row is not as long as the header or a field is no
    number."""
    if len(row) != len(header):
        raise ValueError(f"{where}: line {number} has {len(row)} fields; allowed: {len(header)} as in the header")
    for index in parsed:
        name, text = header[index], row[index]
        try:
            columns[name].append(plain_number(text) if text.strip() else math.nan)
        except ValueError:
            raise ValueError(f"{where}: line {number}, column {name!r}: {text!r} is not a number; allowed: "
                             f"{PLAIN_NUMBER}, or an empty field") from None


def read_profile_table(path: str | os.PathLike) -> TabulatedProfile:
    """A tabulated indenter from a CSV file with a header row naming the columns ``r`` and ``f`` (m; ``#`` lines are
    comments): :class:`~mdr_events.contact.indenters.TabulatedProfile`. Errors name the file and what is allowed."""
    path = Path(path)
    problem = input_file_problem(path)
    if problem is not None:
        raise ValueError(f"table={shown_path(path, quoted=True)}{problem}; allowed: a CSV file with the columns r and "
                         "f (m)")
    columns = read_csv(path, read=("r", "f"))
    where = shown_path(path)
    missing = [name for name in ("r", "f") if name not in columns]
    if missing:
        raise ValueError(f"{where}: no column {' or '.join(map(repr, missing))} (columns: {columns_listed(columns)}); "
                         "allowed: a header naming the columns r and f (m)")
    try:
        return TabulatedProfile(columns["r"], columns["f"])
    except (ValueError, TypeError) as error:
        raise ValueError(f"{where}: {error}") from None


#: Bytes of a file read to tell a text table from a netCDF file.
_SNIFFED_BYTES = 4096
#: The byte-order marks of UTF-16 text, which spreadsheets save as "Unicode text" (its NUL bytes are no netCDF's).
UTF16_MARKS = (b"\xff\xfe", b"\xfe\xff")


def is_text(path: Path) -> bool:
    """Whether the file at ``path`` is a text table whatever its name but ``.nc`` (``run.txt``, ``run.tsv``,
    ``run.dat``: round 30 read them as netCDF and said they do not start as netCDF does): its first bytes are UTF-8
    without a NUL byte and not a netCDF-3 or HDF5 file's, or UTF-16 text (:data:`UTF16_MARKS`)."""
    with open(path, "rb") as handle:
        head = handle.read(_SNIFFED_BYTES)
    if head.startswith(UTF16_MARKS):  # (a spreadsheet's "Unicode text": the CSV reader names its encoding)
        return True
    if not head or head.startswith((NETCDF3_MAGIC, HDF5_MAGIC)) or b"\0" in head:
        return False
    try:
        head.decode("utf-8")
    except UnicodeDecodeError as error:  # (a character cut at the end of the bytes read is text)
        return error.start >= len(head) - 3 and error.reason == "unexpected end of data"
    return True
