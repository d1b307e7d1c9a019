# godot-area: pytest tests of rendering through the Python module `godot_area`: a frame to NumPy,
# the same scene through the CLI (bit-identical), frames with a per-frame callback, EXR files.
import math
import os
import subprocess

import numpy as np
import pytest

import godot_area as ga
from ga_helpers import build_scene, exr_channel_types, look_at

WIDTH, HEIGHT = 48, 32  # Tiny: lavapipe on 2 CPU cores.


def test_render_to_numpy(tree):
	scene = tree.root.add_child(build_scene())
	assert scene.is_inside_tree() and scene.get_path() == "/root/Scene"
	assert tree.camera is scene.get_node("Camera")
	image = ga.render(WIDTH, HEIGHT)
	assert image.shape == (HEIGHT, WIDTH, 4) and image.dtype == np.float32
	assert np.isfinite(image).all()
	assert image[..., :3].max() > 0.01, image[..., :3].max()
	assert tree.size == (WIDTH, HEIGHT)

	# Without the fill light the image changes: it is the engine's, not a constant.
	scene.get_node("Fill").light_energy = 0.0
	key_only = ga.render()
	assert not np.allclose(key_only, image)


def test_render_matches_the_cli_exactly(tree, cli, tmp_path):
	"""The same .tscn rendered by `godot-area render` (its own process, a fresh tree) and by the
	module (after other renders in this process) gives bit-identical pixels. The CLI writes a
	32-bit float EXR (no --half), so the file holds the renderer's float32 values unchanged; the
	header is checked so a half-float file cannot pass by accident."""
	scene_path = str(tmp_path / "scene.tscn")
	ga.save_scene(build_scene(), scene_path)
	cli_path = str(tmp_path / "cli.exr")
	run = subprocess.run([cli, "render", scene_path, "-o", cli_path, "--width", str(WIDTH), "--height", str(HEIGHT)],
			capture_output=True, text=True, timeout=300)
	assert run.returncode == 0, "godot-area render failed:\n%s\n%s" % (run.stdout, run.stderr)
	assert "scene-linear float" in run.stdout, run.stdout
	assert set(exr_channel_types(cli_path).values()) == {"float"}, exr_channel_types(cli_path)

	tree.root.add_child(ga.load_scene(scene_path))
	image = ga.render(WIDTH, HEIGHT)
	reference = ga.load_exr(cli_path)
	assert reference.shape == image.shape and reference.dtype == image.dtype == np.float32
	assert image[..., :3].max() > 0.01 and image[..., :3].std() > 0.0, "a black or flat image proves nothing"
	differing = np.argwhere(image != reference)
	if len(differing):
		first = tuple(differing[0])
		pytest.fail("%d of %d values differ; first at %s: module %.9g, CLI %.9g; max |diff| %.3g" % (len(differing), image.size, first,
				image[first], reference[first], np.abs(image.astype(np.float64) - reference).max()))


def test_run_frames_with_callback(tree):
	scene = tree.root.add_child(build_scene())
	key = scene.get_node("Key")
	before = ga.render(WIDTH, HEIGHT)
	seen = []

	def move(frame, tree_arg):
		assert tree_arg.root is tree.root
		seen.append(frame)
		key.position = (1.5 + 0.2 * frame, 2.0, 0.5)

	profiles = ga.run_frames(3, move)
	assert seen == [0, 1, 2]
	assert len(profiles) == 3 and all(isinstance(p, dict) and p for p in profiles), profiles
	assert all(isinstance(ms, float) and ms >= 0.0 and math.isfinite(ms) for p in profiles for ms in p.values())
	assert "opaque" in profiles[-1], profiles[-1]
	assert key.position == pytest.approx((1.9, 2.0, 0.5))
	moved = ga.render()
	assert np.isfinite(moved).all()
	assert np.abs(moved - before).max() > 1e-3, "moving the light must change the image"
	with pytest.raises(ValueError):
		ga.run_frames(-1)
	with pytest.raises(ZeroDivisionError):  # An exception in the callback reaches the caller.
		ga.run_frames(2, lambda frame, t: 1 / 0)


@pytest.mark.parametrize("width, height", [(20000, 20000), (0, 16), (16, 0), (-4, 16), (16, 16385)])
def test_run_frames_rejects_sizes_out_of_range(tree, width, height):
	tree.root.add_child(build_scene())
	with pytest.raises(ValueError, match="out of range"):
		ga.run_frames(1, None, width, height)


def test_run_frames_draws_at_the_size_it_is_given(tree):
	tree.root.add_child(build_scene())
	profiles = ga.run_frames(1, None, 24, 16)
	assert len(profiles) == 1 and "opaque" in profiles[0], profiles
	assert ga.render().shape[:2] == (16, 24)  # The tree keeps the size of the last draw.


def test_exr_round_trip(tree, tmp_path):
	tree.root.add_child(build_scene())
	image = ga.render(WIDTH, HEIGHT)
	path = str(tmp_path / "frame.exr")
	ga.save_exr(image, path)
	assert set(exr_channel_types(path).values()) == {"float"}
	assert np.array_equal(ga.load_exr(path), image)  # 32-bit float: lossless.
	half = str(tmp_path / "half.exr")
	ga.save_exr(image, half, half=True)
	assert set(exr_channel_types(half).values()) == {"half"}
	assert np.allclose(ga.load_exr(half), image, rtol=1e-3, atol=1e-4)  # 11-bit mantissa.
	gray = np.full((4, 5), 0.5, np.float32)
	assert np.array_equal(ga.load_exr(_saved(gray, tmp_path))[..., :3], np.full((4, 5, 3), 0.5, np.float32))
	with pytest.raises(ValueError):
		ga.save_exr(np.zeros((4, 5, 2), np.float32), str(tmp_path / "bad.exr"))
	with pytest.raises(OSError):
		ga.load_exr(str(tmp_path / "missing.exr"))


def test_save_exr_reports_failed_writes_and_leaves_no_file(tmp_path):
	image = np.full((4, 5, 4), 0.5, np.float32)
	if os.path.exists("/dev/full"):
		with pytest.raises(OSError, match="/dev/full"):
			ga.save_exr(image, "/dev/full")  # Every write fails with ENOSPC.
	missing = tmp_path / "no_such_folder" / "frame.exr"
	with pytest.raises(OSError, match="no_such_folder"):
		ga.save_exr(image, str(missing))
	assert not missing.parent.exists()
	target = tmp_path / "kept.exr"
	ga.save_exr(image, str(target))
	assert sorted(os.listdir(tmp_path)) == ["kept.exr"]  # No temporary left beside it.


def _saved(array, tmp_path):
	path = str(tmp_path / "array.exr")
	ga.save_exr(array, path)
	return path


def test_render_errors_and_freed_nodes(tree):
	with pytest.raises(RuntimeError, match="Camera3D"):
		ga.render(WIDTH, HEIGHT)  # Empty tree: nothing to render from.
	scene = tree.root.add_child(build_scene())
	key = scene.get_node("Key")
	tree.root.remove_child(scene)
	assert not scene.is_inside_tree() and tree.camera is None
	scene.free()
	assert not key.is_valid()
	with pytest.raises(RuntimeError, match="freed"):
		key.area_size


def _floor_scene(size_after_assignment):
	scene = ga.create("Node3D")
	floor = scene.add_child(ga.create("MeshInstance3D"))
	plane = ga.create("PlaneMesh")
	if size_after_assignment:
		floor.mesh = plane
		plane.size = (6, 6)
	else:
		plane.size = (6, 6)
		floor.mesh = plane
	camera = scene.add_child(ga.create("Camera3D"))
	camera.transform = [[1, 0, 0, 0], [0, 0.8, 0.6, 3], [0, -0.6, 0.8, 4]]
	light = scene.add_child(ga.create("AreaLight3D"))
	light.transform = [[1, 0, 0, 0], [0, 0, 1, 2], [0, -1, 0, 0]]
	light.area_size = (2, 1)
	return scene


def test_mesh_resource_changes_after_assignment_are_rendered(tree):
	expected_scene = tree.root.add_child(_floor_scene(size_after_assignment=False))
	expected = ga.render(WIDTH, HEIGHT)
	tree.root.remove_child(expected_scene)
	expected_scene.free()
	tree.root.add_child(_floor_scene(size_after_assignment=True))
	assert np.array_equal(ga.render(WIDTH, HEIGHT), expected)


def test_render_settles_adaptive_shadows(tree):
	"""An AREA_SHADOW_ADAPTIVE light refines over frames: render() draws until it settles (the key light's
	penumbra seen from close by refines beyond the root quad), render(settle_frames=1) draws one frame."""
	scene = tree.root.add_child(build_scene())
	scene.get_node("Key").area_shadow_mode = 2  # AREA_SHADOW_ADAPTIVE.
	# Close above the box's shadow edge, so the penumbra spans many reprojection cells.
	scene.get_node("Camera").transform = look_at((0.45, 0.6, 0.5), (0.45, 0.0, 0.5), up=(0.0, 0.0, -1.0))
	one = ga.render(96, 64, settle_frames=1)
	settled = ga.render(96, 64)
	again = ga.render(96, 64)
	assert np.isfinite(settled).all()
	assert np.abs(settled - one).max() > 1e-4, "the settled render must use the refined tree"
	assert np.array_equal(settled, again), "a settled tree renders the same image again"
	with pytest.raises(RuntimeError, match="settle_frames 0 is out of range"):
		ga.render(96, 64, settle_frames=0)
