"""Compiled loops for the kernels whose work numpy cannot vectorise.

A scan or a fill visits pixels in an order that depends on what it has
already drawn; numpy would need a Python loop per pixel. Those loops are
compiled with numba. Importing numba and compiling cost about a second, so
nothing here happens at import: a function decorated with ``compiled`` is
compiled on its first call, and numba's on-disk cache (``cache=True``)
keeps the machine code for the next start of the program.
"""
from __future__ import annotations

import functools


def compiled(function):
    """``function`` compiled with numba on its first call (no Python objects inside)."""
    machine_code = None

    @functools.wraps(function)
    def call(*args):
        nonlocal machine_code
        if machine_code is None:
            import numba  # deferred: start-up and `rasterlab list` must not pay for it

            machine_code = numba.njit(cache=True, nogil=True)(function)
        return machine_code(*args)

    call.python = function  # the same loop uncompiled, for tests that step into it
    return call
