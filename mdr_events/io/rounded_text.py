"""Rounded text that agrees: the same words, and each number within one unit of its last written digit
(:func:`rounded_text_differences`; ``results/README.md`` computed on another machine against the committed one). A
value determined to better than that unit differs between machines by at most one such unit, when it lies at a
rounding boundary."""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["Unit", "rounded_text_differences"]


#: Share of a last digit's unit allowed beyond it: the binary difference of two decimals (21.2058 - 21.2057 is
#: 1.0000000000331966e-4) carries their round-off.
_DECIMAL_SLACK = 1e-9
#: A number in rounded text: digits with an optional fraction and exponent.
_NUMBER = re.compile(r"(?<![\w.])[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?(?!\w|\.\d)")


@dataclass(frozen=True)
class Unit:
    """A number as written: its value, one unit of its last written digit (``None`` for an integer, which is
    compared exactly: a count or a label), and its form (decimals written, exponent or ``None``)."""

    value: float
    last_digit: float | None
    decimals: int = 0
    exponent: int | None = None

    @classmethod
    def read(cls, text: str) -> "Unit":
        mantissa, _, exponent = text.lower().partition("e")
        if "." not in mantissa and not exponent:
            return cls(float(text), None)
        decimals = len(mantissa.partition(".")[2])
        power = int(exponent) if exponent else None
        return cls(float(text), 10.0 ** ((power or 0) - decimals), decimals, power)

    def rounds_alike(self, other: "Unit") -> bool:
        """Whether ``other`` is this number rounded alike (the same format; another CPU changes digits, not
        formats) to within one unit of the last digit: the same decimals, both with an exponent or neither, the
        exponents equal or one apart where the mantissa rounds over 10 (9.99e-05 and 1.00e-04)."""
        if self.last_digit is None or other.last_digit is None:
            return self.last_digit is other.last_digit and self.value == other.value
        if self.decimals != other.decimals or (self.exponent is None) != (other.exponent is None):
            return False
        if self.exponent is not None and abs(self.exponent - other.exponent) > 1:
            return False
        return abs(self.value - other.value) <= max(self.last_digit, other.last_digit) * (1.0 + _DECIMAL_SLACK)


def rounded_text_differences(actual: str, expected: str) -> list[str]:
    """How two rounded texts differ beyond a rounding boundary ([] if not).

    Parameters
    ----------
    actual, expected : str
        Texts that round their numbers (``results/README.md`` computed here and committed).

    Returns
    -------
    list of str
        The words between the numbers must be the same (else one line quoting the first line that differs);
        integers (counts, labels) the same; a number with a decimal point or an exponent written alike and within
        one unit of the last digit written (:meth:`Unit.rounds_alike`): one line per number beyond that.
    """
    words = _NUMBER.split(actual), _NUMBER.split(expected)
    if words[0] != words[1]:
        lines = [(a, b) for a, b in zip(actual.splitlines(), expected.splitlines()) if
                 _NUMBER.split(a) != _NUMBER.split(b)]
        first = lines[0] if lines else ("", "")
        return [f"the words differ: {first[0]!r} instead of {first[1]!r}"]
    found = []
    for mine, theirs in zip(_NUMBER.findall(actual), _NUMBER.findall(expected)):
        if not Unit.read(mine).rounds_alike(Unit.read(theirs)):
            found.append(f"{mine} instead of {theirs}")
    return found
