# godot-area: pytest tests of the Python module `godot_area` (modules/python): classes, every
# AreaLight3D property by attribute and by set/get, property hints, errors, scene save/load.
# Rendering is in test_render.py. Run through the README test command, or by hand (conftest.py).
import enum
import os

import numpy as np
import pytest

import godot_area as ga
from ga_helpers import build_scene, start_engine

USAGE_MARKERS = (1 << 6) | (1 << 7) | (1 << 8)  # PROPERTY_USAGE_GROUP | CATEGORY | SUBGROUP.
HINT_RANGE, HINT_ENUM, HINT_RESOURCE_TYPE = 1, 2, 17  # PropertyHint (core/object/property_info.h).


def _area_light_properties():
	"""AreaLight3D's ClassDB property list (group markers left out), read from the engine itself."""
	start_engine()
	return [p for p in ga.class_get_property_list("AreaLight3D") if not p["usage"] & USAGE_MARKERS]


def _range(info):
	parts = info["hint_string"].split(",")
	return float(parts[0]), float(parts[1])


def _new_value(info, current):
	"""A valid value of the property's type that differs from current, chosen from type and hint
	only, so a property added to AreaLight3D later is covered without editing this file."""
	kind, hint = info["type_name"], info["hint"]
	if kind == "bool":
		return not current
	if kind == "int":
		if hint == HINT_ENUM:
			count = len(info["hint_string"].split(","))
			return (current + 1) % count
		if hint == HINT_RANGE:
			lo, hi = _range(info)
			return int(lo) if current + 1 > hi else current + 1
		return current ^ 0b101  # Flags and layer masks: toggle two bits; plain ints: a different number.
	if kind == "float":
		if hint == HINT_RANGE:
			lo, hi = _range(info)
			value = lo + (hi - lo) * 0.375
			return value if not np.isclose(value, current) else lo + (hi - lo) * 0.625
		return current + 0.25
	if kind == "String":
		return (current or "Prop") + "_renamed"
	if kind == "Vector2":
		return (current[0] + 0.25, current[1] + 0.5)
	if kind == "Vector3":
		return (current[0] + 0.25, current[1] + 0.5, current[2] + 0.125)
	if kind == "Color":
		return (0.25, 0.5, 0.75, 1.0) if not np.allclose(current, (0.25, 0.5, 0.75, 1.0)) else (0.5, 0.25, 0.125, 1.0)
	if kind == "Transform3D":
		c, s = np.cos(0.3), np.sin(0.3)
		moved = [[c, 0.0, s, 1.0], [0.0, 1.0, 0.0, 2.0], [-s, 0.0, c, 3.0]]  # Rotated about Y, moved.
		return moved if not np.allclose(current, moved) else [[1.0, 0.0, 0.0, -1.0], [0.0, 1.0, 0.0, 0.5], [0.0, 0.0, 1.0, 0.0]]
	if kind == "Object":
		assert hint == HINT_RESOURCE_TYPE, info
		base = info["hint_string"]
		if current is not None:
			return None
		for cls in [base] + sorted(ga.get_class_list()):
			candidate = None
			try:
				candidate = ga.create(cls)
			except ValueError:
				continue  # Abstract or not instantiable.
			if candidate.is_class(base):
				return candidate
		raise AssertionError("no instantiable class for %s" % base)
	raise AssertionError("property %s has type %s: teach _new_value() about it" % (info["name"], kind))


def _assert_same(name, got, expected):
	if expected is None or isinstance(expected, (bool, str, ga.Object)):
		assert got is expected or got == expected, (name, got, expected)
		if isinstance(expected, ga.Object):
			assert got is expected, "one Python wrapper per engine object"
	elif isinstance(expected, int):
		# Enum properties read as their IntEnum member (an int); get() gives the plain int.
		assert (type(got) is int or isinstance(got, enum.IntEnum)) and got == expected, (name, got, expected)
	else:
		# float32 storage in the engine; Euler angles (rotation) go through a Basis.
		assert np.allclose(np.asarray(got, float), np.asarray(expected, float), rtol=1e-5, atol=1e-5), (name, got, expected)


AREA_LIGHT_PROPERTIES = _area_light_properties()


def test_create_by_class_name():
	light = ga.create("AreaLight3D")
	assert isinstance(light, ga.Node) and isinstance(light, ga.Object)
	assert light.get_class() == "AreaLight3D"
	assert light.is_class("Light3D") and light.is_class("Node3D")
	material = ga.create("StandardMaterial3D")
	assert not isinstance(material, ga.Node) and material.get_class() == "StandardMaterial3D"
	assert ga.class_exists("AreaLight3D") and "AreaLight3D" in ga.get_class_list()


def test_area_light_property_list_is_complete():
	names = [p["name"] for p in AREA_LIGHT_PROPERTIES]
	for own in ("area_size", "area_range", "area_attenuation", "area_normalize_energy", "area_shading_method",
			"area_stochastic_samples", "area_shadow_mode", "area_shadow_grid", "light_energy", "light_color", "shadow_enabled", "transform"):
		assert own in names, (own, names)
	light = ga.create("AreaLight3D")
	listed = [p["name"] for p in light.get_property_list() if not p["usage"] & USAGE_MARKERS]
	assert listed == names, "the instance and ClassDB lists differ"
	assert set(names) <= set(dir(light)), "dir() lists every property"


@pytest.mark.parametrize("info", AREA_LIGHT_PROPERTIES, ids=[p["name"] for p in AREA_LIGHT_PROPERTIES])
def test_area_light_property_attribute_and_set_get(info):
	name = info["name"]
	light = ga.create("AreaLight3D")
	current = light.get(name)
	_assert_same(name, getattr(light, name), current)
	light.set(name, current)  # Writing back what was read is accepted.
	_assert_same(name, light.get(name), current)

	first = _new_value(info, current)
	setattr(light, name, first)  # Attribute write, read by name.
	_assert_same(name, light.get(name), first)
	second = _new_value(info, light.get(name))
	light.set(name, second)  # Write by name, attribute read.
	_assert_same(name, getattr(light, name), second)


def test_area_light_values_by_attribute():
	light = ga.create("AreaLight3D")
	light.area_size = (2, 1)
	assert light.area_size == (2.0, 1.0)
	light.light_color = (1.0, 0.5, 0.25)
	assert light.light_color == (1.0, 0.5, 0.25, 1.0)  # Color: alpha 1 when omitted.
	light.position = np.array([1.0, 2.0, 3.0])  # numpy arrays are accepted.
	assert light.position == (1.0, 2.0, 3.0)
	t = light.transform
	assert len(t) == 3 and all(len(row) == 4 for row in t) and t[0][3] == 1.0 and t[2][3] == 3.0
	light.transform = np.eye(4)  # 4x4 works too.
	assert light.position == (0.0, 0.0, 0.0)


def test_property_list_hints():
	light = ga.create("AreaLight3D")
	info = {p["name"]: p for p in light.get_property_list()}
	size = info["area_size"]
	assert set(size) >= {"name", "type", "type_name", "class_name", "hint", "hint_string", "usage"}
	assert size["type_name"] == "Vector2" and size["hint"] == HINT_RANGE and "suffix:m" in size["hint_string"], size
	method = info["area_shading_method"]
	assert method["type_name"] == "int" and method["hint"] == HINT_ENUM
	assert method["hint_string"].split(",") == ["LTC", "LTC Polynomial", "MRP", "Stochastic", "Auto", "LTC 2-Lobe"]
	assert info["light_projector"]["class_name"] == "Texture2D"
	assert "Area" in info and info["Area"]["usage"] & USAGE_MARKERS, "the inspector group marker is listed"
	by_class = {p["name"]: p for p in ga.class_get_property_list("AreaLight3D")}
	assert by_class["area_size"] == size


def _raises(exc_type, action):
	with pytest.raises(exc_type) as caught:
		action()
	return str(caught.value)


def test_unknown_names_raise_attribute_error_with_the_engine_message():
	light = ga.create("AreaLight3D")
	expected = "Invalid property 'area_sise' on class 'AreaLight3D': no such property."
	assert _raises(AttributeError, lambda: light.area_sise) == expected
	assert _raises(AttributeError, lambda: light.get("area_sise")) == expected
	assert _raises(AttributeError, lambda: setattr(light, "area_sise", (1, 1))) == expected
	assert _raises(AttributeError, lambda: light.set("area_sise", 1)) == expected
	assert _raises(AttributeError, lambda: light.set("area_sise", {"not": "a value"})) == expected
	assert _raises(AttributeError, lambda: light.call("no_method")) == "Invalid call: method 'no_method' does not exist on class 'AreaLight3D'."
	assert _raises(ValueError, lambda: ga.create("NoSuchClass3D")) == "Cannot instantiate class 'NoSuchClass3D': it is not registered in ClassDB."
	assert _raises(ValueError, lambda: ga.create("Light3D")) == "Cannot instantiate class 'Light3D': it is abstract."


@pytest.mark.parametrize("name, value, engine_message", [
	("area_size", "big", "expected Vector2, got String."),
	("area_size", 2.0, "expected Vector2, got float."),
	("area_range", (1, 2, 3), "expected float, got Vector3."),
	("area_normalize_energy", (1.0, 2.0), "expected bool, got Vector2."),
	("light_projector", 3, "expected Object, got int."),
])
def test_wrong_types_raise_type_error_with_the_engine_message(name, value, engine_message):
	light = ga.create("AreaLight3D")
	before = light.get(name)
	message = _raises(TypeError, lambda: light.set(name, value))
	assert message == "Cannot set property '%s' of class 'AreaLight3D': %s" % (name, engine_message)
	assert _raises(TypeError, lambda: setattr(light, name, value)) == message
	_assert_same(name, light.get(name), before)


def test_values_without_an_engine_form_raise_type_error():
	light = ga.create("AreaLight3D")
	assert "Transform3D" in _raises(TypeError, lambda: light.set("transform", [[1, 2], [3, 4]]))
	assert "dict" in _raises(TypeError, lambda: light.set("area_size", {"not": "a value"}))
	assert "StandardMaterial3D" in _raises(TypeError, lambda: light.set("light_projector", ga.create("StandardMaterial3D")))


@pytest.mark.parametrize("name, value, engine_message", [
	("area_size", (float("nan"), 2), 'AreaLight3D "Key": area_size must be finite in both components (got (nan, 2)); the old value (2, 1) is kept.'),
	("area_range", float("nan"), 'AreaLight3D "Key": area_range must be finite (not NaN or infinity) (got nan); the old value 5 is kept.'),
	("area_shading_method", 9, 'AreaLight3D "Key": area_shading_method must be 0..5 (LTC, LTC Polynomial, MRP, Stochastic, Auto, LTC 2-Lobe); got 9. The old value is kept.'),
	("area_stochastic_samples", 0, 'AreaLight3D "Key": area_stochastic_samples must be 1..256; got 0. The old value is kept.'),
	("area_shadow_grid", 1, 'AreaLight3D "Key": area_shadow_grid must be 2..9; got 1. The old value is kept.'),
	("light_temperature", -1.0, 'AreaLight3D "Key": light_temperature must be finite and > 0 Kelvin (got -1); the old value is kept.'),
])
def test_rejected_values_raise_value_error_with_the_engine_message(name, value, engine_message):
	light = ga.create("AreaLight3D")
	light.name = "Key"
	light.area_size = (2, 1)
	before = light.get(name)
	assert _raises(ValueError, lambda: light.set(name, value)) == engine_message
	assert _raises(ValueError, lambda: setattr(light, name, value)) == engine_message
	_assert_same(name, light.get(name), before)  # The old value stays.


def test_scene_errors():
	with pytest.raises(FileNotFoundError):
		ga.load_scene("/nonexistent/scene.tscn")
	node = ga.create("Node3D")
	assert "Missing/Child" in _raises(KeyError, lambda: node.get_node("Missing/Child"))
	assert node.get_node_or_null("Missing/Child") is None
	assert "Node" in _raises(TypeError, lambda: ga.save_scene(ga.create("StandardMaterial3D"), "/tmp/never.tscn"))


def test_save_load_round_trip(tmp_path):
	scene = build_scene()
	assert scene.get_node("Key").area_size == (1.5, 1.0)
	path = str(tmp_path / "built.tscn")
	ga.save_scene(scene, path)
	assert os.path.getsize(path) > 0
	loaded = ga.load_scene(path)
	assert loaded.get_class() == "Node3D" and loaded.name == "Scene"
	assert [c.name for c in loaded.get_children()] == ["Floor", "Box", "Camera", "Key", "Fill"]
	for name in ("Key", "Fill"):
		a, b = scene.get_node(name), loaded.get_node(name)
		assert b.get_class() == "AreaLight3D"
		for info in AREA_LIGHT_PROPERTIES:  # Every stored property comes back.
			if info["usage"] & 2 and info["type_name"] != "Object":  # PROPERTY_USAGE_STORAGE
				_assert_same(name + "." + info["name"], b.get(info["name"]), a.get(info["name"]))
	floor = loaded.get_node("Floor")
	assert floor.mesh.get_class() == "PlaneMesh" and floor.mesh.size == (6.0, 6.0)
	assert np.allclose(floor.material_override.albedo_color, (0.7, 0.7, 0.7, 1.0), atol=1e-5)
	assert np.allclose(loaded.get_node("Box").mesh.size, (0.6, 0.6, 0.6))
	# Python keeps one wrapper per engine object.
	assert loaded.get_node("Floor") is floor and floor.get_parent() is loaded
	# Saving the loaded scene again gives the same file.
	again = str(tmp_path / "again.tscn")
	ga.save_scene(loaded, again)
	assert open(again).read() == open(path).read()
