"""The installed wheel beside same-named code: installed next to an unrelated
distribution called ``algorithms`` and run from a folder that holds an
``algorithms/`` folder (both raise if imported), RasterLab still uses its own
packages. The wheel goes into a plain folder with the test environment's
dependencies; scripts/smoke.py does the same in a clean venv, with the
commands a user types."""
from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.support.bresenham import bresenham_pixels

ROOT = Path(__file__).resolve().parents[1]


def load_smoke():
    spec = importlib.util.spec_from_file_location("smoke", ROOT / "scripts" / "smoke.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


smoke = load_smoke()


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """The wheel and the impostor installed into one folder; a course folder
    with an algorithms/ folder; the environment that puts the install first."""
    tmp = tmp_path_factory.mktemp("wheel")
    wheel = smoke.build_wheel(tmp)
    target = tmp / "site"
    subprocess.run([sys.executable, "-m", "pip", "install", "--quiet", "--no-deps",
                    "--disable-pip-version-check", "--target", str(target), str(wheel),
                    str(smoke.fake_algorithms_wheel(tmp))], check=True)
    env = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
    env["PYTHONPATH"] = str(target)
    return target, smoke.course_folder(tmp / "course"), env


def rasterlab(installed, *args: str) -> str:
    target, course, env = installed
    done = subprocess.run([sys.executable, "-m", "rasterlab", *args], cwd=course, env=env,
                          capture_output=True, text=True, encoding="utf-8")
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_the_impostor_is_installed_beside_rasterlab(installed):
    target = installed[0]
    assert "unrelated distribution" in (target / "algorithms" / "__init__.py").read_text()
    assert (target / "rasterlab" / "_lib" / "algorithms" / "__init__.py").is_file()


def test_the_program_is_imported_from_the_wheel(installed):
    target, course, env = installed
    done = subprocess.run([sys.executable, "-c", "import json, rasterlab, app, algorithms\n"
                                                 "print(json.dumps([app.__file__, algorithms.__file__]))"],
                          cwd=course, env=env, capture_output=True, text=True, check=True)
    lib = (target / "rasterlab" / "_lib").resolve()
    for path in json.loads(done.stdout):
        assert Path(path).resolve().is_relative_to(lib)


def test_shipped_scenes_are_listed(installed):
    listed = {line.split()[0] for line in rasterlab(installed, "list", "--scenes").splitlines()}
    scenes = ROOT / "resources" / "scenes"
    assert listed == {path.relative_to(scenes).with_suffix("").as_posix()
                      for path in scenes.rglob("*.json")}


def test_a_shipped_scene_runs_by_name(installed):
    result = json.loads(rasterlab(installed, "run", "--scene", "demo-bresenham", "--json"))
    scene = json.loads((ROOT / "resources" / "scenes" / "demo-bresenham.json").read_text())
    p, q = scene["primitives"][0]["points"]
    assert [tuple(pixel) for pixel in result["pixels"]] == bresenham_pixels(tuple(p), tuple(q))
