"""Elementwise closed forms evaluated over blocks of their arrays: the same values, bit for bit, with temporaries of a
block's size (over 10⁵ angles at once, the page faults of each fresh temporary cost more than its arithmetic)."""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

__all__ = ["BLOCK", "blockwise"]

#: Elements per block (16 000 doubles, 128 kB: small enough to be reused from the allocator and kept in cache).
BLOCK = 16_000


def blockwise(function: Callable, *arguments, out: np.ndarray | None = None):
    """``function(*arguments)`` of an elementwise ``function``, evaluated block by block.

    Parameters
    ----------
    function : callable
        Elementwise in its array arguments; returns an array, or a list or tuple whose entries are arrays or scalars
        that do not depend on the arrays (a polynomial's coefficients).
    *arguments
        Arrays (broadcast together) and scalars (passed whole).
    out : numpy.ndarray, optional
        A C-contiguous float array of the arguments' broadcast shape (e.g. a row of a larger array) that a ``function`` returning
        one array writes into, block by block: no array of the result's size is allocated (for 10⁵ elements a fresh
        one costs its page faults, more than the arithmetic that fills it).

    Returns
    -------
    numpy.ndarray or list
        What ``function(*arguments)`` returns, the arrays of the arguments' broadcast shape (``out`` where given).
    """
    arrays = [np.ndim(argument) > 0 for argument in arguments]
    shape = np.broadcast_shapes(*[np.shape(a) for a, is_array in zip(arguments, arrays) if is_array])
    size = math.prod(shape)
    if size <= BLOCK:
        found = function(*arguments)
        if out is None:
            return found
        out[...] = found
        return out
    flat = [np.broadcast_to(a, shape).reshape(-1) if is_array else a for a, is_array in zip(arguments, arrays)]
    if out is not None and not out.flags.c_contiguous:
        raise ValueError("out is not allowed: it is not C-contiguous; allowed: a C-contiguous array (a row of one)")
    outputs = None if out is None else [out.reshape(-1)]
    for first in range(0, size, BLOCK):
        block = slice(first, first + BLOCK)
        found = function(*[a[block] if is_array else a for a, is_array in zip(flat, arrays)])
        entries = list(found) if isinstance(found, (list, tuple)) else [found]
        if outputs is None:
            outputs = [entry if np.ndim(entry) == 0 else np.empty(size, dtype=np.result_type(entry))
                       for entry in entries]
        for output, entry in zip(outputs, entries):
            if np.ndim(output) > 0:
                output[block] = entry
    if out is not None:
        return out
    outputs = [output if np.ndim(output) == 0 else output.reshape(shape) for output in outputs]
    return type(found)(outputs) if isinstance(found, (list, tuple)) else outputs[0]
