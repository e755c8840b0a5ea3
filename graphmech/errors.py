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


def one_line(error: GraphmechError, file: str | None = None) -> str:
    """What the command prints for ``error`` met while doing ``file``: one line, the file first.

    >>> one_line(GraphmechError("c: the circles do not meet"), "crank.toml")
    'crank.toml: c: the circles do not meet'
    """
    if isinstance(error, SceneError):
        return error.one_line(file)
    return printable(f"{file or 'graphmech'}: {error}")


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


# The refusals of the methods (methods/, exact/) and the library's other public functions. Each is
# also the built-in it replaced (as ezdxf's DXFValueError is a ValueError), so every caller's
# ``except ValueError`` still catches it, while the command maps it, as a GraphmechError, to a
# one-line refusal (exit 2) instead of an internal error.


class OutOfDomain(GraphmechError, ValueError):
    """An argument outside the domain of the method asked, or data for which it has no answer.

    A scale, a length or a speed that is not positive and finite; δ outside (0, 2); arrays of
    different lengths; an option or a name the method does not offer ('forward' or 'reverse', a
    panel, a position label); data that admit no result (coinciding correction planes, an arm that
    cannot reach the base circle, a flywheel too small to keep the mean speed).
    """


class NotApplicable(GraphmechError, ValueError):
    """The method does not apply to this mechanism, whatever the numbers.

    Extreme positions of a crank that does not turn fully, Grashof's rule for a loop that is not a
    hinged four-bar, the matrix method of kinetostatics for a group it does not take, crank angles
    asked of a linkage driven by a slider.
    """


class UnknownName(GraphmechError, KeyError):
    """A name looked up by key and not there: a step of the construction, a quantity of the cycle's
    diagrams (where the lookup was a KeyError). A name a method refuses among those it offers (a
    point not in the linkage, a quantity or segment a check cannot read) is an :class:`OutOfDomain`:
    its callers catch ValueError.

    Printed as its message: a KeyError's ``str`` would quote it (``'no point X'``).
    """

    def __str__(self) -> str:
        return str(self.args[0]) if len(self.args) == 1 else super().__str__()


class NoSolution(GraphmechError, ArithmeticError):
    """A calculation that found no (finite, unique) result for these data, or did not converge.

    The exact working profile folding over itself (an undercut), a profile vertex not found, a pitch
    curve with no convex arc, an inversion not drawable at some divisions. A construction step
    with no result is a :class:`DegenerateConstruction` instead.
    """


class WrongKind(GraphmechError, TypeError):
    """An object of another kind than the method takes: the rocker angle of a translating follower."""
