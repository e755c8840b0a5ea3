"""Inertia and moments reduced to one member of a gear train, as the book writes them (等效转动惯量,
等效力矩): every speed as a ratio to the reduction member's, from the train's speeds,

    J_red = Σ J_k (ω_k/ω_r)² + Σ m_k (v_k/ω_r)²,   v_k = ω_H·a_k for a planet on an arm a_k,
    M_red = Σ M_k ω_k/ω_r,

a planet's ω its absolute one; a bevel planet's absolute ω the vector sum ω_H + ω^H_p, each part
with its moment of inertia (about the axis J, about a diameter J_t).
"""
from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from graphmech.errors import NoSolution, OutOfDomain
from graphmech.mechanisms.gear_train import GearTrain
from graphmech.mechanisms.train_dynamics import Body, axis_cos, check_body, planet_arm


def ratios(train: GearTrain, omega: Mapping[str, float], to: str) -> dict[str, float]:
    """ω_k/ω_r of every member."""
    wr = omega[train.member_of(to)]
    if wr == 0.0:
        raise NoSolution(f"nothing can be reduced to {to}: it is at rest")
    return {m.name: omega[m.name] / wr for m in train.members}


def book_reduced_inertia(train: GearTrain, omega: Mapping[str, float], bodies: Sequence[Body], to: str,
                         module: float, axes: Mapping[str, str] | None = None,
                         modules: Mapping[str, float] | None = None) -> float:
    """J_red, kg·m² (``modules``: a gear's stage module where it has one, for a planet's arm)."""
    axes = axes or {}
    u = ratios(train, omega, to)
    j = 0.0
    for b in bodies:
        check_body(train, b)
        h = train.member(b.member).carrier
        term = 0.0
        if h is None:
            term = b.inertia * u[b.member] ** 2
        else:
            c = axis_cos(axes, h, b.member)
            if abs(c) == 1.0:
                term = b.inertia * u[b.member] ** 2
                arm = b.arm
                if arm is None and b.mass:
                    arm = planet_arm(train, module, b.member, modules)
            else:  # ω_p = ω_H + ω^H_p: along the planet's axis and across it
                along = u[h] * c + (u[b.member] - u[h])
                across = u[h] * math.sqrt(1.0 - c * c)
                if b.inertia and b.inertia_transverse is None:
                    raise OutOfDomain(f"member {b.member} is a bevel planet: its inertia about a diameter is needed")
                term = b.inertia * along ** 2 + (b.inertia_transverse or 0.0) * across ** 2
                arm = b.arm
                if arm is None and b.mass:
                    raise OutOfDomain(f"member {b.member} is a bevel planet: state its arm")
            if b.mass:
                assert arm is not None
                term += b.mass * (u[h] * arm) ** 2  # v = ω_H·a
        j += b.count * term
    return j


def book_reduced_moment(train: GearTrain, omega: Mapping[str, float], bodies: Sequence[Body], to: str,
                        axes: Mapping[str, str] | None = None) -> float:
    """M_red, N·m: Σ M_k ω_k/ω_r (a bevel planet's moment with its absolute ω along its axis)."""
    axes = axes or {}
    u = ratios(train, omega, to)
    m = 0.0
    for b in bodies:
        h = train.member(b.member).carrier
        w = u[b.member]
        if h is not None and abs(c := axis_cos(axes, h, b.member)) != 1.0:
            w = u[h] * c + (u[b.member] - u[h])
        m += b.count * b.moment * w
    return m


__all__ = ["book_reduced_inertia", "book_reduced_moment", "ratios"]
