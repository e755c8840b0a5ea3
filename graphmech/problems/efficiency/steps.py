"""The protocol of an efficiency scene: a chain of machines walked from the output back to the
motor; an incline, a screw (its thread unrolled into an incline) or a wedge by force polygons —
the friction angle, the frictionless polygon for the ideal force F0, the total reactions turned
by φ, each polygon laid off and closed with its lengths in mm, η, and the self-locking limit.

The numbers are the check's own (:func:`analyse_efficiency`): the polygons' drawn sides, the
chain's stages, the rows' values.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, cast

from graphmech.problems.efficiency.check import EfficiencyAnalysis, analyse_efficiency, unit_thread
from graphmech.problems.judging import Row
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, scale_choice, text

if TYPE_CHECKING:
    from graphmech.methods.efficiency import (
        DrawnForce,
        ForcePolygon,
        StageResult,
        Stroke,
    )
    from graphmech.problems.efficiency.scene import EfficiencyProblem
    from graphmech.problems.reader import Scene

Say = Callable[..., str]

#: The efficiency's phrases: key → (English, 中文, русский). 孙桓: 摩擦角, 当量摩擦角, 总反力,
#: 理想驱动力, 串联/并联机组的效率, 自锁; the Russian books: угол трения, полная реакция, КПД.
PHRASES: Phrases = {
    **COMMON,
    # a chain
    "output": ("the output power: P_out = Q·v = {Q} N × {v} m/s = {P} W", "输出功率：P_out = Q·v = {Q} N × {v} m/s = {P} W",
               "мощность на выходе: P_out = Q·v = {Q} N × {v} m/s = {P} W"),
    "stage": ("stage {name}: η{i} = {formula} = {eta}", "第{i}级（{name}）：η{i} = {formula} = {eta}",
              "ступень {name}: η{i} = {formula} = {eta}"),
    "stage one": ("stage {name}: η{i} = {eta}", "第{i}级（{name}）：η{i} = {eta}", "ступень {name}: η{i} = {eta}"),
    "in series": ("machines in series: η = {formula} = {eta}", "串联机组：η = {formula} = {eta}",
                  "последовательное соединение: η = {formula} = {eta}"),
    "walk": ("stage {name}: P_in = P_out/η{i} = {out}/{eta} = {P} W", "第{i}级（{name}）：P_in = P_out/η{i} = {out}/{eta} = {P} W",
             "ступень {name}: P_in = P_out/η{i} = {out}/{eta} = {P} W"),
    "input": ("the motor's power: P_in = P_out/η = {out}/{eta} = {P} W", "电动机功率：P_in = P_out/η = {out}/{eta} = {P} W",
              "мощность двигателя: P_in = P_out/η = {out}/{eta} = {P} W"),
    # angles and sizes
    "phi": ("the friction angle: φ = arctan f = arctan {f} = {value}°", "摩擦角：φ = arctan f = arctan {f} = {value}°",
            "угол трения: φ = arctan f = arctan {f} = {value}°"),
    "phi_v given": ("the equivalent friction angle: φv = arctan f_v = arctan {f} = {value}°",
                    "当量摩擦角：φv = arctan f_v = arctan {f} = {value}°",
                    "приведённый угол трения: φv = arctan f_v = arctan {f} = {value}°"),
    "phi_v": ("the equivalent friction angle: φv = arctan(f/cos β) = arctan({f}/cos {beta}°) = {value}°",
              "当量摩擦角：φv = arctan(f/cos β) = arctan({f}/cos {beta}°) = {value}°",
              "приведённый угол трения: φv = arctan(f/cos β) = arctan({f}/cos {beta}°) = {value}°"),
    "psi": ("unroll the thread: a right triangle with legs π·d₂ = {pd} m and the lead L = {L} m; its slope is the "
            "lead angle ψ = arctan(L/(π·d₂)) = {value}°",
            "将螺纹展开：两直角边为π·d₂ = {pd} m与导程L = {L} m的直角三角形，其斜角即螺纹升角ψ = arctan(L/(π·d₂)) = {value}°",
            "развёртываем резьбу: прямоугольный треугольник с катетами π·d₂ = {pd} m и ход L = {L} m; его угол — "
            "угол подъёма ψ = arctan(L/(π·d₂)) = {value}°"),
    "psi limit": ("at the self-locking limit the lead angle is ψ = φv = {value}°", "在自锁极限处螺纹升角ψ = φv = {value}°",
                  "на границе самоторможения ψ = φv = {value}°"),
    "psi given": ("the lead angle as given: ψ = {value}°", "螺纹升角（题给）：ψ = {value}°", "угол подъёма задан: ψ = {value}°"),
    "r_f": ("the collar's friction radius: r_f = (d₀ + d_w)/4 = ({d0} + {dw})/4 = {value} m",
            "支承面摩擦半径：r_f = (d₀ + d_w)/4 = ({d0} + {dw})/4 = {value} m",
            "радиус трения опорной поверхности: r_f = (d₀ + d_w)/4 = ({d0} + {dw})/4 = {value} m"),
    "sigma": ("the tensile stress: σ = Q/(π·d₁²/4) = {Q}/(π × {d1}²/4) = {value} Pa",
              "拉应力：σ = Q/(π·d₁²/4) = {Q}/(π × {d1}²/4) = {value} Pa",
              "напряжение растяжения: σ = Q/(π·d₁²/4) = {Q}/(π × {d1}²/4) = {value} Pa"),
    # the polygons
    "choose": ("choose {mu}", "取{mu}", "выбираем {mu}"),
    "forward": ("the forward stroke (F drives)", "正行程（F为驱动力）", "прямой ход (движет сила F)"),
    "reverse": ("the reverse stroke (the load drives, F holds it back)", "反行程（载荷为驱动力，F为阻力）",
                "обратный ход (движет нагрузка, F её удерживает)"),
    "ideal": ("{stroke}, without friction: the polygon of {body}", "{stroke}，不计摩擦：{body}的力多边形",
              "{stroke}, без трения: план сил {body}"),
    "real": ("{stroke}, with friction: turn each total reaction from its normal by φ against the relative velocity; "
             "the polygon of {body}",
             "{stroke}，计摩擦：各总反力偏离法线φ角，偏向与相对速度相反的一侧；{body}的力多边形",
             "{stroke}, с трением: каждую полную реакцию отклоняем от нормали на угол φ против относительной "
             "скорости; план сил {body}"),
    "lay off": ("from {frm} lay off {name} = {value} N: {value}/{mu} = {mm} mm at {angle}° to the x axis",
                "自{frm}作{name} = {value} N：{value}/{mu} = {mm} mm，与x轴成{angle}°",
                "от {frm} откладываем {name} = {value} N: {value}/{mu} = {mm} mm под углом {angle}° к оси x"),
    "reuse": ("reuse the side {old} of the previous polygon, reversed: {name} = −{old}",
              "利用前一多边形的边{old}反向即为{name} = −{old}",
              "используем сторону {old} предыдущего плана в обратном направлении: {name} = −{old}"),
    "close": ("through its end draw a line ∥ {a} ({aa}° to the x axis), through the start a line ∥ {b} ({bb}°); "
              "they meet", "过其末端作{a}的平行线（与x轴成{aa}°），过起点作{b}的平行线（{bb}°），两线相交",
              "через его конец проводим прямую ∥ {a} ({aa}° к оси x), через начало — прямую ∥ {b} ({bb}°); "
              "они пересекаются"),
    "parallel": ("the lines ∥ {a} and ∥ {b} are parallel: the polygon cannot close — no finite force moves it, η = 0",
                 "{a}与{b}的平行线互相平行，力多边形不能封闭：任何有限的力都不能使其运动，η = 0",
                 "прямые ∥ {a} и ∥ {b} параллельны: план не замыкается — никакая конечная сила не сдвинет, η = 0"),
    "read": ("measure {name}: {mm} mm × {mu} = {value} N", "量得{name}：{mm} mm × {mu} = {value} N",
             "измеряем {name}: {mm} mm × {mu} = {value} N"),
    "eta forward": ("η = F₀/F = {F0}/{F} = {value}{locked}", "η = F₀/F = {F0}/{F} = {value}{locked}",
                    "η = F₀/F = {F0}/{F} = {value}{locked}"),
    "eta reverse": ("η′ = F/F₀ = {F}/{F0} = {value}{locked}", "η′ = F/F₀ = {F}/{F0} = {value}{locked}",
                    "η′ = F/F₀ = {F}/{F0} = {value}{locked}"),
    "locked": (" ≤ 0: self-locking", " ≤ 0：自锁", " ≤ 0: самоторможение"),
    "moment": ("the driving moment: M = F·d₂/2 = {mm} mm × {mu} × {r} = {value} N·m",
               "驱动力矩：M = F·d₂/2 = {mm} mm × {mu} × {r} = {value} N·m",
               "движущий момент: M = F·d₂/2 = {mm} mm × {mu} × {r} = {value} N·m"),
    "limit angle": ("redraw the reverse polygon at steeper angles until η′ = 0: the self-locking limit {sym} = {value}°",
                    "逐渐增大倾角重作反行程力多边形，直至η′ = 0：自锁极限{sym} = {value}°",
                    "перестраиваем план обратного хода при больших углах, пока η′ = 0: граница самоторможения "
                    "{sym} = {value}°"),
    "limit eta": ("the forward η there: η = {value} (< 0.5: a self-locking screw wastes half its work or more)",
                  "此时正行程效率η = {value}（< 0.5：自锁螺旋的效率不超过50%）",
                  "КПД прямого хода там: η = {value} (< 0.5: самотормозящий винт теряет не меньше половины работы)"),
    "block": ("the block", "滑块", "ползуна"),
    "slider 1": ("slider 1", "滑块1", "ползуна 1"),
    "slider 2": ("slider 2", "滑块2", "ползуна 2"),
    "wedge": ("the wedge", "楔块", "клина"),
    "wedge 1": ("wedge 1", "楔块1", "клина 1"),
    "wedge 2": ("wedge 2", "楔块2", "клина 2"),
    "faces": (("face 1 ({n1}): φ₁ = arctan {f1} = {p1}°; face 2 ({n2}): φ₂ = arctan {f2} = {p2}° (f = 0: "
               "frictionless, its reaction stays on the normal)"),
              "接触面1（{n1}）：φ₁ = arctan {f1} = {p1}°；接触面2（{n2}）：φ₂ = arctan {f2} = {p2}°（f = 0：无摩擦，反力沿法线）",
              ("поверхность 1 ({n1}): φ₁ = arctan {f1} = {p1}°; поверхность 2 ({n2}): φ₂ = arctan {f2} = {p2}° "
               "(f = 0: без трения, реакция по нормали)")),
    "lock limit": ("redraw the polygon at other {what} until F = 0 (η = 0): {stroke} locks for {cond}",
                   "改变{what}重作力多边形，直至F = 0（η = 0）：{stroke}在{cond}时自锁",
                   "перестраиваем план при других {what}, пока F = 0 (η = 0): {stroke} самотормозится при {cond}"),
    "wedge angles": ("wedge angles", "楔角", "углах клина"),
    "friction angles": ("friction angles", "摩擦角", "углах трения"),
    "r_c mean": ("the collar's friction radius, the mean: r_c = (d₀ + d_w)/4 = {value} m",
                 "支承面摩擦半径（平均半径）：r_c = (d₀ + d_w)/4 = {value} m",
                 "радиус трения опорной поверхности (средний): r_c = (d₀ + d_w)/4 = {value} m"),
    "r_c annulus": ("the collar's friction radius, the annulus' exact: r_c = (2/3)(R³ − r³)/(R² − r²) = {value} m",
                    "支承面摩擦半径（圆环精确值）：r_c = (2/3)(R³ − r³)/(R² − r²) = {value} m",
                    "радиус трения опорной поверхности (точный, кольцо): r_c = (2/3)(R³ − r³)/(R² − r²) = {value} m"),
    "F_a": (("the bolt force from the wrench: F_a = T/[d₂/2·tan(ψ + φv) + f_c·r_c] = {T}/[{r2} × {k} + {fc} × {rc}] "
             "= {value} N (tan(ψ + φv) = {k}: the raising polygon's F at Q = 1 N)"),
            ("扳手拧紧的轴向力：F_a = T/[d₂/2·tan(ψ + φv) + f_c·r_c] = {T}/[{r2} × {k} + {fc} × {rc}] = {value} N"
             "（tan(ψ + φv) = {k}：Q = 1 N时正行程力多边形的F）"),
            ("осевая сила от ключа: F_a = T/[d₂/2·tan(ψ + φv) + f_c·r_c] = {T}/[{r2} × {k} + {fc} × {rc}] = {value} N "
             "(tan(ψ + φv) = {k}: F плана подъёма при Q = 1 N)")),
    "M_c": ("the collar's friction moment: M_c = f_c·Q·r_c = {fc} × {Q} × {rc} = {value} N·m",
            "支承面摩擦力矩：M_c = f_c·Q·r_c = {fc} × {Q} × {rc} = {value} N·m",
            "момент трения на опорной поверхности: M_c = f_c·Q·r_c = {fc} × {Q} × {rc} = {value} N·m"),
    "T_tighten": ("the tightening torque: T = Q·[d₂/2·tan(ψ + φv) + f_c·r_c] = {value} N·m",
                  "拧紧力矩：T = Q·[d₂/2·tan(ψ + φv) + f_c·r_c] = {value} N·m",
                  "момент затяжки: T = Q·[d₂/2·tan(ψ + φv) + f_c·r_c] = {value} N·m"),
    "sigma_a": ("the bolt's tensile stress: σ = F_a/(π·d₁²/4) = {value} Pa", "螺栓拉应力：σ = F_a/(π·d₁²/4) = {value} Pa",
                "напряжение растяжения болта: σ = F_a/(π·d₁²/4) = {value} Pa"),
    "P_drive": ("the drive power: P = Q·v/η = {Q} × {v}/{eta} = {value} W", "驱动功率：P = Q·v/η = {Q} × {v}/{eta} = {value} W",
                "мощность привода: P = Q·v/η = {Q} × {v}/{eta} = {value} W"),
    "n_screw": ("the screw's speed: n = v/L = {v}/{L} × 60 = {value} r/min", "螺杆转速：n = v/L = {v}/{L} × 60 = {value} r/min",
                "частота вращения винта: n = v/L = {v}/{L} × 60 = {value} об/мин"),
    "o": ("o", "o点", "точки o"),
    "end of": ("the end of {name}", "{name}的末端", "конца {name}"),
}


def efficiency_steps(scene: Scene[EfficiencyProblem]) -> list[str]:
    """The protocol of an efficiency scene, one line per step (not numbered)."""
    return protocol(analyse_efficiency(scene, ()))


def _force(name: str) -> str:
    """R12 → R₁₂, F0 → F₀ (the drawing's letters)."""
    head = name.rstrip("0123456789")
    return head + text(f"_{{{name[len(head):]}}}") if head != name else name


def _angle(s: DrawnForce) -> str:
    return num(math.degrees(math.atan2(s.end[1] - s.start[1], s.end[0] - s.start[0])) % 360.0)


def _line_angle(s: DrawnForce) -> str:
    """A line's direction, 0 … 180° (the side may come out either way along it)."""
    return num(math.degrees(math.atan2(s.end[1] - s.start[1], s.end[0] - s.start[0])) % 180.0)


def protocol(an: EfficiencyAnalysis) -> list[str]:
    notation = getattr(an.scene.page, "notation", "en")

    def say(key: str, **fields: str) -> str:
        return phrase(key, notation, PHRASES, **fields)

    p = an.problem
    rows: dict[str, Row] = {r.name: r for r in an.rows}
    if p.type == "chain":
        return _chain(an, rows, say)
    out = _angles(an, rows, say)
    if an.strokes:
        out.append(say("choose", mu=scale_choice("F", an.scales["F"], "F" in an.stated, notation)))
        # the strokes the rows name (F@forward); all of them when none is named
        named = {r.name.partition("@")[2] for r in an.rows} - {""}
        for d, st in an.strokes.items():
            if not named or d in named:
                out += _stroke(an, d, st, rows, say)
    for base, sym in (("self_locking_angle", "ψ" if p.type == "screw" else "α"), ("gamma_limit", "γ")):
        r = rows.get(base)
        if r is not None:
            out.append(say("limit angle", sym=sym, value=num(r.graphical)))
    r = rows.get("eta_self_locking_max")
    if r is not None:
        out.append(say("limit eta", value=num(r.graphical)))
    out += _extra(an, rows, say)
    return out


def _extra(an: EfficiencyAnalysis, rows: dict[str, Row], say: Say) -> list[str]:
    """The self-locking limits of a clamp or a buffer; a screw's collar, wrench and drive."""
    p, out = an.problem, []
    for base in ("alpha_lock_forward", "alpha_lock_reverse", "f_lock_forward", "f_lock_reverse"):
        r = rows.get(base)
        if r is None:
            continue
        d = "forward" if base.endswith("forward") else "reverse"
        # the clamp's reverse stroke and the buffer's forward one lock below the limit angle
        below = (p.type == "wedge_clamp") == (d == "reverse")
        sym = "f" if base.startswith("f") else "α"
        cond = f"{sym} {'≥' if sym == 'f' or not below else '≤'} {num(r.graphical)}{'' if sym == 'f' else '°'}"
        out.append(say("lock limit", what=say("friction angles" if sym == "f" else "wedge angles"), stroke=say(d),
                       cond=cond))
    r = rows.get("r_c")
    if r is not None:
        out.append(say("r_c " + p.collar_rule, value=num(r.graphical)))
    r = rows.get("F_a")
    if r is not None and p.d2 is not None and p.f_c is not None and p.torque is not None:
        k = cast(float, unit_thread(an).F)  # a thread's raising polygon closes
        rc = num(rows["r_c"].graphical) if "r_c" in rows else "r_c"
        out.append(say("F_a", T=num(p.torque), r2=num(p.d2 / 2.0), k=num(k), fc=num(p.f_c), rc=rc,
                       value=num(r.graphical)))
    for base in ("M_c", "T_tighten", "sigma_a"):
        r = rows.get(base)
        if r is None:
            continue
        if base != "M_c":
            out.append(say(base, value=num(r.graphical)))
            continue
        # the axial force: the load, or the wrench's F_a; the radius as the scene reports it
        Q = p.load if p.load is not None else (rows["F_a"].graphical if "F_a" in rows else None)
        out.append(say(base, fc=num(p.f_c or 0.0), Q="Q" if Q is None else num(Q),
                       rc=num(rows["r_c"].graphical) if "r_c" in rows else "r_c", value=num(r.graphical)))
    r = rows.get("P_drive")
    if r is not None and p.speed is not None:
        out.append(say("P_drive", Q=num(p.load or 0.0), v=num(p.speed), eta=num(unit_thread(an).eta),
                       value=num(r.graphical)))
    r = rows.get("n_screw")
    if r is not None and p.speed is not None and p.lead is not None:
        out.append(say("n_screw", v=num(p.speed), L=num(p.lead), value=num(r.graphical)))
    return out


def _chain(an: EfficiencyAnalysis, rows: dict[str, Row], say: Say) -> list[str]:
    p = an.problem
    eta, stages = cast("tuple[float, tuple[StageResult, ...]]", an.chain)  # a chain's analysis walks it
    out = [say("output", Q=num(cast(float, p.load)), v=num(cast(float, p.speed)), P=num(stages[-1].power_out))]
    for i, (s, res) in enumerate(zip(p.stages, stages), start=1):
        total = sum(share for share, _ in s.branches)
        terms = [" × ".join(num(e) for e in series) for _, series in s.branches]
        if len(s.branches) == 1 and len(s.branches[0][1]) == 1:
            out.append(say("stage one", name=s.name, i=text(f"_{{{i}}}"), eta=num(res.eta)))
            continue
        if len(s.branches) == 1:
            formula = terms[0]
        else:  # machines in parallel: the power-weighted mean of the branches
            formula = "(" + " + ".join(f"{num(share)} × {t}" for (share, _), t in zip(s.branches, terms)) + f")/{num(total)}"
        out.append(say("stage", name=s.name, i=text(f"_{{{i}}}"), formula=formula, eta=num(res.eta)))
    out.append(say("in series", formula=" × ".join(num(r.eta) for r in stages), eta=num(eta)))
    for i in range(len(stages), 0, -1):
        r = stages[i - 1]
        out.append(say("walk", name=r.name, i=text(f"_{{{i}}}"), out=num(r.power_out), eta=num(r.eta), P=num(r.power_in)))
    if "P_in" in rows:
        out.append(say("input", out=num(stages[-1].power_out), eta=num(eta), P=num(rows["P_in"].graphical)))
    return out


def _angles(an: EfficiencyAnalysis, rows: dict[str, Row], say: Say) -> list[str]:
    p, out = an.problem, []
    if p.type == "wedge_clamp":  # each face with its own friction, declared
        (n1, f1), (n2, f2) = p.faces
        out.append(say("faces", n1=n1, f1=num(f1), p1=num(math.degrees(math.atan(f1))), n2=n2, f2=num(f2),
                       p2=num(math.degrees(math.atan(f2)))))
    r: Row | None = rows.get("phi") or rows.get("phi_v")
    if r is not None:
        if p.half_angle and not p.f_is_equivalent:
            out.append(say("phi_v", f=num(p.f or 0.0), beta=num(math.degrees(p.half_angle)), value=num(r.graphical)))
        elif p.f_is_equivalent:
            out.append(say("phi_v given", f=num(p.f or 0.0), value=num(r.graphical)))
        else:
            out.append(say("phi", f=num(p.f or 0.0), value=num(r.graphical)))
    r = rows.get("psi")
    if r is not None:
        if p.at_limit:
            out.append(say("psi limit", value=num(r.graphical)))
        elif p.lead is not None and p.d2 is not None:
            out.append(say("psi", pd=num(math.pi * p.d2), L=num(p.lead), value=num(r.graphical)))
        else:
            out.append(say("psi given", value=num(r.graphical)))
    r = rows.get("r_f")
    if r is not None and p.collar is not None:
        out.append(say("r_f", d0=num(p.collar[0]), dw=num(p.collar[1]), value=num(r.graphical)))
    r = rows.get("sigma")
    if r is not None and p.d1 is not None:
        out.append(say("sigma", Q=num(cast(float, p.load)), d1=num(p.d1), value=num(r.graphical)))
    return out


def _stroke(an: EfficiencyAnalysis, d: str, st: Stroke, rows: dict[str, Row], say: Say) -> list[str]:
    mu = an.scales["F"]
    stroke = say(d)
    out: list[str] = []
    # a side drawn 0 mm long (F at the self-locking limit) still has its line: F's is the same in
    # every polygon of the stroke
    lines = {s.name: _line_angle(s) for poly in st.polygons for s in poly.forces if math.dist(s.start, s.end) > 0}
    for poly in st.polygons:
        out.append(say("ideal" if poly.ideal else "real", stroke=stroke, body=say(poly.body)))
        out += _polygon(poly, mu, say, lines)
    if st.F is None:
        real = [s.name for s in st.polygons[-1].forces[-2:]] if st.polygons else ["F", "R"]
        out.append(say("parallel", a=_force(real[0]), b="R"))
        return out
    eta = st.eta
    if d == "forward":
        out.append(say("eta forward", F0=num(st.F0), F=num(st.F), value=num(eta), locked=say("locked") if eta < 0 else ""))
    else:
        out.append(say("eta reverse", F0=num(st.F0), F=num(st.F), value=num(eta), locked=say("locked") if eta <= 0 else ""))
    p = an.problem
    multi = len(p.directions) > 1
    if (f"M@{d}" if multi else "M") in rows and p.d2 is not None:
        out.append(say("moment", mm=num(abs(st.F) / mu), mu=num(mu), r=num(p.d2 / 2.0), value=num(st.F * p.d2 / 2.0)))
    return out


def _polygon(poly: ForcePolygon, mu: float, say: Say, lines: dict[str, str]) -> list[str]:
    """The known sides laid off head to tail, the two unknowns' lines drawn, the unknowns measured."""
    sides = poly.forces
    known, (a, b) = sides[:-2], sides[-2:]
    out, prev = [], ""
    for s in known:
        if s.name == "R21":  # the previous polygon's R12, turned round (the book joins them)
            out.append(say("reuse", old=_force("R12"), name=_force("R21")))
        else:
            frm = say("end of", name=prev) if prev else say("o")
            out.append(say("lay off", frm=frm, name=_force(s.name), value=num(s.value), mu="μF",
                           mm=num(math.dist(s.start, s.end)), angle=_angle(s)))
        prev = _force(s.name)
    out.append(say("close", a=_force(a.name), aa=_line_angle(a) if math.dist(a.start, a.end) else lines.get(a.name, "—"),
                   b=_force(b.name), bb=_line_angle(b) if math.dist(b.start, b.end) else lines.get(b.name, "—")))
    for s in (a, b):
        name = _force(s.name) + ("₀" if poly.ideal and s.name == "F" else "")
        out.append(say("read", name=name, mm=num(math.dist(s.start, s.end)), mu=num(mu), value=num(s.value)))
    return out


__all__ = ["PHRASES", "efficiency_steps", "protocol"]
