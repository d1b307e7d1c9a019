/**************************************************************************/
/*  method_bind.h                                                         */
/**************************************************************************/
/* A bound C++ member function callable with Variant arguments. Argument  */
/* types are checked with VariantCaster<T>::check before the call, so a   */
/* wrong type is reported instead of silently converted.                  */

#pragma once

#include "core/string/ustring.h"
#include "core/variant/variant.h"
#include "core/variant/variant_caster.h"

#include <type_traits>
#include <utility>
#include <vector>

class Object;

struct CallError {
	enum Error {
		CALL_OK,
		CALL_ERROR_INVALID_METHOD,
		CALL_ERROR_INVALID_ARGUMENT,
		CALL_ERROR_TOO_MANY_ARGUMENTS,
		CALL_ERROR_TOO_FEW_ARGUMENTS,
		CALL_ERROR_INSTANCE_IS_NULL,
	};
	Error error = CALL_OK;
	int argument = 0; // Index of the bad argument, or the expected count.
	Variant::Type expected = Variant::NIL;
};

// D_METHOD("set_param", "param", "value") records the method and argument names.
struct MethodDefinition {
	String name;
	std::vector<String> args;
	MethodDefinition() {}
	template <class... A>
	MethodDefinition(const char *p_name, A... p_args) :
			name(p_name), args{ String(p_args)... } {}
};
#define D_METHOD(...) MethodDefinition(__VA_ARGS__)
// ClassDB::bind_method(D_METHOD("look_at", "target", "up"), &Node3D::look_at, DEFVAL(Vector3(0, 1, 0)));
#define DEFVAL(m_value) (Variant(m_value))

class MethodBind {
	friend class ClassDB;

protected:
	String name;
	String instance_class;
	std::vector<String> arg_names;
	std::vector<Variant::Type> arg_types; // NIL = any Variant.
	std::vector<Variant> default_arguments; // Of the last arguments (Godot's DEFVAL), in order.
	Variant::Type return_type = Variant::NIL;
	bool returns = false;
	bool is_const = false;

	// Checks argument count and types; fills r_error.
	bool _check_args(const Variant **p_args, int p_argcount, const std::vector<bool> &p_ok, CallError &r_error) const;

public:
	const String &get_name() const { return name; }
	const String &get_instance_class() const { return instance_class; }
	const std::vector<String> &get_argument_names() const { return arg_names; }
	int get_argument_count() const { return (int)arg_types.size(); }
	Variant::Type get_argument_type(int p_arg) const;
	Variant::Type get_return_type() const { return return_type; }
	bool has_return() const { return returns; }
	bool is_const_method() const { return is_const; }
	// Defaults of the trailing arguments: argument i has one when i >= count - defaults.size().
	const std::vector<Variant> &get_default_arguments() const { return default_arguments; }

	virtual Variant call(Object *p_object, const Variant **p_args, int p_argcount, CallError &r_error) const = 0;
	Variant call(Object *p_object, const std::vector<Variant> &p_args, CallError &r_error) const;

	// "Invalid type in argument 1 of 'set_param': expected float, got String." style text.
	String get_call_error_text(const CallError &p_error, const Variant **p_args) const;

	virtual ~MethodBind() {}
};

template <class T, class M, class R, class... P>
class MethodBindT : public MethodBind {
	M method;

	template <size_t... I>
	Variant _call(T *p_instance, const Variant **p_args, std::index_sequence<I...>) const {
		if constexpr (std::is_void<R>::value) {
			(p_instance->*method)(VariantCaster<typename std::decay<P>::type>::cast(*p_args[I])...);
			return Variant();
		} else {
			return VariantCaster<typename std::decay<R>::type>::to_variant((p_instance->*method)(VariantCaster<typename std::decay<P>::type>::cast(*p_args[I])...));
		}
	}

public:
	virtual Variant call(Object *p_object, const Variant **p_args, int p_argcount, CallError &r_error) const override {
		T *instance = dynamic_cast<T *>(p_object);
		if (!instance) {
			r_error.error = CallError::CALL_ERROR_INSTANCE_IS_NULL;
			return Variant();
		}
		std::vector<bool> ok;
		if (p_argcount == (int)sizeof...(P)) {
			ok = _check_each(p_args, std::index_sequence_for<P...>{});
		}
		if (!_check_args(p_args, p_argcount, ok, r_error)) {
			return Variant();
		}
		r_error.error = CallError::CALL_OK;
		return _call(instance, p_args, std::index_sequence_for<P...>{});
	}

	template <size_t... I>
	std::vector<bool> _check_each(const Variant **p_args, std::index_sequence<I...>) const {
		return std::vector<bool>{ VariantCaster<typename std::decay<P>::type>::check(*p_args[I])... };
	}

	MethodBindT(M p_method, bool p_const) :
			method(p_method) {
		is_const = p_const;
		arg_types = std::vector<Variant::Type>{ VariantCaster<typename std::decay<P>::type>::TYPE... };
		if constexpr (!std::is_void<R>::value) {
			returns = true;
			return_type = VariantCaster<typename std::decay<R>::type>::TYPE;
		}
		instance_class = T::get_class_static();
	}
};

template <class T, class R, class... P>
MethodBind *create_method_bind(R (T::*p_method)(P...)) {
	return new MethodBindT<T, R (T::*)(P...), R, P...>(p_method, false);
}

template <class T, class R, class... P>
MethodBind *create_method_bind(R (T::*p_method)(P...) const) {
	return new MethodBindT<T, R (T::*)(P...) const, R, P...>(p_method, true);
}
