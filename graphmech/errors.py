"""One root error and the domain errors.

Each error is mixed into the matching built-in so callers can catch either,
and carries *where* it happened: a scene's key path or a construction step.
"""
from __future__ import annotations


def printable(text: str) -> str:
    """``text`` with every control or other unprintable character escaped (``\\n``, ``\\x1b``),
    so a message built from a user's names and titles stays on one line.

    >>> printable("v_C\\nrm -rf")
    'v_C\\\\nrm -rf'
    """
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in text)


class GraphmechError(Exception):
    """Root of every error graphmech raises on purpose."""


COMMAND_LINE = "command line"  # the source of a problem with the command's own arguments


class SceneError(GraphmechError, ValueError):
    """A scene file (or scene data) is invalid.

    Parameters
    ----------
    problems : list of (key_path, reason)
        Every problem found; validation collects them all, then raises once.
    source : str
        The file name, used in the one-line message.
    """

    def __init__(self, problems: list[tuple[str, str]], source: str = "scene") -> None:
        self.problems = list(problems)
        self.source = source
        super().__init__(self.one_line())

    def one_line(self, file: str | None = None) -> str:
        """``file: key: reason`` on one line. A problem found below the scene reader (its source a
        section such as ``machine`` or ``linkage``) is put under the scene ``file`` that led to it."""
        key, reason = self.problems[0]
        more = f" (and {len(self.problems) - 1} more)" if len(self.problems) > 1 else ""
        where = [self.source, key]
        if file and self.source not in (file, COMMAND_LINE):
            where.insert(0, file)
        return printable(": ".join([w for w in where if w] + [f"{reason}{more}"]))


class DegenerateConstruction(GraphmechError, ArithmeticError):
    """A construction step has no (unique) result: parallel lines, circles that do not meet.

    Parameters
    ----------
    step : str
        The step's name, as the draftsman says it ("c = ⟂BC through b ∩ ⟂DC through p").
    reason : str
        Why it fails, in the textbook's words.
    position : str, optional
        Which position (e.g. "φ1 = 170°") when known.
    """

    def __init__(self, step: str, reason: str, position: str | None = None) -> None:
        self.step = step
        self.reason = reason
        self.position = position
        at = f" at {position}" if position else ""
        super().__init__(f"{step}: {reason}{at}")


class AssemblyError(DegenerateConstruction):
    """The linkage cannot be assembled at a position (a dyad's joints cannot meet).

    The message reads ``step: cannot be assembled at φ₁ = 170°: |BD| = 0.21 m > l2 + l3 = 0.2 m``.
    """

    def __init__(self, step: str, reason: str, position: str | None = None) -> None:
        super().__init__(step, reason, position)
        at = f" at {position}" if position else ""
        self.args = (f"{step}: cannot be assembled{at}: {reason}",)
