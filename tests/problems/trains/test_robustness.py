"""Hostile and extreme gear-train scenes: each refusal one line naming the key, each extreme case
(a converted ratio of 1, a 10⁶ reducer, a worm of many starts, a wrong mobility, identical planets)
said or solved."""
from __future__ import annotations

import math
import tomllib

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphmech.errors import GraphmechError, SceneError
from graphmech.problems import check
from tests.conftest import SCENES, assert_refused, check_json, run_cli, values
from tests.mutation import mutate, scene_or_refusal, toml_values

train_values = toml_values(["external", "internal", "bevel", "worm", "right", "left", "coaxial", "+x", "-y", "+z",
                            "H", "1", "2", "2'", "3", 0, 1, 2, -1, 100000, 1e300, 0.5], max_leaves=10)

SIMPLE = """
find = {find}
[train]
z = {{ "1" = 20, "2" = 40 }}
{extra}
[[train.mesh]]
gears = ["1", "2"]
{mesh}
[[train.input]]
member = "1"
speed_rpm = 100
"""

#: sun 1 (20) – double planet 2 (30) / 2' (30) – sun 3 (20), two external meshes: i^H_13 = +1.
LOCKING = """
find = ["nH"]
[train]
fixed = ["3"]
z = { "1" = 20, "2" = 30, "2'" = 30, "3" = 20 }
[[train.member]]
name = "2"
gears = ["2", "2'"]
carrier = "H"
[[train.member]]
name = "H"
gears = []
[[train.mesh]]
gears = ["1", "2"]
[[train.mesh]]
gears = ["2'", "3"]
[[train.input]]
member = "1"
speed_rpm = 100
"""


def write(tmp_path, text, name="t.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def test_a_converted_ratio_of_one_locks_the_train(tmp_path):
    err = assert_refused(run_cli("check", str(write(tmp_path, LOCKING))), "t.toml", "the train locks",
                         "i^H_1,3 = 1 with 3 fixed")
    assert "cannot be driven" in err


def test_a_ratio_of_a_million(tmp_path):
    text = """
find = ["i13", "n3"]
[train]
z = { "1" = 1, "2" = 1000, "2'" = 1, "3" = 1000 }
[[train.member]]
name = "2"
gears = ["2", "2'"]
axis = "+z"
[[train.member]]
name = "3"
axis = "+x"
[[train.mesh]]
gears = ["1", "2"]
kind = "worm"
hand = "right"
towards = ["+y", "-y"]
[[train.mesh]]
gears = ["2'", "3"]
kind = "worm"
hand = "right"
towards = ["+y", "-y"]
[[train.input]]
member = "1"
speed_rpm = 1000000
"""
    q = values(check_json(write(tmp_path, text)))
    # worm 1 (+x) into wheel 2 (+z) below it: (+z) × (−y) = +x, against the right thumb: −1000;
    # worm 2' (+z) into wheel 3 (+x): (+x) × (−y) = −z, with the right thumb: +1000
    assert q["i13"]["graphical"] == q["i13"]["exact"] == -1e6
    assert q["n3"]["graphical"] == pytest.approx(-1.0, rel=1e-15)


@pytest.mark.parametrize("starts, wheel", [(1, 40), (4, 60), (10, 30), (45, 50)])
def test_a_worm_with_many_starts(tmp_path, starts, wheel):
    text = f"""
find = ["i12"]
[train]
z = {{ "1" = {starts}, "2" = {wheel} }}
[[train.member]]
name = "2"
axis = "+z"
[[train.mesh]]
gears = ["1", "2"]
kind = "worm"
hand = "left"
towards = ["+y", "-y"]
[[train.input]]
member = "1"
speed_rpm = 1450
"""
    q = values(check_json(write(tmp_path, text)))
    # left hand, worm along +x turning +: the wheel's pitch point (below its +z axis... at −y) moves
    # along +x, and (+z) × (−y) = +x: the wheel turns + too
    assert q["i12"]["graphical"] == q["i12"]["exact"] == wheel / starts


def test_a_wrong_mobility_is_said_in_one_line(tmp_path):
    text = LOCKING.replace('fixed = ["3"]', "mobility = 1").replace("\n[[train.input]]", "\n[[train.input]]", 1)
    assert_refused(run_cli("check", str(write(tmp_path, text))), "t.toml",
                   "train.mobility: the meshes give mobility 2 (a differential: two inputs), not 1")


def test_too_few_inputs_for_a_differential(tmp_path):
    text = LOCKING.replace('fixed = ["3"]', "")
    assert_refused(run_cli("check", str(write(tmp_path, text))), "t.toml",
                   "train.input: the train has mobility 2 (a differential: two inputs) but 1 input is given")


def test_identical_planets_are_counted_once(tmp_path):
    text = """
find = ["nH", "dof"]
[train]
fixed = ["3"]
z = { "1" = 20, "2a" = 30, "2b" = 30, "2c" = 30, "3" = "coaxial" }
[[train.member]]
name = "2a"
carrier = "H"
[[train.member]]
name = "2b"
carrier = "H"
[[train.member]]
name = "2c"
carrier = "H"
[[train.member]]
name = "H"
gears = []
[[train.mesh]]
gears = ["1", "2a"]
[[train.mesh]]
gears = ["2a", "3"]
kind = "internal"
[[train.mesh]]
gears = ["1", "2b"]
[[train.mesh]]
gears = ["2b", "3"]
kind = "internal"
[[train.mesh]]
gears = ["1", "2c"]
[[train.mesh]]
gears = ["2c", "3"]
kind = "internal"
[[train.input]]
member = "1"
speed_rpm = 500
"""
    doc = check_json(write(tmp_path, text))
    q = values(doc)
    assert q["nH"]["exact"] == 100.0  # i1H = 1 + 80/20
    assert q["nH"]["graphical"] == pytest.approx(100.0, rel=1e-14)  # ℓ × μω off the diagram
    assert q["dof"]["graphical"] == 1 and doc["train"]["redundant_meshes"] == 2  # the second and third planets repeat the first
    _code, out, _ = run_cli("check", str(tmp_path / "t.toml"))
    assert "redundant meshes counted once: 2" in out


@pytest.mark.parametrize("extra, mesh, words", [
    ('[train.z]\n"3" = "coaxial"', "", ["train.z.3: \"coaxial\" needs a planet set to close", "gear 3 meshes no planet"]),
    ("", 'kind = "bevel"\ntowards = ["+x", "-y"]', ["train.mesh[0].towards", "along gear 1's axis"]),
    ("", 'kind = "bevel"\ntowards = ["+y", "+y"]\nsign = 1', ["train.mesh[0].sign", "towards and sign together"]),
    ("", 'kind = "worm"\ntowards = ["+y", "-y"]', ["train.mesh[0].hand", "missing"]),
    ("", 'sign = 1', ["train.mesh[0].sign", "an external mesh's sense comes from its kind"]),
    ("", 'kind = "bevel"', ["train.mesh[0].towards", "missing"]),
    ("", 'kind = "spur"', ["train.mesh[0].kind", "unknown value"]),
])
def test_refusals_name_the_key(tmp_path, extra, mesh, words):
    text = SIMPLE.format(find='["i12"]', extra=extra, mesh=mesh)
    if extra.startswith("[train.z]"):
        text = text.replace('z = { "1" = 20, "2" = 40 }\n', "").replace('[train.z]\n"3"', '[train.z]\n"1" = 20\n"2" = 40\n"3"')
    assert_refused(run_cli("check", str(write(tmp_path, text))), "t.toml", *words)


def test_an_ambiguous_ratio_name(tmp_path):
    text = """
find = ["i1H2"]
[train]
fixed = ["3"]
z = { "1" = 20, "H2" = 30, "2" = 30, "1H" = 20, "3" = 80 }
[[train.member]]
name = "H2"
gears = ["H2", "2"]
carrier = "H"
[[train.member]]
name = "H"
gears = []
[[train.mesh]]
gears = ["1", "H2"]
[[train.mesh]]
gears = ["2", "3"]
kind = "internal"
[[train.mesh]]
gears = ["1H", "2"]
[[train.input]]
member = "1"
speed_rpm = 100
"""
    assert_refused(run_cli("check", str(write(tmp_path, text))), "t.toml",
                   "find[0]: 'i1H2' is ambiguous (1|H2, 1H|2); write i1_H2")


def test_an_unknown_name_gets_a_suggestion(tmp_path):
    text = SIMPLE.format(find='["n3", "omeg2"]', extra="", mesh="")
    err = assert_refused(run_cli("check", str(write(tmp_path, text))), "t.toml", "find[0]", "unknown gear-train quantity")
    assert "find[1]" in err or "(and 1 more)" in err


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data())
def test_any_mutation_of_a_bank_train_checks_or_is_refused_in_one_line(data):
    stem = data.draw(st.sampled_from(sorted(p.stem for p in SCENES.glob("train.*.toml"))))
    base = tomllib.loads((SCENES / f"{stem}.toml").read_text(encoding="utf-8"))
    scene = scene_or_refusal(mutate(data, base, train_values, most=2))
    if scene is None:
        return
    assert all(1 <= g.z <= 100_000 for g in scene.problem.train.gears)
    try:
        an, _, _, _ = check(scene)
        for r in an.rows:
            assert math.isfinite(r.graphical) and math.isfinite(r.exact)
            assert r.rel_error <= 1e-9, r  # the split and the linear system agree whatever the train
    except GraphmechError as err:
        text = err.one_line(scene.source) if isinstance(err, SceneError) else str(err)
        assert "\n" not in text and text


#: sun 1 – planet 2 on carrier H – ring 3 fixed: the hostile inputs below each change one thing.
PLANETARY = """
find = ["nH"]
[train]
fixed = ["3"]
z = { "1" = 20, "2" = 30, "3" = 80 }
[[train.member]]
name = "2"
carrier = "H"
[[train.member]]
name = "H"
gears = []
[[train.mesh]]
gears = ["1", "2"]
[[train.mesh]]
gears = ["2", "3"]
kind = "internal"
[[train.input]]
member = "1"
speed_rpm = 100
"""
WORM_EFF = """
find = ["eta_train"]
[train]
z = { "1" = 1, "2" = 40 }
[[train.member]]
name = "2"
axis = "+z"
[[train.mesh]]
gears = ["1", "2"]
kind = "worm"
hand = "right"
towards = ["+y", "-y"]
[[train.input]]
member = "1"
speed_rpm = 1450
[train.efficiency]
eta_mesh = 0.9
output = "2"
[[train.efficiency.worm]]
"""
DYN = PLANETARY + """
[train.dynamics]
reduce_to = "1"
[[train.dynamics.member]]
name = "H"
"""


def _chain(n: int) -> str:
    z = ", ".join(f'"{i}" = 20' for i in range(1, n + 1))
    meshes = "".join(f'[[train.mesh]]\ngears = ["{i}", "{i + 1}"]\n' for i in range(1, n))
    return f'[train]\nz = {{ {z} }}\n{meshes}[[train.input]]\nmember = "1"\nspeed_rpm = 100\n'


def _swap(text: str, old: str, new: str) -> str:
    assert old in text, old
    return text.replace(old, new, 1)


HOSTILE = {
    # a planet held in the frame or driven (a KeyError in the split before)
    "planet fixed": (_swap(PLANETARY, 'fixed = ["3"]', 'fixed = ["3", "2"]'),
                     ("train.fixed[1]: member 2 is a planet of H: its axis moves with the carrier, it cannot be held "
                     "in the frame")),
    "planet driven": (_swap(PLANETARY, 'member = "1"', 'member = "2"'),
                      "train.input[0].member: member 2 is a planet of H: drive its carrier or a central gear"),
    # a planet meshing a gear on its own arm (an unsolvable converted train, said without a key before)
    "planet meshes its carrier's gear": (_swap(PLANETARY, 'carrier = "H"', 'carrier = "1"'),
                                         ("train.mesh[0].gears: gear 1 is on 2's own carrier 1: a planet meshes a gear "
                                         "coaxial with its carrier, not one on its arm")),
    "two gears mesh twice": (SIMPLE.format(find='["i12"]', extra="", mesh='[[train.mesh]]\ngears = ["2", "1"]\n'
                                                                         'kind = "internal"'),
                             "train.mesh[1].gears: gears 2 and 1 already mesh in train.mesh[0]"),
    "a fixed member twice": (_swap(PLANETARY, 'fixed = ["3"]', 'fixed = ["3", "3"]'),
                             "train.fixed[1]: member 3 is listed twice"),
    "a coaxial pair of one member": (_swap(PLANETARY, "[train]\n", '[train]\ncoaxial = [["1", "1"]]\n'),
                                     "train.coaxial[0]: a pair of two members, not 1 twice"),
    "a coaxial pair twice": (_swap(PLANETARY, "[train]\n", '[train]\ncoaxial = [["1", "3"], ["3", "1"]]\n'),
                             "train.coaxial[1]: 3 and 1 are listed twice"),
    "no meshes": (SIMPLE.format(find='["n1"]', extra="mesh = []", mesh="").replace('[[train.mesh]]\ngears = ["1", "2"]\n', ""),
                  "train.mesh: no [[train.mesh]]: a train needs its meshes"),
    # 1.7e308 r/min overflowed to inf in rad/s: "train: the input speed of 1 is a finite number, not inf"
    "an input beyond double precision": (_swap(PLANETARY, "speed_rpm = 100", "speed_rpm = 1.7e308"),
                                         ("train.input[0].speed_rpm: 1.7e+308 r/min is faster than the work limit of "
                                         "1e+12 rad/s (the powers and reduced moments would leave double precision)")),
    "a list input too fast": (_swap(PLANETARY, "speed_rpm = 100", "speed_rad_s = [1, 1e300]"),
                              ("train.input[0].speed_rad_s[1]: 1e+300 rad/s is faster than the work limit of 1e+12 "
                              "rad/s (the powers and reduced moments would leave double precision)")),
    "61 gears": (_chain(61), "train.z: too many gears (61 > 60, the work limit of a train)"),
    # a ratio to a member at rest: said at the name asked (no key before)
    "a ratio to the fixed member": (_swap(PLANETARY, 'find = ["nH"]', 'find = ["nH", "i13"]'),
                                    "find[1]: i13 has no value: 3 is at rest"),
    "a ratio to a member stopped": (_swap(_swap(PLANETARY, 'find = ["nH"]', 'find = ["i1H"]'), "speed_rpm = 100",
                                          "speed_rpm = 0"),
                                    "find[0]: i1H has no value: H is at rest"),
    # worms and bevels whose arrows cannot be drawn
    "a worm's pitch point not between the axes": (
        SIMPLE.format(find='["i12"]', extra='[[train.member]]\nname = "2"\naxis = "+z"',
                      mesh='kind = "worm"\nhand = "right"\ntowards = ["+y", "+y"]'),
        ("train.mesh[0].towards: the pitch point lies between the axes: from wheel 2's axis toward +y, so from worm "
        "1's toward the opposite, not +y")),
    "a bevel pair on parallel axes": (
        SIMPLE.format(find='["i12"]', extra='[[train.member]]\nname = "2"\naxis = "-x"',
                      mesh='kind = "bevel"\ntowards = ["+y", "-y"]'),
        ("train.mesh[0].towards: a bevel pair's axes meet at an angle: 1 (+x) and 2 (-x) are parallel (an external "
        "or internal mesh)")),
    # efficiency and dynamics tables beyond double precision (η = 1e-300 raised an OverflowError)
    "a mesh efficiency of 1e-300": (PLANETARY + '[train.efficiency]\neta_mesh = 1e-300\noutput = "H"\n',
                                    ("train.efficiency.eta_mesh: 1e-300 is below 0.01, the poorest mesh efficiency "
                                    "read (such a mesh transmits nothing)")),
    "a worm's q of 1e-300": (WORM_EFF + "q = 1e-300\nf_v = 0.1\n",
                             ("train.efficiency.worm[0].q: 1e-300 gives a lead angle of 90°: a lead angle lies "
                             "between 0° and 90°")),
    "a worm's f_v of 1e300": (WORM_EFF + "q = 10\nf_v = 1e300\n",
                              ("train.efficiency.worm[0].f_v: 1e+300 makes the friction angle 90°: a friction angle "
                              "lies in [0°, 90°)")),
    "a moment of -1e308": (DYN + "moment_Nm = -1e308\n",
                           ("train.dynamics.member[0].moment_Nm: -1e+308 in SI units is beyond the work limit of 1e+15 "
                           "(reduced through the train, it would leave double precision)")),
}


@pytest.mark.parametrize("case", sorted(HOSTILE))
def test_a_hostile_train_is_refused_in_one_line(tmp_path, case):
    text, line = HOSTILE[case]
    for command in (["check"], ["check", "--json"], ["steps"]):
        err = assert_refused(run_cli(*command, str(write(tmp_path, text))), "t.toml")
        assert err == f"t.toml: {line}", (command, err)
    out = tmp_path / "t.svg"
    if case.startswith("a ratio to"):  # a find name's value: the figures do not need it
        return
    assert_refused(run_cli("render", str(tmp_path / "t.toml"), "-o", str(out)), "t.toml")
    assert not out.exists()


def test_a_train_at_the_work_limit_checks():
    from graphmech.problems.trains.scene import MAX_GEARS

    doc = tomllib.loads(f'find = ["n{MAX_GEARS}"]\n' + _chain(MAX_GEARS))
    from graphmech.scene import parse_scene

    an, _, _, _ = check(parse_scene(doc, "t.toml"))
    # 59 external meshes of equal gears: the last turns against the first, as fast
    assert [(r.name, r.exact) for r in an.rows] == [(f"n{MAX_GEARS}", pytest.approx(-100.0, rel=1e-12))]


def test_a_subnormal_input_speed_is_refused_at_its_key(tmp_path):
    """−5e-324 rad/s (found by a mutation campaign: the reduced inertia divided by ω² = 0): the
    speeds through the train would keep a digit or none."""
    p = write(tmp_path, SIMPLE.format(find='["n2"]', extra="", mesh="").replace("speed_rpm = 100", "speed_rad_s = -5e-324"))
    code, out, err = run_cli("check", str(p))
    assert (code, out) == (2, "")
    assert err == ("t.toml: train.input[0].speed_rad_s: -4.94066e-324 rad/s is slower than 1e-200 rad/s: the train's "
                   "speeds would underflow double precision (0 is at rest)\n")
