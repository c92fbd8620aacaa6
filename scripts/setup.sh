#!/usr/bin/env bash
# Set up RasterLab from this checkout: the system libraries Qt needs (Debian
# and Ubuntu), a virtual environment in .venv, and RasterLab in it with the
# versions pinned in requirements/ (made from uv.lock by scripts/lock.sh).
#
#   bash scripts/setup.sh          what the program needs, to open the window
#   bash scripts/setup.sh --test   and the test tools and Chromium, to run the tests
#
# PYTHON=python3.12 bash scripts/setup.sh makes the venv with another Python.
set -euo pipefail
cd "$(dirname "$0")/.."

MODE=app
case "${1:-}" in
  "") ;;
  --test) MODE=test ;;
  *) echo "usage: bash scripts/setup.sh [--test]" >&2; exit 2 ;;
esac
PYTHON="${PYTHON:-python3}"

# Qt's offscreen and X11 platforms, fonts for the panels.
SYSTEM_PACKAGES="libegl1 libgl1 libglib2.0-0 libfontconfig1 libdbus-1-3 fonts-dejavu-core
  libxkbcommon0 libxkbcommon-x11-0 libxcb-cursor0 libxcb-icccm4 libxcb-image0
  libxcb-keysyms1 libxcb-randr0 libxcb-render-util0 libxcb-shape0 libxcb-xinerama0 libxcb-xkb1"
# bubblewrap: `rasterlab check` runs each student's case in its sandbox.
SYSTEM_PACKAGES="$SYSTEM_PACKAGES bubblewrap"
# Stock Debian and Ubuntu Pythons make no venv without their -venv package
# (it holds ensurepip); Python's own message names the versioned one.
if ! "$PYTHON" -c "import ensurepip" >/dev/null 2>&1; then
  SYSTEM_PACKAGES="$SYSTEM_PACKAGES python3-venv python$("$PYTHON" -c \
    'import sys; print("%d.%d" % sys.version_info[:2])')-venv"
fi
# The tests drive a real browser: Debian's Chromium, unless Google Chrome is
# there (as on CI's Ubuntu machines), which Selenium finds with its driver.
if [ "$MODE" = test ] && ! command -v google-chrome >/dev/null 2>&1; then
  SYSTEM_PACKAGES="$SYSTEM_PACKAGES chromium chromium-driver"
fi
# The tests build the C and C++ templates of `check --cmd` (skipped without a compiler).
if [ "$MODE" = test ]; then
  SYSTEM_PACKAGES="$SYSTEM_PACKAGES gcc g++"
fi

if command -v apt-get >/dev/null 2>&1 && command -v dpkg >/dev/null 2>&1; then
  missing=""
  for package in $SYSTEM_PACKAGES; do
    dpkg -s "$package" >/dev/null 2>&1 || missing="$missing $package"
  done
  if [ -n "$missing" ]; then
    echo "installing system packages:$missing"
    if [ "$(id -u)" -eq 0 ]; then SUDO=""; else SUDO="sudo"; fi
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing >/dev/null
  fi
else
  # macOS and Windows need no system package: the Qt wheels carry their libraries.
  echo "no apt-get here: system packages skipped (on Linux, install the equivalents of:" \
       $SYSTEM_PACKAGES")"
fi

venv_bin() { if [ -d .venv/Scripts ]; then echo .venv/Scripts; else echo .venv/bin; fi; }
BIN="$(venv_bin)"  # .venv/Scripts where the Python is a Windows one
if ! "$BIN/python" -m pip --version >/dev/null 2>&1; then
  # None yet, or one left without pip by a Python that lacked ensurepip.
  "$PYTHON" -m venv --clear .venv
  BIN="$(venv_bin)"
fi

# The install is repeated only when the pinned requirements or pyproject.toml
# changed since the last one (their checksum is kept in .venv), so running
# set-up again is quiet and quick. The test install holds the program's, so
# its stamp serves the plain set-up too.
checksum() {
  "$PYTHON" -c 'import hashlib, sys
print(hashlib.sha256(b"".join(open(name, "rb").read() for name in sys.argv[1:])).hexdigest())' \
    "$@"
}
stamp_ok() {
  [ "$(cat ".venv/.rasterlab-$1" 2>/dev/null)" = "$(checksum "requirements/$1.txt" pyproject.toml)" ]
}
installed() { [ -x "$BIN/rasterlab" ] || [ -f "$BIN/rasterlab.exe" ]; }
up_to_date() {
  installed || return 1
  stamp_ok "$MODE" || { [ "$MODE" = app ] && stamp_ok test; }
}
if ! up_to_date; then
  "$BIN/python" -m pip install --quiet --disable-pip-version-check --require-hashes \
    -r "requirements/$MODE.txt"
  # The editable install's build prints a long warning about same-named
  # folders; it is about the build, not this project, so it is kept out.
  log="$(mktemp)"
  status=0
  "$BIN/python" -m pip install --quiet --disable-pip-version-check --no-deps -e . 2> "$log" \
    || status=$?
  grep -v -e BuildBackendWarning -e '^ *!!' -e '^ *\*\*\*' -e 'Please be careful' \
    -e 'name as your package' -e 'with strategy' -e '^ *$' "$log" >&2 || true
  rm -f "$log"
  [ "$status" -eq 0 ] || exit "$status"
  checksum "requirements/$MODE.txt" pyproject.toml > ".venv/.rasterlab-$MODE"
fi
# The HTML page's accessibility tests run axe-core from npm: fetched once into
# a cache outside the checkout and checked against npm's published integrity.
if [ "$MODE" = test ]; then
  "$BIN/python" -m tests.support.axe
fi
echo "RasterLab is set up in .venv (run $BIN/rasterlab, or 'source $BIN/activate' first to type just rasterlab)"
