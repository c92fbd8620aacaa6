"""The lock: uv.lock and requirements/*.txt agree with pyproject.toml, and
the exports pin every dependency once on every system and Python that CI runs."""
from __future__ import annotations

import importlib.util
import re
from pathlib import Path

import pytest
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

try:
    import tomllib
except ImportError:  # Python 3.10; pytest brings tomli there
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[1]
PROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
SYSTEMS = {"linux": ("Linux", "posix", "x86_64"), "darwin": ("Darwin", "posix", "arm64"),
           "win32": ("Windows", "nt", "AMD64")}
PYTHONS = ("3.10", "3.11", "3.12", "3.13")


def load_lock_script():
    spec = importlib.util.spec_from_file_location("lock", ROOT / "scripts" / "lock.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def pins(name: str) -> list[Requirement]:
    """The requirements of an export, continuation lines joined, hashes dropped."""
    text = (ROOT / "requirements" / name).read_text(encoding="utf-8").replace("\\\n", " ")
    lines = (re.sub(r"--hash=\S+", "", line).strip() for line in text.splitlines())
    return [Requirement(line) for line in lines if line and not line.startswith("#")]


def environment(system: str, python: str) -> dict:
    platform_system, os_name, machine = SYSTEMS[system]
    return {"sys_platform": system, "platform_system": platform_system, "os_name": os_name,
            "platform_machine": machine, "python_version": python,
            "python_full_version": f"{python}.0", "implementation_name": "cpython",
            "platform_python_implementation": "CPython"}


def test_uv_lock_and_the_exports_agree_with_pyproject():
    assert load_lock_script().stale() == []


@pytest.mark.parametrize("export, groups", [("app.txt", ()),
                                            ("test.txt", tuple(PROJECT["optional-dependencies"]))])
@pytest.mark.parametrize("system", SYSTEMS)
@pytest.mark.parametrize("python", PYTHONS)
def test_every_dependency_is_pinned_once_within_its_range(export, groups, system, python):
    """What pip would install from the export on that system: exactly one
    pinned version of each dependency pyproject.toml names, inside its range."""
    declared = [Requirement(text) for text in PROJECT["dependencies"]]
    declared += [Requirement(text) for group in groups
                 for text in PROJECT["optional-dependencies"][group]]
    env = environment(system, python)
    chosen = {}
    for pin in pins(export):
        if pin.marker is None or pin.marker.evaluate(env):
            chosen.setdefault(canonicalize_name(pin.name), []).append(pin)
    for requirement in declared:
        if requirement.marker is not None and not requirement.marker.evaluate(env):
            continue
        if canonicalize_name(requirement.name) == canonicalize_name(PROJECT["name"]):
            continue  # an extra naming another ("rasterlab[fast]"): that one's lines are checked
        found = chosen.get(canonicalize_name(requirement.name), [])
        assert len(found) == 1, f"{export} pins {requirement.name} {len(found)} times"
        (version,) = [spec.version for spec in found[0].specifier if spec.operator == "=="]
        assert requirement.specifier.contains(version, prereleases=True), \
            f"{export}: {requirement.name}=={version} is outside {requirement.specifier}"


def test_the_program_export_holds_no_test_tool():
    test_only = {canonicalize_name(Requirement(text).name)
                 for text in PROJECT["optional-dependencies"]["test"]}
    assert not test_only & {canonicalize_name(pin.name) for pin in pins("app.txt")}

