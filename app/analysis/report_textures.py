"""The report's texture section (measured by measure_textures.py)."""
from __future__ import annotations

from .measure_textures import FAMILY
from .report_findings import View, table


def _rounded(value, digits=2):
    return None if value is None else round(value, digits)


def section_textures(view: View) -> str:
    scenes = view.values(FAMILY, "filters")
    if not scenes:
        return ""
    out = ["## Textures", "",
           "Each filter of triangle-texture against the reference (the texture averaged over "
           "each pixel's pre-image by dense sub-pixel sampling), on a 48 x 32 floor receding "
           "from w = 1 to w = 10: per pixel the mean over the channels of |filter - reference| "
           "in levels of 255, RMS and maximum over the covered pixels. Cost: texels fetched per "
           "pixel (from the executed pseudo-code) and the numpy kernel's time per pixel.", ""]
    rows = []
    for scene in scenes:
        for name in view.variants(FAMILY, "filters"):
            get = lambda metric: view.get(FAMILY, "filters", name, scene, metric)  # noqa: E731
            rows.append([scene, name, _rounded(get("rms error")), _rounded(get("max error")),
                         _rounded(get("fetches")), _rounded(get("kernel time"), 3)])
    out.append(table(["scene", "filter", "RMS error", "max error", "texels/px", "kernel us/px"],
                     rows))
    ratios = view.values(FAMILY, "affine")
    if ratios:
        out += ["", "Affine against perspective-correct texture coordinates on the same floor "
                    "(checker:4, 64 texels per unit of uv) with w = 1 at the front and w = r at "
                    "the back: |uv_affine - uv_perspective| in texels.", ""]
        out.append(table(["w ratio r", "RMS (texels)", "max (texels)"],
                         [[r, _rounded(view.get(FAMILY, "affine", "affine", r, "rms error")),
                           _rounded(view.get(FAMILY, "affine", "affine", r, "max error"))]
                          for r in ratios]))
    return "\n".join(out)


def texture_figure(view: View):
    """Error against cost, texels fetched and kernel time, one line per scene (or None)."""
    scenes = view.values(FAMILY, "filters")
    if not scenes:
        return None
    from .charts import Chart, figure  # Pillow loads only when figures are drawn
    names = view.variants(FAMILY, "filters")
    panels = []
    for metric, label, log in (("fetches", "texels fetched per pixel", True),
                               ("kernel time", "kernel time, us per pixel", True)):
        chart = Chart(f"RMS error against {label}", label, "RMS error (levels of 255)",
                      xlog=log, note="each point a filter, named beside it")
        for scene in scenes:
            points = [(view.get(FAMILY, "filters", f, scene, metric),
                       view.get(FAMILY, "filters", f, scene, "rms error")) for f in names]
            chart.add(scene, points, labels=list(names))
        panels.append(chart)
    return figure("Textures: filter error against cost", panels)
