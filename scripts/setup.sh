#!/usr/bin/env bash
# Set up RasterLab on a fresh Debian or Ubuntu machine: the system libraries
# Qt needs, a virtual environment in .venv, and RasterLab with its test tools.
set -euo pipefail
cd "$(dirname "$0")/.."

# Qt's offscreen and X11 platforms, fonts for the panels; Chromium, in
# which the tests open the exported interactive page.
SYSTEM_PACKAGES="libegl1 libgl1 libglib2.0-0 libfontconfig1 libdbus-1-3 fonts-dejavu-core
  libxkbcommon0 libxkbcommon-x11-0 libxcb-cursor0 libxcb-icccm4 libxcb-image0
  libxcb-keysyms1 libxcb-randr0 libxcb-render-util0 libxcb-shape0 libxcb-xinerama0 libxcb-xkb1
  chromium chromium-driver"

missing=""
if command -v dpkg >/dev/null 2>&1; then
  for package in $SYSTEM_PACKAGES; do
    dpkg -s "$package" >/dev/null 2>&1 || missing="$missing $package"
  done
fi
if [ -n "$missing" ]; then
  echo "installing system packages:$missing"
  if [ "$(id -u)" -eq 0 ]; then SUDO=""; else SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing >/dev/null
fi

PYTHON="${PYTHON:-python3}"
if [ ! -x .venv/bin/python ]; then
  "$PYTHON" -m venv .venv
fi
# The install is repeated only when pyproject.toml changed since the last
# one (its checksum is kept in .venv), so running set-up again is quiet.
STAMP=.venv/.rasterlab-installed
WANTED="$(sha256sum pyproject.toml | cut -d' ' -f1)"
if [ "$(cat "$STAMP" 2>/dev/null)" != "$WANTED" ] || [ ! -x .venv/bin/rasterlab ]; then
  .venv/bin/python -m pip install --quiet --upgrade pip
  # The editable install's build prints a long warning about same-named
  # folders; it is about the build, not this project, so it is kept out.
  log="$(mktemp)"
  status=0
  .venv/bin/python -m pip install --quiet -e ".[test]" 2> "$log" || status=$?
  grep -v -e BuildBackendWarning -e '^ *!!' -e '^ *\*\*\*' -e 'Please be careful' \
    -e 'name as your package' -e 'with strategy' -e '^ *$' "$log" >&2 || true
  rm -f "$log"
  [ "$status" -eq 0 ] || exit "$status"
  echo "$WANTED" > "$STAMP"
fi
echo "RasterLab is set up in .venv (run .venv/bin/rasterlab, or 'source .venv/bin/activate' first to type just rasterlab)"
