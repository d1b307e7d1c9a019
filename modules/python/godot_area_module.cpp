/**************************************************************************/
/*  godot_area_module.cpp                                                 */
/**************************************************************************/
/* godot-area: the Python extension module `godot_area` (pybind11).       */
/*                                                                        */
/*   import godot_area as ga                                              */
/*   ga.init("rd")                     # or "dummy" (no GPU, no render)   */
/*   scene = ga.create("Node3D")                                          */
/*   light = scene.add_child(ga.create("AreaLight3D"))                    */
/*   light.area_size = (2, 1)          # any ClassDB property             */
/*   ga.get_tree().root.add_child(scene)                                  */
/*   image = ga.render(64, 64)         # numpy float32 (H, W, 4), linear  */
/*   times = ga.run_frames(10, lambda i, tree: ...)  # [{pass: ms}, ...]  */
/*                                                                        */
/* Without init(), the first call that needs the engine starts it on     */
/* "rd", or on "dummy" with a RuntimeWarning when no Vulkan device works. */

#include "modules/python/godot_area_bindings.h"
#include "modules/python/godot_area_embedded.gen.h"

#include "modules/openexr/image_loader_exr.h"
#include "modules/openexr/image_saver_exr.h"
#include "modules/python/python_session.h"
#include "scene/3d/camera_3d.h"
#include "scene/main/godot_instance.h"
#include "scene/main/node.h"
#include "scene/main/scene_tree.h"
#include "scene/register_scene_types.h"
#include "scene/resources/resource_format_text.h"
#include "servers/rendering/rendering_device.h"

#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstring>
#include <fstream>

using namespace godot_area_py;

namespace {

// The Python face of the process-wide SceneTree (stateless; every instance is the same tree).
struct TreeHandle {};

void _start_engine(const String &p_backend) {
	PythonSession::Backend backend = PythonSession::backend_from_name(p_backend);
	if (backend == PythonSession::BACKEND_NONE) {
		throw py::value_error(vformat("Unknown backend '%s': use 'rd' (Vulkan) or 'dummy' (no rendering).", p_backend.c_str()));
	}
	String error;
	bool ok = false;
	{
		ErrorCapture capture;
		ok = PythonSession::setup(backend, &error);
		if (!ok && !capture.errors.empty()) {
			error += "\n" + capture.joined();
		}
	}
	if (!ok) {
		throw std::runtime_error(error);
	}
}

void _ensure_engine() {
	if (PythonSession::is_active()) {
		return;
	}
	try {
		_start_engine("rd");
	} catch (const std::runtime_error &e) {
		if (PyErr_WarnEx(PyExc_RuntimeWarning, (String("godot_area: no Vulkan renderer, using the 'dummy' backend (no rendering): ") + e.what()).c_str(), 2) != 0) {
			throw py::error_already_set();
		}
		_start_engine("dummy");
	}
}

SceneTree *_tree() {
	_ensure_engine();
	return PythonSession::get_tree();
}

py::array_t<float> _image_to_array(const Image &p_image) {
	py::array_t<float> array({ (py::ssize_t)p_image.get_height(), (py::ssize_t)p_image.get_width(), (py::ssize_t)Image::CHANNELS });
	std::memcpy(array.mutable_data(), p_image.ptr(), p_image.get_data().size() * sizeof(float));
	return array;
}

Image _array_to_image(py::handle p_array) {
	py::array_t<float, py::array::c_style | py::array::forcecast> array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(p_array);
	if (!array) {
		PyErr_Clear();
		throw py::type_error("Expected an array of numbers with shape (H, W), (H, W, 3) or (H, W, 4).");
	}
	const int dims = (int)array.ndim();
	const int channels = dims == 2 ? 1 : (dims == 3 ? (int)array.shape(2) : 0);
	if ((dims != 2 && dims != 3) || (channels != 1 && channels != 3 && channels != 4)) {
		throw py::value_error("Expected an image array with shape (H, W), (H, W, 3) or (H, W, 4).");
	}
	const int height = (int)array.shape(0);
	const int width = (int)array.shape(1);
	Image image;
	if (!image.create(width, height)) {
		throw py::value_error(vformat("Image size %dx%d is out of range (1..%d).", width, height, Image::MAX_SIZE));
	}
	const float *src = array.data();
	float *dst = image.ptrw();
	for (int i = 0; i < width * height; i++) {
		const float *s = src + (size_t)i * channels;
		float *d = dst + (size_t)i * Image::CHANNELS;
		d[0] = s[0];
		d[1] = channels >= 3 ? s[1] : s[0];
		d[2] = channels >= 3 ? s[2] : s[0];
		d[3] = channels == 4 ? s[3] : 1.0f;
	}
	return image;
}

py::array_t<float> _render(int p_width, int p_height, int p_settle_frames) {
	SceneTree *tree = _tree();
	Image image;
	String error;
	bool ok = false;
	{
		ErrorCapture capture;
		ok = PythonSession::render(p_width, p_height, image, &error, p_settle_frames);
		if (!ok && !capture.errors.empty()) {
			error += "\n" + capture.joined();
		}
	}
	(void)tree;
	if (!ok) {
		throw std::runtime_error(error);
	}
	return _image_to_array(image);
}

py::list _run_frames(int p_count, py::object p_callback, int p_width, int p_height) {
	SceneTree *tree = _tree();
	if (p_count < 0) {
		throw py::value_error("run_frames() needs a frame count >= 0.");
	}
	// 0 x 0 keeps the tree's size; anything else must be a drawable size (20000 x 20000 used to draw nothing).
	if (p_width < 0 || p_height < 0 || p_width > Image::MAX_SIZE || p_height > Image::MAX_SIZE || ((p_width == 0) != (p_height == 0))) {
		throw py::value_error(vformat("run_frames(): size %dx%d is out of range (both 1..%d, or both 0 to keep the tree's size).", p_width, p_height, Image::MAX_SIZE));
	}
	if (p_width > 0 && p_height > 0) {
		tree->set_size(p_width, p_height);
	}
	if (PythonSession::get_backend() == PythonSession::BACKEND_RD && (!tree->get_camera_3d() || tree->get_width() <= 0 || tree->get_height() <= 0)) {
		throw std::runtime_error("run_frames() needs a current Camera3D in the tree and a size (pass width and height).");
	}
	py::object handle = py::cast(TreeHandle());
	py::list profiles;
	for (int i = 0; i < p_count; i++) {
		if (!p_callback.is_none()) {
			p_callback(i, handle);
		}
		PythonSession::FrameProfile profile;
		String error;
		if (!PythonSession::draw_frame(profile, &error)) {
			throw std::runtime_error(error);
		}
		py::dict d;
		for (const auto &p : profile) {
			d[py::str(p.first)] = p.second;
		}
		profiles.append(d);
	}
	return profiles;
}

void _shutdown() {
	release_all_wrappers();
	PythonSession::shutdown();
}

// Runs one embedded Python source (modules/python/godot_area_*.py) in its own namespace.
py::dict _run_embedded(const char *p_source, const char *p_name) {
	py::dict ns;
	ns["__builtins__"] = py::module_::import("builtins");
	ns["__name__"] = py::str(p_name);
	py::exec(py::str(p_source), ns);
	return ns;
}

} // namespace

PYBIND11_MODULE(godot_area, m) {
	m.doc() = "godot-area engine: build, load and save scenes, set any ClassDB property, render frames to NumPy.\n\n"
			  "One Python class per engine class (ga.AreaLight3D, ga.Node3D, ...), with the ClassDB properties, methods,\n"
			  "enums and constants as attributes; Vector2/3/4, Color, Basis and Transform3D value types.";

	// ClassDB is filled at import (no GPU needed), so the classes exist before init().
	register_scene_types();
	Node::predelete_callback = &on_node_deleted;

	bind_objects(m);

	py::dict math = _run_embedded(GODOT_AREA_MATH_PY, "godot_area");
	const char *math_names[MATH_TYPE_MAX] = { "Vector2", "Vector3", "Vector4", "Color", "Basis", "Transform3D" };
	for (int i = 0; i < MATH_TYPE_MAX; i++) {
		m.attr(math_names[i]) = math[math_names[i]];
		set_math_type(MathType(i), math[math_names[i]]);
	}
	m.def("_class_api", &class_api, "ClassDB as data (for the class generator and the stub writer).");
	m.def(
			"_class_docs", []() {
				py::list out;
				for (const char *const *doc = GODOT_AREA_CLASS_DOCS; *doc; doc++) {
					out.append(py::str(*doc));
				}
				return out;
			},
			"The class reference (doc/classes/*.xml) embedded at build time.");
	m.def("_set_class_map", &set_class_map);

	py::class_<TreeHandle>(m, "SceneTree", "The process-wide scene tree: its root node, viewport size and rendering.")
			.def_property_readonly("root", [](TreeHandle &) { return wrap_object(_tree()->get_root()); })
			.def_property_readonly(
					"camera", [](TreeHandle &) { return wrap_object(_tree()->get_camera_3d()); }, "The current Camera3D (None without one).")
			.def_property_readonly("size", [](TreeHandle &) { return py::make_tuple(_tree()->get_width(), _tree()->get_height()); })
			.def(
					"get_nodes_in_group", [](TreeHandle &, const String &p_group) {
						py::list out;
						std::vector<Node *> stack = { _tree()->get_root() };
						while (!stack.empty()) {
							Node *node = stack.back();
							stack.pop_back();
							if (node->is_in_group(p_group)) {
								out.append(wrap_object(node));
							}
							for (int i = node->get_child_count() - 1; i >= 0; i--) {
								stack.push_back(node->get_child(i));
							}
						}
						return out;
					},
					py::arg("group"), "Nodes of the tree in the group, in tree order (Godot's SceneTree.get_nodes_in_group).")
			.def(
					"set_size", [](TreeHandle &, int p_width, int p_height) {
						if (p_width < 0 || p_height < 0 || p_width > Image::MAX_SIZE || p_height > Image::MAX_SIZE) {
							throw py::value_error(vformat("Size %dx%d is out of range (0..%d).", p_width, p_height, Image::MAX_SIZE));
						}
						_tree()->set_size(p_width, p_height);
					},
					py::arg("width"), py::arg("height"))
			.def(
					"render", [](TreeHandle &, int p_width, int p_height, int p_settle_frames) { return _render(p_width, p_height, p_settle_frames); }, py::arg("width") = 0, py::arg("height") = 0, py::arg("settle_frames") = int(SceneTree::DEFAULT_SETTLE_FRAMES))
			.def(
					"run_frames", [](TreeHandle &, int p_count, py::object p_callback, int p_width, int p_height) { return _run_frames(p_count, p_callback, p_width, p_height); }, py::arg("count"), py::arg("callback") = py::none(), py::arg("width") = 0, py::arg("height") = 0);

	m.def("init", &_start_engine, py::arg("backend") = "rd", "Starts the engine: 'rd' (Vulkan Forward+, lavapipe without a GPU) or 'dummy' (no rendering). Once per process.");
	m.def(
			"backend", []() { return PythonSession::get_backend_name(PythonSession::get_backend()); }, "'rd', 'dummy' or 'none' (not started).");
	m.def("shutdown", &_shutdown, "Frees every node and resource and stops the engine (also runs at exit). Wrappers become invalid.");
	m.def("get_tree", []() { _ensure_engine(); return TreeHandle(); });

	m.def(
			"create", [](const String &p_class) {
				_ensure_engine();
				Object *object = nullptr;
				{
					ErrorCapture capture;
					object = ClassDB::instantiate(p_class);
					if (!object) {
						throw py::value_error(capture.errors.empty() ? vformat("Cannot instantiate class '%s'.", p_class.c_str()) : capture.joined());
					}
				}
				return wrap_object(object, true);
			},
			py::arg("class_name"), "A new instance of an engine class by name (Python owns it until it gets a parent).");
	// ClassDB queries need no engine (the classes are registered at import).
	m.def(
			"class_exists", [](const String &p_class) { return ClassDB::class_exists(p_class); }, py::arg("class_name"));
	m.def("get_class_list", []() {
		std::vector<String> classes;
		ClassDB::get_class_list(&classes);
		return classes;
	});
	m.def(
			"class_get_property_list", [](const String &p_class) {
				if (!ClassDB::class_exists(p_class)) {
					throw py::value_error(vformat("Class '%s' does not exist.", p_class.c_str()));
				}
				std::vector<PropertyInfo> list;
				ClassDB::get_property_list(p_class, &list);
				py::list out;
				for (const PropertyInfo &pi : list) {
					out.append(property_info_to_dict(pi));
				}
				return out;
			},
			py::arg("class_name"));

	m.def(
			"load_scene", [](const String &p_path) {
				_ensure_engine();
				if (!p_path.empty() && !std::ifstream(p_path).good()) {
					PyErr_SetString(PyExc_FileNotFoundError, vformat("Scene file not found: '%s'.", p_path.c_str()).c_str());
					throw py::error_already_set();
				}
				String error;
				Node *scene = nullptr;
				std::vector<String> warnings;
				{
					ErrorCapture capture;
					scene = GodotInstance::load_scene(p_path, &error);
					warnings = capture.warnings;
				}
				if (!scene) {
					throw py::value_error(vformat("Cannot load scene '%s': %s", p_path.c_str(), error.c_str()));
				}
				py::object result = wrap_object(scene); // Owned by Python before a warning can raise.
				for (const String &w : warnings) {
					if (PyErr_WarnEx(PyExc_RuntimeWarning, w.c_str(), 2) != 0) {
						throw py::error_already_set(); // The warnings filter made it an error.
					}
				}
				return result;
			},
			py::arg("path"), "Loads a .tscn (or glTF) scene; '' gives the embedded demo scene. Python owns the returned root.");
	m.def(
			"save_scene", [](py::object p_node, const String &p_path) {
				if (!py::isinstance<EngineNode>(p_node)) {
					throw py::type_error("save_scene() needs a Node.");
				}
				Node *node = p_node.cast<EngineNode *>()->get_node_checked();
				String error;
				bool ok = false;
				{
					ErrorCapture capture;
					ok = ResourceFormatText::save_scene(node, p_path, &error);
				}
				if (!ok) {
					PyErr_SetString(PyExc_OSError, vformat("Cannot save scene '%s': %s", p_path.c_str(), error.c_str()).c_str());
					throw py::error_already_set();
				}
			},
			py::arg("node"), py::arg("path"), "Writes the node and its subtree as a .tscn text scene.");

	m.def("render", &_render, py::arg("width") = 0, py::arg("height") = 0, py::arg("settle_frames") = int(SceneTree::DEFAULT_SETTLE_FRAMES), "Draws the tree (until ADAPTIVE area shadows settle, at most settle_frames frames; 1 = one frame) and returns linear HDR RGBA as numpy float32 (H, W, 4).");
	m.def("run_frames", &_run_frames, py::arg("count"), py::arg("callback") = py::none(), py::arg("width") = 0, py::arg("height") = 0,
			"Draws count frames, calling callback(frame_index, tree) before each; returns one {pass name: GPU ms} dict per frame.");
	m.def(
			"save_exr", [](py::object p_array, const String &p_path, bool p_half) {
				Image image = _array_to_image(p_array);
				String error;
				if (!ImageSaverEXR::save(image, p_path, p_half, &error)) {
					PyErr_SetString(PyExc_OSError, error.c_str());
					throw py::error_already_set();
				}
			},
			py::arg("array"), py::arg("path"), py::arg("half") = false, "Writes an (H, W[, 3|4]) array as a scene-linear OpenEXR file.");
	m.def(
			"load_exr", [](const String &p_path) {
				Image image;
				String error;
				if (!ImageLoaderEXR::load(p_path, image, &error)) {
					PyErr_SetString(PyExc_OSError, error.c_str());
					throw py::error_already_set();
				}
				return _image_to_array(image);
			},
			py::arg("path"), "Reads an OpenEXR file as numpy float32 (H, W, 4).");
	m.def(
			"device_name", []() -> String {
				RenderingDevice *rd = RenderingDevice::get_singleton();
				return rd && PythonSession::get_backend() == PythonSession::BACKEND_RD ? rd->get_device_info().name : String();
			},
			"The Vulkan device that renders ('' on the dummy backend or before init()).");
	m.def(
			"validation_error_count", []() { return PythonSession::get_validation_error_count(); }, "Vulkan validation errors so far (GODOT_AREA_VALIDATION=1 enables the layer).");

	py::module_::import("atexit").attr("register")(py::cpp_function(&_shutdown));

	// The generated classes last: they wrap every module-level name above.
	_run_embedded(GODOT_AREA_CLASSES_PY, "godot_area")["_build"](m);
	py::dict stubs = _run_embedded(GODOT_AREA_STUBS_PY, "godot_area");
	m.attr("_write_stubs") = stubs["write_stubs"];
}
