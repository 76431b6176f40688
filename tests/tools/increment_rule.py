"""The automatic increment rule of fem/load_history.hpp's file comment, restated for the CLI
tests: from a run's summary.json, the load factors one step of it must have taken.

Rule (CalculiX's checkconvergence.c constants): start at the initial increment; after each
increment the next is 1.5 times it where it and the one before took at most 4 outer
iterations, 0.75 times where it took more than 10, else the same, kept within [minimum,
maximum]; the rest of the step is planned in equal increments no larger than that.
"""
import math


def plan(at, increment):
    n = max(1, math.ceil((1 - at) / increment - 1e-9))
    return [at + (1 - at) * k / n for k in range(1, n)] + [1.0]


def expected_fractions(iterations, initial, minimum, maximum):
    """The fractions of a step whose increments took `iterations` outer iterations each."""
    fractions = plan(0.0, initial)
    easy_before = False
    for j, taken in enumerate(iterations):
        at = fractions[j]
        if at == 1.0:
            return fractions[: j + 1]
        increment = at - (fractions[j - 1] if j else 0.0)
        factor = 0.75 if taken > 10 else 1.5 if taken <= 4 and easy_before else 1.0
        easy_before = taken <= 4
        following = min(max(factor * increment, minimum), maximum)
        if abs(fractions[j + 1] - at - following) > 1e-9 * following:
            fractions = fractions[: j + 1] + plan(at, following)
    return fractions


def check(steps, start, initial, minimum, maximum):
    """Asserts that the summary's `steps` (one stage, load factors start + fraction) follow the
    rule; returns their fractions."""
    taken = [s["load_factor"] - start for s in steps]
    expected = expected_fractions([s["outer_iterations"] for s in steps], initial, minimum, maximum)
    assert len(taken) == len(expected) and all(abs(a - b) <= 1e-12 for a, b in zip(taken, expected)), (
        taken,
        expected,
    )
    return taken
