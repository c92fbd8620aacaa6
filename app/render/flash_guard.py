"""Exports that do not flash (WCAG 2.3.1): an animation that would flash
more than three times a second over a large area is slowed until it cannot.

A flash takes two changes of frame, so at ``SAFE_FPS`` (7) frames a second
or fewer nothing can flash more than three times in any second, and such an
export is not measured. Faster ones whose frames are a run's animation
frames (aa-temporal: a spinning wheel, a moving triangle, where whole areas
change from frame to frame) are drawn and measured first
(``app.render.flashes``); one that flashes too often is exported at
``SAFE_FPS`` instead, and its summary line says so. Frames of single steps
only add or outline a few cells each and are not measured.

Playback (the window's transport, the HTML page) is held to the same
SAFE_FPS animation frames a second by ``flashes.playback_cap``, for every run with
animation frames, without measuring: a person can change the speed at any
moment, and measuring means drawing every frame of the run first.
"""
from __future__ import annotations

from dataclasses import replace

from algorithms.antialias import animation_frame_steps
from algorithms.core import registry

from app.render import flashes
from app.render.export import FrameRenderer
from app.render.flashes import SAFE_FPS
from app.render.settings import chosen_frames, frame_durations, record


def flash_safe(scene, settings, trace=None):
    """(settings, trace, note): ``settings`` slowed to SAFE_FPS where its
    animation would flash more than flashes.LIMIT times a second, the run
    (recorded here when it had to be measured and was not given), and one
    line saying what was slowed and why ('' when nothing was)."""
    checked = settings.checked()
    if checked.fps <= SAFE_FPS:
        return settings, trace, ""
    if trace is None:
        trace = record(scene, memory_limit=checked.memory_limit, time_limit=checked.time_limit,
                       progress=checked.recording)
    checked = checked.for_grid(trace.width, trace.height)
    steps = chosen_frames(scene, trace, checked)[0]
    animation = set(animation_frame_steps(registry.get(scene.algorithm), trace))
    if not animation or not set(steps) <= animation:
        return settings, trace, ""
    found = measure(FrameRenderer(scene, checked, trace), steps, checked)
    if found.safe:
        return settings, trace, ""
    return replace(settings, fps=SAFE_FPS), trace, (
        f"slowed from {checked.fps:g} to {SAFE_FPS} frames a second: at {checked.fps:g} the "
        f"animation would flash {found.per_second} times a second over a large area "
        f"(WCAG 2.3.1 allows {flashes.LIMIT})")


def measure(renderer, steps, settings) -> flashes.Flashes:
    """The flashes of the frames ``renderer`` draws for ``steps``, at the
    timing and looping of ``settings``."""
    frames = [renderer.rgb(index) for index in steps]
    durations = frame_durations(len(steps), settings.fps, settings.hold)
    return flashes.flash_rate(frames, durations, loop=settings.loop)
