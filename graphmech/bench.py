"""Benchmarks: run time and error of the graphical methods against the exact solutions.

Speed is measured here, never in timed tests. Each record is
``{"method", "case", "n", "seconds", "max_rel_error"}`` (some methods add fields of their own);
``seconds`` is the best of several repetitions of one whole run over ``n`` positions (for the cam
inversion: ``n`` divisions of the turn). Each kind of problem times its own methods
(``graphmech/problems/<kind>/bench.py``, its ``Kind.bench``); this module runs them all, kind
by kind from the linkage to the kinds built on it (:data:`graphmech.problems.KINDS` read
backwards), and times one whole sheet, 100 variants of one scene and every example scene
(figure and check) on a process pool.
"""
from __future__ import annotations

import json
import math
import os
import time
from importlib.resources import as_file
from pathlib import Path
from typing import Any

from graphmech.errors import SceneError
from graphmech.packaged import examples
from graphmech.problems import KINDS
from graphmech.scene import render_scene
from graphmech.timing import best_time

#: The full-cycle sheet timed from the scene file to the SVG: an example scene, installed with
#: the package (graphmech.packaged).
SHEET_SCENE = "linkage.slider_crank_offset-cycle.toml"
#: The scene whose variants the batch record makes: a teacher's exercise, one per crank angle.
BATCH_SCENE = "kin.oscillating_block.toml"
#: Variants in the batch record (``--quick``: fewer).
BATCH_VARIANTS, BATCH_VARIANTS_QUICK = 100, 12
#: ``--quick``: the reference-scenes record takes every this many of the example scenes.
REFERENCE_STRIDE_QUICK = 10
#: What a reference scene may take on average, figure and check (issue 23), s.
REFERENCE_TARGET_S = 0.1


def batch_record(quick: bool = False) -> dict[str, Any]:
    """The time to make the figures (SVG) and checks of ``BATCH_VARIANTS`` variants of one scene
    (the crank angle over a turn) on every core, as ``graphmech batch`` does, but writing
    nothing; ``max_rel_error`` is the largest of all their check tables."""
    from graphmech import batch

    n = BATCH_VARIANTS_QUICK if quick else BATCH_VARIANTS
    with as_file(examples().joinpath(BATCH_SCENE)) as scene:
        todo = batch.jobs([str(scene)], [{"driver.angle": round(360.0 * k / n, 6)} for k in range(n)])
        start = time.perf_counter()
        results = batch.run(todo, batch.Options(figure="svg", check=True))
        seconds = time.perf_counter() - start
    failed = [r.error for r in results if r.error is not None]
    errors = [row.rel_error for r in results if r.table is not None for row in r.table]
    return {"method": "batch", "case": "oscillating-block-variants", "n": n, "seconds": seconds,
            "max_rel_error": max(errors) if errors else None, "failed": len(failed), "workers": os.cpu_count() or 1,
            "note": f"{n} variants of the example scene {BATCH_SCENE} (figure + check each), on a process pool"}


def batch_note(record: dict[str, Any]) -> str:
    """The bench's note on the variants: their time on the pool."""
    return (f"batch: {record['n']} variants (figure and check each) in {record['seconds']:.2f} s on "
            f"{record.get('workers', 1)} processes ({1e3 * record['seconds'] / max(1, record['n']):.0f} ms each)")


def reference_record(quick: bool = False) -> dict[str, Any]:
    """The time to make the figure (SVG) and the check of every example scene — the reference
    scenes of figures/scenes, installed with the package — on every core in one run, as
    ``graphmech batch`` does, but writing nothing (``quick``: every
    :data:`REFERENCE_STRIDE_QUICK`-th of them). A scene that fails is counted in ``failed``."""
    from contextlib import ExitStack

    from graphmech import batch
    from graphmech.packaged import example_names

    names = example_names()
    if quick:
        names = names[::REFERENCE_STRIDE_QUICK]
    folder = examples()
    with ExitStack() as stack:
        paths = [str(stack.enter_context(as_file(folder.joinpath(f"{n}.toml")))) for n in names]
        cpu0, start = _cpu_seconds(), time.perf_counter()
        results = batch.run(batch.jobs(paths, []), batch.Options(figure="svg", check=True))
        seconds, cpu = time.perf_counter() - start, _cpu_seconds() - cpu0
    n = len(names)
    workers = max(1, min(os.cpu_count() or 1, n))
    return {"method": "reference-scenes", "case": f"every-{REFERENCE_STRIDE_QUICK}th-example" if quick
            else "all-examples", "n": n, "seconds": seconds, "max_rel_error": None,
            "failed": sum(1 for r in results if r.error is not None), "workers": workers,
            "per_scene": seconds / max(1, n), "cpu_seconds": cpu,
            "note": f"{n} example scenes (figures/scenes), figure + check each, on a process pool: "
                    f"{1e3 * seconds / max(1, n):.0f} ms a scene"}


def _cpu_seconds() -> float:
    """CPU time of this process and of its children that have ended (the pool's workers, once it
    has closed), s: what the scenes cost whatever else the machine runs."""
    try:
        import resource
    except ImportError:  # not on Windows: no such count
        return 0.0
    me, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return me.ru_utime + me.ru_stime + kids.ru_utime + kids.ru_stime


def reference_note(record: dict[str, Any]) -> str:
    """The bench's note on the reference scenes: their time against the target."""
    each = record["per_scene"]
    verdict = "within" if each <= REFERENCE_TARGET_S else "OVER"
    failed = f", {record['failed']} FAILED" if record.get("failed") else ""
    return (f"reference scenes: {record['n']} example scenes (figure and check each) in {record['seconds']:.2f} s "
            f"on {record.get('workers', 1)} processes, {1e3 * each:.0f} ms a scene ({verdict} the target of "
            f"{1e3 * REFERENCE_TARGET_S:.0f} ms); CPU {record.get('cpu_seconds', 0.0):.1f} s in all{failed}")


def sheet_record(repeat: int = 3) -> dict[str, Any]:
    """The time to render the 12-position full-cycle sheet of the offset slider-crank, from the
    scene file to the SVG text."""
    with as_file(examples().joinpath(SHEET_SCENE)) as scene:
        secs = best_time(lambda: render_scene(scene), repeat)[0]
    return {"method": "full-cycle-sheet", "case": "slider-crank-offset-12", "n": 12,
            "seconds": secs, "max_rel_error": None, "note": f"render of the example scene {SHEET_SCENE}"}


def sheet_note(record: dict[str, Any]) -> str:
    """The bench's note on the timed sheet."""
    return f"full-cycle sheet, 12 positions ({record['case']}): rendered in {record['seconds'] * 1e3:.0f} ms"


#: The cycle whose memory the ``cycle-memory`` record measures: the offset slider-crank's sheet
#: scene, checked at the most positions a scene may have.
MEMORY_POSITIONS = 3600


def memory_record(quick: bool = False) -> dict[str, Any]:
    """The check of a 3600-position full cycle (the example scene SHEET_SCENE with that many
    positions): its time (best of 3, one run with ``quick``) and the peak of the memory Python and
    numpy allocate for it (tracemalloc, in a run of its own: tracing slows it down)."""
    import tracemalloc

    from graphmech import api

    with as_file(examples().joinpath(SHEET_SCENE)) as scene:
        cycle = api.load(scene).replace({"cycle.positions": MEMORY_POSITIONS})
    secs, table = best_time(cycle.check, 1 if quick else 3)
    tracemalloc.start()
    try:
        cycle.check()
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    errors = [row.rel_error for row in table.rows if row.rel_error is not None]
    return {"method": "cycle-memory", "case": "slider-crank-offset-3600", "n": MEMORY_POSITIONS, "seconds": secs,
            "max_rel_error": max(errors) if errors else None, "peak_mib": peak / 2**20,
            "note": f"check of {SHEET_SCENE} at {MEMORY_POSITIONS} positions; peak_mib: tracemalloc's peak"}


def memory_note(record: dict[str, Any]) -> str:
    """The bench's note on the memory of a long cycle."""
    return (f"full cycle, {record['n']} positions ({record['case']}): checked in {record['seconds']:.2f} s, "
            f"memory peak {record['peak_mib']:.1f} MiB")


def run_bench(quick: bool = False, explicit: bool = False) -> dict[str, Any]:
    """All benchmark records, plus notes comparing them with the targets; ``explicit``: also
    RK45's steps on the stiff flywheel (the demonstration that the stiff solvers earn their place)."""
    records: list[dict[str, Any]] = []
    notes: list[str] = []
    for kind in reversed(KINDS.values()):  # the four-bar's polygons first, as the README presents them
        if kind.bench is not None:
            more, said = kind.bench(quick)
            records += more
            notes += said
    if explicit:
        from graphmech.problems.flywheel.bench import explicit_record, true_motion_notes

        records.append(explicit_record(quick))
        notes += [n for n in true_motion_notes(records) if n.startswith("RK45")]
    sheet = sheet_record(repeat=1 if quick else 3)
    notes.append(sheet_note(sheet))
    many = batch_record(quick)
    notes.append(batch_note(many))
    scenes = reference_record(quick)
    notes.append(reference_note(scenes))
    memory = memory_record(quick)
    notes.append(memory_note(memory))
    return {"records": records + [sheet, many, scenes, memory], "notes": notes}


# ---------------------------------------------------------------------------- comparing two runs

#: The fields that tell one record from another besides method, case and n (the integrators').
KEY_FIELDS = ("solver", "rtol")


def record_key(r: dict[str, Any]) -> tuple[Any, ...]:
    """What names a record across runs: method, case, n and, for an integrator, solver and rtol."""
    return (r["method"], r["case"], r["n"], *(r.get(k) for k in KEY_FIELDS))


def read_records(path: str | Path) -> list[dict[str, Any]]:
    """The records of an earlier ``bench.json``; a file that is not one is a one-line SceneError
    naming the key path (``records[3].seconds``), read before any bench runs."""
    name = str(path)
    try:
        doc = json.loads(Path(path).read_text(encoding="utf-8"))
    except OSError as e:
        raise SceneError([("", f"cannot read it ({e.strerror or e})")], name) from None
    except (UnicodeDecodeError, json.JSONDecodeError) as e:
        raise SceneError([("", f"not a bench.json ({e})")], name) from None
    records = doc.get("records") if isinstance(doc, dict) else None
    if not isinstance(records, list):
        raise SceneError([("records", "missing: a bench.json written by graphmech bench -o DIR has a list of records")],
                         name)
    for i, r in enumerate(records):
        if not isinstance(r, dict):
            raise SceneError([(f"records[{i}]", "must be a table of method, case, n, seconds")], name)
        for k, what in (("method", "a name"), ("case", "a name"), ("n", "a whole number"),
                        ("seconds", "a positive number")):
            if not _field_ok(k, r.get(k)):
                raise SceneError([(f"records[{i}].{k}", f"must be {what}, not {r.get(k)!r}")], name)
    return records


def _field_ok(key: str, v: Any) -> bool:
    if key in ("method", "case"):
        return isinstance(v, str)
    if isinstance(v, bool):
        return False
    if key == "n":
        return isinstance(v, int)
    return isinstance(v, (int, float)) and math.isfinite(v) and v > 0


def compare(old: list[dict[str, Any]], new: list[dict[str, Any]]) -> list[str]:
    """One line per record: its time before and after and the ratio (and the error where it
    changed); records only in one run are listed as new or gone."""
    before = {record_key(r): r for r in old}
    now = {record_key(r): r for r in new}
    lines = []
    for key, r in now.items():
        name = f"{r['method']} {r['case']} n={r['n']}" + "".join(f" {k}={r[k]}" for k in KEY_FIELDS if r.get(k) is not None)
        o = before.get(key)
        if o is None:
            lines.append(f"{name}: {r['seconds'] * 1e6:.1f} µs (new)")
            continue
        ratio = r["seconds"] / o["seconds"]
        err = ""
        e0, e1 = o.get("max_rel_error"), r.get("max_rel_error")
        if e0 != e1 and e0 is not None and e1 is not None:
            err = f", error {e0:.1e} → {e1:.1e}"
        lines.append(f"{name}: {o['seconds'] * 1e6:.1f} → {r['seconds'] * 1e6:.1f} µs (×{ratio:.2f}){err}")
    for key, o in before.items():
        if key not in now:
            lines.append(f"{o['method']} {o['case']} n={o['n']}: gone")
    return lines
