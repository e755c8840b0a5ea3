"""What is installed besides the code: the example scenes (figures/scenes), the docs (docs/) and
the scene templates — one copy each in the repository, installed as package data — and the
commands that hand them out, ``graphmech examples`` and ``graphmech new``."""
from __future__ import annotations

import re
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from graphmech import packaged
from graphmech.problems import check
from graphmech.scene import load_scene, render_scene
from tests.conftest import ROOT, SCENES, assert_refused, run_cli

PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["setuptools"]
SCENE_NAMES = sorted(p.stem for p in SCENES.glob("*.toml"))
DOCS = sorted(p.name for p in (ROOT / "docs").iterdir() if p.is_file() and not p.name.startswith("."))


# ---------------------------------------------------------------------------- packaging


def test_the_listed_packages_are_the_packages_on_disk_and_the_data_is_mapped_to_its_one_copy():
    on_disk = {".".join(p.parent.relative_to(ROOT).parts) for p in (ROOT / "graphmech").rglob("__init__.py")}
    data = {"graphmech.examples", "graphmech.docs", "graphmech.templates"}
    assert set(PYPROJECT["packages"]) == on_disk | data  # a new package must be listed, or it is not installed
    assert PYPROJECT["package-dir"] == {"graphmech.examples": "figures/scenes", "graphmech.docs": "docs"}
    assert not (ROOT / "graphmech" / "examples").exists() and not (ROOT / "graphmech" / "docs").exists()


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> Path:
    """The package as setuptools lays it out for a wheel (``build_py``), built from a copy of the
    repository's sources so that nothing is written into the checkout."""
    src = tmp_path_factory.mktemp("src")
    for name in ("pyproject.toml", "README.md"):
        shutil.copy2(ROOT / name, src / name)
    ignore = shutil.ignore_patterns("__pycache__", "*.pyc")
    for folder in ("graphmech", "figures/scenes", "docs"):
        shutil.copytree(ROOT / folder, src / folder, ignore=ignore)
    out = tmp_path_factory.mktemp("lib")
    done = subprocess.run([sys.executable, "-c", "from setuptools import setup; setup()", "-q", "build_py",
                           "--build-lib", str(out)], cwd=src, capture_output=True, text=True, timeout=300,
                          check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    return out


def test_a_build_installs_the_examples_docs_and_templates_as_package_data(built):
    lib = built / "graphmech"
    assert sorted(p.stem for p in (lib / "examples").glob("*.toml")) == SCENE_NAMES
    for name in SCENE_NAMES:
        assert (lib / "examples" / f"{name}.toml").read_bytes() == (SCENES / f"{name}.toml").read_bytes()
    assert sorted(p.name for p in (lib / "docs").iterdir()) == DOCS
    assert (lib / "docs" / "scene-format.md").read_bytes() == (ROOT / "docs" / "scene-format.md").read_bytes()
    assert sorted(p.stem for p in (lib / "templates").glob("*.toml")) == sorted(packaged.TEMPLATES)
    assert (lib / "py.typed").is_file() and (lib / "problems" / "linkage" / "__init__.py").is_file()


def test_an_installed_package_reads_its_own_data_through_importlib_resources(built, tmp_path):
    """Imported from the build (no checkout beside it), graphmech finds the examples it carries."""
    script = ("from graphmech import packaged; print(packaged.examples()); print(packaged.docs()); "
              "print(len(packaged.example_names())); print(packaged.example_title('bal.disc_static'))")
    done = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True, text=True,
                          timeout=120, env={"PYTHONPATH": str(built), "PATH": "/usr/bin:/bin"}, check=False)
    assert done.returncode == 0, done.stderr
    examples, docs, count, title = done.stdout.splitlines()
    assert Path(examples) == built / "graphmech" / "examples" and Path(docs) == built / "graphmech" / "docs"
    assert int(count) == len(SCENE_NAMES)
    assert title == "Static balancing of a disc: mass-radius polygon"


def test_a_checkout_reads_its_own_copies():
    assert Path(str(packaged.examples())) == SCENES and Path(str(packaged.docs())) == ROOT / "docs"
    assert packaged.example_names() == SCENE_NAMES


# ---------------------------------------------------------------------------- graphmech examples


def test_examples_lists_each_scene_with_its_title():
    code, out, err = run_cli("examples")
    assert code == 0 and err == ""
    lines = out.splitlines()
    assert [line.split()[0] for line in lines] == SCENE_NAMES
    for line, name in zip(lines, SCENE_NAMES):
        title = tomllib.loads((SCENES / f"{name}.toml").read_text(encoding="utf-8")).get("title", "")
        assert line.rstrip() == f"{name:<{max(map(len, SCENE_NAMES))}}  {title}".rstrip()


def test_examples_copies_one_and_never_overwrites(tmp_path):
    name = "cam.oscillating_roller"
    source = (SCENES / f"{name}.toml").read_bytes()
    code, out, err = run_cli("examples", name, "-d", str(tmp_path))
    assert (code, err) == (0, "") and out == f"{tmp_path / (name + '.toml')}\n"
    assert (tmp_path / f"{name}.toml").read_bytes() == source
    (tmp_path / f"{name}.toml").write_text("# my edits\n", encoding="utf-8")
    assert_refused(run_cli("examples", name, "-d", str(tmp_path)), "graphmech", "exists", "not overwriting")
    assert (tmp_path / f"{name}.toml").read_text(encoding="utf-8") == "# my edits\n"
    # -o FILE, and a name given with its .toml
    code, _, err = run_cli("examples", f"{name}.toml", "-o", str(tmp_path / "mine.toml"))
    assert (code, err) == (0, "") and (tmp_path / "mine.toml").read_bytes() == source
    assert_refused(run_cli("examples", name, "-o", str(tmp_path / "mine.toml")), "graphmech", "exists")
    assert_refused(run_cli("examples", name, "-o", str(tmp_path / "x.toml"), "-d", str(tmp_path)), "graphmech",
                   "not both")
    assert_refused(run_cli("examples", name, "-o", str(tmp_path / "no" / "x.toml")), "graphmech",
                   "folder does not exist")


def test_an_unknown_example_is_refused_with_the_closest_name(tmp_path):
    err = assert_refused(run_cli("examples", "linkage.slider_crank", "-d", str(tmp_path)), "graphmech",
                         "unknown example")
    assert "did you mean 'linkage.slider_crank_offset'?" in err
    err = assert_refused(run_cli("examples", "zzzz\x1b[31m"), "graphmech", "unknown example")
    assert "did you mean" not in err and "\x1b" not in err
    assert err.endswith("' (graphmech examples lists them)")  # not "…'; (graphmech …"
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------------------- graphmech new


def _reference(text: str) -> str:
    """The example scene a template is a commented copy of: the first "(graphmech examples NAME)"."""
    m = re.search(r"\(graphmech examples ([\w.-]+)\)", text)
    assert m, "a template names the example scene it copies"
    return m.group(1)


@pytest.mark.parametrize("kind", packaged.TEMPLATES)
def test_each_template_is_its_reference_scene_with_comments(kind):
    """The data is the reference scene's, so the template stays true as the scene format moves."""
    text = packaged.template(kind)
    name = _reference(text)
    assert tomllib.loads(text) == tomllib.loads((SCENES / f"{name}.toml").read_text(encoding="utf-8"))
    assert text.startswith(f"# graphmech new {kind}: ")
    assert "docs/scene-format.md" in text


@pytest.mark.parametrize("kind", packaged.TEMPLATES)
def test_each_key_of_a_template_is_explained_where_it_first_appears(kind):
    table, seen, previous, bare = "", set(), "", []
    for number, line in enumerate(packaged.template(kind).splitlines(), 1):
        s = line.strip()
        if (header := re.match(r"^\[\[?([^\]]+)\]\]?", s)) is not None:
            table = header.group(1)
        elif (key := re.match(r'^("[^"]+"|[\w-]+)\s*=', s)) is not None:
            if (table, key.group(1)) not in seen and "#" not in line and not previous.startswith("#"):
                bare.append(f"{number}: {line}")
            seen.add((table, key.group(1)))
        previous = s
    assert not bare, "keys without a comment:\n" + "\n".join(bare)


@pytest.mark.parametrize("kind", packaged.TEMPLATES)
def test_each_template_loads_renders_and_checks_as_written(kind, tmp_path):
    path = tmp_path / "s.toml"
    assert run_cli("new", kind, "-o", str(path)) == (0, f"{path}\n", "")
    assert path.read_text(encoding="utf-8") == packaged.template(kind)
    svg, _ = render_scene(path)
    assert svg.lstrip().startswith(("<?xml", "<svg")) and "</svg>" in svg
    an, verdicts, _, _ = check(load_scene(path))
    assert an.rows and all(v.ok for v in verdicts)
    assert all(r.rel_error < 0.05 for r in an.rows), [(r.name, r.rel_error) for r in an.rows]


def test_new_prints_to_stdout_and_never_overwrites(tmp_path):
    code, out, err = run_cli("new", "cam")
    assert (code, err) == (0, "") and out == packaged.template("cam")
    (tmp_path / "cam.toml").write_text("mine\n", encoding="utf-8")
    assert_refused(run_cli("new", "cam", "-o", str(tmp_path / "cam.toml")), "graphmech", "exists")
    assert (tmp_path / "cam.toml").read_text(encoding="utf-8") == "mine\n"
    assert_refused(run_cli("new", "cam", "-o", str(tmp_path)), "graphmech", "is a folder")


def test_an_unknown_template_is_refused_with_the_closest_kind():
    err = assert_refused(run_cli("new", "fly"), "graphmech", "unknown template")
    assert "did you mean 'flywheel'?" in err and "choose from linkage, cam, flywheel, forces" in err
    err = assert_refused(run_cli("new", "LINKAGE"), "graphmech", "unknown template 'LINKAGE'; did you mean 'linkage'?")


def test_the_templates_on_disk_are_the_kinds_listed():
    assert sorted(p.stem for p in (ROOT / "graphmech" / "templates").glob("*.toml")) == sorted(packaged.TEMPLATES)
