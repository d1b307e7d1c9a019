/**************************************************************************/
/*  undo_redo.cpp                                                         */
/**************************************************************************/
/* godot-area: UndoRedo (see undo_redo.h).                                */

#include "core/object/undo_redo.h"

#include "core/error/error_macros.h"

bool UndoRedo::_check_open(const char *p_what) const {
	if (action_level <= 0) {
		ERR_PRINT(vformat("UndoRedo::%s(): no action is open; call create_action() first.", p_what));
		return false;
	}
	return true;
}

void UndoRedo::_run(const Operation &p_op) {
	switch (p_op.type) {
		case Operation::TYPE_METHOD: {
			ERR_FAIL_NULL_MSG(p_op.object, vformat("UndoRedo: the object of method '%s' is null.", p_op.name.c_str()));
			bool valid = true;
			p_op.object->call(p_op.name, p_op.args, &valid);
			if (!valid) {
				ERR_PRINT(vformat("UndoRedo: calling '%s' on a %s failed.", p_op.name.c_str(), p_op.object->get_class().c_str()));
			}
		} break;
		case Operation::TYPE_PROPERTY: {
			ERR_FAIL_NULL_MSG(p_op.object, vformat("UndoRedo: the object of property '%s' is null.", p_op.name.c_str()));
			bool valid = true;
			p_op.object->set(p_op.name, p_op.args.empty() ? Variant() : p_op.args[0], &valid);
			if (!valid) {
				ERR_PRINT(vformat("UndoRedo: setting '%s' on a %s failed.", p_op.name.c_str(), p_op.object->get_class().c_str()));
			}
		} break;
		case Operation::TYPE_CALLABLE: {
			if (p_op.callable) {
				p_op.callable();
			}
		} break;
	}
}

void UndoRedo::create_action(const String &p_name) {
	if (action_level == 0) {
		ERR_FAIL_COND_MSG(p_name.empty(), "UndoRedo::create_action(): the action name must not be empty.");
		pending = Action();
		pending.name = p_name;
	}
	action_level++;
}

void UndoRedo::add_do_method(Object *p_object, const String &p_method, const std::vector<Variant> &p_args) {
	if (!_check_open("add_do_method")) {
		return;
	}
	ERR_FAIL_NULL_MSG(p_object, vformat("UndoRedo::add_do_method(): the object for '%s' is null.", p_method.c_str()));
	Operation op;
	op.type = Operation::TYPE_METHOD;
	op.object = p_object;
	op.name = p_method;
	op.args = p_args;
	pending.do_ops.push_back(op);
}

void UndoRedo::add_undo_method(Object *p_object, const String &p_method, const std::vector<Variant> &p_args) {
	if (!_check_open("add_undo_method")) {
		return;
	}
	ERR_FAIL_NULL_MSG(p_object, vformat("UndoRedo::add_undo_method(): the object for '%s' is null.", p_method.c_str()));
	Operation op;
	op.type = Operation::TYPE_METHOD;
	op.object = p_object;
	op.name = p_method;
	op.args = p_args;
	pending.undo_ops.push_back(op);
}

void UndoRedo::add_do_method(const std::function<void()> &p_callable) {
	if (!_check_open("add_do_method")) {
		return;
	}
	ERR_FAIL_COND_MSG(!p_callable, "UndoRedo::add_do_method(): the callable is empty.");
	Operation op;
	op.type = Operation::TYPE_CALLABLE;
	op.callable = p_callable;
	pending.do_ops.push_back(op);
}

void UndoRedo::add_undo_method(const std::function<void()> &p_callable) {
	if (!_check_open("add_undo_method")) {
		return;
	}
	ERR_FAIL_COND_MSG(!p_callable, "UndoRedo::add_undo_method(): the callable is empty.");
	Operation op;
	op.type = Operation::TYPE_CALLABLE;
	op.callable = p_callable;
	pending.undo_ops.push_back(op);
}

void UndoRedo::add_do_property(Object *p_object, const String &p_property, const Variant &p_value) {
	if (!_check_open("add_do_property")) {
		return;
	}
	ERR_FAIL_NULL_MSG(p_object, vformat("UndoRedo::add_do_property(): the object for '%s' is null.", p_property.c_str()));
	Operation op;
	op.type = Operation::TYPE_PROPERTY;
	op.object = p_object;
	op.name = p_property;
	op.args.push_back(p_value);
	pending.do_ops.push_back(op);
}

void UndoRedo::add_undo_property(Object *p_object, const String &p_property, const Variant &p_value) {
	if (!_check_open("add_undo_property")) {
		return;
	}
	ERR_FAIL_NULL_MSG(p_object, vformat("UndoRedo::add_undo_property(): the object for '%s' is null.", p_property.c_str()));
	Operation op;
	op.type = Operation::TYPE_PROPERTY;
	op.object = p_object;
	op.name = p_property;
	op.args.push_back(p_value);
	pending.undo_ops.push_back(op);
}

bool UndoRedo::commit_action(bool p_execute) {
	ERR_FAIL_COND_V_MSG(action_level <= 0, false, "UndoRedo::commit_action(): no action is open; call create_action() first.");
	action_level--;
	if (action_level > 0) {
		return true; // Nested: the outermost commit stores the action.
	}
	// A new action drops everything that could have been redone.
	actions.resize(current_action + 1);
	actions.push_back(pending);
	pending = Action();
	current_action = (int)actions.size() - 1;
	version++;
	if (p_execute) {
		committing = true;
		for (const Operation &op : actions[current_action].do_ops) {
			_run(op);
		}
		committing = false;
	}
	return true;
}

bool UndoRedo::undo() {
	ERR_FAIL_COND_V_MSG(action_level > 0, false, "UndoRedo::undo(): an action is still open; commit it first.");
	if (!has_undo()) {
		return false;
	}
	const Action &a = actions[current_action];
	// Undo operations run in reverse order, so later changes are taken back first.
	for (int i = (int)a.undo_ops.size() - 1; i >= 0; i--) {
		_run(a.undo_ops[i]);
	}
	current_action--;
	version++;
	return true;
}

bool UndoRedo::redo() {
	ERR_FAIL_COND_V_MSG(action_level > 0, false, "UndoRedo::redo(): an action is still open; commit it first.");
	if (!has_redo()) {
		return false;
	}
	current_action++;
	for (const Operation &op : actions[current_action].do_ops) {
		_run(op);
	}
	version++;
	return true;
}

String UndoRedo::get_action_name(int p_index) const {
	ERR_FAIL_INDEX_V_MSG(p_index, (int)actions.size(), String(), vformat("UndoRedo::get_action_name(): index %d is outside the history (%d actions).", p_index, (int)actions.size()));
	return actions[p_index].name;
}

String UndoRedo::get_current_action_name() const {
	return current_action >= 0 ? actions[current_action].name : String();
}

void UndoRedo::clear_history() {
	ERR_FAIL_COND_MSG(action_level > 0, "UndoRedo::clear_history(): an action is still open; commit it first.");
	actions.clear();
	current_action = -1;
	version++;
}
