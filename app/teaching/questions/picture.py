"""The picture that goes with a question: the scene's grid and primitive at
step 0, before any pixel is decided, so the picture never gives the answer
away. Drawn by the export's frame composer (app/render/export.py), the
one that draws the window's frames, as a PNG."""
from __future__ import annotations

import io

from app.render.export import ExportSettings, FrameRenderer

CELL = 16  # screen pixels per grid cell: a 16x12 grid is 256x192


def picture(scene, cell: int = CELL) -> bytes:
    """A PNG of ``scene`` at its first frame, with axes to read coordinates from."""
    settings = ExportSettings(scale=cell, axes=True, caption=False, panel="none", reasoning=False,
                              highlight=False)
    image = FrameRenderer(scene, settings).image(0)
    out = io.BytesIO()
    image.save(out, format="PNG", optimize=True)
    return out.getvalue()
