"""The protocol of a gear-train scene (graphmech/problems/trains/steps.py): the coaxial condition,
the split, Willis' equations with numbers, the joins, the values — in three notations."""
from __future__ import annotations

import dataclasses

from graphmech.problems import steps
from graphmech.problems.reader import Page
from graphmech.scene import load_scene
from tests.conftest import SCENES


def test_the_closed_differential_as_the_book_solves_it():
    lines = steps(load_scene(SCENES / "train.closed_differential_n3_n5.toml"))
    assert lines[:3] == ["the coaxial condition (one module): z3 = z1 + z2 + z2' = 80",
                         "the coaxial condition (one module): z5 = z3' + 2·z4 = 100",
                         "split the train: the differential 1-2-2'-3-6-6'-5 (carrier 5); the ordinary train 3'-4-5-7"]
    assert ("in the differential 1-2-2'-3-6-6'-5 (carrier 5), the converted train (carrier held): "
            "i^5_1,3 = (n1 − n5)/(n3 − n5) = −z2·z3/(z1·z2') = −8") in lines
    assert "in the ordinary train 3'-4-5-7: i3',5 = n3'/n5 = −z5/z3' = −5" in lines
    solved = lines.index("solve the equations together")
    assert lines[solved + 4:solved + 6] == ["n5 = 20 r/min", "n3 = −100 r/min"]  # the book's values
    assert lines[-3].startswith("by the velocity diagram (μl = 0.002 m/mm, μv = 0.05 (m/s)/mm)")
    # H chosen for the speeds asked (40 mm): the input's ray is clipped, n5 and n3 long enough to read
    assert lines[-3].endswith("H = 40 mm the rays parallel to them cut the ω line, ω = ℓ·μv/(μl·H) = ℓ × 0.625 (rad/s)/mm")
    assert lines[-2:] == ["read n5 = 3.351 mm × 5.968 = 20 r/min", "read n3 = −16.76 mm × 5.968 = −100 r/min"]


def test_other_notations():
    s = load_scene(SCENES / "train.ysj10_9_planetary_i14.toml")
    zh = steps(dataclasses.replace(s, page=Page(notation="zh")))
    ru = steps(dataclasses.replace(s, page=Page(notation="ru")))
    assert zh[0] == "划分基本轮系：行星轮系1-2-3-2'-4-H（系杆H）"
    assert ru[0] == "разбиваем механизм: планетарный механизм 1-2-3-2'-4-H (водило H)"
    assert zh[-1] == ru[-1] == "i14 = 116"
