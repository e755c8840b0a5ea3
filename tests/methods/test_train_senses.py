"""Mesh senses from the arrows (graphmech/methods/train_senses.py): parallel axes by kind, bevel
pitch points moving together, the worm's hand rule; arrows that cannot be drawn refused."""
from __future__ import annotations

import pytest

from graphmech.errors import OutOfDomain
from graphmech.methods.train_senses import (
    arrow,
    bevel_sign,
    parallel_sign,
    worm_sign,
)


def test_parallel_meshes_take_their_sign_from_the_kind_and_the_axes():
    assert parallel_sign("external", "+x", "+x") == -1
    assert parallel_sign("internal", "+x", "+x") == 1
    assert parallel_sign("external", "+x", "-x") == 1  # b's speed counted the other way
    with pytest.raises(OutOfDomain, match="needs parallel axes"):
        parallel_sign("external", "+x", "+y")


def test_bevel_pitch_points_move_together():
    # a along +x, b along +y, meeting at the pitch point above a's axis and to the right of b's:
    # û_a × t_a = x × y = +z, û_b × t_b = y × x = −z: opposite signs
    assert bevel_sign("+x", "+y", ("+y", "+x")) == -1
    assert bevel_sign("+x", "-y", ("+y", "+x")) == 1
    assert bevel_sign("+x", "+y", ("-y", "-x")) == -1
    with pytest.raises(OutOfDomain, match="is along gear a's axis"):
        bevel_sign("+x", "+y", ("+x", "+x"))
    with pytest.raises(OutOfDomain, match="do not meet"):
        bevel_sign("+x", "+y", ("+z", "+x"))
    with pytest.raises(OutOfDomain, match=r"a bevel pair's axes meet at an angle: a \(\+x\) and b \(-x\) are parallel"):
        bevel_sign("+x", "-x", ("+y", "-y"))  # the pitch points agree, but no bevel pair has parallel axes


def test_the_worm_hand_rule():
    # a right-hand worm along +x turning +: the wheel's pitch point moves along −x; a wheel along +z
    # whose pitch point is below its axis (t = −y) moves along z × (−y) = +x when it turns +
    assert worm_sign("+x", "+z", ("+y", "-y"), "right") == -1
    assert worm_sign("+x", "+z", ("+y", "-y"), "left") == 1
    assert worm_sign("+x", "+z", ("-y", "+y"), "right") == 1
    with pytest.raises(OutOfDomain, match="the pitch point lies between the axes: from wheel b's axis toward "
                                          r"\+y, so from worm a's toward the opposite, not \+y"):
        worm_sign("+x", "+z", ("+y", "+y"), "right")  # both axes below the pitch point: the gears overlap
    with pytest.raises(OutOfDomain, match="along wheel b's axis"):
        worm_sign("+x", "+z", ("+y", "+z"), "right")
    with pytest.raises(OutOfDomain, match="do not meet"):
        worm_sign("+x", "+y", ("+y", "-x"), "right")  # the wheel's pitch point moves along z, across the worm
    with pytest.raises(OutOfDomain, match="hand"):
        worm_sign("+x", "+z", ("+y", "-y"), "up")


def test_arrows():
    assert arrow("+x", 1.0) == "-y" and arrow("-x", 1.0) == "+y"  # the near side of a positive speed moves down
    assert arrow("+z", -1.0) == "cw" and arrow("-z", -1.0) == "ccw" and arrow("+y", 0.0) == ""
    assert arrow("+y", -3.0) == "-x"  # ω along −y: the near side moves −x
    with pytest.raises(OutOfDomain, match="not a direction"):
        arrow("x", 1.0)
