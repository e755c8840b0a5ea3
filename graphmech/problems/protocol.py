"""What every kind's construction protocol (``graphmech steps``) shares: its phrases in the
scene's notation, numbers as a drawing writes them, and a scale's choice.

A protocol is the list of a construction's steps as the book words them — "through b draw a
line ⟂ BC", "measure pc = 52.1 mm: v_C = pc·μv = 0.521 m/s" — with every length drawn and
every value read off, so a student can follow it against their own drawing (GeoGebra's
construction protocol is the model). The lines carry no numbers: the caller numbers them.
Each kind words its own steps with a phrase table laid out as
:data:`graphmech.drawing.notation.WORDS` is — key → (English, 中文, русский) — whose templates
take ``str.format`` fields.

>>> num(0.52134), num(-26.384), num(1234567.0)
('0.5213', '−26.38', '1.235×10⁶')
>>> phrase("measure", "zh", PHRASES, seg="pc", mm="52.1", value="v_C = pc·μv = 0.521 m/s")
'量得pc = 52.1 mm：v_C = pc·μv = 0.521 m/s'
"""
from __future__ import annotations

import math
from collections.abc import Mapping

from graphmech.drawing.lettering import number, runs
from graphmech.drawing.notation import word
from graphmech.problems.judging import Row, estimate_text
from graphmech.scales import ANGLE_SCALES, SCALE_INFO

#: A kind's phrases: key → (English, 中文, русский) templates with ``str.format`` fields.
Phrases = Mapping[str, tuple[str, str, str]]

_SUPERSCRIPT = str.maketrans("0123456789−-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁻")
_SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")

#: The phrases every kind's protocol uses.
PHRASES: Phrases = {
    "measure": ("measure {seg} = {mm} mm: {value}", "量得{seg} = {mm} mm：{value}",
                "измеряем {seg} = {mm} mm: {value}"),
    "stated": ("as the scene gives it", "题给", "задан"),
    "chosen": ("chosen to fit the page", "按图幅选取", "выбран по формату листа"),
    "counter-clockwise": ("counter-clockwise", "逆时针", "против часовой стрелки"),
    "clockwise": ("clockwise", "顺时针", "по часовой стрелке"),
    "read": ("read {name} = {drawn} mm × {mu} = {value}{unit}{acc}", "量得{name} = {drawn} mm × {mu} = {value}{unit}{acc}",
             "измеряем {name} = {drawn} mm × {mu} = {value}{unit}{acc}"),
    "value": ("{name} = {value}{unit}{acc}", "{name} = {value}{unit}{acc}", "{name} = {value}{unit}{acc}"),
}


def phrase(key: str, notation: str, table: Phrases, **fields: str) -> str:
    """The phrase ``key`` of ``table`` in ``notation`` (en, zh, ru), its fields filled in."""
    return word(key, notation, table).format(**fields)


def text(marked: str) -> str:
    """A drawing's marked-up text (``μ_{v}``, ``10^{6}``) as a line of plain text: a subscript's
    digits as subscript characters, its letters as they are; a superscript's as superscript
    characters.

    >>> text("μ_{v} = 2×10^{−6} (m/s)/mm"), text("ω_{2}")
    ('μv = 2×10⁻⁶ (m/s)/mm', 'ω₂')
    """
    out = []
    for t, level in runs(marked):
        out.append(t.translate(_SUPERSCRIPT) if level > 0 else t.translate(_SUBSCRIPT) if level < 0 else t)
    return "".join(out)


def num(x: float) -> str:
    """``x`` to four significant figures as a drawing writes it (a true minus, ×10ⁿ outside
    10⁻⁴ … 10⁶), in plain text."""
    return text(number(float(x)))


def scale(symbol: str, value: float) -> str:
    """A scale as the book states it, ``μv = 0.005 (m/s)/mm`` (four significant figures)."""
    shown = math.degrees(value) if symbol in ANGLE_SCALES else value
    sym, unit = SCALE_INFO[symbol]
    return f"{sym} = {num(shown)} {unit}"


def scale_choice(symbol: str, value: float, stated: bool, notation: str) -> str:
    """``μv = 0.005 (m/s)/mm (as the scene gives it)`` or ``(chosen to fit the page)``."""
    why = phrase("stated" if stated else "chosen", notation, PHRASES)
    return f"{scale(symbol, value)}（{why}）" if notation == "zh" else f"{scale(symbol, value)} ({why})"


def read_row(row: Row, notation: str) -> str:
    """A check table's row as the protocol reads it: ``read R_12 = 63.49 mm × 25 = 1587 N`` (drawn
    length × μ), or the value alone where nothing is drawn to be measured; a discretised or
    read-off value says how accurate its method estimates it, as the table does."""
    acc = f" {estimate_text(row)}" if row.error_estimate is not None else ""
    fields = {"name": row.name, "value": num(row.graphical), "unit": f" {row.unit}" if row.unit else "", "acc": acc}
    if row.drawn_mm is None or row.scale == 1.0:
        return phrase("value", notation, PHRASES, **fields)
    return phrase("read", notation, PHRASES, drawn=num(row.drawn_mm), mu=num(row.scale), **fields)


def sense(value: float, notation: str) -> str:
    """The sense of a signed angular rate (+ counter-clockwise), in words; "" for zero."""
    if value == 0.0:
        return ""
    return phrase("counter-clockwise" if value > 0 else "clockwise", notation, PHRASES)


__all__ = ["PHRASES", "Phrases", "num", "phrase", "read_row", "scale", "scale_choice", "sense", "text"]
