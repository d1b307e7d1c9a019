# godot-area: the Python example examples/python/area_lights_demo.py still runs (a scene built from
# nothing, a light animated over frames, a render, a matplotlib plot of the per-pass times).
import os
import subprocess
import sys

import pytest

import godot_area as ga

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def test_area_lights_demo_runs(rd, tmp_path):
	pytest.importorskip("matplotlib")
	png, exr, tscn = (str(tmp_path / name) for name in ("times.png", "last.exr", "demo.tscn"))
	env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.abspath(ga.__file__)), MPLCONFIGDIR=str(tmp_path / "mpl"))
	run = subprocess.run([sys.executable, os.path.join(ROOT, "examples", "python", "area_lights_demo.py"), "--frames", "2", "--warmup", "0",
			"--width", "32", "--height", "18", "--png", png, "--exr", exr, "--save-scene", tscn], capture_output=True, text=True, env=env, timeout=600)
	assert run.returncode == 0, "the example failed:\n%s\n%s" % (run.stdout, run.stderr)
	assert "opaque" in run.stdout and "wrote " + png in run.stdout, run.stdout
	with open(png, "rb") as f:
		assert f.read(8) == b"\x89PNG\r\n\x1a\n"
	image = ga.load_exr(exr)
	assert image.shape == (18, 32, 4) and image[..., :3].max() > 0.01
	scene = ga.load_scene(tscn)
	try:
		lights = [c for c in scene.get_children() if c.get_class() == "AreaLight3D"]
		assert len(lights) == 2, [c.name for c in scene.get_children()]
	finally:
		scene.free()
