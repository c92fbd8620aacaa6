"""The wheel's layout, which pyproject.toml cannot say on its own: the
program's packages go inside ``rasterlab/_lib`` (see rasterlab/__init__.py
for why). They are found here, not listed by hand."""
from setuptools import find_namespace_packages, find_packages, setup

TOP = ("algorithms", "app", "widgets", "resources")
# resources/ and its folders of data (scenes, templates, ...) are packages
# to setuptools, so that their files go into the wheel as package data.
PROGRAM = (find_packages(include=["algorithms*", "app*", "widgets*"])
           + find_namespace_packages(include=["resources", "resources.*"], exclude=["*__pycache__*"]))

setup(
    packages=["rasterlab", *(f"rasterlab._lib.{name}" for name in PROGRAM)],
    package_dir={"rasterlab": "rasterlab", **{f"rasterlab._lib.{top}": top for top in TOP}},
    package_data={"": ["*.json", "*.html", "*.py", "*.c", "*.cpp", "*.js", "*.png", "*.ttf",
                      "LICENSE.txt"]},
    # The README's pictures stay in the repository.
    exclude_package_data={"rasterlab._lib.resources": ["*.png", "*.gif"]},
)
