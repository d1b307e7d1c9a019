# godot-area: the benchmark charts are written atomically (misc/scripts/chart_io.py, issue 20): a
# failed write raises and leaves neither a partial chart nor a temporary file.
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "misc", "scripts"))
matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from chart_io import save_figure  # noqa: E402


def _figure():
	fig, ax = plt.subplots(figsize=(2, 2))
	ax.plot([0, 1], [1, 0])
	return fig


def test_save_figure_replaces_the_chart_whole(tmp_path):
	target = tmp_path / "chart.png"
	target.write_bytes(b"old")
	save_figure(_figure(), str(target), dpi=50)
	assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
	assert sorted(os.listdir(tmp_path)) == ["chart.png"]


def test_a_failed_render_keeps_the_old_chart_and_no_temporary(tmp_path):
	target = tmp_path / "chart.png"
	target.write_bytes(b"old")
	with pytest.raises(ValueError):
		save_figure(_figure(), str(target), format="no-such-format")
	assert target.read_bytes() == b"old"
	assert sorted(os.listdir(tmp_path)) == ["chart.png"]


def test_a_missing_folder_raises(tmp_path):
	with pytest.raises(OSError):
		save_figure(_figure(), str(tmp_path / "missing" / "chart.png"))
	assert not (tmp_path / "missing").exists()
