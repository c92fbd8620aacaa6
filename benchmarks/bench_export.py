"""Cost of a GIF export against the cost of Pillow's GIF encoding alone.

Exports 300 frames of a 64 x 64 grid (a scan-line polygon fill) at scale 8
with the caption and the pseudo-code panel, as ``rasterlab export`` does,
and times:

* total: ``app.render.export.export`` from the recorded run to the GIF on disk
  (drawing every frame, palette lookup, Pillow's encoding, the write);
* encode: Pillow writing the same frames, drawn beforehand, with the same
  arguments (the floor any exporter built on Pillow pays);
* draw: drawing the frames alone.

Prints the best of ``--repeat`` runs of each. The target is a total of at
most twice the encode time.

    python benchmarks/bench_export.py [--frames 300] [--scale 8] [--repeat 3] [--panel code]
"""
from __future__ import annotations

import argparse
import io
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from app.render.export import ExportSettings, FrameRenderer, export, record  # noqa: E402
from app.model.scene import Scene  # noqa: E402


def best(seconds):
    return min(seconds)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--scale", type=int, default=8)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--panel", default="code", choices=("code", "variables", "both", "none"))
    args = parser.parse_args(argv)

    scene = Scene(algorithm="polygon-scanline", points=[[[3, 4], [60, 10], [50, 58], [8, 40]]],
                  width=64, height=64)
    trace = record(scene)
    frames = min(args.frames, len(trace))
    settings = ExportSettings(first=0, last=frames - 1, fps=10, scale=args.scale, caption=True,
                              panel=args.panel)

    totals = []
    with tempfile.TemporaryDirectory() as folder:
        target = Path(folder) / "bench.gif"
        for _ in range(args.repeat):
            start = time.perf_counter()
            result = export(scene, settings, gif=target, trace=trace)
            totals.append(time.perf_counter() - start)
        size = target.stat().st_size

    draws, encodes = [], []
    for _ in range(args.repeat):
        start = time.perf_counter()
        renderer = FrameRenderer(scene, settings, trace)
        images = [renderer.image(i) for i in range(frames)]
        draws.append(time.perf_counter() - start)
        start = time.perf_counter()
        stream = io.BytesIO()
        images[0].save(stream, format="GIF", save_all=True, append_images=images[1:],
                       duration=result.durations, palette=renderer.palette_bytes, optimize=True,
                       transparency=renderer.colours.transparent, disposal=1, loop=0)
        encodes.append(time.perf_counter() - start)

    total, encode, draw = best(totals), best(encodes), best(draws)
    width, height = result.size
    print(f"export of {frames} frames, {scene.width}x{scene.height} grid at scale {args.scale}, "
          f"caption on, panel {args.panel}: frames {width}x{height} px, GIF {size / 1024:.0f} KiB")
    print(f"total export            {total:7.3f} s   ({total / frames * 1000:6.2f} ms a frame)")
    print(f"Pillow encoding alone   {encode:7.3f} s   ({encode / frames * 1000:6.2f} ms a frame)"
          f"   {encode / total:5.1%} of the total")
    print(f"drawing alone           {draw:7.3f} s   ({draw / frames * 1000:6.2f} ms a frame)")
    ratio = total / encode
    print(f"total / encoding        {ratio:7.2f}    (target <= 2.00: {'met' if ratio <= 2 else 'MISSED'})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
