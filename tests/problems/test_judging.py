"""Judging (graphmech/problems/judging.py): a check table's rows, a hand measurement's verdict
within the drawing precision × μ, a value as written judged as a teacher does (significant
figures, sign), names with a position, drawn segments, and values that leave double precision
refused in words."""
from __future__ import annotations

import json
import math
from types import SimpleNamespace

import numpy as np
import pytest

from graphmech.accuracy import CONSTRUCTION
from graphmech.errors import DegenerateConstruction
from graphmech.problems.judging import (OUT_OF_RANGE, Row, Verdict, as_written, close_names, finite,
                                        in_double_precision, is_segment, judge_value, judge_written, measured_entries,
                                        refuse_non_finite, split_name)
from graphmech.problems.reader import Written
from tests.conftest import SCENES, assert_refused, run_cli

#: pc = 43.36 mm at μv = 0.02 (m/s)/mm: v_C = 0.8672 m/s against the exact 0.86713 m/s.
PC = Row("v_C@50", "m/s", 43.36, 0.02, 0.8672, 0.86713, 8.1e-5)


def test_a_row_is_a_construction_until_it_carries_its_own_estimate():
    assert PC.error_source == CONSTRUCTION and PC.error_estimate is None and not PC.ill_conditioned
    chord = PC.estimated("chords", 0.016, "12 positions")
    assert (chord.error_source, chord.error_estimate, chord.basis) == ("chords", 0.016, "12 positions")
    assert chord.graphical == PC.graphical and PC.error_source == CONSTRUCTION  # a new row; the old one unchanged
    assert list(PC.as_dict()) == ["name", "unit", "drawn_mm", "scale", "graphical", "exact", "rel_error",
                                  "ill_conditioned", "error_source", "error_estimate", "basis"]
    assert PC.as_dict()["drawn_mm"] == 43.36


def test_a_length_off_the_drawing_is_judged_within_the_precision_times_mu():
    """0.5 mm at μv = 0.02 (m/s)/mm: ± 0.01 m/s about 0.86713."""
    ok = judge_value("v_C", 0.876, 0.86713, 43.36, 0.02, 0.5, "m/s")
    assert ok == Verdict("v_C", 0.876, 0.86713, pytest.approx(0.01), True, "m/s")
    assert not judge_value("v_C", 0.878, 0.86713, 43.36, 0.02, 0.5, "m/s").ok
    assert judge_value("v_C", 0.86713 - 0.01, 0.86713, 43.36, -0.02, 0.5, "m/s").ok  # |μ|, the edge included


def test_a_computed_value_is_judged_within_a_thousandth():
    v = judge_value("omega_3", 2.502, 2.5, None, 1.0, 0.5, "rad/s")
    assert v.tolerance == pytest.approx(0.0025) and v.ok
    assert not judge_value("omega_3", 2.503, 2.5, None, 1.0, 0.5, "rad/s").ok
    zero = judge_value("v_C", 0.0, 0.0, None, 1.0, 0.5, "m/s")
    assert zero.ok and zero.tolerance > 0.0  # a zero expected value still has a tolerance
    assert zero.as_dict() == {"name": "v_C", "measured": 0.0, "expected": 0.0, "tolerance": zero.tolerance,
                              "ok": True, "unit": "m/s"}


def test_names_split_at_the_position():
    assert split_name("v_C@50") == ("v_C", "50")
    assert split_name("omega_2") == ("omega_2", None)
    assert split_name("v_C_diagram@1.5") == ("v_C_diagram", "1.5")


@pytest.mark.parametrize("name, segment", [
    ("pc", True), ("p'c'", True), ("n2'c'", True), ("b′c′", True), ("v_C", False), ("pcd", False), ("p", False),
    ("omega", False),
])
def test_a_drawn_segment_is_named_by_its_two_end_letters(name, segment):
    assert is_segment(name) is segment


def test_close_names_suggest_up_to_three():
    assert close_names("omega_4", ["omega_2", "omega_3", "v_C"]) == "; did you mean omega_3, omega_2?"  # best first
    assert close_names("zzz", ["v_C"]) == ""


def test_measured_entries_keep_where_each_value_came_from():
    scene = SimpleNamespace(measured=(("pc", 43.0), ("omega_3@30", -2.5)))
    assert measured_entries(scene, (("v_C", 0.86),)) == [
        ("measured.pc", "pc", 43.0), ("measured.omega_3@30", "omega_3@30", -2.5), ("--measured v_C", "v_C", 0.86)]


def test_numbers_out_of_double_precision_are_said_in_one_line():
    with in_double_precision("J_F"):
        assert np.isinf(np.float64(1e300) * 1e300)  # numpy quiet
    with pytest.raises(DegenerateConstruction) as info:
        with in_double_precision("J_F"):
            raise OverflowError("(34, 'Numerical result out of range')")
    assert OUT_OF_RANGE in str(info.value) and "J_F" in str(info.value)


def test_a_row_that_is_not_finite_is_refused_by_name():
    refuse_non_finite([PC])
    with pytest.raises(DegenerateConstruction, match="J_F"):
        refuse_non_finite([Row("J_F", "kg·m²", None, 1.0, math.inf, 1.0, 0.0)])
    with pytest.raises(DegenerateConstruction, match="its error estimate left double precision"):
        refuse_non_finite([PC.estimated("chords", math.nan, "12 positions")])
    an = SimpleNamespace(rows=[PC])
    assert finite(an) is an
    with pytest.raises(DegenerateConstruction):
        finite(SimpleNamespace(rows=[Row("x", "m", None, 1.0, 1.0, math.nan, 0.0)]))


# ---------------------------------------------------------------- values as written (a teacher's judging)

#: ψ of the fine thread M20×1.5 (001, 10-2: d2 = 19.026 mm, P = 1.5 mm), the book's "1.44°".
PSI = math.degrees(math.atan(1.5 / (math.pi * 19.026)))
FINE = SCENES / "thread.m20_lead_angles-fine.toml"
FLY = SCENES / "fly.ic_engine_flywheel.toml"
SLIDER = SCENES / "linkage.slider_crank_offset.toml"


@pytest.mark.parametrize("text, value, figures, half, signed", [
    ("1.44", 1.44, 3, 0.005, False), ("1.440", 1.44, 4, 0.0005, False), ("0.0120", 0.012, 3, 0.00005, False),
    ("1440", 1440.0, 4, 0.5, False),  # every written digit counts
    ("1.44e3", 1440.0, 3, 5.0, False), ("1.44E-2", 0.0144, 3, 0.00005, False),
    ("+2.17", 2.17, 3, 0.005, True), ("-2.17", -2.17, 3, 0.005, True), (" 116.67 ", 116.67, 5, 0.005, False),
    (".5", 0.5, 1, 0.05, False), ("0.00", 0.0, 0, 0.005, False),
])
def test_a_written_value_keeps_its_figures_its_last_place_and_its_sign(text, value, figures, half, signed):
    w = Written(text)
    assert (float(w), w.figures, w.signed) == (value, figures, signed) and w.half_unit == pytest.approx(half, rel=1e-12)
    assert w.text == text.strip() and repr(w) == f"Written({text.strip()!r})"


@pytest.mark.parametrize("text", ["abc", "1,44", "1.4.4", "0x10", "1_000", "", ".", "+", "1.44 deg", "nan", "inf",
                                  "-Infinity", "1e400"])
def test_what_is_no_finite_number_as_written_is_refused(text):
    with pytest.raises(ValueError, match="must be a finite number"):
        Written(text)


def test_a_written_value_survives_a_trip_to_a_worker():
    import pickle

    w = pickle.loads(pickle.dumps(Written("-1.440")))
    assert isinstance(w, Written) and (w.text, w.figures, w.signed) == ("-1.440", 4, True)


def test_three_figures_are_judged_by_their_rounding():
    """ψ = 1.43756°: the book's 1.44 is right, 1.43 is not; 1.4376 is judged to 5 s.f."""
    right = judge_written("psi", Written("1.44"), PSI, None, "deg")
    assert right.ok and right.tolerance == 0.005 and right.rule == "rounding to 3 s.f., magnitude only"
    assert not judge_written("psi", Written("1.43"), PSI, None, "deg").ok
    five = judge_written("psi", Written("1.4376"), PSI, None, "deg")
    assert five.ok and five.tolerance == pytest.approx(5e-5) and five.rule.startswith("rounding to 5 s.f.")
    assert not judge_written("psi", Written("1.4377"), PSI, None, "deg").ok  # right to 0.1 %, wrong to 5 s.f.
    assert not judge_written("psi", Written("1.440"), PSI, None, "deg").ok  # the trailing zero claims 4 s.f.


@pytest.mark.parametrize("text, exact, ok", [
    ("1.44", 1.435, True), ("1.43", 1.435, True),  # a tie: right whichever way it was rounded
    ("1.44", 1.4349, False), ("1.43", 1.4351, False), ("1.44", 1.4449, True), ("1.44", 1.4451, False),
    ("1.000", 0.99951, True), ("1.000", 0.99949, False),  # across a power of ten: the interval, not the rounding
    ("1440", 1440.49, True), ("1440", 1440.51, False), ("1.44e3", 1444.9, True), ("1.44e3", 1445.1, False),
    ("0.00", 0.004, True), ("0.00", 0.006, False),
])
def test_half_a_unit_of_the_last_written_digit_both_ends_included(text, exact, ok):
    assert judge_written("x", Written(text), exact, None, "").ok is ok


def test_a_magnitude_is_accepted_unless_a_sign_is_written():
    """Mr = −116.667 N·m (000, 飞轮 4): the book's 116.67 is its magnitude."""
    mr = -350.0 / 3.0
    bare = judge_written("Mr", Written("116.67"), mr, None, "N·m")
    assert bare.ok and bare.rule == "rounding to 5 s.f., magnitude only" and bare.expected == mr
    assert judge_written("Mr", Written("-116.67"), mr, None, "N·m").rule.endswith("sign checked")
    assert judge_written("Mr", Written("-116.67"), mr, None, "N·m").ok
    assert not judge_written("Mr", Written("+116.67"), mr, None, "N·m").ok
    assert judge_written("w", Written("+2.17"), 2.16896, None, "rad/s").ok
    assert not judge_written("w", Written("-2.17"), 2.16896, None, "rad/s").ok


def test_a_reading_off_the_drawing_is_never_judged_finer_than_the_drawing():
    """v_C = 0.86713 m/s read at μv = 0.02 (m/s)/mm, ±0.5 mm: ±0.01 m/s, wider than 0.876's ±0.0005."""
    v = judge_value("v_C", Written("0.876"), 0.86713, 43.36, 0.02, 0.5, "m/s")
    assert v.ok and v.tolerance == pytest.approx(0.01) and v.rule == "drawing precision, magnitude only"
    assert not judge_value("v_C", Written("0.878"), 0.86713, 43.36, 0.02, 0.5, "m/s").ok
    coarse = judge_value("v_C", Written("0.9"), 0.86713, 43.36, 0.02, 0.5, "m/s")  # fewer digits than it reads
    assert coarse.ok and coarse.tolerance == 0.05 and coarse.rule == "rounding to 1 s.f., magnitude only"
    computed = judge_value("omega_3", Written("2.502"), 2.5, None, 1.0, 0.5, "rad/s")  # 0.1 % would take it
    assert not computed.ok and computed.rule == "rounding to 4 s.f., magnitude only"


def test_a_kinds_verdict_is_judged_again_only_for_a_written_value():
    plain = Verdict("alpha", 30.2, 30.0, 0.3, True, "deg")
    assert as_written(plain) is plain
    count = Verdict("F", Written("1"), -1.0, 0.0, False, "")  # a count is exact, whatever its sign
    assert as_written(count) is count
    again = as_written(Verdict("alpha", Written("-30.2"), -30.0, 0.3, True, "deg"))
    assert again.ok and again.rule == "drawing precision, sign checked" and again.written == "-30.2"
    for text in ("+359.9", "359.9"):  # the kind judged it across 0°: that stands, sign written or not
        assert as_written(Verdict("alpha", Written(text), -0.1, 0.3, True, "deg")).ok
    assert not as_written(Verdict("alpha", Written("359.9"), -0.1, 0.3, False, "deg")).ok
    assert as_written(again) is again


def test_the_json_of_a_written_value_says_how_it_was_judged_and_a_number_keeps_its_own():
    w = judge_written("psi", Written("1.44"), PSI, None, "deg")
    assert w.as_dict() == {"name": "psi", "measured": 1.44, "expected": PSI, "tolerance": 0.005, "ok": True,
                           "unit": "deg", "written": "1.44", "rule": "rounding to 3 s.f., magnitude only",
                           "significant_figures": 3}
    assert list(judge_value("psi", 1.44, PSI, None, 1.0, 0.5, "deg").as_dict()) == [
        "name", "measured", "expected", "tolerance", "ok", "unit"]


# ---------------------------------------------------------------- the same from the command line and scenes


def _verdict(code_out_err: tuple[int, str, str]) -> dict:
    return json.loads(code_out_err[1])["measured"][0]


@pytest.mark.parametrize("value, code, rule", [
    ("1.44", 0, "rounding to 3 s.f., magnitude only"), ("1.43", 1, "rounding to 3 s.f., magnitude only"),
    ("1.4376", 0, "rounding to 5 s.f., magnitude only"), ("1.4377", 1, "rounding to 5 s.f., magnitude only"),
    ("+1.44", 0, "rounding to 3 s.f., sign checked"), ("-1.44", 1, "rounding to 3 s.f., sign checked"),
    ("1.44e0", 0, "rounding to 3 s.f., magnitude only"),
])
def test_measured_on_the_command_line_is_judged_as_written(value, code, rule):
    result = run_cli("check", str(FINE), "--json", "--measured", f"psi={value}")
    v = _verdict(result)
    assert result[0] == code and (v["written"], v["rule"], v["ok"]) == (value, rule, code == 0)
    assert v["expected"] == pytest.approx(PSI, rel=1e-12)
    text = run_cli("check", str(FINE), "--measured", f"psi={value}")[1].splitlines()[-1]
    assert text.split()[:2] == ["psi", value] and text.endswith(f"(deg; {rule})")


@pytest.mark.parametrize("value", ["abc", "nan", "inf", "1.4.4"])
def test_a_command_line_value_that_is_no_number_is_refused_in_one_line(value):
    assert_refused(run_cli("check", str(FINE), "--measured", f"psi={value}"), "command line", "--measured psi",
                   "must be a finite number")


def _scene(tmp_path, source, measured: str, old: str = "", new: str = ""):
    text = source.read_text(encoding="utf-8")
    if old:
        assert old in text
        text = text.replace(old, new, 1)
    path = tmp_path / "answer.toml"
    path.write_text(text + "\n[measured]\n" + measured + "\n", encoding="utf-8")
    return path


def test_a_toml_string_is_judged_as_written_and_a_toml_number_as_always(tmp_path):
    result = run_cli("check", str(_scene(tmp_path, FINE, 'psi = "1.44"')), "--json")
    assert result[0] == 0 and _verdict(result)["significant_figures"] == 3
    four = run_cli("check", str(_scene(tmp_path, FINE, 'psi = "1.440"')), "--json")
    assert four[0] == 1 and _verdict(four)["tolerance"] == pytest.approx(5e-4)
    number = run_cli("check", str(_scene(tmp_path, FINE, "psi = 1.44")), "--json")  # within 0.1 %? no
    assert number[0] == 1 and "rule" not in _verdict(number)
    assert _verdict(number)["tolerance"] == pytest.approx(PSI * 1e-3)


@pytest.mark.parametrize("value, words", [('"1.44 deg"', "must be a finite number as written"),
                                          ('"nan"', "must be a finite number, not 'nan'"),
                                          ('"-inf"', "must be a finite number, not '-inf'")])
def test_a_toml_string_that_is_no_number_is_refused_naming_its_key(tmp_path, value, words):
    assert_refused(run_cli("check", str(_scene(tmp_path, FINE, f"psi = {value}"))), "answer.toml",
                   "measured.psi", words)


def test_mr_as_the_book_prints_it_is_its_magnitude(tmp_path):
    """fly.ic_engine_flywheel: Mr = −116.67 N·m drawn at μM = 10 (N·m)/mm: the book prints 116.67."""
    bare = _verdict(run_cli("check", str(_scene(tmp_path, FLY, 'Mr = "116.67"')), "--json"))
    assert bare["ok"] and bare["rule"] == "drawing precision, magnitude only" and bare["expected"] < 0
    assert bare["tolerance"] == pytest.approx(5.0)  # 0.5 mm at μM = 10 (N·m)/mm
    signed = run_cli("check", str(_scene(tmp_path, FLY, 'Mr = "+116.67"')), "--json")
    assert signed[0] == 1 and _verdict(signed)["rule"] == "drawing precision, sign checked"
    assert run_cli("check", str(_scene(tmp_path, FLY, "Mr = 116.67")))[0] == 1  # a number keeps its sign
    n = _verdict(run_cli("check", str(FLY), "--json", "--measured", "n_max=623"))  # computed: by its digits
    assert n["ok"] and n["rule"] == "rounding to 3 s.f., magnitude only" and n["tolerance"] == 0.5
    assert run_cli("check", str(FLY), "--measured", "n_max=622")[0] == 1


@pytest.mark.parametrize("omega, value, code", [
    ("10", "-2.17", 0), ("10", "+2.17", 1), ("10", "2.17", 0),
    ("-10", "+2.17", 0), ("-10", "-2.17", 1), ("-10", "2.17", 0),  # the crank turned back: ω2 = +2.169 rad/s
])
def test_the_sign_is_judged_when_written(tmp_path, omega, value, code):
    scene = _scene(tmp_path, SLIDER, f'"omega_2@50" = "{value}"', "omega = 10", f"omega = {omega}")
    result = run_cli("check", str(scene), "--json")
    v = _verdict(result)
    assert result[0] == code and v["expected"] == pytest.approx(-2.16895697 * float(omega) / 10, rel=1e-8)
    assert v["rule"] == "drawing precision, " + ("magnitude only" if value[0].isdigit() else "sign checked")


def test_the_books_flywheel_answers_as_printed_are_right(tmp_path):
    """fly.ic_engine_flywheel-answers (000, 飞轮 4): the book prints Mr = 116.67 N·m (a magnitude),
    ΔWmax = 89.08 J, n_max = 623.1 rpm; as TOML numbers Mr would be out (its sign is −)."""
    path = SCENES / "fly.ic_engine_flywheel-answers.toml"
    result = run_cli("check", str(path), "--json")
    got = {v["name"]: (v["written"], v["ok"], v["rule"]) for v in json.loads(result[1])["measured"]}
    assert result[0] == 0 and got == {"Mr": ("116.67", True, "drawing precision, magnitude only"),
                                      "DeltaW_max": ("89.08", True, "drawing precision, magnitude only"),
                                      "n_max": ("623.1", True, "rounding to 4 s.f., magnitude only")}
    text = path.read_text(encoding="utf-8").replace('Mr = "116.67"', "Mr = 116.67")
    (tmp_path / "numbers.toml").write_text(text, encoding="utf-8")
    assert run_cli("check", str(tmp_path / "numbers.toml"))[0] == 1
