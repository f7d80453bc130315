"""How results/README.md writes what the sections found: one Markdown table helper and the numbers' texts.

Every table of the report goes through :func:`markdown_table`; the texts of differences that may lie below the
accuracy of what they compare (:func:`relative_difference_text`) print the same everywhere, whatever the digits
of round-off on another machine.
"""

from __future__ import annotations

from typing import Iterable, Sequence

from mdr_events.models.continuum import Tolerances

__all__ = ["markdown_table", "ALIGNMENTS", "relative_difference_text", "REPORT_ROUNDOFF", "INTEGRATED_ACCURACY"]

#: Relative differences below this are round-off, whose digits differ between machines: the report prints
#: "< 1e-12" for them, so that it stays the same text everywhere.
REPORT_ROUNDOFF = 1e-12
#: The relative accuracy of what the continuum integrates (its ``rtol``, :class:`mdr_events.io.agreement.Integrated`):
#: a difference from it below this is printed as "< 1e-10" (the energy of a fretting loop, the flat punch's F_x).
INTEGRATED_ACCURACY = Tolerances().rtol
#: How a column is aligned -> its cell in the table's rule line.
ALIGNMENTS = {"default": "---", "right": "---:", "centre": ":---:"}


def _row(cells: Sequence[str]) -> str:
    return "| " + " | ".join(cells) + " |"


def markdown_table(header: Sequence[str], rows: Iterable[Sequence[str]],
                   alignments: Sequence[str] | None = None) -> list[str]:
    """The lines of a Markdown table: the header, the rule line, one line per row.

    Parameters
    ----------
    header : sequence of str
        The column titles.
    rows : iterable of sequences of str
        The cells of each row, already written as text, as many as the header's.
    alignments : sequence of str, optional
        One key of :data:`ALIGNMENTS` per column (default: ``"default"`` for each).

    Returns
    -------
    list of str
        ``| a | b |``, ``|---|---:|``, then the rows.

    Raises
    ------
    ValueError
        If a row or the alignments do not have one entry per column, or an alignment is unknown.
    """
    alignments = ["default"] * len(header) if alignments is None else list(alignments)
    if len(alignments) != len(header):
        raise ValueError(f"alignments={alignments!r} has {len(alignments)} entries; allowed: one per column "
                         f"({len(header)})")
    unknown = [alignment for alignment in alignments if alignment not in ALIGNMENTS]
    if unknown:
        raise ValueError(f"alignment {unknown[0]!r} is not allowed; allowed: {', '.join(ALIGNMENTS)}")
    lines = [_row(header), "|" + "|".join(ALIGNMENTS[alignment] for alignment in alignments) + "|"]
    for cells in rows:
        if len(cells) != len(header):
            raise ValueError(f"the row {list(cells)!r} has {len(cells)} cells; allowed: one per column "
                             f"({len(header)})")
        lines.append(_row(cells))
    return lines


def relative_difference_text(value: float, accuracy: float = REPORT_ROUNDOFF) -> str:
    """A relative difference as the report prints it: ``< accuracy`` below the accuracy of what it compares (default
    :data:`REPORT_ROUNDOFF`, round-off; :data:`INTEGRATED_ACCURACY` for a value integrated by the continuum), whose
    digits differ between machines, else two digits (``2.5e-09``)."""
    return f"< {accuracy:g}" if abs(value) < accuracy else f"{value:.1e}"
