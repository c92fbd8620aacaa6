"""Pictures as a person with a colour-vision deficiency sees them.

daltonlens's simulation of Machado, Oliveira and Fernandes (2009) at full
severity: the same one the palette test (tests/app/render/test_palette_vision.py)
applies to the colours with a meaning, so that what View > Colour vision
previews is what the test checks.
"""
from __future__ import annotations

import numpy as np
from daltonlens import simulate

DEFICIENCIES = {"protanopia": simulate.Deficiency.PROTAN,
                "deuteranopia": simulate.Deficiency.DEUTAN,
                "tritanopia": simulate.Deficiency.TRITAN}
_SIMULATOR = simulate.Simulator_Machado2009()


def simulate_rgb(rgb: np.ndarray, deficiency: str) -> np.ndarray:
    """(H, W, 3) uint8 sRGB as seen with ``deficiency`` (a DEFICIENCIES key)."""
    if deficiency not in DEFICIENCIES:
        raise ValueError(f"colour vision {deficiency!r}: use one of {', '.join(DEFICIENCIES)}")
    return _SIMULATOR.simulate_cvd(np.ascontiguousarray(rgb, dtype=np.uint8),
                                   DEFICIENCIES[deficiency], severity=1.0)
