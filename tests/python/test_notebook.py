"""docs/notebooks/lecture.ipynb: every code cell runs with this build's module, and the file
keeps its outputs so that it reads without running."""

import json
import os
import subprocess
import sys

from conftest import SOURCE

NOTEBOOK = os.path.join(SOURCE, "docs", "notebooks", "lecture.ipynb")


def test_every_code_cell_has_its_outputs_saved():
    with open(NOTEBOOK, encoding="utf-8") as f:
        cells = json.load(f)["cells"]
    code = [c for c in cells if c["cell_type"] == "code"]
    assert len(code) >= 10
    for number, cell in enumerate(code, 1):
        assert cell["outputs"], f"code cell {number} has no saved output"
        assert cell["execution_count"] == number


def test_every_code_cell_runs(tmp_path):
    # A copy, so that running it leaves the repository's file alone.
    copy = tmp_path / "lecture.ipynb"
    with open(NOTEBOOK, encoding="utf-8") as f:
        copy.write_text(f.read(), encoding="utf-8")
    # The copy is outside the repository: point it at the repository's scenes.
    (tmp_path / "scenes").symlink_to(os.path.join(SOURCE, "scenes"))
    (tmp_path / "scenes" / "assignment.json").stat()
    result = subprocess.run(
        [sys.executable, os.path.join(SOURCE, "scripts", "run-notebook.py"), str(copy)],
        capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert "code cells ran" in result.stdout
