"""The protocol of an other-mechanisms scene: the Geneva wheel laid out at μl (the line of
centres, the slot at π/z, the perpendicular from O₁ giving the entry point K), its times from k,
and the pin's velocity and acceleration polygons at the dial angle; the differential screw's
displacements composed. Every number is the check's own (:func:`analyse_other`).
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from graphmech.problems.other.check import OtherAnalysis, analyse_other
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, read_row, scale_choice

if TYPE_CHECKING:
    from graphmech.problems.other.scene import OtherScene
    from graphmech.problems.reader import Scene

#: key → (English, 中文, русский). 孙桓: 拨盘, 槽轮, 圆销, 锁止弧, 运动系数; the Russian books:
#: мальтийский механизм, кривошип, палец, запирающая дуга.
PHRASES: Phrases = {
    **COMMON,
    "choose": ("choose {mu}", "选取{mu}", "выбираем {mu}"),
    "centres": ("draw the line of centres O₁O₂ = L/μl = {mm} mm", "作中心线O₁O₂ = L/μl = {mm} mm",
                "проводим линию центров O₁O₂ = L/μl = {mm} mm"),
    "slot": (("through O₂ draw the slot's line at π/z = {a}° to O₂O₁; from O₁ drop the perpendicular to it: "
             "its foot K is where the pin enters"), "过O₂作与O₂O₁成π/z = {a}°的槽中心线，自O₁向其作垂线，垂足K为圆销进入点",
             ("через O₂ проводим ось паза под углом π/z = {a}° к O₂O₁; из O₁ опускаем на неё перпендикуляр: "
             "его основание K — точка входа пальца")),
    "depth": ("the pin comes nearest to O₂ on the line of centres, L − R from it; the slot's bottom lies r beyond",
              "圆销在中心线上离O₂最近（L − R），槽底再深r", "ближе всего к O₂ палец на линии центров (L − R); дно паза глубже на r"),
    "k": ("the dial turns 2φ₁ = {two}° while the pin drives the wheel: k = 2φ₁/360° = {k}",
          "圆销拨动槽轮时拨盘转过2φ₁ = {two}°：运动系数k = 2φ₁/360° = {k}",
          "за время движения креста кривошип поворачивается на 2φ₁ = {two}°: k = 2φ₁/360° = {k}"),
    "rest": ("the wheel rests for (1 − k)T = {rest} s: T = {T} s, n = 60/T = {n} r/min",
             "槽轮静止时间(1 − k)T = {rest} s：T = {T} s，拨盘转速n = 60/T = {n} r/min",
             "крест стоит (1 − k)T = {rest} s: T = {T} s, n = 60/T = {n} r/min"),
    "speed": ("the dial turns at ω₁ = {w} rad/s: T = 2π/ω₁ = {T} s", "拨盘角速度ω₁ = {w} rad/s：T = 2π/ω₁ = {T} s",
              "кривошип вращается с ω₁ = {w} rad/s: T = 2π/ω₁ = {T} s"),
    "pin": ("the pin A at φ = {phi}° from O₁O₂; v_A1 = ω₁R = {v} m/s ⟂ O₁A: lay off pa₁ = {mm} mm",
            "圆销A位于φ = {phi}°；v_A1 = ω₁R = {v} m/s ⟂ O₁A：作pa₁ = {mm} mm",
            "палец A при φ = {phi}°; v_A1 = ω₁R = {v} m/s ⟂ O₁A: откладываем pa₁ = {mm} mm"),
    "split": ("v_A2 = v_A1 + v_A2A1: through p a line ⟂ O₂A, through a₁ a line ∥ O₂A (the slot); they meet at a₂",
              "v_A2 = v_A1 + v_A2A1：过p作⟂ O₂A的直线，过a₁作∥ O₂A（槽）的直线，交于a₂",
              "v_A2 = v_A1 + v_A2A1: через p — прямая ⟂ O₂A, через a₁ — прямая ∥ O₂A (паз); пересечение a₂"),
    "accel": (("a_A1 = a_A2ⁿ + a_A2ᵗ + a^k + a^r: lay off πa₁′ = ω₁²R/μa = {a1} mm ∥ AO₁, πn₂′ = ω₂²·O₂A/μa = {n2} mm "
              "∥ AO₂, the Coriolis 2ω₂v_A1A2 = {k} mm ⟂ the slot back from a₁′ to k′; through n₂′ a line ⟂ O₂A, "
              "through k′ a line ∥ O₂A: they meet at a₂′"),
              ("a_A1 = a_A2ⁿ + a_A2ᵗ + a^k + a^r：作πa₁′ = ω₁²R/μa = {a1} mm ∥ AO₁，πn₂′ = ω₂²·O₂A/μa = {n2} mm ∥ AO₂，"
              "哥氏加速度2ω₂v_A1A2 = {k} mm ⟂槽，由a₁′反向作至k′；过n₂′作⟂ O₂A的直线，过k′作∥ O₂A的直线，交于a₂′"),
              ("a_A1 = a_A2ⁿ + a_A2ᵗ + a^k + a^r: откладываем πa₁′ = ω₁²R/μa = {a1} mm ∥ AO₁, πn₂′ = ω₂²·O₂A/μa = {n2} mm "
              "∥ AO₂, кориолисово 2ω₂v_A1A2 = {k} mm ⟂ пазу назад от a₁′ до k′; через n₂′ — прямая ⟂ O₂A, "
              "через k′ — ∥ O₂A: пересечение a₂′")),
    "screw": ("one turn of link 1 advances it p_A = {pA} mm along screw A ({hA}-hand)",
              "构件1转一周沿螺旋副A（{hA}旋）移动p_A = {pA} mm",
              "за оборот звено 1 смещается по винту A ({hA}) на p_A = {pA} mm"),
    "branch": ("link 2 {how} by s = {s} mm: screw B carries it back by p_B = {pB} mm, {hB}-hand",
               "构件2{how}s = {s} mm：螺旋副B应使其相对1退回p_B = {pB} mm，{hB}旋",
               "звено 2 {how} на s = {s} mm: винт B относит его назад на p_B = {pB} mm, {hB}"),
    "against": ("moves against link 1's advance", "与1的移动方向相反移动", "движется против смещения звена 1"),
    "with": ("moves with link 1's advance", "与1同向移动", "движется вместе со смещением звена 1"),
    "given": ("screw B is given, p_B = {pB} mm, {hB}-hand: s = p_A ∓ p_B = {s} mm per turn",
              "已知螺旋副B：p_B = {pB} mm，{hB}旋：s = p_A ∓ p_B = {s} mm",
              "винт B задан, p_B = {pB} mm, {hB}: s = p_A ∓ p_B = {s} mm за оборот"),
    "right": ("right", "右", "правый"), "left": ("left", "左", "левый"),
}


def other_steps(scene: Scene[OtherScene]) -> list[str]:
    """The protocol of an other-mechanisms scene, one line per step (not numbered)."""
    return protocol(analyse_other(scene, ()))


def protocol(an: OtherAnalysis) -> list[str]:
    notation = an.scene.page.notation
    p = an.scene.problem

    def say(key: str, **fields: str) -> str:
        return phrase(key, notation, PHRASES, **fields)

    out: list[str] = []
    rows = {r.name: r for r in an.rows}
    g, lay = p.geneva, an.lay
    if g is not None and lay is not None:
        out.append(say("choose", mu=scale_choice("l", an.scales["l"], "l" in an.stated, notation)))
        out.append(say("centres", mm=num(g.L / an.scales["l"])))
        out.append(say("slot", a=num(180.0 / g.z)))
        out.append(say("depth"))
        k = lay.half_angle / math.pi
        out.append(say("k", two=num(math.degrees(2 * lay.half_angle)), k=num(k)))
        if g.t_rest is not None:
            T = g.t_rest / (1 - k)
            out.append(say("rest", rest=num(g.t_rest), T=num(T), n=num(60 / T)))
        else:
            out.append(say("speed", w=num(g.omega1), T=num(2 * math.pi / g.omega1)))
        pp = an.at_angle
        if pp is not None and g.phi is not None:
            for sym in ("v", "a"):
                out.append(say("choose", mu=scale_choice(sym, an.scales[sym], sym in an.stated, notation)))
            out.append(say("pin", phi=num(math.degrees(g.phi)), v=num(g.omega1 * lay.R_mm * an.scales["l"]),
                           mm=num(math.hypot(*pp.a1))))
            out.append(say("split"))
            out.append(say("accel", a1=num(math.hypot(*pp.a1_)), n2=num(math.hypot(*pp.n2_)),
                           k=num(math.hypot(pp.a1_[0] - pp.k_[0], pp.a1_[1] - pp.k_[1]))))
    s = p.screw
    if s is not None:
        out.append(say("screw", pA=num(s.p_A * 1000), hA=say(s.hand_A)))
        for name, lead, hand, how in an.screw:
            if how == "given":
                out.append(say("given", pB=num((s.p_B or 0.0) * 1000), hB=say(s.hand_B or "right"),
                               s=num(lead * 1000)))
            else:
                out.append(say("branch", how=say(how), s=num((s.travel or 0.0) * 1000), pB=num(lead * 1000),
                               hB=say(hand)))
    out += [read_row(r, notation) for r in rows.values()]
    return out


__all__ = ["PHRASES", "other_steps", "protocol"]
