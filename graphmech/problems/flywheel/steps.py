"""The construction protocol of a flywheel scene: the reduced moment Mп and inertia Jп at the N
positions, the scales and the pole distance, Mп integrated by chords into the work Aп, the
constant moment by the ray parallel to its work line, ΔT = Aп + A_b, then J_F from the Wittenbauer
diagram's tangents at ψmax and ψmin or from the energy indicator's ΔW_max — as the scene asks.

The numbers are the check's: the design is :func:`graphmech.problems.flywheel.check.analyse_flywheel`'s
(without the error estimates, which redo it at 2N and 4N), and every value the table has comes from
:func:`graphmech.problems.flywheel.check.quantity_values`. Each line that reads a value off N
positions says so, as the check states its discretisation.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from graphmech.problems.flywheel.check import (
    QUANTITIES,
    FlywheelAnalysis,
    analyse_flywheel,
    quantity_values,
    requested,
    split,
)
from graphmech.problems.protocol import PHRASES as COMMON
from graphmech.problems.protocol import Phrases, num, phrase, scale, scale_choice

if TYPE_CHECKING:
    from graphmech.problems.flywheel.scene import FlywheelScene
    from graphmech.problems.reader import Scene

#: The flywheel's phrases: key → (English, 中文, русский); fields in braces.
PHRASES: Phrases = {
    **COMMON,
    "divide": ("divide the cycle Φ = {cycle}° into N = {n} positions, Δφ = {step}° (every value below read off "
               "these {n} positions)",
               "将一个周期Φ = {cycle}°等分为N = {n}个位置，Δφ = {step}°（以下各值均由这{n}个位置求得）",
               "делим цикл Φ = {cycle}° на N = {n} положений, Δφ = {step}° (все значения ниже — по этим {n} "
               "положениям)"),
    "reduce": ("position {k} (φ = {phi}°): from its velocity polygon Jп = Σ(m·v_S² + J_S·ω²)/ω₁² = {J} kg·m², "
               "Mп = Σ(F·v + M·ω)/ω₁ = {M} N·m",
               "位置{k}（φ = {phi}°）：由速度多边形求得Jп = Σ(m·v_S² + J_S·ω²)/ω₁² = {J} kg·m²，"
               "Mп = Σ(F·v + M·ω)/ω₁ = {M} N·m",
               "положение {k} (φ = {phi}°): по плану скоростей Jп = Σ(m·v_S² + J_S·ω²)/ω₁² = {J} kg·m², "
               "Mп = Σ(F·v + M·ω)/ω₁ = {M} N·m"),
    "reduce loads": ("position {k} (φ = {phi}°): Jп = {J} kg·m², Mп = {M} N·m (from the scene's loads)",
                     "位置{k}（φ = {phi}°）：Jп = {J} kg·m²，Mп = {M} N·m（由题给载荷）",
                     "положение {k} (φ = {phi}°): Jп = {J} kg·m², Mп = {M} N·m (по заданным нагрузкам)"),
    "reduce table": ("position {k} (φ = {phi}°): Jп = {J} kg·m², ΔT = {T} J (read off the scene's table of ΔT)",
                     "位置{k}（φ = {phi}°）：Jп = {J} kg·m²，ΔT = {T} J（由题给ΔT表查得）",
                     "положение {k} (φ = {phi}°): Jп = {J} kg·m², ΔT = {T} J (по заданной таблице ΔT)"),
    "scales table": ("choose {phi}, {T} and {J}: ΔT is given, so nothing is integrated (no μM, no pole)",
                     "取{phi}、{T}及{J}：ΔT已给出，无需积分（无μM，无极点）",
                     "выбираем {phi}, {T} и {J}: ΔT задано, интегрировать нечего (ни μM, ни полюса)"),
    "energy table": ("lay off ΔT/μT at φ/μφ and Jп/μJ from the tables: ΔT zero at position 1 and again at the end "
                     + "of the cycle",
                     "按表作ΔT/μT（φ/μφ处）及Jп/μJ：ΔT在位置1及周期终点均为零",
                     "откладываем по таблицам ΔT/μT при φ/μφ и Jп/μJ: ΔT ноль в положении 1 и в конце цикла"),
    "scales": ("choose {phi}, {M} and the pole distance H = {H} mm ({Hwhy}): μT = μM·μφ·H = {T}; {J}",
               "取{phi}、{M}，极距H = {H} mm（{Hwhy}）：μT = μM·μφ·H = {T}；{J}",
               "выбираем {phi}, {M} и полюсное расстояние H = {H} mm ({Hwhy}): μT = μM·μφ·H = {T}; {J}"),
    "H chosen": ("chosen to fit the page", "按图幅选取", "выбрано по формату листа"),
    "H given": ("as the scene gives it", "题给", "задано"),
    "H from T": ("from the scene's μT", "由题给μT求得", "из заданного μT"),
    "ordinates": ("lay off the ordinates Mп/μM at φ/μφ and Jп/μJ (mm):", "按φ/μφ作纵坐标Mп/μM及Jп/μJ（mm）：",
                  "откладываем ординаты Mп/μM при φ/μφ и Jп/μJ (mm):"),
    "ordinate": ("position {k}: x = {x} mm, Mп/μM = {y} mm, Jп/μJ = {j} mm",
                 "位置{k}：x = {x} mm，Mп/μM = {y} mm，Jп/μJ = {j} mm",
                 "положение {k}: x = {x} mm, Mп/μM = {y} mm, Jп/μJ = {j} mm"),
    "chords": ("integrate Mп by chords: in each interval project the mean ordinate onto the M axis, draw the ray "
               "from the pole P (H = {H} mm to the left of the origin) and, from the end of the chord before, "
               "the chord parallel to it: the work of the loads Aп at μT",
               "用弦线法对Mп图解积分：将每一区间的平均纵坐标投影到M轴上，自极点P（在原点左侧H = {H} mm）作射线，"
               "自前一弦线终点作其平行线，得载荷功Aп（按μT）",
               "графически интегрируем Mп методом хорд: среднюю ординату каждого интервала проецируем на ось M, "
               "проводим луч из полюса P (H = {H} mm левее начала) и из конца предыдущей хорды — хорду, "
               "параллельную ему: работа нагрузок Aп в масштабе μT"),
    "chord": ("interval {k}–{k1}: mean ordinate {mean} mm; Aп at {k1} = {A} mm",
              "区间{k}–{k1}：平均纵坐标{mean} mm；{k1}处Aп = {A} mm",
              "интервал {k}–{k1}: средняя ордината {mean} mm; Aп в {k1} = {A} mm"),
    "balancing": ("the constant moment's work A_b is the straight line from the origin to −Aп(Φ) = {end} mm; the ray "
                  "from P parallel to it cuts the M axis at {mm} mm: {sym} = {mm} × {mu} = {M} N·m",
                  "常力矩的功A_b为自原点至−Aп(Φ) = {end} mm的直线；自P作其平行射线交M轴于{mm} mm：{sym} = {mm} × {mu} = {M} N·m",
                  "работа постоянного момента A_b — прямая от начала до −Aп(Φ) = {end} mm; луч из P, параллельный ей, "
                  "отсекает на оси M {mm} mm: {sym} = {mm} × {mu} = {M} N·m"),
    "energy": ("add the two works: ΔT = Aп + A_b at μT, zero at position 1 and again at the end of the cycle",
               "两功相加：ΔT = Aп + A_b（按μT），在位置1及周期终点均为零",
               "складываем работы: ΔT = Aп + A_b в масштабе μT, ноль в положении 1 и в конце цикла"),
    "energy at": ("ΔT at {k} = {mm} mm: ΔT = {mm} × {mu} = {T} J", "{k}处ΔT = {mm} mm：ΔT = {mm} × {mu} = {T} J",
                  "ΔT в {k} = {mm} mm: ΔT = {mm} × {mu} = {T} J"),
    "work at": ("Aп at {k} = {mm} mm: Aп = {mm} × {mu} = {A} J", "{k}处Aп = {mm} mm：Aп = {mm} × {mu} = {A} J",
                "Aп в {k} = {mm} mm: Aп = {mm} × {mu} = {A} J"),
    "extreme": ("the {which} ordinate of ΔT is at position {k} (φ = {phi}°): {mm} mm: {name} = {mm} × {mu} = {T} J",
                "ΔT的{which}纵坐标在位置{k}（φ = {phi}°）：{mm} mm：{name} = {mm} × {mu} = {T} J",
                "{which} ордината ΔT — в положении {k} (φ = {phi}°): {mm} mm: {name} = {mm} × {mu} = {T} J"),
    "highest": ("highest", "最高", "наибольшая"),
    "lowest": ("lowest", "最低", "наименьшая"),
    "wittenbauer": ("draw the Wittenbauer diagram ΔT(Jп): the point of position k at x = Jп/μJ, y = ΔT/μT",
                    "作维滕包尔图ΔT(Jп)：位置k的点取x = Jп/μJ，y = ΔT/μT",
                    "строим диаграмму Виттенбауэра ΔT(Jп): точка положения k при x = Jп/μJ, y = ΔT/μT"),
    "psi": ("tan ψ{w} = μJ·ω{w}²/(2μT) = {mJ} × {om}²/(2 × {mT}) = {tan}: ψ{w} = {psi}°",
            "tan ψ{w} = μJ·ω{w}²/(2μT) = {mJ} × {om}²/(2 × {mT}) = {tan}：ψ{w} = {psi}°",
            "tg ψ{w} = μJ·ω{w}²/(2μT) = {mJ} × {om}²/(2 × {mT}) = {tan}: ψ{w} = {psi}°"),
    "omega": ("{name} = {formula} = {w} rad/s", "{name} = {formula} = {w} rad/s", "{name} = {formula} = {w} rad/s"),
    "speed": ("{name} = {w}·30/π = {n} r/min", "{name} = {w}·30/π = {n} r/min", "{name} = {w}·30/π = {n} об/мин"),
    "tangent": ("draw the {which} tangent at ψ{w} touching the diagram (at position {k}); it cuts the ΔT axis at "
                "{p} = {mm} mm ({val} J)",
                "作与曲线相切、倾角为ψ{w}的{which}切线（切于位置{k}），交ΔT轴于{p} = {mm} mm（{val} J）",
                "проводим {which} касательную под углом ψ{w} к диаграмме (касается в положении {k}); она отсекает "
                "на оси ΔT {p} = {mm} mm ({val} J)"),
    "upper": ("upper", "上", "верхнюю"),
    "lower": ("lower", "下", "нижнюю"),
    "kl": ("measure kl = {mm} mm: J_F = μT·kl/(ω_m²·δ) = {mT} × {mm}/({wm}² × {delta}) = {J} kg·m²",
           "量得kl = {mm} mm：J_F = μT·kl/(ω_m²·δ) = {mT} × {mm}/({wm}² × {delta}) = {J} kg·m²",
           "измеряем kl = {mm} mm: J_F = μT·kl/(ω_m²·δ) = {mT} × {mm}/({wm}² × {delta}) = {J} kg·m²"),
    "indicator": ("draw the energy indicator: from a, the chain of vertical vectors of the excess and deficit "
                  "areas between the extremes of ΔT, at μT′ = μT/{f} = {mu} J/mm: {levels}",
                  "作能量指示图：自a点起，按μT′ = μT/{f} = {mu} J/mm依次作各盈亏功的铅垂矢量：{levels}",
                  "строим диаграмму избыточных работ: от точки a — цепь вертикальных векторов избытков и "
                  "недостатков работы между экстремумами ΔT в масштабе μT′ = μT/{f} = {mu} J/mm: {levels}"),
    "delta W": ("the highest and lowest points of the chain are {hi} and {lo}: measure {mm} mm: "
                "ΔW_max = {mm} × {mu} = {W} J",
                "指示图的最高点{hi}、最低点{lo}：量得{mm} mm：ΔW_max = {mm} × {mu} = {W} J",
                "наивысшая и наинизшая точки цепи — {hi} и {lo}: измеряем {mm} mm: ΔW_max = {mm} × {mu} = {W} J"),
    "J_F indicator": ("J_F = ΔW_max/(ω_m²·δ) − J_mean = {W}/({wm}² × {delta}) − {Jm} = {J} kg·m² (J_mean, the mean "
                      "of Jп over the cycle)",
                      "J_F = ΔW_max/(ω_m²·δ) − J_mean = {W}/({wm}² × {delta}) − {Jm} = {J} kg·m²（J_mean为Jп在一个周期内的平均值）",
                      "J_F = ΔW_max/(ω_m²·δ) − J_mean = {W}/({wm}² × {delta}) − {Jm} = {J} kg·m² (J_mean — среднее "
                      "Jп за цикл)"),
    "motion": ("with this flywheel the equation of motion is integrated (not a construction): {values}",
               "装上此飞轮后积分机器的运动方程（非图解）：{values}",
               "с этим маховиком интегрируем уравнение движения (не построение): {values}"),
    "braking": ("the run-down diagram ω(t): its intercept on the t axis is {mm} mm: t_stop = {mm} × {mu} = {t} s",
                "制动过程ω(t)图在t轴上的截距为{mm} mm：t_stop = {mm} × {mu} = {t} s",
                "диаграмма выбега ω(t) отсекает на оси t {mm} mm: t_stop = {mm} × {mu} = {t} s"),
}


def flywheel_steps(scene: Scene[FlywheelScene]) -> list[str]:
    """The protocol of a flywheel scene, one line per step (not numbered)."""
    return protocol(analyse_flywheel(scene, estimates=False))


def protocol(an: FlywheelAnalysis) -> list[str]:
    """The protocol of an analysed flywheel scene, in the course project's order."""
    return _Words(an).lines()


class _Words:
    def __init__(self, an: FlywheelAnalysis) -> None:
        self.an = an
        self.notation = getattr(an.scene.page, "notation", "en")
        self.names = requested(an.scene, an.extra_measured)
        self.bases = {split(n)[0] for n in self.names}

    def say(self, key: str, **fields: str) -> str:
        return phrase(key, self.notation, PHRASES, **fields)

    def value(self, name: str) -> tuple[float, float | None, float]:
        """(value, drawn mm, μ) of a quantity, as the check table has it."""
        base, at = split(name)
        g, _, drawn, scale, _ = quantity_values(self.an, base, None if at is None else int(at) - 1)
        return g, drawn, scale

    def lines(self) -> list[str]:
        an = self.an
        out: list[str] = []
        if an.reduction is not None:
            out += self.reduction()
        d = an.design
        if d is not None:
            out += self.design()
            if d.wittenbauer is not None:
                out += self.wittenbauer()
            if d.indicator is not None:
                out += self.indicator()
        out += self.speeds()
        if an.motion is not None:
            values = [f"{n} = {num(self.value(n)[0])} {QUANTITIES[split(n)[0]][0]}".rstrip() for n in self.names
                      if QUANTITIES[split(n)[0]][1] == "motion"]
            if values:
                out.append(self.say("motion", values=", ".join(values)))
        if an.rundown is not None:
            t, mm, mu = self.value("t_stop")
            out.append(self.say("braking", mm=num(mm or 0.0), mu=num(mu), t=num(t)))
        return out

    def reduction(self) -> list[str]:
        an = self.an
        r = an.reduction
        n = len(an.phi)
        cycle = math.degrees(an.machine.cycle)
        out = [self.say("divide", cycle=num(cycle), n=str(n), step=num(cycle / n))]
        key = "reduce" if an.machine.linkage is not None else "reduce loads"
        if an.machine.energy_table is not None and an.design is not None:  # ΔT given: no moments
            return out + [self.say("reduce table", k=str(k + 1), phi=num(math.degrees(float(an.phi[k]))),
                                   J=num(float(r.J[k])), T=num(float(an.design.dT[k]))) for k in range(n)]
        for k in range(n):
            out.append(self.say(key, k=str(k + 1), phi=num(math.degrees(float(an.phi[k]))), J=num(float(r.J[k])),
                                M=num(float(r.M[k]))))
        return out

    def design(self) -> list[str]:
        an, d = self.an, self.an.design
        sc = d.scales
        why = {"given": "H given", "μT/(μM·μφ)": "H from T"}.get(d.sources.get("H", ""), "H chosen")

        def mu(k: str) -> str:
            return scale_choice(k, float(sc[k]), k in an.stated, self.notation)

        m = d.moment
        if m is None:  # ΔT given as a table: straight to its extremes
            out = [self.say("scales table", phi=mu("phi"), T=mu("T"), J=mu("J")), self.say("energy table")]
            return out + self._energy_values()
        assert d.work_mm is not None and d.H_mm is not None
        out = [self.say("scales", phi=mu("phi"), M=mu("M"), H=num(d.H_mm), Hwhy=self.say(why),
                        T=scale("T", float(sc["T"])).partition(" = ")[2], J=mu("J"))]
        out.append(self.say("ordinates"))
        for k in range(len(an.phi)):
            out.append(self.say("ordinate", k=str(k + 1), x=num(float(m.x_mm[k])), y=num(float(m.y_mm[k])),
                                j=num(float(d.inertia_mm[k]))))
        out.append(self.say("chords", H=num(d.H_mm)))
        n = len(an.phi)
        for k in range(n):
            k1 = str(k + 2) if k + 1 < n else f"{n + 1} (= 1)"
            out.append(self.say("chord", k=str(k + 1), k1=k1, mean=num(float(m.mean_mm[k])),
                                A=num(float(d.work_mm[k + 1]))))
        for name in self.names:
            if split(name)[0] == "A_p":
                A, mm, mu_T = self.value(name)
                out.append(self.say("work at", k=split(name)[1] or "", mm=num(mm or 0.0), mu=num(mu_T), A=num(A)))
        sym = "Md" if an.machine.balance == "driving" else "Mr"
        M, mm, mu_M = self.value("M_b")
        out.append(self.say("balancing", end=num(-float(d.work_mm[-1])), mm=num(mm or 0.0), mu=num(mu_M), M=num(M),
                            sym=sym))
        out.append(self.say("energy"))
        return out + self._energy_values()

    def _energy_values(self) -> list[str]:
        """ΔT at the positions asked for, and its extremes."""
        d = self.an.design
        out: list[str] = []
        for name in self.names:
            if split(name)[0] == "DeltaT":
                T, mm, mu_T = self.value(name)
                out.append(self.say("energy at", k=split(name)[1] or "", mm=num(mm or 0.0), mu=num(mu_T), T=num(T)))
        for top in (True, False):
            name = "DeltaT_max" if top else "DeltaT_min"
            if not ({name, "phi_" + name} & self.bases):
                continue
            T, mm, mu_T = self.value(name)
            k = int(d.energy_max_index if top else d.energy_min_index)
            out.append(self.say("extreme", which=self.say("highest" if top else "lowest"), k=str(k + 1),
                                phi=num(self.value("phi_" + name)[0]), mm=num(mm or 0.0), mu=num(mu_T), T=num(T),
                                name=name))
        return out

    def omegas(self) -> tuple[float, float, str, str]:
        """ω_max, ω_min of the tangents and how the scene's reading gets them."""
        wmax, _, _ = self.value("omega_max")
        wmin, _, _ = self.value("omega_min")
        if self.an.scene.problem.tangents == "book":
            return wmax, wmin, "ω_m·√(1 + δ)", "ω_m·√(1 − δ)"
        return wmax, wmin, "ω_m·(1 + δ/2)", "ω_m·(1 − δ/2)"

    def speeds(self) -> list[str]:
        out = []
        wmax, wmin, fmax, fmin = self.omegas()
        for name in ("omega_max", "omega_min", "n_max", "n_min"):
            if name in self.bases and (self.an.design is None or self.an.design.wittenbauer is None
                                       or name.startswith("n")):
                w = wmax if name.endswith("max") else wmin
                if name.startswith("omega"):
                    out.append(self.say("omega", name=name, formula=fmax if name.endswith("max") else fmin, w=num(w)))
                else:
                    out.append(self.say("speed", name=name, w=num(w), n=num(self.value(name)[0])))
        return out

    def wittenbauer(self) -> list[str]:
        an, d = self.an, self.an.design
        w = d.wittenbauer
        mT, mJ = float(d.scales["T"]), float(d.scales["J"])
        wmax, wmin, fmax, fmin = self.omegas()
        out = [self.say("wittenbauer"),
               self.say("omega", name="ω_max", formula=fmax, w=num(wmax)),
               self.say("omega", name="ω_min", formula=fmin, w=num(wmin))]
        for top in (True, False):
            tan = float(w.tan_psi_max if top else w.tan_psi_min)
            out.append(self.say("psi", w="max" if top else "min", mJ=num(mJ), om=num(wmax if top else wmin), mT=num(mT),
                                tan=num(tan), psi=num(math.degrees(math.atan(tan)))))
        for top in (True, False):
            mm = float(w.k_mm if top else w.l_mm)
            out.append(self.say("tangent", which=self.say("upper" if top else "lower"), w="max" if top else "min",
                                k=str(int(w.k_index if top else w.l_index) + 1), p="k" if top else "l", mm=num(mm),
                                val=num(mm * mT)))
        m = an.machine
        J, _, _ = self.value("J_F_wittenbauer")
        out.append(self.say("kl", mm=num(float(w.kl_mm)), mT=num(mT), wm=num(m.omega_m), delta=num(m.delta), J=num(J)))
        return out

    def indicator(self) -> list[str]:
        an, d = self.an, self.an.design
        from graphmech.problems.flywheel.figures import energy_factor

        ind = d.indicator
        f = energy_factor(d)
        W, mm, mu = self.value("DeltaW_max")
        letters = "abcdefghijklmnopqrstuvwxyz"
        levels = ", ".join(f"{letters[j % 26] if j < len(ind.levels_mm) - 1 else 'a′'} = {num(float(y) * f)} mm"
                           for j, y in enumerate(ind.levels_mm))
        out = [self.say("indicator", f=str(f), mu=num(mu), levels=levels)]
        hi, lo = int(ind.highest), int(ind.lowest)
        last = len(ind.levels_mm) - 1
        out.append(self.say("delta W", hi=letters[hi] if hi < last else "a′", lo=letters[lo] if lo < last else "a′",
                            mm=num(mm or 0.0), mu=num(mu), W=num(W)))
        m = an.machine
        J, _, _ = self.value("J_F_indicator")
        Jm, _, _ = self.value("J_mean")
        out.append(self.say("J_F indicator", W=num(W), wm=num(m.omega_m), delta=num(m.delta), Jm=num(Jm), J=num(J)))
        return out


__all__ = ["PHRASES", "flywheel_steps", "protocol"]
