"""The report's section on visibility: the painter's algorithm against the
painter with splitting, from the rows app/analysis/measure_visibility.py adds."""
from __future__ import annotations

from .report_findings import View, table


def section_visibility(view: View) -> str:
    scenes = view.values("visibility", "painter")
    if not scenes:
        return ""
    out = ["## Visibility: the painter's algorithm and splitting", "",
           "Pixels unlike the z-buffer's picture (*wrong*), for the painter's algorithm "
           "(whole triangles sorted by mean depth) and for the painter with splitting (a BSP "
           "tree cuts the triangles along the planes they cross, then paints far to near). "
           "The splitting's price: the cuts, the pieces drawn, and the operations of the "
           "run.", ""]
    rows = []
    for scene in scenes:
        def get(algorithm, metric):
            return view.get("visibility", "painter", algorithm, scene, metric)
        rows.append([scene, get("painter", "disagree"), get("painter-split", "disagree"),
                     get("painter-split", "splits"), get("painter-split", "pieces"),
                     get("painter", "ops"), get("painter-split", "ops")])
    out.append(table(["scene", "painter wrong", "split wrong", "splits", "pieces",
                      "painter ops", "split ops"], rows))
    return "\n".join(out)
