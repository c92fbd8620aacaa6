"""Every question template, by name, collected from the family modules.

A family module of this package defines ``TEMPLATES``, a tuple of
``Template``; adding a family is adding its module's name to FAMILIES.
Names are listed in family order, then in each module's own order.
"""
from __future__ import annotations

from importlib import import_module

from app.teaching.questions.model import Template

FAMILIES = ("lines", "circles", "fill", "triangles", "visibility", "antialias", "textures")


def _collect() -> dict[str, Template]:
    templates: dict[str, Template] = {}
    for family in FAMILIES:
        for template in import_module(f"app.teaching.questions.{family}").TEMPLATES:
            if template.name in templates:
                raise RuntimeError(f"two question templates are named {template.name}")
            templates[template.name] = template
    return templates


TEMPLATES: dict[str, Template] = _collect()


def get(name: str) -> Template:
    """The template called ``name``; ValueError (one line) for an unknown name."""
    try:
        return TEMPLATES[name]
    except KeyError:
        raise ValueError(f"no question template {name!r}; `rasterlab questions --list` "
                         "names them") from None


def for_algorithm(algorithm: str) -> list[Template]:
    """The templates that can ask about a scene of ``algorithm``."""
    return [template for template in TEMPLATES.values() if algorithm in template.algorithms]
