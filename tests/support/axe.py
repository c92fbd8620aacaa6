"""axe-core, the accessibility checker, for the interactive page's tests.

The tests run axe-core's own script in the browser that shows the page. The
script comes from the npm registry once, into a cache folder outside the
checkout ($RASTERLAB_TEST_CACHE, else ~/.cache/rasterlab-tests/), and is
used only when its package matches the integrity npm publishes for it.
`bash scripts/setup.sh --test` fetches it (``python -m tests.support.axe``),
so CI has it before the tests; without it, and with no way to download it,
the tests fail with one line saying so.
"""
from __future__ import annotations

import base64
import hashlib
import io
import os
import sys
import tarfile
import urllib.request
from pathlib import Path

VERSION = "4.14.1"
URL = f"https://registry.npmjs.org/axe-core/-/axe-core-{VERSION}.tgz"
INTEGRITY = ("sha512-FHfa+lmNjQZfJz1q8wKqIDwC6DExcHt/pkjNQb09a3NPjCKg2rhu5qb2S4r76ASyFNNtuFooJpZe"
             "37OgudVGtQ==")
MEMBER = "package/axe.min.js"
# WCAG 2.1 level A and AA, as axe-core tags its rules.
WCAG21_AA = ("wcag2a", "wcag2aa", "wcag21a", "wcag21aa")


class AxeUnavailable(RuntimeError):
    """axe-core is neither in the cache nor downloadable; the message is one line."""


def cache_folder() -> Path:
    folder = os.environ.get("RASTERLAB_TEST_CACHE")
    return Path(folder) if folder else Path.home() / ".cache" / "rasterlab-tests"


def script_path() -> Path:
    return cache_folder() / f"axe-core-{VERSION}" / "axe.min.js"


def integrity_of(package: bytes) -> str:
    """The package's integrity in npm's form (Subresource Integrity, sha512)."""
    return "sha512-" + base64.b64encode(hashlib.sha512(package).digest()).decode("ascii")


def unpack(package: bytes) -> bytes:
    """axe.min.js out of the npm package, once the package proves to be the published one."""
    found = integrity_of(package)
    if found != INTEGRITY:
        raise AxeUnavailable(f"axe-core {VERSION} from {URL} has integrity {found[:24]}..., "
                             f"not the published {INTEGRITY[:24]}...: not used")
    with tarfile.open(fileobj=io.BytesIO(package), mode="r:gz") as archive:
        return archive.extractfile(MEMBER).read()


def fetch(timeout: float = 60.0) -> Path:
    """The path of axe.min.js, downloaded and checked first if not yet cached."""
    path = script_path()
    if path.is_file():
        return path
    try:
        with urllib.request.urlopen(URL, timeout=timeout) as response:
            package = response.read()
    except OSError as error:
        raise AxeUnavailable(f"axe-core {VERSION} is not in {path.parent} and could not be "
                             f"downloaded from {URL} ({error}); run `bash scripts/setup.sh --test` "
                             "where the network is reachable") from None
    script = unpack(package)
    path.parent.mkdir(parents=True, exist_ok=True)
    partial = path.with_suffix(".partial")
    partial.write_bytes(script)
    partial.replace(path)   # never a half-written script in the cache
    return path


def audit(driver, tags=WCAG21_AA) -> dict:
    """axe-core's results for the page open in ``driver`` (a Selenium driver),
    with only the rules of ``tags``: {"violations": [...], "passes": [...], ...}."""
    driver.execute_script(fetch().read_text(encoding="utf-8"))
    return driver.execute_async_script(
        "const done = arguments[arguments.length - 1];"
        "axe.run(document, {runOnly: {type: 'tag', values: arguments[0]}})"
        "  .then(r => done({violations: r.violations, passes: r.passes.length,"
        "                   incomplete: r.incomplete, version: r.testEngine.version}))"
        "  .catch(e => done({error: String(e)}));", list(tags))


def summary(results: dict) -> dict[str, int]:
    """{rule id: how many elements break it} of axe-core's results."""
    return {v["id"]: len(v["nodes"]) for v in results["violations"]}


if __name__ == "__main__":
    try:
        print(f"axe-core {VERSION}: {fetch()}")
    except AxeUnavailable as error:
        print(f"error: {error}", file=sys.stderr)
        sys.exit(1)
