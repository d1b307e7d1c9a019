/**************************************************************************/
/*  undo_redo.h                                                           */
/**************************************************************************/
/* godot-area: Godot's UndoRedo, reduced. An action is a named list of    */
/* "do" operations and a list of "undo" operations:                       */
/*                                                                        */
/*   ur.create_action("Change Area Light Size");                          */
/*   ur.add_do_method(light, "set_area_size", { new_size });              */
/*   ur.add_undo_method(light, "set_area_size", { old_size });            */
/*   ur.commit_action();   // runs the do operations (by default)         */
/*   ur.undo();            // runs the undo operations, in reverse order  */
/*   ur.redo();            // runs the do operations again, in order      */
/*                                                                        */
/* Operations call a bound method (Object::call), set a bound property    */
/* (Object::set) or run a C++ callable. Committing a new action after an  */
/* undo drops the actions that could have been redone (as Godot).         */
/* create_action() inside an open action nests: the inner operations join */
/* the outer action, which is committed by the outermost commit_action(). */
/* Merge modes are not implemented (every action is MERGE_DISABLE).       */
/*                                                                        */
/* Objects are held by plain pointer (we have no ObjectID): clear the     */
/* history (clear_history) before deleting an object an action names.     */

#pragma once

#include "core/object/object.h"
#include "core/string/ustring.h"
#include "core/variant/variant.h"

#include <functional>
#include <vector>

class UndoRedo {
public:
	struct Operation {
		enum Type {
			TYPE_METHOD,
			TYPE_PROPERTY,
			TYPE_CALLABLE,
		};
		Type type = TYPE_METHOD;
		Object *object = nullptr;
		String name; // Method or property name.
		std::vector<Variant> args; // Method arguments, or the property value in args[0].
		std::function<void()> callable;
	};

	struct Action {
		String name;
		std::vector<Operation> do_ops;
		std::vector<Operation> undo_ops;
	};

private:
	std::vector<Action> actions;
	// Index of the last applied action; -1 when everything is undone.
	int current_action = -1;
	// Nesting depth of create_action(); 0 = no open action.
	int action_level = 0;
	Action pending;
	bool committing = false;
	// Bumped by every commit, undo and redo (Godot's get_version()).
	uint64_t version = 1;

	bool _check_open(const char *p_what) const;
	static void _run(const Operation &p_op);

public:
	// Opens an action (or nests into the open one). p_name must not be empty at the outer level.
	void create_action(const String &p_name);

	// Calls p_object->call(p_method, p_args) when the action is done (or redone).
	void add_do_method(Object *p_object, const String &p_method, const std::vector<Variant> &p_args = std::vector<Variant>());
	// Calls p_object->call(p_method, p_args) when the action is undone.
	void add_undo_method(Object *p_object, const String &p_method, const std::vector<Variant> &p_args = std::vector<Variant>());
	// C++ callables (Godot 4 takes a Callable here).
	void add_do_method(const std::function<void()> &p_callable);
	void add_undo_method(const std::function<void()> &p_callable);
	// p_object->set(p_property, p_value) on do / undo.
	void add_do_property(Object *p_object, const String &p_property, const Variant &p_value);
	void add_undo_property(Object *p_object, const String &p_property, const Variant &p_value);

	// Closes the open action (the outermost commit stores it). With p_execute the do operations
	// run now; without, the caller has already applied them. Returns false when no action is open.
	bool commit_action(bool p_execute = true);
	bool is_committing_action() const { return committing; }

	// Undoes the last applied action; false when there is nothing to undo or an action is open.
	bool undo();
	// Redoes the next undone action; false when there is nothing to redo or an action is open.
	bool redo();
	bool has_undo() const { return current_action >= 0; }
	bool has_redo() const { return current_action + 1 < (int)actions.size(); }

	// Actions in history order (applied ones first, then the redoable ones).
	int get_history_count() const { return (int)actions.size(); }
	// Index of the last applied action, -1 when none.
	int get_current_action() const { return current_action; }
	String get_action_name(int p_index) const;
	// Name of the last applied action, empty when none.
	String get_current_action_name() const;
	uint64_t get_version() const { return version; }

	// Forgets every action (the objects keep their current state).
	void clear_history();

	UndoRedo() {}
	UndoRedo(const UndoRedo &) = delete;
	UndoRedo &operator=(const UndoRedo &) = delete;
};
