#!/usr/bin/python3
# godot-area: tests of the Python module `godot_area` (modules/python). Plain asserts, no pytest:
#   PYTHONPATH=bin/python_<variant> /usr/bin/python3 tests/python/test_godot_area.py
# The doctest case "[Python] ..." (tests/modules/test_python_module.cpp) runs it in a subprocess.
# Exit code 0 when every test passes; the first failure stops the run with a traceback.
import math
import os
import sys
import tempfile
import time
import warnings

import numpy as np

import godot_area as ga

VECTOR2 = 5  # Variant::VECTOR2


def look_at(eye, target, up=(0.0, 1.0, 0.0)):
	"""A 3x4 Transform3D (basis rows, then origin) whose -Z axis points from eye to target."""
	eye, target, up = np.asarray(eye, float), np.asarray(target, float), np.asarray(up, float)
	back = eye - target
	back /= np.linalg.norm(back)
	right = np.cross(up, back)
	right /= np.linalg.norm(right)
	new_up = np.cross(back, right)
	basis = np.stack([right, new_up, back], axis=1)  # Columns are the local axes.
	return np.hstack([basis, eye.reshape(3, 1)])


def build_scene():
	"""Floor, a box, a camera and two area lights, from nothing."""
	root = ga.create("Node3D")
	root.name = "Scene"

	floor = root.add_child(ga.create("MeshInstance3D"))
	floor.name = "Floor"
	plane = ga.create("PlaneMesh")
	plane.size = (6, 6)
	floor.mesh = plane
	material = ga.create("StandardMaterial3D")
	material.albedo_color = (0.7, 0.7, 0.7)
	material.roughness = 0.5
	floor.material_override = material

	box = root.add_child(ga.create("MeshInstance3D"))
	box.name = "Box"
	box_mesh = ga.create("BoxMesh")
	box_mesh.size = (0.6, 0.6, 0.6)
	box.mesh = box_mesh
	box.position = (0.0, 0.3, 0.0)

	camera = root.add_child(ga.create("Camera3D"))
	camera.name = "Camera"
	camera.transform = look_at((0.0, 3.0, 4.0), (0.0, 0.0, 0.0))
	camera.fov = 60.0

	key = root.add_child(ga.create("AreaLight3D"))
	key.name = "Key"
	key.transform = look_at((0.0, 2.0, 0.5), (0.0, 0.0, 0.5), up=(0.0, 0.0, -1.0))
	key.area_size = (1.5, 1.0)
	key.light_energy = 2.0

	fill = root.add_child(ga.create("AreaLight3D"))
	fill.name = "Fill"
	fill.transform = look_at((-2.0, 1.5, 1.0), (0.0, 0.0, 0.0))
	fill.area_size = (0.5, 0.5)
	fill.light_color = (0.6, 0.7, 1.0)
	return root


def test_create_by_class_name():
	light = ga.create("AreaLight3D")
	assert isinstance(light, ga.Node) and isinstance(light, ga.Object)
	assert light.get_class() == "AreaLight3D"
	assert light.is_class("Light3D") and light.is_class("Node3D")
	material = ga.create("StandardMaterial3D")
	assert not isinstance(material, ga.Node) and material.get_class() == "StandardMaterial3D"
	assert ga.class_exists("AreaLight3D") and "AreaLight3D" in ga.get_class_list()
	try:
		ga.create("NoSuchClass3D")
		raise AssertionError("create() of an unknown class must raise")
	except ValueError as e:
		assert "NoSuchClass3D" in str(e), str(e)


def test_every_area_light_property():
	light = ga.create("AreaLight3D")
	props = [p for p in light.get_property_list() if not p["usage"] & (64 | 128 | 256)]  # Skip group/category markers.
	names = [p["name"] for p in props]
	for own in ("area_size", "area_range", "area_attenuation", "area_normalize_energy", "area_shading_method", "light_energy", "light_color", "transform"):
		assert own in names, (own, names)
	for name in names:
		value = light.get(name)
		assert getattr(light, name) == value, name
		light.set(name, value)  # Writing back what was read is accepted for every property.
		assert light.get(name) == value, (name, value, light.get(name))
	# New values, by attribute and by name.
	light.area_size = (2, 1)
	assert light.area_size == (2.0, 1.0)
	light.set("area_range", 7.5)
	assert light.get("area_range") == 7.5 and light.area_range == 7.5
	light.area_attenuation = 0.5
	assert light.area_attenuation == 0.5
	light.area_normalize_energy = False
	assert light.area_normalize_energy is False
	light.area_shading_method = 0
	assert light.area_shading_method == 0
	light.light_color = (1.0, 0.5, 0.25)
	assert light.light_color == (1.0, 0.5, 0.25, 1.0)
	light.position = np.array([1.0, 2.0, 3.0])
	assert light.position == (1.0, 2.0, 3.0)
	t = light.transform
	assert len(t) == 3 and all(len(row) == 4 for row in t) and t[0][3] == 1.0 and t[2][3] == 3.0


def test_property_list_hints():
	light = ga.create("AreaLight3D")
	info = {p["name"]: p for p in light.get_property_list()}
	size = info["area_size"]
	assert size["type"] == VECTOR2 and size["type_name"] == "Vector2", size
	assert "suffix:m" in size["hint_string"], size
	assert set(size) >= {"name", "type", "hint", "hint_string", "usage"}
	assert "suffix:m" in info["area_range"]["hint_string"]
	by_class = {p["name"]: p for p in ga.class_get_property_list("AreaLight3D")}
	assert by_class["area_size"]["hint_string"] == size["hint_string"]


def test_errors_carry_engine_messages():
	light = ga.create("AreaLight3D")
	for action in (lambda: light.area_sise, lambda: light.get("area_sise"), lambda: setattr(light, "area_sise", (1, 1)), lambda: light.set("area_sise", 1), lambda: light.set("area_sise", {"not": "a value"})):
		try:
			action()
			raise AssertionError("an unknown property must raise AttributeError")
		except AttributeError as e:
			assert "area_sise" in str(e), str(e)
	for name, value in (("area_size", "big"), ("area_range", (1, 2, 3)), ("area_normalize_energy", (1.0, 2.0)), ("transform", [[1, 2], [3, 4]])):
		try:
			light.set(name, value)
			raise AssertionError("a wrong type must raise TypeError: %s = %r" % (name, value))
		except TypeError as e:
			assert name in str(e), (name, str(e))
	light.area_size = (2, 1)
	try:
		light.area_size = (-1, 2)
		raise AssertionError("a negative area_size must be rejected")
	except ValueError as e:
		assert "area_size" in str(e), str(e)
	assert light.area_size == (2.0, 1.0)  # The old value stays.
	try:
		ga.load_scene("/nonexistent/scene.tscn")
		raise AssertionError("a missing scene must raise")
	except FileNotFoundError:
		pass
	node = ga.create("Node3D")
	try:
		node.get_node("Missing/Child")
		raise AssertionError("get_node() of a missing path must raise KeyError")
	except KeyError as e:
		assert "Missing/Child" in str(e)


def test_save_load_round_trip(tmp):
	scene = build_scene()
	assert scene.get_node("Key").area_size == (1.5, 1.0)
	path = os.path.join(tmp, "built.tscn")
	ga.save_scene(scene, path)
	loaded = ga.load_scene(path)
	assert loaded.get_class() == "Node3D" and loaded.name == "Scene"
	assert [c.name for c in loaded.get_children()] == ["Floor", "Box", "Camera", "Key", "Fill"]
	for name in ("Key", "Fill"):
		a, b = scene.get_node(name), loaded.get_node(name)
		assert b.get_class() == "AreaLight3D"
		for prop in ("area_size", "area_range", "area_attenuation", "area_normalize_energy", "light_energy", "light_color"):
			assert np.allclose(a.get(prop), b.get(prop), atol=1e-5), (name, prop, a.get(prop), b.get(prop))
		assert np.allclose(a.transform, b.transform, atol=1e-5), name
	floor = loaded.get_node("Floor")
	assert floor.mesh.get_class() == "PlaneMesh" and floor.mesh.size == (6.0, 6.0)
	assert np.allclose(floor.material_override.albedo_color, (0.7, 0.7, 0.7, 1.0), atol=1e-5)
	assert np.allclose(loaded.get_node("Box").mesh.size, (0.6, 0.6, 0.6))
	# Python keeps one wrapper per engine object.
	assert loaded.get_node("Floor") is floor and floor.get_parent() is loaded


def test_render_and_run_frames(tmp):
	if ga.backend() != "rd":
		print("test_render_and_run_frames: skipped, backend is '%s' (no Vulkan)" % ga.backend())
		return
	tree = ga.get_tree()
	scene = tree.root.add_child(build_scene())
	assert scene.is_inside_tree() and scene.get_path() == "/root/Scene"
	assert tree.camera is scene.get_node("Camera")
	image = ga.render(32, 32)
	assert image.shape == (32, 32, 4) and image.dtype == np.float32
	assert np.isfinite(image).all()
	assert image[..., :3].max() > 0.01, image[..., :3].max()

	# The key light alone still lights the floor: the image is the engine's, not a constant.
	fill = scene.get_node("Fill")
	fill.light_energy = 0.0
	key_only = ga.render()
	assert not np.allclose(key_only, image)

	key = scene.get_node("Key")
	seen = []

	def move(frame, tree_arg):
		assert tree_arg.root is tree.root
		seen.append(frame)
		key.position = (1.5 + 0.2 * frame, 2.0, 0.5)

	profiles = ga.run_frames(3, move)
	assert seen == [0, 1, 2]
	assert len(profiles) == 3 and all(isinstance(p, dict) and p for p in profiles), profiles
	assert all(isinstance(ms, float) and ms >= 0.0 and math.isfinite(ms) for p in profiles for ms in p.values())
	moved = ga.render()
	assert np.isfinite(moved).all()
	assert np.abs(moved - key_only).max() > 1e-3, "moving the light must change the image"

	exr = os.path.join(tmp, "frame.exr")
	ga.save_exr(moved, exr)
	assert np.allclose(ga.load_exr(exr), moved, rtol=1e-6, atol=1e-6)

	tree.root.remove_child(scene)
	assert not scene.is_inside_tree() and tree.camera is None
	scene.free()
	assert not key.is_valid()
	try:
		key.area_size
		raise AssertionError("a freed node must raise")
	except RuntimeError:
		pass


def main():
	start = time.time()
	warnings.simplefilter("error", RuntimeWarning)  # Engine warnings become failures in this test.
	# GODOT_AREA_PY_BACKEND=dummy runs everything but rendering (machines without Vulkan).
	backend = os.environ.get("GODOT_AREA_PY_BACKEND", "rd")
	ga.init(backend)
	assert ga.backend() == backend
	tests = [
		test_create_by_class_name,
		test_every_area_light_property,
		test_property_list_hints,
		test_errors_carry_engine_messages,
	]
	with tempfile.TemporaryDirectory(prefix="godot_area_py_") as tmp:
		for test in tests + [lambda: test_save_load_round_trip(tmp), lambda: test_render_and_run_frames(tmp)]:
			test()
		validation_errors = ga.validation_error_count()
	assert validation_errors == 0, "%d Vulkan validation error(s)" % validation_errors
	ga.shutdown()
	assert ga.backend() == "none"
	print("test_godot_area.py: %d tests passed on backend '%s' in %.1f s" % (len(tests) + 2, backend, time.time() - start))
	return 0


if __name__ == "__main__":
	sys.exit(main())
