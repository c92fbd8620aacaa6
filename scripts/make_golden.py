"""Write the golden frames the export tests compare with.

For each scene of ``GOLDEN`` (tests/support/golden_frames.py), the exported
frame at its first, middle and last step is reduced to the colour at the
centre of each grid cell and stored in tests/app/render/golden/NAME.npz. The tests
never write these files: run this command when a change to what the frames
show is intended, check the cells the failing test listed, and commit the
new files with that change.

    python scripts/make_golden.py
"""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from tests.support.golden_frames import GOLDEN, GOLDEN_DIR, golden_frames  # noqa: E402


def main() -> int:
    GOLDEN_DIR.mkdir(parents=True, exist_ok=True)
    for name in GOLDEN:
        frames = golden_frames(name)
        path = GOLDEN_DIR / f"{name}.npz"
        np.savez_compressed(path, **frames)
        print(f"{path.relative_to(ROOT)}: steps {frames['steps'].tolist()}, "
              f"{path.stat().st_size:,} bytes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
