/**************************************************************************/
/*  method_bind.cpp                                                       */
/**************************************************************************/

#include "core/object/method_bind.h"

#include "core/error/error_macros.h"

Variant::Type MethodBind::get_argument_type(int p_arg) const {
	ERR_FAIL_INDEX_V_MSG(p_arg, (int)arg_types.size(), Variant::NIL, vformat("Method '%s' has no argument %d.", name.c_str(), p_arg));
	return arg_types[p_arg];
}

bool MethodBind::_check_args(const Variant **p_args, int p_argcount, const std::vector<bool> &p_ok, CallError &r_error) const {
	int expected = (int)arg_types.size();
	if (p_argcount > expected) {
		r_error.error = CallError::CALL_ERROR_TOO_MANY_ARGUMENTS;
		r_error.argument = expected;
		return false;
	}
	if (p_argcount < expected) {
		r_error.error = CallError::CALL_ERROR_TOO_FEW_ARGUMENTS;
		r_error.argument = expected;
		return false;
	}
	for (int i = 0; i < expected; i++) {
		if (i >= (int)p_ok.size() || !p_ok[i]) {
			r_error.error = CallError::CALL_ERROR_INVALID_ARGUMENT;
			r_error.argument = i;
			r_error.expected = arg_types[i];
			return false;
		}
	}
	return true;
}

Variant MethodBind::call(Object *p_object, const std::vector<Variant> &p_args, CallError &r_error) const {
	std::vector<const Variant *> ptrs;
	for (const Variant &v : p_args) {
		ptrs.push_back(&v);
	}
	// Missing trailing arguments take their defaults (DEFVAL).
	const int missing = get_argument_count() - (int)p_args.size();
	if (missing > 0 && missing <= (int)default_arguments.size()) {
		for (int i = (int)default_arguments.size() - missing; i < (int)default_arguments.size(); i++) {
			ptrs.push_back(&default_arguments[i]);
		}
	}
	return call(p_object, ptrs.empty() ? nullptr : ptrs.data(), (int)ptrs.size(), r_error);
}

String MethodBind::get_call_error_text(const CallError &p_error, const Variant **p_args) const {
	switch (p_error.error) {
		case CallError::CALL_OK:
			return String();
		case CallError::CALL_ERROR_INVALID_METHOD:
			return vformat("Method '%s' does not exist.", name.c_str());
		case CallError::CALL_ERROR_INVALID_ARGUMENT: {
			String got = p_args ? Variant::get_type_name(p_args[p_error.argument]->get_type()) : String("?");
			if (p_args && p_args[p_error.argument]->get_type() == Variant::OBJECT && p_args[p_error.argument]->get_object()) {
				got = p_args[p_error.argument]->stringify();
			}
			String arg_name = p_error.argument < (int)arg_names.size() ? arg_names[p_error.argument] : itos(p_error.argument);
			return vformat("Invalid type in argument '%s' of '%s': expected %s, got %s.", arg_name.c_str(), name.c_str(), Variant::get_type_name(p_error.expected).c_str(), got.c_str());
		}
		case CallError::CALL_ERROR_TOO_MANY_ARGUMENTS:
			return vformat("Too many arguments for '%s': expected %d.", name.c_str(), p_error.argument);
		case CallError::CALL_ERROR_TOO_FEW_ARGUMENTS:
			return vformat("Too few arguments for '%s': expected %d.", name.c_str(), p_error.argument);
		case CallError::CALL_ERROR_INSTANCE_IS_NULL:
			return vformat("Method '%s' called on a null or wrong-class instance.", name.c_str());
	}
	return String();
}
