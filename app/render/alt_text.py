"""Alt text of exported frames: a title (the scene) and a description (the
algorithm, the grid and the step in words, ``app.model.step_words.describe``,
the same words the interactive page reads out). SVG frames carry them as
``<title>`` and ``<desc>``, PNG frames as the text chunks "Title" and
"Description", a PDF of frames as its document title and subject, with an
outline entry (bookmark) per page naming its step."""
from __future__ import annotations

from algorithms.core import registry
from app.model.escape import encodable
from app.model.step_words import describe

LANGUAGE = "en"   # every text the program writes is English


class AltText:
    """The alt text of one export's frames."""

    def __init__(self, scene, trace, numbers: str = "decimal"):
        self.scene, self.trace, self.numbers = scene, trace, numbers
        self.spec = registry.get(scene.algorithm)

    @property
    def title(self) -> str:
        """The scene's title, its lone surrogates (which no PNG chunk or PDF
        string can hold) as U+FFFD; each format escapes the rest."""
        return encodable(self.scene.title) or self.spec.title

    @property
    def subject(self) -> str:
        """What the whole export shows: the algorithm on its grid."""
        spec, trace = self.spec, self.trace
        return (f"{spec.title} ({spec.name}: {spec.summary}) on a {trace.width} x "
                f"{trace.height} grid, {len(trace) - 1:,} steps")

    def words(self, index: int) -> str:
        """Step ``index`` in words, as the interactive page and the window say it."""
        return describe(self.trace, index, self.numbers)

    def description(self, index: int) -> str:
        """Frame ``index``: the algorithm, the grid, and step ``index`` in words."""
        return f"{self.title}: {self.subject}. {self.words(index)}."

    def png_info(self, index: int) -> dict[str, str]:
        """The PNG tEXt chunks of frame ``index``."""
        return {"Title": self.title, "Description": self.description(index)}

