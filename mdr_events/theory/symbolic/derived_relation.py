"""One derived relation ``lhs = rhs``, evaluated through the expression SymPy derived (:class:`Relation`)."""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import sympy as sp

from mdr_events.theory.symbolic.symbols import LATEX_NAMES

__all__ = ["Relation"]


@dataclass(frozen=True)
class Relation:
    """One derived relation ``lhs = rhs`` of the model.

    Parameters
    ----------
    key : str
        Stable identifier, e.g. ``"jkr_depth"``.
    equation : str
        The paper's equation number, e.g. ``"(9)"`` (``""`` for consequences
        the paper uses without numbering them).
    title : str
        What the relation says, in words.
    lhs : sympy.Expr
        The left-hand side; for a polynomial reduction the polynomial.
    rhs : sympy.Expr
        The right-hand side; ``0`` for a polynomial reduction.
    args : tuple of sympy.Symbol, default ()
        The arguments, in order, of :attr:`numeric` (keyword names are the
        symbol names).
    variable : sympy.Symbol or None, default None
        For a polynomial relation, its unknown (:attr:`coefficients` are the
        coefficients in that variable, highest power first).
    """

    key: str
    equation: str
    title: str
    lhs: sp.Expr
    rhs: sp.Expr
    args: tuple[sp.Symbol, ...] = field(default=())
    variable: sp.Symbol | None = None

    @property
    def eq(self) -> sp.Eq:
        """The relation as a SymPy equation (for notebooks and printing)."""
        return sp.Eq(self.lhs, self.rhs, evaluate=False)

    def latex(self) -> str:
        """LaTeX of the relation with the paper's symbols.

        Returns
        -------
        str
            ``lhs = rhs`` in LaTeX, the symbols named by :data:`LATEX_NAMES`.
        """
        return sp.latex(self.eq, symbol_names=LATEX_NAMES)

    def pretty(self) -> str:
        """Unicode pretty print of the relation.

        Returns
        -------
        str
            SymPy's two-dimensional rendering, in Unicode.
        """
        return sp.pretty(self.eq, use_unicode=True)

    @functools.cached_property
    def _numeric(self) -> Callable[..., object]:
        expr = self.lhs if self.variable is not None else self.rhs
        return sp.lambdify(self.args, expr, modules="numpy", cse=True)

    def numeric(self, *values, **named):
        """Evaluate the right-hand side with NumPy (vectorised, built once).

        Arguments are given positionally in the order of :attr:`args` or by
        the symbol names. For a polynomial relation the polynomial itself is
        evaluated (its :attr:`variable` must be among the arguments).

        Parameters
        ----------
        *values : float or array_like
            The arguments in the order of :attr:`args` (Python numbers become NumPy floats: 1/0 gives ``inf``).
        **named : float or array_like
            Or all of them by their symbols' names; not both.

        Returns
        -------
        float or numpy.ndarray
            The right-hand side (the polynomial for a polynomial relation), broadcast over the arguments.

        Raises
        ------
        TypeError
            Arguments both positional and named, unknown, missing or too many.
        """
        return self._numeric(*self._ordered(values, named))

    @functools.cached_property
    def scalar(self) -> Callable[..., float]:
        """The same expression as :attr:`numeric`, compiled for Python floats.

        Built once with the ``math`` module (no NumPy scalars), for scalar hot
        loops such as the continuum right-hand side. Arguments are positional,
        in the order of :attr:`args`; where :meth:`numeric` would give ``nan``
        (e.g. the square root of a negative number) it raises ``ValueError``.
        """
        expr = self.lhs if self.variable is not None else self.rhs
        return sp.lambdify(self.args, expr, modules="math", cse=True)

    @functools.cached_property
    def scalar_coefficients(self) -> Callable[..., list]:
        """:meth:`coefficients` for Python floats (``math`` module), positional arguments."""
        args, _ = self._coefficients
        coeffs = sp.Poly(self.lhs, self.variable).all_coeffs()
        return sp.lambdify(args, coeffs, modules="math", cse=True)

    @functools.cached_property
    def _coefficients(self) -> Callable[..., list]:
        if self.variable is None:
            raise TypeError(f"relation {self.key!r} is not a polynomial")
        coeffs = sp.Poly(self.lhs, self.variable).all_coeffs()
        args = tuple(a_ for a_ in self.args if a_ != self.variable)
        return args, sp.lambdify(args, coeffs, modules="numpy", cse=True)

    def coefficients(self, *values, **named) -> list:
        """Coefficients of the polynomial in :attr:`variable`, highest first.

        Parameters
        ----------
        *values : float or array_like
            The arguments of :attr:`args` but :attr:`variable`, in order.
        **named : float or array_like
            Or all of them by their symbols' names; not both.

        Returns
        -------
        list
            The coefficients (floats or arrays), highest power first.

        Raises
        ------
        TypeError
            A relation that is not a polynomial, or arguments as :meth:`numeric` refuses them.
        """
        args, fn = self._coefficients
        return fn(*self._ordered(values, named, args))

    def bound_numeric(self, *trailing) -> Callable[..., object]:
        """:meth:`numeric` with its last arguments fixed, converted once (a model's constants: a run calls it many
        times); the function of the first arguments gives :meth:`numeric`'s values, bit for bit.

        Parameters
        ----------
        *trailing : float or array_like
            The last arguments of :attr:`args`, in order.

        Returns
        -------
        callable
            ``f(*leading)``: :meth:`numeric` of ``(*leading, *trailing)``; wrong counts raise ``TypeError``.
        """
        return _bound(self.key, self._numeric, self.args, trailing)

    def bound_coefficients(self, *trailing) -> Callable[..., list]:
        """:meth:`coefficients` with its last arguments fixed, converted once (:meth:`bound_numeric`'s way).

        Parameters
        ----------
        *trailing : float or array_like
            The last arguments of :meth:`coefficients`, in order.

        Returns
        -------
        callable
            ``f(*leading)``: :meth:`coefficients` of ``(*leading, *trailing)``; wrong counts raise ``TypeError``.
        """
        args, function = self._coefficients
        return _bound(self.key, function, args, trailing)

    def _ordered(self, values, named, args=None):
        args = self.args if args is None else args
        if values and named:
            raise TypeError(f"{self.key}: give arguments by position or by name, not both")
        if named:
            names = [a_.name for a_ in args]
            unknown = set(named) - set(names)
            missing = [nm for nm in names if nm not in named]
            if unknown or missing:
                raise TypeError(
                    f"{self.key}: arguments are {names}; "
                    f"unknown {sorted(unknown)}, missing {missing}"
                )
            return [_as_numpy_scalar(named[nm]) for nm in names]
        if len(values) != len(args):
            raise TypeError(
                f"{self.key}: expected {len(args)} arguments {[a_.name for a_ in args]}, "
                f"got {len(values)}"
            )
        return [_as_numpy_scalar(value) for value in values]


def _bound(key: str, function: Callable, args: tuple, trailing: tuple) -> Callable:
    """``function`` of ``args`` with its last ones ``trailing`` fixed, each argument converted as
    :func:`_as_numpy_scalar` converts it (:meth:`Relation.bound_numeric`)."""
    fixed = tuple(_as_numpy_scalar(value) for value in trailing)
    count = len(args) - len(fixed)
    if count < 0:
        raise TypeError(f"{key}: expected at most {len(args)} arguments {[a_.name for a_ in args]}, got {len(fixed)}")

    def bound(*values):
        if len(values) != count:
            raise TypeError(f"{key}: expected {count} arguments {[a_.name for a_ in args[:count]]}, got {len(values)}")
        return function(*[_as_numpy_scalar(value) for value in values], *fixed)

    return bound


def _as_numpy_scalar(value):
    """Python ints and floats become NumPy floats, so 1/0 gives inf, not ZeroDivisionError."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return np.float64(value)
    return value
