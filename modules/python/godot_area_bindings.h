/**************************************************************************/
/*  godot_area_bindings.h                                                 */
/**************************************************************************/
/* godot-area: shared pieces of the pybind11 extension `godot_area`.      */
/* Only the extension's sources (modules/python/godot_area_*.cpp, which  */
/* SConstruct builds into bin/python[_VARIANT]) include it (pybind11).    */
/*                                                                        */
/* Every engine object reaches Python as one wrapper (EngineObject, or    */
/* its subclass EngineNode for nodes); the same Object* always gives the  */
/* same Python object. Properties go through ClassDB only.                */
/* Ownership: RefCounted objects are held by a Ref; a Node is deleted     */
/* when its last wrapper goes and it has neither a parent nor a tree      */
/* (the Python side owns orphan nodes); other plain Objects made by       */
/* create() are deleted with their wrapper.                               */

#pragma once

#include "core/error/error_macros.h"
#include "core/object/object.h"
#include "core/object/property_info.h"
#include "core/object/ref_counted.h"
#include "core/variant/variant.h"

#include <pybind11/pybind11.h>

#include <vector>

namespace py = pybind11;

class Node;

namespace godot_area_py {

class EngineObject {
public:
	Object *object = nullptr; // Null once the engine freed it.
	Ref<RefCounted> ref;
	bool owns_object = false;

	// The live object, or a RuntimeError naming what happened.
	Object *get_checked() const;
	virtual ~EngineObject();
};

class EngineNode : public EngineObject {
public:
	Node *get_node_checked() const;
};

// The one Python wrapper of p_object (None for null). p_owns: a plain (non-node, non-refcounted)
// Object whose wrapper should delete it.
py::object wrap_object(Object *p_object, bool p_owns = false);
// The generated Python classes by ClassDB name (wrap_object gives each wrapper its class).
void set_class_map(py::dict p_map);
// Node::predelete_callback: the node's wrapper (if any) becomes invalid.
void on_node_deleted(Node *p_node);
// Every ClassDB class with its own methods, properties and constants (no inheritance), for
// the class generator (godot_area_classes.py).
py::list class_api();
// Marks the wrappers of p_node and its descendants as freed (call right before the engine deletes them).
void invalidate_subtree(Node *p_node);
// Engine shutdown: deletes orphan nodes still held by Python, drops every Ref and marks every
// wrapper freed, so wrappers that outlive the engine are inert.
void release_all_wrappers();

// Collects the engine's errors (and warnings) while alive; printing is silenced meanwhile.
class ErrorCapture {
	ErrorHandlerList handler;

public:
	std::vector<String> errors;
	std::vector<String> warnings;
	String joined() const;
	ErrorCapture();
	~ErrorCapture();
	ErrorCapture(const ErrorCapture &) = delete;
	ErrorCapture &operator=(const ErrorCapture &) = delete;
};

// Variant <-> Python (godot_area_variant.cpp). Vector2/3, Color, Transform3D <-> the math types
// (tuples, lists and NumPy arrays of the right shape are accepted too), objects <-> wrappers.
py::object variant_to_python(const Variant &p_value);
// The Python math types (godot_area_math.py) the conversions produce and recognise.
enum MathType {
	MATH_VECTOR2,
	MATH_VECTOR3,
	MATH_VECTOR4,
	MATH_COLOR,
	MATH_BASIS,
	MATH_TRANSFORM3D,
	MATH_TYPE_MAX,
};
void set_math_type(MathType p_type, py::object p_class);
bool is_math_type(py::handle p_value, MathType p_type);
// p_hint: the expected type (a property's), or NIL to guess from the Python value. Throws
// py::type_error when the value has no Variant form.
Variant python_to_variant(py::handle p_value, Variant::Type p_hint = Variant::NIL);
String python_type_name(py::handle p_value);

// Objects (godot_area_object.cpp).
void bind_objects(py::module_ &p_module);
py::dict property_info_to_dict(const PropertyInfo &p_info);

} // namespace godot_area_py
