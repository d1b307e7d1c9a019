# godot-area: the Python API as a GDScript user writes it: one class per engine class, methods
# and enums as attributes, value types that mutate in place and write back, the Node3D helpers,
# the class reference as docstrings, and the generated stub file (bin/python*/godot_area.pyi).
# Each test says in a comment what the GDScript line would be.
import ast
import copy
import enum
import inspect
import math
import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import godot_area as ga

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ENGINE_CLASSES = [name for name in ga.get_class_list()]


# --- 1. one generated Python class per ClassDB class --------------------------------------------

def test_every_engine_class_is_a_python_class_with_classdb_inheritance():
	for name in ENGINE_CLASSES:
		cls = getattr(ga, name)
		assert isinstance(cls, type) and cls.__name__ == name
		engine_parent = cls._engine_api["parent"]
		if engine_parent in ENGINE_CLASSES:
			assert cls.__mro__[1] is getattr(ga, engine_parent), (name, cls.__mro__)
	assert issubclass(ga.AreaLight3D, ga.Light3D) and issubclass(ga.Light3D, ga.Node3D) and issubclass(ga.Node3D, ga.Node)
	assert issubclass(ga.StandardMaterial3D, ga.Object) and not issubclass(ga.StandardMaterial3D, ga.Node)


def test_type_and_isinstance_follow_the_engine_class():
	# var light = AreaLight3D.new(); light is Light3D
	light = ga.AreaLight3D()
	assert type(light) is ga.AreaLight3D
	assert isinstance(light, ga.Light3D) and isinstance(light, ga.Node3D) and isinstance(light, ga.Node)
	assert not isinstance(light, ga.Camera3D)
	# Objects made by the engine (a loaded scene, ga.create) get their class too.
	assert type(ga.create("OmniLight3D")) is ga.OmniLight3D
	scene = ga.load_scene("")
	try:
		lights = scene.find_children("*", "AreaLight3D")
		assert lights and all(type(l) is ga.AreaLight3D for l in lights)
		assert all(isinstance(c, ga.Camera3D) for c in scene.find_children("*", "Camera3D"))
	finally:
		scene.free()
	assert type(ga.PlaneMesh()) is ga.PlaneMesh and isinstance(ga.PlaneMesh(), ga.Mesh)


def test_constructor_takes_properties_and_abstract_classes_refuse():
	light = ga.AreaLight3D(name="Key", area_size=(2, 1), light_energy=3.0)
	assert light.name == "Key" and light.area_size == (2, 1) and light.light_energy == 3.0
	with pytest.raises(TypeError, match="Light3D is abstract"):
		ga.Light3D()
	with pytest.raises(AttributeError, match="no_such_property"):
		ga.AreaLight3D(no_such_property=1)


def test_bound_methods_are_attributes_with_signatures():
	# light.set_area_size(Vector2(2, 1)); print(light.get_area_size())
	light = ga.AreaLight3D()
	light.set_area_size(ga.Vector2(2, 1))
	assert light.get_area_size() == ga.Vector2(2, 1)
	light.set_param(ga.Light3D.PARAM_ENERGY, 2.5)
	assert light.get_param(ga.Light3D.PARAM_ENERGY) == 2.5 == light.light_energy
	sig = inspect.signature(ga.Node3D.look_at)
	assert list(sig.parameters) == ["self", "target", "up"]
	assert sig.parameters["up"].default == ga.Vector3.UP  # DEFVAL in ClassDB.
	assert list(inspect.signature(ga.AreaLight3D.set_area_size).parameters) == ["self", "size"]
	assert inspect.signature(ga.AreaLight3D.get_area_size).return_annotation == "Vector2"
	# Keyword arguments and wrong counts are reported with the signature.
	light.set_area_size(size=(3, 1))
	assert light.area_size.x == 3
	with pytest.raises(TypeError, match=r"AreaLight3D.set_area_size\(size"):
		light.set_area_size()
	with pytest.raises(TypeError, match="argument 'size' of 'set_area_size': expected Vector2"):
		light.set_area_size("wide")


def test_help_shows_the_class_reference_and_the_properties():
	# The text of doc/classes/AreaLight3D.xml, embedded at build time.
	doc = ga.AreaLight3D.__doc__
	assert doc.startswith("AreaLight3D (inherits Light3D)")
	assert "Rectangular area light" in doc and "[member" not in doc
	area_size = ga.AreaLight3D.area_size.__doc__
	assert area_size.startswith("area_size: Vector2") and "default Vector2(1, 1)" in area_size and "meters" in area_size
	xml = ET.parse(os.path.join(ROOT, "doc", "classes", "AreaLight3D.xml")).getroot()
	member_text = xml.find("members/member[@name='area_attenuation']").text.strip()
	first_words = " ".join(member_text.split()[:4])
	assert first_words in ga.AreaLight3D.area_attenuation.__doc__, (first_words, ga.AreaLight3D.area_attenuation.__doc__)
	assert ga.Node3D.__doc__.startswith("Node3D (inherits Node)")  # No XML page: generated text.
	assert "area_shading_method" in dir(ga.AreaLight3D()) and "look_at" in dir(ga.AreaLight3D)


def test_class_docs_do_not_read_the_source_tree(tmp_path):
	# Docstrings come from the extension itself: a copy of the module outside the tree has them.
	import shutil
	import subprocess
	import sys

	module = ga.__file__
	shutil.copy(module, tmp_path / os.path.basename(module))
	code = "import godot_area as ga; print('Rectangular area light' in ga.AreaLight3D.__doc__)"
	run = subprocess.run([sys.executable, "-c", code], cwd=str(tmp_path), capture_output=True, text=True,
			env=dict(os.environ, PYTHONPATH=str(tmp_path)), timeout=120)
	assert run.returncode == 0 and run.stdout.strip() == "True", run.stderr


# --- 2. enums and constants -------------------------------------------------------------------

def test_enums_and_flat_constants_on_the_classes():
	# light.area_shading_method = AreaLight3D.AREA_SHADING_MRP
	method = ga.AreaLight3D.AreaShadingMethod
	assert issubclass(method, enum.IntEnum)
	assert ga.AreaLight3D.AREA_SHADING_MRP is method.MRP and int(method.MRP) == 2
	assert [m.name for m in method] == ["LTC", "LTC_POLYNOMIAL", "MRP", "STOCHASTIC", "AUTO", "LTC_2LOBE"]
	assert ga.AreaLight3D.AreaShadowMode.ADAPTIVE is ga.AreaLight3D.AREA_SHADOW_ADAPTIVE
	assert ga.Light3D.Param.ENERGY is ga.Light3D.PARAM_ENERGY and ga.AreaLight3D.PARAM_ENERGY is ga.Light3D.PARAM_ENERGY
	assert ga.Node.NOTIFICATION_READY == 13  # Plain (non-enum) constants are ints.
	assert ga.Environment.BG_COLOR == 1


def test_enum_properties_take_members_ints_and_names():
	light = ga.AreaLight3D()
	light.area_shading_method = ga.AreaLight3D.AREA_SHADING_MRP
	assert light.area_shading_method is ga.AreaLight3D.AreaShadingMethod.MRP
	assert light.get("area_shading_method") == 2 and type(light.get("area_shading_method")) is int
	light.area_shading_method = 3  # Ints as in GDScript.
	assert light.area_shading_method == ga.AreaLight3D.AREA_SHADING_STOCHASTIC
	light.area_shading_method = "LTC_POLYNOMIAL"  # Member names, any case, and the inspector labels.
	assert light.area_shading_method is ga.AreaLight3D.AreaShadingMethod.LTC_POLYNOMIAL
	light.area_shadow_mode = "pcss baseline"
	assert light.area_shadow_mode is ga.AreaLight3D.AREA_SHADOW_PCSS_BASELINE
	light.area_shading_method = "AREA_SHADING_AUTO"
	assert light.area_shading_method is ga.AreaLight3D.AreaShadingMethod.AUTO


def test_bad_enum_values_name_class_property_and_value():
	light = ga.AreaLight3D()
	light.name = "Key"
	with pytest.raises(ValueError) as e:
		light.area_shading_method = "fastest"
	assert "AreaLight3D.area_shading_method" in str(e.value) and "'fastest'" in str(e.value) and "AreaShadingMethod.MRP (2)" in str(e.value)
	with pytest.raises(TypeError) as e:
		light.area_shading_method = 2.5
	assert "AreaLight3D.area_shading_method" in str(e.value) and "2.5" in str(e.value)
	with pytest.raises(TypeError):
		light.area_shading_method = True
	with pytest.raises(ValueError, match='AreaLight3D "Key": area_shading_method must be 0..5'):
		light.area_shading_method = 9  # The setter's own message (it names the node).
	assert light.area_shading_method is ga.AreaLight3D.AREA_SHADING_LTC  # The default is kept.


# --- 3. value types ---------------------------------------------------------------------------

def test_vector_components_and_arithmetic():
	v = ga.Vector3(1, 2, 3)
	assert (v.x, v.y, v.z) == (1, 2, 3) and v[2] == 3 and len(v) == 3 and list(v) == [1, 2, 3]
	assert v + ga.Vector3(1, 1, 1) == (2, 3, 4) and v - (1, 1, 1) == (0, 1, 2) and v * 2 == (2, 4, 6) and 2 * v == (2, 4, 6)
	assert v / 2 == (0.5, 1, 1.5) and -v == (-1, -2, -3) and v * v == (1, 4, 9)
	assert ga.Vector3.RIGHT.cross(ga.Vector3.UP) == ga.Vector3.BACK
	assert math.isclose(ga.Vector3(3, 4, 0).length(), 5) and ga.Vector3(3, 4, 0).normalized().is_equal_approx((0.6, 0.8, 0))
	assert ga.Vector2(1, 2).dot((3, 4)) == 11 and ga.Vector4(1, 2, 3, 4).w == 4
	assert ga.Vector3.ZERO.lerp((2, 4, 6), 0.5) == (1, 2, 3)
	ga.Vector3.UP.x = 5  # Constants are fresh values: changing one changes nothing else.
	assert ga.Vector3.UP == (0, 1, 0)
	with pytest.raises(TypeError):
		ga.Vector3(1, 2)
	with pytest.raises(AttributeError, match="components: x, y, z"):
		v.w = 1
	c = ga.Color(1, 0.5, 0)
	assert c.a == 1 and c == (1, 0.5, 0) and c.to_html(False) == "ff8000" and ga.Color("#ff8000").g == pytest.approx(128 / 255)


def test_basis_and_transform_math():
	t = ga.Transform3D(ga.Basis.from_axis_angle(ga.Vector3.UP, math.pi / 2), ga.Vector3(1, 2, 3))
	assert (t * ga.Vector3(1, 0, 0)).is_equal_approx((1, 2, 2))
	assert (t.affine_inverse() * (t * ga.Vector3(0.3, -2, 5))).is_equal_approx((0.3, -2, 5))
	assert t.basis.x.is_equal_approx((0, 0, -1)) and t.origin == (1, 2, 3)
	assert (t * t.inverse()).is_equal_approx(ga.Transform3D.IDENTITY)
	b = ga.Basis.from_euler((0.1, 0.2, 0.3))
	assert (b * b.inverse()).is_equal_approx(ga.Basis.IDENTITY) and math.isclose(b.determinant(), 1.0)
	m = np.asarray(t)
	assert m.shape == (3, 4) and np.allclose(m[:, 3], (1, 2, 3)) and np.asarray(b).shape == (3, 3)
	assert ga.Transform3D(m) == t and ga.Transform3D(np.vstack([m, [0, 0, 0, 1]])) == t  # 3x4 and 4x4 back.
	looking = ga.Transform3D().looking_at((0, 0, -5))
	assert looking.basis.z.is_equal_approx((0, 0, 1))


def test_numpy_conversion_both_ways():
	light = ga.AreaLight3D()
	light.position = np.array([1.0, 2.0, 3.0])
	assert isinstance(light.position, ga.Vector3) and np.allclose(np.asarray(light.position), (1, 2, 3))
	assert np.asarray(light.area_size).dtype == np.float64 and np.asarray(light.light_color).shape == (4,)
	light.transform = np.eye(4)
	assert isinstance(light.transform, ga.Transform3D) and light.transform == ga.Transform3D.IDENTITY
	with pytest.raises(TypeError, match="Vector4 cannot be stored"):
		light.position = ga.Vector4(1, 2, 3, 4)


def test_mutations_write_back_through_the_property():
	# GDScript: light.position.x = 1 (the property setter runs with the new vector).
	light = ga.AreaLight3D()
	light.position.x = 1
	assert light.position == (1, 0, 0)
	light.area_size[0] = 5
	assert light.area_size == (5, 1)
	light.light_color.g = 0.25
	assert light.light_color == (1, 0.25, 1, 1)
	light.position += ga.Vector3(0, 2, 0)  # In place, also written back.
	assert light.position == (1, 2, 0)
	light.transform.origin.z = -4  # Through two levels.
	assert light.position == (1, 2, -4)
	light.transform.basis.x = ga.Vector3(2, 0, 0)
	assert light.scale.is_equal_approx((2, 1, 1))
	# The setter still runs on the whole value: a negative side is clamped, with its warning.
	with pytest.warns(RuntimeWarning, match="negative component; clamped"):
		light.area_size.y = -1
	assert light.area_size == (5, 0)
	with pytest.raises(ValueError, match="area_size"):
		light.area_size.x = float("nan")  # Rejected: the old value stays.
	assert light.area_size == (5, 0)


def test_values_stay_bound_copies_do_not():
	light = ga.AreaLight3D()
	p = light.position
	p.y = 3  # Bound to light.position, as bpy's mathutils (documented in doc/scripting.md).
	assert light.position.y == 3
	detached = light.position.copy()
	detached.y = 7
	assert light.position.y == 3
	other = copy.copy(light.position)
	other.x = 9
	assert light.position.x == 0
	total = light.position + ga.Vector3(1, 1, 1)  # Results of arithmetic are new, unbound values.
	total.x = 100
	assert light.position == (0, 3, 0)


# --- 4. the Node3D and Node helpers (bound in ClassDB) ----------------------------------------

def test_node3d_helpers():
	parent = ga.Node3D(position=ga.Vector3(10, 0, 0))
	node = parent.add_child(ga.Node3D(name="Lamp"))
	node.rotate_y(math.pi / 2)  # rotate_y(PI / 2)
	assert node.rotation.is_equal_approx((0, math.pi / 2, 0))
	node.translate(ga.Vector3(0, 0, -1))  # Along the node's own -Z, which now is -X.
	assert node.position.is_equal_approx((-1, 0, 0))
	assert node.to_global(ga.Vector3.ZERO).is_equal_approx((9, 0, 0))
	assert node.to_local(ga.Vector3(9, 0, -1)).is_equal_approx((1, 0, 0))  # World -Z is local +X.
	node.global_translate((0, 1, 0))
	assert node.global_position.is_equal_approx((9, 1, 0))
	node.look_at(ga.Vector3(9, 1, -5))  # up defaults to Vector3.UP
	assert node.global_transform.basis.z.is_equal_approx((0, 0, 1))
	node.rotate_object_local(ga.Vector3.RIGHT, 0.25)
	node.rotate(ga.Vector3.UP, 0.5)
	node.hide()
	assert not node.visible
	with pytest.raises(ValueError, match="rotate\\(\\) needs a non-zero axis"):
		node.rotate(ga.Vector3.ZERO, 1.0)
	parent.free()


def test_groups_and_duplicate():
	root = ga.Node3D(name="Root")
	lamp = root.add_child(ga.OmniLight3D(name="Lamp", light_energy=2.0, position=ga.Vector3(0, 3, 0)))
	lamp.add_to_group("lights")
	assert lamp.is_in_group("lights") and lamp.get_groups() == ["lights"]
	copy_ = lamp.duplicate()
	assert type(copy_) is ga.OmniLight3D and copy_ is not lamp
	assert copy_.light_energy == 2.0 and copy_.position == (0, 3, 0) and copy_.is_in_group("lights")
	assert copy_.get_parent() is None
	root.add_child(copy_)
	assert copy_.name != lamp.name  # Sibling names stay unique.
	lamp.remove_from_group("lights")
	assert not lamp.is_in_group("lights")
	root.free()


def test_queue_free_deletes_at_the_next_frame(engine):
	tree = ga.get_tree()
	camera = tree.root.add_child(ga.Camera3D(name="Camera"))  # run_frames() needs one on 'rd'.
	node = tree.root.add_child(ga.Node3D(name="Doomed"))
	node.add_to_group("doomed")
	child = node.add_child(ga.Node3D(name="Child"))
	assert tree.get_nodes_in_group("doomed") == [node]
	node.queue_free()  # queue_free()
	assert node.is_valid() and node.is_queued_for_deletion()  # Still usable this frame.
	node.position = ga.Vector3(1, 0, 0)
	tree.run_frames(1, width=8, height=8)
	assert not node.is_valid() and not child.is_valid()
	with pytest.raises(RuntimeError, match="freed"):
		node.position
	assert tree.get_nodes_in_group("doomed") == [] and tree.root.get_children() == [camera]
	tree.root.remove_child(camera)
	camera.free()


# --- 5. the stub file -------------------------------------------------------------------------

def test_stub_file_parses_and_lists_every_class():
	path = os.path.join(os.path.dirname(os.path.abspath(ga.__file__)), "godot_area.pyi")
	assert os.path.exists(path), "the build writes godot_area.pyi next to the module"
	with open(path, encoding="utf-8") as f:
		tree = ast.parse(f.read(), path)
	classes = {node.name: node for node in tree.body if isinstance(node, ast.ClassDef)}
	for name in ENGINE_CLASSES + ["Vector2", "Vector3", "Vector4", "Color", "Basis", "Transform3D", "SceneTree"]:
		assert name in classes, name
	light = classes["AreaLight3D"]
	assert [b.id for b in light.bases] == ["Light3D"]
	members = {getattr(n, "name", None) or getattr(getattr(n, "target", None), "id", None) for n in light.body}
	for expected in ("AreaShadingMethod", "AREA_SHADING_MRP", "area_size", "set_area_size", "__init__"):
		assert expected in members, expected
	functions = {node.name for node in tree.body if isinstance(node, ast.FunctionDef)}
	assert {"init", "render", "load_scene", "save_scene", "run_frames"} <= functions
	look_at = next(n for n in classes["Node3D"].body if isinstance(n, ast.FunctionDef) and n.name == "look_at")
	assert [a.arg for a in look_at.args.args] == ["self", "target", "up"] and len(look_at.args.defaults) == 1
