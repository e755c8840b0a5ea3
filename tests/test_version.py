from pathlib import Path
import re

import graphmech
from graphmech.version import __version__


def test_one_version_read_by_the_package_and_pyproject():
    assert graphmech.__version__ == __version__ and re.fullmatch(r"\d+\.\d+\.\d+", __version__)
    pyproject = (Path(__file__).resolve().parents[1] / "pyproject.toml").read_text()
    assert 'version = {attr = "graphmech.version.__version__"}' in pyproject
