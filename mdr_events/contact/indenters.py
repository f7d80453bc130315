"""Indenters as data: the paper's paraboloid, the power law ``f(r) = c rⁿ``, the flat punch and a table ``f(r)``.

The paper's indenter is the paraboloid ``f = r²/(2R)`` (:class:`Paraboloid`, eq. (4)), the power law with ``n = 2``
and ``c = 1/(2R)`` (:meth:`PowerLaw.paraboloid`); the paraboloid keeps its own type so that the paper's functions
serve it bit for bit. The MDR maps any axisymmetric profile to the equivalent profile ``g(x)`` of the springs by the
Abel transform (3); for the power law ``g(x) = κₙ c |x|ⁿ`` with ``κₙ = √π Γ(n/2 + 1) / Γ(n/2 + 1/2)`` (2 for the
paraboloid, π/2 for the cone; derived in :mod:`mdr_events.theory.symbolic`, evaluated in
:mod:`mdr_events.theory.power_law`).

Each kind says what it is in words (``describe``) and in a result's attributes (``to_attrs``; read back by
:func:`indenter_from_attrs`). The closed forms of the theory layer take every kind; the simulators (continuum and
discrete), ``validate``, ``fit``, ``sweep`` and the command line take a power law with ``n >= 1``, the flat punch
and a table beside the paraboloid.
"""

from __future__ import annotations

import functools
import hashlib
import math
import warnings
from dataclasses import dataclass

import numpy as np

from mdr_events.limits import values_in
from mdr_events.validation import PLAIN_NUMBER, SCALE_MAX, SCALE_MIN, check_real, plain_number, reads_attrs, real_array, shown

__all__ = ["Paraboloid", "PowerLaw", "FlatPunch", "TabulatedProfile", "Profile", "Indenter", "profile_attrs",
           "indenter_from_attrs", "indenter_kind", "INDENTER_KINDS"]


#: Significant digits of a computed shape in words: a shape computed from other parameters (the cone that reaches the
#: paraboloid's radius) is determined to round-off, far below the last of these digits, so that the words are the
#: same on every CPU (the exact values are in their own float attributes, compared numerically).
DESCRIBED_DIGITS = 9


@dataclass(frozen=True)
class Paraboloid:
    """The paper's indenter (4): ``f(r) = r²/(2R)``, a sphere of radius ``R`` near its tip.

    Parameters
    ----------
    R : float
        Radius of curvature in m, finite and > 0.

    Raises
    ------
    ValueError
        ``R`` not a finite number > 0.
    """

    R: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "R", check_real("Paraboloid.R", self.R, "a finite number > 0 (m)",
                                                 lambda value: value > 0.0))

    def describe(self) -> str:
        """The profile in words.

        Returns
        -------
        str
            ``"paraboloid f = r^2/(2R), R = ... m"``, ``R`` to :data:`DESCRIBED_DIGITS` digits.
        """
        return f"paraboloid f = r^2/(2R), R = {self.R:.{DESCRIBED_DIGITS}g} m"

    def to_attrs(self) -> dict[str, object]:
        """A result's attributes: ``param_R`` and its unit (the paper's results name no other indenter).

        Returns
        -------
        dict of str to object
            ``param_R`` (m) and ``param_R_units``.
        """
        return {"param_R": self.R, "param_R_units": "m"}


@dataclass(frozen=True)
class PowerLaw:
    """The axisymmetric power-law indenter ``f(r) = c rⁿ``.

    Parameters
    ----------
    c : float
        Prefactor (m^(1−n)), finite and > 0.
    n : float
        Exponent, finite and > 0: 1 the cone, 2 the paraboloid, larger ever flatter punches. With
        adhesion the relations need ``n > 1/2`` (below it the adhesive term ``√a`` outgrows ``aⁿ``
        and no contact is stable).

    Raises
    ------
    ValueError
        ``c`` or ``n`` not a finite number > 0.
    """

    c: float
    n: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "c", check_real("PowerLaw.c", self.c, "a finite number > 0 (m^(1-n))",
                                                 lambda value: value > 0.0))
        object.__setattr__(self, "n", check_real("PowerLaw.n", self.n, "a finite number > 0",
                                                 lambda value: value > 0.0))

    @classmethod
    def paraboloid(cls, R: float) -> "PowerLaw":
        """The paper's indenter (4): ``f = r²/(2R)``, ``R`` the radius of curvature (m, > 0).

        Parameters
        ----------
        R : float
            Radius of curvature (m), finite and > 0.

        Returns
        -------
        PowerLaw
            The power law with ``c = 1/(2R)`` and ``n = 2``.
        """
        radius = check_real("R", R, "a finite number > 0 (m)", lambda value: value > 0.0)
        return cls(1.0 / (2.0 * radius), 2.0)

    @classmethod
    def cone(cls, slope: float) -> "PowerLaw":
        """The cone ``f = r tan θ``, ``slope = tan θ`` (θ the angle between its flank and the surface, > 0).

        Parameters
        ----------
        slope : float
            ``tan θ``, finite and > 0.

        Returns
        -------
        PowerLaw
            The power law with ``c = slope`` and ``n = 1``.
        """
        return cls(check_real("slope", slope, "a finite number > 0 (tan of the flank's angle to the surface)",
                              lambda value: value > 0.0), 1.0)

    def describe(self) -> str:
        """The profile in words, for a dataset's ``profile`` attribute (to :data:`DESCRIBED_DIGITS`; the exact values
        are the attributes ``profile_c`` and ``profile_n``).

        Returns
        -------
        str
            ``"power law f = c r^n, c = ... m^(1-n), n = ..."``.
        """
        return f"power law f = c r^n, c = {self.c:.{DESCRIBED_DIGITS}g} m^(1-n), n = {self.n:.{DESCRIBED_DIGITS}g}"

    def to_attrs(self) -> dict[str, object]:
        """A result's attributes: ``profile`` (in words), ``profile_c`` and ``profile_n``.

        Returns
        -------
        dict of str to object
            The three attributes, read back by :func:`indenter_from_attrs`.
        """
        return {"profile": self.describe(), "profile_c": self.c, "profile_n": self.n}


@dataclass(frozen=True)
class FlatPunch:
    """The flat-ended cylindrical punch of radius ``radius``: ``g(x) = 0`` for ``|x| <= radius``.

    In contact the radius is the punch's; adhesion holds it until the edge spring reaches Heß's
    limit (8), and then every spring (all of one length) lets go at once: Kendall's pull-off.

    Parameters
    ----------
    radius : float
        The punch's radius (m), finite and > 0.

    Raises
    ------
    ValueError
        ``radius`` not a finite number > 0.
    """

    radius: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", check_real("FlatPunch.radius", self.radius, "a finite number > 0 (m)",
                                                      lambda value: value > 0.0))

    def describe(self) -> str:
        """The profile in words, for a dataset's ``profile`` attribute (to :data:`DESCRIBED_DIGITS`; the exact value
        is the attribute ``profile_radius``).

        Returns
        -------
        str
            ``"flat punch of radius ... m"``.
        """
        return f"flat punch of radius {self.radius:.{DESCRIBED_DIGITS}g} m"

    def to_attrs(self) -> dict[str, object]:
        """A result's attributes: ``profile`` (in words) and ``profile_radius``.

        Returns
        -------
        dict of str to object
            The two attributes, read back by :func:`indenter_from_attrs`.
        """
        return {"profile": self.describe(), "profile_radius": self.radius}


#: The most points a :class:`TabulatedProfile` takes: its Abel transform's quadrature costs the square of the points
#: (10 000 take about 4 s here, 20 000 about 15 s), and a tip's measured profile is described to well below its
#: noise by far fewer.
MAX_TABLE_POINTS = 10_000


@dataclass(frozen=True, repr=False)
class TabulatedProfile:
    """An axisymmetric indenter given as a table ``f(r)``: measured (an AFM tip's profile) or of any shape.

    The table is interpolated by a monotone cubic (PCHIP) and its Abel transform (3), the springs' profile
    ``g(x)``, computed numerically (:mod:`mdr_events.theory.tabulated`); beyond the last radius the indenter
    is too high for any contact (the depths that need it are refused).

    Parameters
    ----------
    r : sequence of float
        Radii (m): finite, strictly increasing, from 0, at least 3.
    f : sequence of float
        Heights above the tip (m) at ``r``: finite, 0 at ``r = 0``, strictly increasing (an indenter whose
        profile falls would touch first off its axis). Both columns are kept as tuples of float.

    Raises
    ------
    ValueError
        Columns of unequal lengths, fewer than 3 or more than :data:`MAX_TABLE_POINTS` points, not increasing
        from 0, or whose scales do not fit in double precision.
    """

    r: tuple
    f: tuple

    def __post_init__(self) -> None:
        # (counted before they are read: round twenty-four, a million points were converted, 70 MB and 1.5 s, to be
        # refused for their count; what cannot be counted is read and named below)
        counted = values_in(self.r), values_in(self.f)
        if max(counted) > MAX_TABLE_POINTS:
            _refuse_table_lengths(*counted)
        r = _table_column("TabulatedProfile.r", self.r)
        f = _table_column("TabulatedProfile.f", self.f)
        if len(r) != len(f) or not 3 <= len(r) <= MAX_TABLE_POINTS:
            _refuse_table_lengths(len(r), len(f))
        if r[0] != 0.0 or any(b <= a for a, b in zip(r, r[1:])):
            raise ValueError(f"TabulatedProfile.r={shown(self.r)} is not allowed; allowed: strictly increasing radii "
                             "from 0 (m)")
        if f[0] != 0.0 or any(b <= a for a, b in zip(f, f[1:])):
            raise ValueError(f"TabulatedProfile.f={shown(self.f)} is not allowed; allowed: heights from 0 at r = 0, "
                             "strictly increasing (m)")
        _check_table_scales(r, f)
        object.__setattr__(self, "r", r)
        object.__setattr__(self, "f", f)

    @functools.cached_property
    def _memo_key(self) -> tuple[int, bytes]:
        """The table's exact key for :func:`mdr_events.memo.exact_key`: its length and a digest of its columns' bytes
        (every bit of every value: ``-0.0`` is not ``0.0``), made once, so that a run's set-up keyed on the table
        does not walk its thousands of points each time (issue 28)."""
        digest = hashlib.blake2b(np.array((self.r, self.f), dtype=np.float64).tobytes(), digest_size=32)
        return len(self.r), digest.digest()

    def __repr__(self) -> str:  # (a measured table has thousands of points: errors name it in one short line)
        return f"TabulatedProfile(<{len(self.r)} points, r to {self.r[-1]!r} m, f to {self.f[-1]!r} m>)"

    @property
    def radius(self) -> float:
        """The table's last radius (m): the largest contact it can describe."""
        return self.r[-1]

    def describe(self) -> str:
        """The profile in words, for a dataset's ``profile`` attribute.

        Returns
        -------
        str
            The number of points and the table's last radius and height.
        """
        return f"tabulated profile f(r), {len(self.r)} points to r = {self.r[-1]!r} m, f = {self.f[-1]!r} m there"

    def to_attrs(self) -> dict[str, object]:
        """A result's attributes: ``profile`` (in words) and the table itself, ``profile_table_r`` and
        ``profile_table_f`` (every value as Python writes it back, exact, separated by commas).

        Returns
        -------
        dict of str to object
            The three attributes, read back by :func:`indenter_from_attrs`.
        """
        return {"profile": self.describe(), "profile_table_r": ", ".join(map(repr, self.r)),
                "profile_table_f": ", ".join(map(repr, self.f))}


def _refuse_table_lengths(r_count: int, f_count: int) -> None:
    raise ValueError(f"TabulatedProfile.r and .f of lengths {r_count} and {f_count} are not allowed; allowed: equal "
                     f"lengths, 3 to {MAX_TABLE_POINTS} (the Abel transform's quadrature costs the square of the points; "
                     "resample a denser measurement)")


def _check_table_scales(r: tuple[float, ...], f: tuple[float, ...]) -> None:
    """Refuse a table whose scales do not fit in double precision: its last radius and height, its narrowest
    interval, and the coefficients of its interpolant's slope on each interval, ``f' = c₀ + c₁ s + c₂ s²`` (the
    Abel transform multiplies them by radii: the bounds of :mod:`mdr_events.theory.scales`, 0 allowed)."""
    from scipy import interpolate  # (only a table needs it: a Contact of the other indenters leaves SciPy unloaded)

    radii, heights = np.array(r), np.array(f)
    scales = {"its last radius (m)": radii[-1], "its last height (m)": heights[-1],
              "its narrowest interval of r (m)": np.min(np.diff(radii))}
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", RuntimeWarning)
            slope = interpolate.PchipInterpolator(radii, heights).derivative().c
            for order, unit in enumerate(("1", "1/m", "1/m²")):
                scales[f"its interpolant's largest slope coefficient c{order} ({unit})"] = np.max(np.abs(slope[2 - order]))
    except (RuntimeWarning, FloatingPointError, OverflowError) as error:
        scales["its interpolant's slope coefficients"] = math.inf
        failure = str(error)
    else:
        failure = ""
    for what, value in scales.items():
        if value != 0.0 and not SCALE_MIN <= abs(value) <= SCALE_MAX:
            shown_value = f"overflow ({failure})" if failure and not math.isfinite(value) else f"{value:.3g}"
            raise ValueError(f"TabulatedProfile(<{len(r)} points, r to {r[-1]!r} m, f to {f[-1]!r} m>) is not allowed: "
                             f"{what} is {shown_value}; allowed: a table whose scales lie within {SCALE_MIN:.2g} to "
                             f"{SCALE_MAX:.2g} in SI units (or are 0), so that their products stay finite in double "
                             "precision")


def _table_column(name: str, values) -> tuple[float, ...]:
    """A table column as a tuple of finite floats, or an error naming it."""
    column = real_array(name, values, "a 1-D sequence of finite numbers (m)")
    if column.ndim != 1 or not np.all(np.isfinite(column)):
        raise ValueError(f"{name}={shown(values)} is not allowed; allowed: a 1-D sequence of finite numbers (m)")
    return tuple(float(value) for value in column)


#: Any profile the theory layer takes beside the paraboloid of ``Parameters.R``.
Profile = PowerLaw | FlatPunch | TabulatedProfile
#: Any indenter.
Indenter = Paraboloid | PowerLaw | FlatPunch | TabulatedProfile
#: What each kind is called in a note (the paraboloid names itself by ``param_R``).
_KIND_NAMES = {PowerLaw: "power law", FlatPunch: "flat punch", TabulatedProfile: "tabulated profile"}
#: The indenter types, each a kind of its own: what the theory and the simulators look their functions up by
#: (:func:`indenter_kind`).
INDENTER_KINDS = (Paraboloid, PowerLaw, FlatPunch, TabulatedProfile)


def indenter_kind(indenter: object) -> type:
    """The kind of ``indenter``, the type the theory and the simulators look what they compute up by: the first of
    :data:`INDENTER_KINDS` along its type's MRO, so that a user's subclass of an indenter type is of its base's kind
    (issue 32, round 27: a subclass of ``PowerLaw`` was taken by ``critical_angle`` and refused by ``simulate``, and
    ``phase_diagram`` ended in a ``KeyError``); else its own type (``NoneType``: the paper's paraboloid of
    ``Parameters.R``; anything else, which the lookups refuse by name).

    Parameters
    ----------
    indenter : object
        The indenter (``None``: the paraboloid of ``Parameters.R``).

    Returns
    -------
    type
        Its kind.
    """
    return _kind_of_type(type(indenter))


@functools.lru_cache(maxsize=64)
def _kind_of_type(cls: type) -> type:
    """:func:`indenter_kind` of an instance of ``cls``."""
    return next((kind for kind in cls.__mro__ if kind in INDENTER_KINDS), cls)


def profile_attrs(profile: Profile | None) -> dict[str, object]:
    """A result of :class:`~mdr_events.Parameters` and another indenter than its paraboloid: the indenter's attributes
    (``to_attrs``) and ``profile_note`` (``param_R`` is then unused); none for the paraboloid (``None``)."""
    if profile is None:
        return {}
    kind = _KIND_NAMES[indenter_kind(profile)]
    return {**profile.to_attrs(), "profile_note": f"the indenter is this {kind}: param_R (the paraboloid's radius) is "
                                                   "not used"}


@reads_attrs("an indenter")
def indenter_from_attrs(attrs) -> Indenter:
    """The indenter a result names (its ``to_attrs``): a power law, flat punch or table where ``profile_*`` says so,
    else the paraboloid of ``param_R``; the attributes of an indenter in part, or of two, are refused (a stray
    ``profile_n`` beside ``param_R`` was read silently as the paraboloid)."""
    groups = [group for group in (("profile_c", "profile_n"), ("profile_radius",),
                                  ("profile_table_r", "profile_table_f")) if any(key in attrs for key in group)]
    if len(groups) > 1 or (groups and not all(key in attrs for key in groups[0])):
        found = [key for group in groups for key in group if key in attrs]
        raise ValueError(f"the attributes {', '.join(found)} do not name one indenter; allowed: profile_c and "
                         "profile_n, profile_radius, or profile_table_r and profile_table_f (or none: the paraboloid "
                         "of param_R)")
    if "profile_c" in attrs:
        return PowerLaw(float(attrs["profile_c"]), float(attrs["profile_n"]))
    if "profile_radius" in attrs:
        return FlatPunch(float(attrs["profile_radius"]))
    if "profile_table_r" in attrs:
        columns = []
        for name in ("profile_table_r", "profile_table_f"):
            try:
                columns.append(tuple(plain_number(value) for value in str(attrs[name]).split(",")))
            except ValueError:
                raise ValueError(f"the attribute {name}={shown(attrs[name])} is not allowed; allowed: numbers "
                                 f"separated by commas, each {PLAIN_NUMBER}") from None
        return TabulatedProfile(*columns)
    if "profile" in attrs:  # (a profile in words without its shape: not the paraboloid silently)
        raise ValueError(f"profile={shown(attrs['profile'])} without its shape (profile_c and profile_n, "
                         "profile_radius or profile_table_r and profile_table_f)")
    return Paraboloid(float(attrs["param_R"]))
