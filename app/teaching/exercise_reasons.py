"""Why an exercise's answer is what it is, said with the step's numbers.

Qt-free. ``reason`` words the outcome of one step for the feedback: the
algorithm's own explanation of the decision where it gives one (Bresenham's
"d_i = -3 < 0, so E", a triangle's verdict, a scan line's run and pixels),
the rounding of a float position for an algorithm that plots round(x),
round(y) (DDA: "y = 5.4167 -> 5"), else the decision variable's value.
``shown`` writes an answer as the question means it: a span as its first and
last pixel ("x = 10..10"), never as a pixel.
"""
from __future__ import annotations

from app.model.notation import number, tidy

# The explanation rows (AlgorithmSpec.explain) that say why a step goes as it does.
EXPLAINING = ("decision", "verdict", "run", "pixels")


def shown(kind: str, value) -> str:
    """An answer (the right one or the given one) as a person reads it."""
    if kind == "span" and isinstance(value, tuple) and len(value) == 2:
        return f"x = {value[0]}..{value[1]}"
    if isinstance(value, tuple) and len(value) == 2:
        return f"({value[0]}, {value[1]})"
    if isinstance(value, float):
        return number(value)
    return str(value)


def reason(trace, explain, question, decision: str | None) -> str:
    """The numbers that decide ``question``, ending in its answer."""
    step = trace.step(question.step)
    answer = shown(question.kind, question.answer)
    rows = dict(explain(trace, question.step)) if explain is not None else {}
    said = [tidy(rows[name]) for name in EXPLAINING if name in rows]
    if question.kind == "value":
        return f"{decision} = {answer}" + (f" ({'; '.join(said)})" if said else "")
    if question.kind == "inside" and step.values:
        # The verdict's own numbers: the edge functions, a depth, ...
        said.insert(0, ", ".join(f"{name} = {number(float(value))}"
                                 for name, value in step.values.items()))
    if said:
        text = "; ".join(said)
    elif question.kind == "pixel":
        text = rounding(step.values, question.answer)
    elif decision is not None and decision in step.values:
        text = f"{decision} = {number(float(step.values[decision]))}"
    else:
        text = ""
    if not text:
        return f"the answer is {answer}"
    return text if text.endswith(answer) else f"{text}, so {answer}"


def rounding(values: dict, pixel) -> str:
    """"x = 6, y = 5.4167 -> 5" where the step's x and y round to its pixel."""
    if pixel is None or not all(name in values for name in ("x", "y")):
        return ""
    parts = []
    for name, target in zip(("x", "y"), pixel):
        value = float(values[name])
        if abs(value - target) > 0.5:
            return ""  # x and y are not the pixel's position (a circle's offsets, say)
        parts.append(f"{name} = {number(value)}" if value == target
                     else f"{name} = {number(value)} -> {target}")
    return ", ".join(parts)
