/**************************************************************************/
/*  godot_area_variant.cpp                                                */
/**************************************************************************/
/* godot-area: Variant <-> Python values for the `godot_area` extension.  */

#include "modules/python/godot_area_bindings.h"

#include "core/math/basis.h"

#include <cmath>

namespace godot_area_py {

namespace {

// The math types of godot_area_math.py (set at import; strong references kept for the process).
PyObject *math_types[MATH_TYPE_MAX] = {};

py::object _math(MathType p_type, py::args p_args) {
	if (!math_types[p_type]) {
		return py::tuple(p_args); // Before the module finished importing.
	}
	return py::reinterpret_borrow<py::object>(math_types[p_type])(*p_args);
}

} // namespace

void set_math_type(MathType p_type, py::object p_class) {
	Py_XDECREF(math_types[p_type]);
	math_types[p_type] = p_class.inc_ref().ptr();
}

bool is_math_type(py::handle p_value, MathType p_type) {
	return math_types[p_type] && PyObject_IsInstance(p_value.ptr(), math_types[p_type]) == 1;
}

String python_type_name(py::handle p_value) {
	return String(py::str(py::type::handle_of(p_value).attr("__name__")));
}

py::object variant_to_python(const Variant &p_value) {
	switch (p_value.get_type()) {
		case Variant::NIL:
			return py::none();
		case Variant::BOOL:
			return py::bool_(p_value.to_bool());
		case Variant::INT:
			return py::int_(p_value.to_int());
		case Variant::FLOAT:
			return py::float_(p_value.to_float());
		case Variant::STRING:
			return py::str(p_value.to_string());
		case Variant::VECTOR2: {
			Vector2 v = p_value;
			return _math(MATH_VECTOR2, py::make_tuple(v.x, v.y));
		}
		case Variant::VECTOR3: {
			Vector3 v = p_value;
			return _math(MATH_VECTOR3, py::make_tuple(v.x, v.y, v.z));
		}
		case Variant::COLOR: {
			Color c = p_value;
			return _math(MATH_COLOR, py::make_tuple(c.r, c.g, c.b, c.a));
		}
		case Variant::TRANSFORM3D: {
			Transform3D t = p_value;
			py::list rows;
			for (int i = 0; i < 3; i++) {
				rows.append(py::make_tuple(t.basis.rows[i].x, t.basis.rows[i].y, t.basis.rows[i].z, t.origin[i]));
			}
			return _math(MATH_TRANSFORM3D, py::make_tuple(rows));
		}
		case Variant::OBJECT:
			return wrap_object(p_value.get_object());
		default:
			throw py::type_error(vformat("Variant type %s has no Python form.", Variant::get_type_name(p_value.get_type()).c_str()));
	}
}

namespace {

bool _is_number(py::handle p_value) {
	return py::isinstance<py::float_>(p_value) || (py::isinstance<py::int_>(p_value) && !py::isinstance<py::bool_>(p_value)) || py::hasattr(p_value, "__float__");
}

bool _is_sequence(py::handle p_value) {
	return !py::isinstance<py::str>(p_value) && !py::isinstance<py::bytes>(p_value) && py::hasattr(p_value, "__len__") && py::hasattr(p_value, "__getitem__");
}

// Numbers of a flat sequence; false when an item is not a number.
bool _numbers(py::handle p_value, std::vector<double> &r_numbers) {
	r_numbers.clear();
	for (py::handle item : p_value) {
		if (!_is_number(item) || _is_sequence(item)) {
			return false;
		}
		r_numbers.push_back(py::float_(py::reinterpret_borrow<py::object>(item)));
	}
	return true;
}

bool _to_transform(py::handle p_value, Transform3D &r_transform) {
	py::object value = py::reinterpret_borrow<py::object>(p_value);
	if (py::hasattr(value, "tolist")) {
		value = value.attr("tolist")(); // numpy arrays.
	}
	if (!_is_sequence(value)) {
		return false;
	}
	size_t rows = py::len(value);
	if (rows != 3 && rows != 4) {
		return false;
	}
	std::vector<double> row;
	for (size_t i = 0; i < 3; i++) {
		py::object r = value[py::int_(i)];
		if (!_is_sequence(r) || py::len(r) != 4 || !_numbers(r, row)) {
			return false;
		}
		r_transform.basis.rows[i] = Vector3(row[0], row[1], row[2]);
		r_transform.origin[i] = row[3];
	}
	return true;
}

} // namespace

Variant python_to_variant(py::handle p_value, Variant::Type p_hint) {
	if (p_value.is_none()) {
		return Variant();
	}
	if (py::isinstance<EngineObject>(p_value)) {
		return Variant(p_value.cast<EngineObject *>()->get_checked());
	}
	if (py::isinstance<py::bool_>(p_value)) {
		return Variant(p_value.cast<bool>());
	}
	if (py::isinstance<py::int_>(p_value)) {
		if (p_hint == Variant::FLOAT) {
			return Variant(p_value.cast<double>());
		}
		return Variant((int64_t)p_value.cast<long long>());
	}
	if (py::isinstance<py::float_>(p_value)) {
		return Variant(p_value.cast<double>());
	}
	if (py::isinstance<py::str>(p_value)) {
		return Variant(String(p_value.cast<std::string>()));
	}
	// Types the engine's Variant does not hold: say so instead of guessing from their size.
	if (is_math_type(p_value, MATH_VECTOR4) || is_math_type(p_value, MATH_BASIS)) {
		throw py::type_error(vformat("A %s cannot be stored in an engine value (Vector2, Vector3, Color and Transform3D can).", python_type_name(p_value).c_str()));
	}
	if (is_math_type(p_value, MATH_TRANSFORM3D) && p_hint != Variant::TRANSFORM3D && p_hint != Variant::NIL) {
		throw py::type_error(vformat("Expected %s, got a Transform3D.", Variant::get_type_name(p_hint).c_str()));
	}
	// numpy scalars and other number-likes.
	if (!_is_sequence(p_value) && py::hasattr(p_value, "__index__") && p_hint != Variant::FLOAT) {
		return Variant((int64_t)py::int_(py::reinterpret_borrow<py::object>(p_value)).cast<long long>());
	}
	if (!_is_sequence(p_value) && py::hasattr(p_value, "__float__")) {
		return Variant((double)py::float_(py::reinterpret_borrow<py::object>(p_value)));
	}
	if (_is_sequence(p_value) || py::hasattr(p_value, "tolist")) {
		if (p_hint == Variant::TRANSFORM3D || p_hint == Variant::NIL) {
			Transform3D t;
			if (_to_transform(p_value, t)) {
				return Variant(t);
			}
			if (p_hint == Variant::TRANSFORM3D) {
				throw py::type_error(vformat("Expected a Transform3D as 3x4 (or 4x4) nested numbers, got %s.", python_type_name(p_value).c_str()));
			}
		}
		py::object value = py::reinterpret_borrow<py::object>(p_value);
		if (!_is_sequence(value) && py::hasattr(value, "tolist")) {
			value = value.attr("tolist")();
		}
		std::vector<double> n;
		if (!_is_sequence(value) || !_numbers(value, n)) {
			throw py::type_error(vformat("Cannot convert %s to an engine value: expected numbers.", python_type_name(p_value).c_str()));
		}
		if (p_hint == Variant::COLOR && (n.size() == 3 || n.size() == 4)) {
			return Variant(Color(n[0], n[1], n[2], n.size() == 4 ? n[3] : 1.0));
		}
		switch (n.size()) {
			case 2:
				return Variant(Vector2(n[0], n[1]));
			case 3:
				return Variant(Vector3(n[0], n[1], n[2]));
			case 4:
				return Variant(Color(n[0], n[1], n[2], n[3]));
			default:
				throw py::type_error(vformat("Cannot convert a sequence of %d numbers to an engine value (2: Vector2, 3: Vector3, 3/4: Color, 3x4: Transform3D).", (int)n.size()));
		}
	}
	throw py::type_error(vformat("Cannot convert %s to an engine value.", python_type_name(p_value).c_str()));
}

} // namespace godot_area_py
