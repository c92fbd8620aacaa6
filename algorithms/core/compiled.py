"""Loops for the kernels whose work numpy cannot vectorise, compiled when numba is there.

A scan or a fill visits pixels in an order that depends on what it has
already drawn; numpy would need a Python loop per pixel. With numba (the
optional extra ``rasterlab[fast]``) those loops are compiled; without it
they run as the plain Python functions they are written as, which give the
same pixels, more slowly. No command of the program calls them: they serve
the batch fills (``fill_canvas``, ``scanline_fill_many``, ``draw_wu_lines``),
the seed fill's kernel and the benchmarks (docs/developers/numba.md has the
figures behind that choice).

Importing numba and compiling cost seconds, so nothing here happens at
import: a function decorated with ``compiled`` chooses its loop on its
first call, and numba's on-disk cache (``cache=True``) keeps the machine
code for the next process.
"""
from __future__ import annotations

import functools


@functools.lru_cache(maxsize=None)
def _numba():
    """The numba module, or None when it cannot be imported."""
    try:
        import numba  # deferred: start-up and `rasterlab list` must not pay for it
    except ImportError:  # not installed, or unusable with this numpy: the plain loops
        return None
    return numba


def path() -> str:
    """Which loops the kernels run: "numba" (compiled) or "python" (the plain functions)."""
    return "python" if _numba() is None else "numba"


def compiled(function):
    """``function`` compiled with numba on its first call when numba can be
    imported, otherwise ``function`` itself (no Python objects inside)."""
    loop = None

    @functools.wraps(function)
    def call(*args):
        nonlocal loop
        if loop is None:
            numba = _numba()
            loop = function if numba is None else numba.njit(cache=True, nogil=True)(function)
        return loop(*args)

    call.python = function  # the plain loop, whichever path ``call`` takes
    return call
