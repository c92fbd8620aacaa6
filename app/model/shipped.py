"""Where the data RasterLab ships is, and the shipped scenes by name.

The data (scenes, templates, student samples, textures, fonts) is the
package ``resources``; ``importlib.resources`` finds it in a checkout and in
an installed wheel alike. pip, pipx and uv unpack a wheel into real files,
which is what Pillow, fpdf2 and Qt need to open a font or a texture.
"""
from __future__ import annotations

from importlib import resources as importlib_resources
from pathlib import Path


def _root() -> Path:
    root = importlib_resources.files("resources")
    if not isinstance(root, Path):  # a zip import: nothing here can open files inside it
        raise RuntimeError("RasterLab's resources are inside an archive; install it unpacked "
                           "(pip, pipx and uv all do)")
    return root


ROOT = _root()
PROGRAM = ROOT.parent  # the folder that holds the program's packages and its data
SCENES = ROOT / "scenes"
FONTS = ROOT / "fonts"
TEMPLATES = ROOT / "templates"
STUDENTS = ROOT / "students"
TEXTURES = ROOT / "textures"


def scene_files() -> list[Path]:
    """Every shipped scene: the examples and hard cases, then those of rendering/."""
    return sorted(SCENES.glob("*.json")) + sorted((SCENES / "rendering").glob("*.json"))


def scene_name(path: Path) -> str:
    """The name a shipped scene is called by: its file name without .json,
    with the sub-folder in front for the rendering scenes ("rendering/pipeline-cube")."""
    return path.relative_to(SCENES).with_suffix("").as_posix()


def is_program_file(path) -> bool:
    """Does ``path`` lie inside the program's own folder (a shipped scene,
    say)? The window never writes there: an update or reinstall would
    replace the file, and every user of the program shares it."""
    try:
        return Path(path).resolve().is_relative_to(PROGRAM.resolve())
    except OSError:
        return False


def templates() -> dict[str, Path]:
    """The starting files of a student's own algorithm, by name ("line", "fill", ...)."""
    return {path.stem: path for path in sorted(TEMPLATES.glob("*.py"))}


PROGRAM_TEMPLATES = (".c", ".cpp", ".js")  # programs for `check --cmd`


def program_templates() -> dict[str, Path]:
    """The starting files of a program in another language, for `check --cmd`,
    by file name ("line.c", "line.js", ...)."""
    return {path.name: path for path in sorted(TEMPLATES.iterdir())
            if path.suffix in PROGRAM_TEMPLATES}


def template_title(path: Path) -> str:
    """A template's title, the first line of its docstring or comment
    ("A line algorithm of your own, ...")."""
    for line in path.read_text(encoding="utf-8").splitlines():
        text = line.strip().strip('"').strip("/*").strip()
        if text:
            return text
    return ""


def scene_path(text: str) -> Path:
    """A scene given on the command line: a file that exists, else the
    shipped scene of that name (with or without .json). A text that is
    neither is returned as it is, so that reading it reports the missing file."""
    path = Path(text)
    if path.exists():
        return path
    name = text[:-5] if text.endswith(".json") else text
    for candidate in scene_files():
        if scene_name(candidate) == name:
            return candidate
    return path
