"""graphmech.errors: the project's own errors, each also the built-in it stands for, and the rule
that the methods and the exact solutions raise only these (the command maps them to exit 2)."""
from __future__ import annotations

import ast
import builtins
import math
from collections import Counter

import pytest

from graphmech import errors
from graphmech.errors import (AssemblyError, DegenerateConstruction, GraphmechError, NoSolution, NotApplicable,
                              OutOfDomain, SceneError, UnknownName, WrongKind, printable)
from tests.conftest import ROOT, SCENES, assert_refused, run_cli

#: Each refusal of a method and the built-in it also is (so an ``except ValueError`` still holds).
BUILTIN_OF = {OutOfDomain: ValueError, NotApplicable: ValueError, UnknownName: KeyError,
              NoSolution: ArithmeticError, WrongKind: TypeError}


# ---------------------------------------------------------------------------- the classes


@pytest.mark.parametrize("cls", BUILTIN_OF, ids=lambda c: c.__name__)
def test_each_refusal_is_a_graphmech_error_and_its_builtin(cls):
    e = cls("the pole distance H must be positive and finite, not 0.0")
    assert isinstance(e, GraphmechError) and isinstance(e, BUILTIN_OF[cls])
    # not a construction step or a scene problem: the handlers of those (efficiency, forces,
    # flywheel and cam checks) must not start catching what used to pass through them
    assert not isinstance(e, (DegenerateConstruction, SceneError))
    assert cls.__doc__ and cls.__module__ == "graphmech.errors"
    with pytest.raises(BUILTIN_OF[cls]):
        raise e


def test_every_error_class_of_the_module_is_a_graphmech_error():
    classes = {v for v in vars(errors).values() if isinstance(v, type) and issubclass(v, BaseException)}
    assert classes == {GraphmechError, SceneError, DegenerateConstruction, AssemblyError, *BUILTIN_OF}
    assert all(issubclass(c, GraphmechError) and c.__doc__ for c in classes)


def test_the_errors_defined_beside_their_methods_are_graphmech_errors_too():
    from graphmech.exact.true_motion import TrueMotionError
    from graphmech.methods.flywheel import WrongBalance

    assert issubclass(WrongBalance, OutOfDomain) and issubclass(WrongBalance, ValueError)
    assert issubclass(TrueMotionError, GraphmechError) and issubclass(TrueMotionError, ValueError)
    assert WrongBalance("no constant driving moment", 12.5).work == 12.5


def test_an_unknown_name_prints_its_message_not_a_quoted_key():
    e = UnknownName("no point 'X' in the linkage")
    assert str(e) == "no point 'X' in the linkage"
    assert str(KeyError("no point 'X' in the linkage")) == "\"no point 'X' in the linkage\""  # what it avoids
    assert e.args == ("no point 'X' in the linkage",) and repr(e) == "UnknownName(\"no point 'X' in the linkage\")"
    assert str(UnknownName()) == "" and str(UnknownName("a", "b")) == "('a', 'b')"


def test_the_construction_errors_say_step_reason_and_position():
    e = DegenerateConstruction("c = ⟂BC through b ∩ ⟂DC through p", "the lines are parallel", "φ1 = 170°")
    assert str(e) == "c = ⟂BC through b ∩ ⟂DC through p: the lines are parallel at φ1 = 170°"
    a = AssemblyError("dyad BCD", "|BD| = 0.21 m > l2 + l3 = 0.2 m", "φ₁ = 170°")
    assert str(a) == "dyad BCD: cannot be assembled at φ₁ = 170°: |BD| = 0.21 m > l2 + l3 = 0.2 m"
    assert isinstance(a, ArithmeticError) and (a.step, a.position) == ("dyad BCD", "φ₁ = 170°")


def test_a_scene_error_is_one_printable_line_under_its_file():
    e = SceneError([("driver.omega", "must be finite"), ("dyad[0].lengths", "must be > 0")], "linkage")
    assert e.one_line("s.toml") == "s.toml: linkage: driver.omega: must be finite (and 1 more)"
    assert SceneError([("find[0]", "no point 'A\nB'")], "s.toml").one_line("s.toml") == \
        "s.toml: find[0]: no point 'A\\nB'"
    assert printable("v_C\x1b[31m") == "v_C\\x1b[31m"


# ---------------------------------------------------------------------------- real refusals


def test_the_methods_refuse_with_their_own_errors():
    from graphmech.exact.balancing import dynamic_correction
    from graphmech.exact.cam import initial_rocker_angle
    from graphmech.exact.characteristics import guide_bar
    from graphmech.exact.true_motion import braking_time
    from graphmech.mechanisms.cam import DiscCam, MotionProgram, Segment, TranslatingFollower
    from graphmech.methods.graphical_integration import differentiate_by_ray
    from graphmech.scales import round_scale

    with pytest.raises(OutOfDomain, match=r"^a scale must be positive and finite, not 0\.0$"):
        round_scale(0.0)
    with pytest.raises(OutOfDomain, match=r"^J, ω0 and the braking moment must all be > 0$"):
        braking_time(0.0, 10.0, 5.0)
    with pytest.raises(OutOfDomain, match=r"^the correction planes coincide$"):
        dynamic_correction([], 0.1, 0.1)
    with pytest.raises(NotApplicable, match=r"^the bar turns fully \(crank 20 ≥ frame 10\)"):
        guide_bar(0j, 10 + 0j, 20.0)
    program = MotionProgram(0.01, (Segment("rise", math.pi, "sine"), Segment("return", math.pi, "sine")))
    with pytest.raises(WrongKind, match=r"^the rocker angle belongs to an oscillating follower$"):
        initial_rocker_angle(DiscCam(0.03, TranslatingFollower(), program))
    with pytest.raises(ValueError, match=r"pole distance H must be positive and finite, not 0"):
        differentiate_by_ray(10.0, 5.0, 0.0)  # still a ValueError to an old caller


# ---------------------------------------------------------------------------- no bare built-in raise

BUILTIN_EXCEPTIONS = {n for n, v in vars(builtins).items() if isinstance(v, type) and issubclass(v, BaseException)}

#: The built-in raises left outside methods/ and exact/: each a programming error of ours (an
#: invariant that a reader or a method checks first), never a refusal a user meets; a new one fails.
ALLOWED_ELSEWHERE = {
    # a construction names a step twice, reads one not defined yet, prunes to an unknown one
    ("graphmech/construction/graph.py", "KeyError"): 3,
    # not a draw primitive; a polyline of < 2 or non-finite points (the methods refuse those first)
    ("graphmech/drawing/diagrams.py", "TypeError"): 1,
    ("graphmech/drawing/primitives.py", "ValueError"): 2,
    # the file system's own refusal: the command maps OSError to exit 2 with the path
    ("graphmech/files.py", "OSError"): 1,  # a folder that refuses a new file (named as given, not the temporary file)
    ("graphmech/files.py", "FileNotFoundError"): 1,  # the folder to write in is missing: an OSError the command reports
    ("graphmech/files.py", "IsADirectoryError"): 1,  # a folder given as the file to write
    # a motion law validate() has rejected first
    ("graphmech/mechanisms/motion.py", "AssertionError"): 1,
    # a bare `raise ValueError` caught on the next line (a name's "@" part is not a number)
    ("graphmech/problems/cam/check.py", "ValueError"): 1,
    # a requested name with no row, an exact quantity spec we built ourselves
    ("graphmech/problems/flywheel/check.py", "KeyError"): 1,
    ("graphmech/problems/linkage/check.py", "ValueError"): 1,
    # the renderer's invariants: primitives, panels, style keys, the SVG backend's call order
    ("graphmech/render/labels.py", "ValueError"): 1,
    ("graphmech/render/layout.py", "TypeError"): 1,
    ("graphmech/render/layout.py", "ValueError"): 3,
    ("graphmech/render/scalebar.py", "ValueError"): 2,  # a panel's scale: a known symbol, μ > 0
    ("graphmech/render/sheet.py", "TypeError"): 1,
    ("graphmech/render/sheet.py", "ValueError"): 1,
    ("graphmech/render/style.py", "KeyError"): 1,
    ("graphmech/render/svg.py", "RuntimeError"): 10,
    ("graphmech/render/svg.py", "ValueError"): 3,
    # a drawing asked to letter NaN or ∞: a programming error (the methods refuse such input)
    ("graphmech/drawing/lettering.py", "ValueError"): 1,
    # PEP 562: a module's __getattr__ answers a missing name with AttributeError (hasattr relies on it)
    ("graphmech/__init__.py", "AttributeError"): 1,
    # the Python API given a plainly wrong Python type (a list for a dict): Python's own convention
    ("graphmech/api.py", "TypeError"): 4,
}


def bare_builtin_raises() -> Counter[tuple[str, str]]:
    """(file, built-in) → how many ``raise X`` / ``raise X(...)`` with X a built-in exception."""
    found: Counter[tuple[str, str]] = Counter()
    for path in sorted((ROOT / "graphmech").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Raise) and node.exc is not None:
                f = node.exc.func if isinstance(node.exc, ast.Call) else node.exc
                if isinstance(f, ast.Name) and f.id in BUILTIN_EXCEPTIONS:
                    found[(path.relative_to(ROOT).as_posix(), f.id)] += 1
    return found


def test_the_methods_and_the_exact_solutions_raise_no_bare_builtin():
    found = bare_builtin_raises()
    inside = {k: n for k, n in found.items() if k[0].startswith(("graphmech/methods/", "graphmech/exact/"))}
    assert not inside, inside
    assert sum(found.values()) > 0  # the scan sees raises at all (the renderer's invariants)


def test_elsewhere_only_the_named_programming_errors_stay_builtin():
    over = {k: n for k, n in bare_builtin_raises().items() if n > ALLOWED_ELSEWHERE.get(k, 0)}
    assert not over, f"a new bare built-in raise (use graphmech.errors, or name it here with why): {over}"
    assert sum(ALLOWED_ELSEWHERE.values()) == 42


# ---------------------------------------------------------------------------- through the command


@pytest.mark.parametrize("cls", BUILTIN_OF, ids=lambda c: c.__name__)
def test_a_refusal_inside_a_method_reaches_the_user_as_exit_2_one_line(monkeypatch, cls):
    import graphmech.methods.flywheel as flywheel

    def refuse(*args, **kwargs):
        raise cls("no point 'P\nQ' in the flywheel's machine")  # a user's name with a line break

    monkeypatch.setattr(flywheel, "design_flywheel", refuse)  # check imports it when it runs
    err = assert_refused(run_cli("check", str(SCENES / "fly.ic_engine_flywheel.toml")), "fly.ic_engine_flywheel.toml")
    assert err == "fly.ic_engine_flywheel.toml: no point 'P\\nQ' in the flywheel's machine"


def test_a_real_method_refusal_reaches_the_user_as_exit_2(monkeypatch):
    """The method's own check, its own words: the balance passed on as the scene never spells it."""
    import graphmech.methods.flywheel as flywheel

    real = flywheel.design_flywheel
    monkeypatch.setattr(flywheel, "design_flywheel", lambda *a, **k: real(*a, **{**k, "balance": "both"}))
    err = assert_refused(run_cli("check", str(SCENES / "fly.ic_engine_flywheel.toml")), "fly.ic_engine_flywheel.toml")
    assert err.endswith(": balance must be 'driving' or 'resisting', not 'both'")
    # a bare built-in from the same place is still a bug of ours: exit 3, "internal error"
    monkeypatch.setattr(flywheel, "design_flywheel", lambda *a, **k: (_ for _ in ()).throw(ValueError("x")))
    code, out, err = run_cli("check", str(SCENES / "fly.ic_engine_flywheel.toml"))
    assert code == 3 and "internal error (ValueError: x)" in err


def test_a_subnormal_inertia_is_refused_by_its_key(tmp_path):
    """Fuzz find: inertia_kgm2 = 5e-324 reached round_scale as 0.0 (exit 3, "a scale must be positive")."""
    text = (SCENES / "fly.ic_engine_flywheel.toml").read_text(encoding="utf-8")
    assert "\ninertia_kgm2 = 0\n" in text
    scene = tmp_path / "fly.toml"
    scene.write_text(text.replace("\ninertia_kgm2 = 0\n", "\ninertia_kgm2 = 5e-324\n"), encoding="utf-8")
    for argv in (("check", str(scene)), ("render", str(scene), "-o", str(tmp_path / "fly.svg"))):
        err = assert_refused(run_cli(*argv), "fly.toml", "flywheel.inertia_kgm2: must be 0 or at least 2.23e-308")
    assert not (tmp_path / "fly.svg").exists()
    scene.write_text(text.replace("\ninertia_kgm2 = 0\n", "\ninertia_kgm2 = 1e-300\n"), encoding="utf-8")
    code, _, err = run_cli("check", str(scene))
    assert code == 0, err  # a tiny but normal inertia is still a machine
