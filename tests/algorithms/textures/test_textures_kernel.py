"""triangle-texture's numpy kernel gives the generator's colours, filter by filter."""
from __future__ import annotations

import numpy as np
import pytest

from algorithms.core import registry
from algorithms.core.steps import PLOT
from algorithms.textures.kernel import texture_image

SPEC = registry.get("triangle-texture")
FLOOR = [(0, 0), (24, 0), (13.2, 15), (0, 0), (13.2, 15), (10.8, 15)]
UV = (0, 0, 2, 0, 2, 9, 0, 0, 2, 9, 0, 9)


@pytest.mark.parametrize("filter_name", ["nearest", "bilinear", "mip-nearest", "trilinear",
                                         "anisotropic", "reference"])
@pytest.mark.parametrize("texture, wrap, perspective", [("checker:4", "repeat", True),
                                                        ("zoneplate", "clamp", False)])
def test_kernel_equals_generator(filter_name, texture, wrap, perspective):
    options = SPEC.resolve({"uv": UV, "w": (1, 1, 10, 1, 10, 10), "texture": texture,
                            "filter": filter_name, "wrap": wrap, "perspective": perspective,
                            "samples": 4})
    trace = SPEC.record(FLOOR, options, grid=(24, 16))
    got = {}
    for i in range(len(trace)):
        step = trace.step(i)
        if step.pixel is not None and trace.code[step.line].kind == PLOT:
            value = int(step.values["rgb"])
            got[step.pixel] = np.array([(value >> 16) & 255, (value >> 8) & 255, value & 255])
    pixels, colours = texture_image(FLOOR, options, (24, 16))
    assert len(pixels) == len(got) > 100
    for (x, y), colour in zip(pixels.tolist(), colours):
        assert np.all(np.abs(got[(x, y)] - colour) <= 0.5 + 1e-6), (x, y)
