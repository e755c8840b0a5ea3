"""Many figures and checks: render/check --set, graphmech batch on a process pool, each job
all-or-nothing, each failure one line."""
from __future__ import annotations

import json

import pytest

import graphmech as gm
from graphmech import batch
from tests.conftest import SCENES, run_cli

BLOCK = SCENES / "kin.oscillating_block.toml"
CRANK = SCENES / "linkage.slider_crank_offset.toml"


def test_jobs_are_every_scene_with_every_variant():
    todo = batch.jobs([str(BLOCK), str(CRANK)], [{"driver.angle": 30}, {"driver.angle": 40}], "A4")
    assert [(j.file, j.variant, j.page) for j in todo] == [
        ("kin.oscillating_block.toml", {"driver.angle": 30}, "A4"), ("kin.oscillating_block.toml", {"driver.angle": 40}, "A4"),
        ("linkage.slider_crank_offset.toml", {"driver.angle": 30}, "A4"),
        ("linkage.slider_crank_offset.toml", {"driver.angle": 40}, "A4")]
    assert todo[0].label == "kin.oscillating_block.toml [driver.angle=30]" and batch.jobs(["a"], []) == [batch.Job("a")]


def test_a_job_that_fails_is_a_result_with_its_one_line_never_an_exception():
    bad = batch.make(batch.Job(str(BLOCK), {"driver.angel": 1}), batch.Options(check=True))
    assert not bad.ok and bad.error == ("kin.oscillating_block.toml [driver.angel=1]: "
                                        "driver.angel: not in the scene; did you mean angle? (--set changes a value "
                                        "the scene has; add a new key in the file)")
    missing = batch.make(batch.Job("nowhere/x.toml"), batch.Options())
    assert missing.error is not None and "cannot read the file" in missing.error and "\n" not in missing.error


def test_the_pool_gives_the_same_results_in_order_as_one_process():
    todo = batch.jobs([str(BLOCK)], [{"driver.angle": a} for a in (10, 20, 30, 40, 50)])
    options = batch.Options(check=True)
    seen: list[str] = []
    pooled = batch.run(todo, options, workers=2, done=lambda r: seen.append(r.name))
    alone = batch.run(todo, options, workers=1)
    assert [r.name for r in pooled] == seen == [r.name for r in alone] == [
        f"kin.oscillating_block-driver.angle={a}" for a in (10, 20, 30, 40, 50)]
    assert [r.figure for r in pooled] == [r.figure for r in alone]
    assert [r.table.to_dict() for r in pooled if r.table] == [r.table.to_dict() for r in alone if r.table]


def test_render_set_writes_one_figure_per_combination(tmp_path):
    code, out, err = run_cli("render", str(BLOCK), "--set", "driver.angle=30,60", "--set", "driver.omega=10",
                             "-d", str(tmp_path), "-q")
    names = ["kin.oscillating_block-driver.angle=30-driver.omega=10.svg",
             "kin.oscillating_block-driver.angle=60-driver.omega=10.svg"]
    assert code == 0 and err == "" and out.split() == [str(tmp_path / n) for n in names]
    assert sorted(p.name for p in tmp_path.iterdir()) == names
    expected = gm.load(BLOCK).replace({"driver.angle": 60, "driver.omega": 10}).render().svg
    assert (tmp_path / names[1]).read_text(encoding="utf-8") == expected


def test_render_set_with_one_output_file_needs_a_folder(tmp_path):
    code, out, err = run_cli("render", str(BLOCK), "--set", "driver.angle=30,60", "-o", str(tmp_path / "x.svg"))
    assert code == 2 and out == "" and err == "graphmech: -o takes one figure; this makes 2 (one per variant): use -d DIR\n"
    code, _, _ = run_cli("render", str(BLOCK), "--set", "driver.angle=30", "-o", str(tmp_path / "x.svg"))
    assert code == 0 and (tmp_path / "x.svg").is_file()


def test_render_with_a_failing_variant_writes_nothing(tmp_path):
    code, out, err = run_cli("render", str(CRANK), "--set", "driver.angle=50,60", "--set", "dyad[0].length=300,10",
                             "-d", str(tmp_path))
    assert code == 2 and out == "" and err.count("\n") == 1 and list(tmp_path.iterdir()) == []
    assert err.startswith("linkage.slider_crank_offset.toml [driver.angle=50, dyad[0].length=10]: ")


def test_check_set_prints_one_row_per_variant():
    code, out, err = run_cli("check", str(BLOCK), "--set", "driver.angle=30,45", "-q")
    lines = out.splitlines()
    assert code == 0 and err == "" and len(lines) == 3
    assert lines[0].split()[:3] == ["variant", "l_BC", "(m)"]
    exact = gm.load(BLOCK).replace({"driver.angle": 45}).check()["omega_2"].graphical
    assert lines[2].split()[0] == "kin.oscillating_block-driver.angle=45" and f"{exact:.6g}" in lines[2].split()
    code, out, _ = run_cli("check", str(BLOCK), "--set", "driver.angle=30,45", "--json")
    docs = json.loads(out)
    assert code == 0 and [d["variant"] for d in docs] == [{"driver.angle": 30}, {"driver.angle": 45}]
    assert docs[1]["quantities"] == gm.load(BLOCK).replace({"driver.angle": 45}).check().to_dict()["quantities"]


def test_check_set_prints_each_variants_verdicts_on_the_measured_values():
    """Exit 1 says a measured value is out: the text says which, in which variant."""
    code, out, _ = run_cli("check", str(BLOCK), "--set", "driver.angle=30,45", "--measured", "pe=3", "-q")
    expected = [gm.load(BLOCK).replace({"driver.angle": a}).check({"pe": 3}).measured[0].expected for a in (30, 45)]
    blocks = out.split("\n\n")
    assert code == 1 and len(blocks) == 3 and len(blocks[0].splitlines()) == 3
    for block, angle, value in zip(blocks[1:], (30, 45), expected):
        head, columns, verdict = block.splitlines()
        assert head == f"kin.oscillating_block-driver.angle={angle}:" and columns.split()[0] == "measured"
        assert verdict.split()[:3] == ["pe", "3", f"{value:.6g}"] and "OUT OF TOLERANCE (mm; drawing precision" in verdict


def test_check_set_with_a_failing_variant_reports_it_and_exits_2():
    code, out, err = run_cli("check", str(CRANK), "--set", "driver.omega=10,fast", "-q")
    assert code == 2 and len(out.splitlines()) == 2  # the header and the one variant that could be made
    assert err.count("\n") == 1 and err.startswith("linkage.slider_crank_offset.toml [driver.omega=fast]: ")


def test_batch_writes_the_good_jobs_and_reports_each_failure(tmp_path):
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    broken = tmp_path / "broken.toml"
    broken.write_text("title = 1\n", encoding="utf-8")
    code, out, err = run_cli("batch", str(BLOCK), str(CRANK), str(broken), "--set", "driver.angle=30,50",
                             "-d", str(out_dir), "-j", "2", "-q")
    assert code == 2
    made = sorted(p.name for p in out_dir.iterdir())
    assert made == sorted(f"{s}-driver.angle={a}.{x}" for s in ("kin.oscillating_block", "linkage.slider_crank_offset")
                          for a in (30, 50) for x in ("svg", "json"))
    lines = err.splitlines()
    assert len(lines) == 3 and lines[-1] == "graphmech: 2 of 6 failed; the other 4 written"
    assert all(line.startswith("broken.toml [driver.angle=") for line in lines[:2])
    doc = json.loads((out_dir / "linkage.slider_crank_offset-driver.angle=50.json").read_text(encoding="utf-8"))
    assert doc["variant"] == {"driver.angle": 50}
    assert doc["quantities"] == gm.load(CRANK).replace({"driver.angle": 50}).check().to_dict()["quantities"]
    assert len(out.split()) == 4


@pytest.mark.parametrize("command", ["render", "batch"])
def test_jobs_that_would_write_the_same_files_are_refused_before_anything_is_made(tmp_path, command):
    """Two crank.toml in two folders, one scene twice, 30 and 30.0: else the last silently replaced the others."""
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    for folder in ("a", "b"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "s.toml").write_bytes(BLOCK.read_bytes())
    a, b = str(tmp_path / "a" / "s.toml"), str(tmp_path / "b" / "s.toml")
    for args, words in [([a, b], f"{a} and {b} would both be written as s: "),
                        ([a, a], f"{a} and {a} would both be written as s: "),
                        ([a, "--set", "driver.angle=30,30.0"],
                         f"{a} [driver.angle=30] and {a} [driver.angle=30] would both be written as s-driver.angle=30: ")]:
        code, out, err = run_cli(command, *args, "-d", str(out_dir))
        assert code == 2 and out == "" and err.startswith("graphmech: " + words) and err.count("\n") == 1, err
        assert list(out_dir.iterdir()) == []


def test_render_refuses_an_output_file_and_a_folder_together(tmp_path):
    code, out, err = run_cli("render", str(BLOCK), "-o", str(tmp_path / "x.svg"), "-d", str(tmp_path))
    assert (code, out, err) == (2, "", "graphmech: give -o FILE or -d DIR, not both\n")
    assert list(tmp_path.iterdir()) == []


def test_a_variant_whose_name_is_too_long_for_a_file_is_written_under_a_shorter_one(tmp_path):
    """A 150-character Chinese title is 450 bytes: as a file name it could not be written (a batch
    once wrote its figure and failed on its check's .json)."""
    code, out, err = run_cli("batch", str(BLOCK), "--set", 'title="' + "长" * 150 + '"', "-d", str(tmp_path), "-q")
    made = sorted(p.name for p in tmp_path.iterdir())
    assert code == 0 and err == "" and len(made) == 2 and out.split() == [str(tmp_path / made[1])]
    assert made[0].endswith(".json") and made[1] == made[0][:-5] + ".svg"
    assert made[0].startswith("kin.oscillating_block-title=长长") and len(made[0].encode()) <= 200 + len(".json")


def test_batch_refuses_a_missing_folder_and_bad_job_counts(tmp_path):
    code, _, err = run_cli("batch", str(BLOCK), "-d", str(tmp_path / "none"))
    assert code == 2 and err == f"graphmech: {tmp_path / 'none'}: folder does not exist\n"
    for bad in ("0", "x", "1000"):
        with pytest.raises(SystemExit) as e:
            run_cli("batch", str(BLOCK), "-d", str(tmp_path), "-j", bad)
        assert e.value.code == 2


def test_quiet_silences_warnings_not_errors(tmp_path):
    wide = "figures/scenes/kin.oscillating_block.toml"
    code, _, err = run_cli("render", wide, "--set", "driver.omega=20", "-o", str(tmp_path / "w.svg"))
    assert code == 0 and "warning:" in err
    code, _, err = run_cli("render", wide, "--set", "driver.omega=20", "-o", str(tmp_path / "w.svg"), "-q")
    assert code == 0 and err == ""
    code, _, err = run_cli("render", wide, "--set", "driver.nope=1", "-o", str(tmp_path / "w.svg"), "-q")
    assert code == 2 and "driver.nope: not in the scene" in err


def test_batch_prints_pdf_and_png_with_one_browser_per_process(tmp_path):
    import os

    from pypdf import PdfReader

    from graphmech.render.chromium import find_chromium
    from tests.browser import no_browser

    if find_chromium() is None:
        no_browser("CI" in os.environ)
    out = tmp_path / "out"
    out.mkdir()
    code, printed, err = run_cli("batch", str(BLOCK), "--set", "driver.angle=10,20,30,40", "-d", str(out),
                                 "--format", "pdf", "-j", "2", "-q")
    assert code == 0 and err == "" and len(printed.split()) == 4
    for a in (10, 20, 30, 40):
        pdf = PdfReader(out / f"kin.oscillating_block-driver.angle={a}.pdf")
        box = pdf.pages[0].mediabox
        assert len(pdf.pages) == 1 and abs(float(box.width) / 72 * 25.4 - 297) < 0.1
    code, _, err = run_cli("render", str(BLOCK), "--set", "driver.angle=10,20", "-d", str(out), "--format", "png",
                           "--dpi", "50", "-q")
    from PIL import Image

    with Image.open(out / "kin.oscillating_block-driver.angle=20.png") as im:
        assert code == 0 and im.size == (round(297 / 25.4 * 50), round(210 / 25.4 * 50))
    assert batch._BROWSER == []  # closed when the run is done
