"""The catalogue of shipped scenes: every example, by family.

One list serves the window's File > Open Example (a submenu per family),
the gallery (Help > Examples and hard cases, with pictures) and
``rasterlab list --scenes``: the scenes of resources/scenes and of its
rendering/ folder, grouped by the family of the algorithm each runs, in
the registry's family order, and within a family in the order a lecture
meets them (the rest by name).
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from algorithms.core.registry import FAMILIES

from app.model import shipped
from app.model.scene import Scene, SceneError, load

# Headings of the families as people read them.
FAMILY_TITLES = {"lines": "Lines", "circles": "Circles and curves", "polygons": "Polygons",
                 "fill": "Flood fill", "triangles": "Triangles", "visibility": "Visibility",
                 "antialias": "Antialiasing", "textures": "Textures",
                 "pipeline": "The 3-D pipeline"}
# Scenes that are plain examples, not hard cases.
NOT_HARD = ("demo-bresenham",)
# The order a lecture meets them in; scenes not named here follow, by name.
ORDER = ("demo-bresenham", "line-float32-drift", "line-centre-ties", "line-reversed",
         "circle-radius-1", "circle-radius-2", "circle-sqrt4-gaps", "polygon-horizontal-edges",
         "polygon-star-evenodd", "polygon-star-nonzero", "triangle-sliver", "triangle-fan-32",
         "triangle-mesh-1e6", "triangle-behind-eye", "painter-intersecting", "painter-cyclic",
         "aa-siemens-star")


@dataclass(frozen=True)
class Example:
    """One shipped scene: its name (as ``run --scene`` takes it), file and contents."""

    name: str
    path: Path
    scene: Scene

    @property
    def family(self) -> str:
        return self.scene.spec.family

    @property
    def hard(self) -> bool:
        return self.path.stem not in NOT_HARD

    @property
    def title(self) -> str:
        return self.scene.title or self.name

    def text(self) -> str:
        spec = self.scene.spec
        return (f"{self.title}\n{self.scene.description}\n"
                f"{spec.title} ({spec.name}), {self.scene.width} x {self.scene.height} grid")


def family_title(family: str) -> str:
    return FAMILY_TITLES.get(family, family.capitalize())


def examples(paths: list[Path] | None = None) -> list[Example]:
    """Every readable scene of ``paths`` (default: every shipped scene), by
    family, then in lecture order. A broken scene is left out (a shipped one
    is a test failure instead)."""
    found = []
    for path in shipped.scene_files() if paths is None else paths:
        try:
            found.append(Example(_name(path), path, load(path)))
        except SceneError:
            continue
    rank = {name: n for n, name in enumerate(ORDER)}
    return sorted(found, key=lambda e: (_family_rank(e.family), rank.get(e.name, len(ORDER)),
                                        e.name))


def by_family(entries: list[Example]) -> list[tuple[str, list[Example]]]:
    """The entries as (family, its examples), families in catalogue order."""
    groups: dict[str, list[Example]] = {}
    for entry in entries:
        groups.setdefault(entry.family, []).append(entry)
    return list(groups.items())


def _family_rank(family: str) -> int:
    return FAMILIES.index(family) if family in FAMILIES else len(FAMILIES)


def _name(path: Path) -> str:
    try:
        return shipped.scene_name(path)
    except ValueError:  # a scene outside the shipped folder: its file name
        return path.stem
