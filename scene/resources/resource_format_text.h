/**************************************************************************/
/*  resource_format_text.h                                                */
/**************************************************************************/
/* Loader and saver for Godot 4 text scenes (.tscn) and resources (.tres):*/
/*   [gd_scene format=3 uid="uid://..."]                                  */
/*   [ext_resource type="Texture2D" uid="uid://.." path="res://t.png" id="1_abc"] */
/*   [sub_resource type="StandardMaterial3D" id="Mat_1"]                  */
/*   albedo_color = Color(1, 0, 0, 1)                                     */
/*   [node name="Main" type="Node3D"]                                     */
/*   [node name="Model" parent="." instance=ExtResource("2_x")]           */
/*   [node name="Cube" parent="Model" index="0"]   (override section)     */
/*   [connection signal="pressed" from="B" to="." method="_on_b"]         */
/*   [editable path="Model"]                                              */
/*                                                                        */
/* Nothing is lost (Godot's MissingNode/MissingResource idea): an unknown */
/* node type becomes a MissingNode (acts as Node3D, keeps its children),  */
/* an unknown resource type or file format a MissingResource; any value   */
/* the engine cannot apply (unknown property, Array/Dictionary/NodePath,  */
/* wrong type) is kept as its text, and groups, unique_id, index, uids,   */
/* scripts, metadata, [connection] and [editable] are kept too; the saver */
/* writes all of it back (ObjectFileData on the objects). Each problem is */
/* counted: one warning line per distinct problem, "file:line: what (×N)" */
/* after the load; set_verbose(true) prints every occurrence as well.     */
/* Malformed text (bad header, bad literal, unterminated string...) fails */
/* the load with "file:line: message" and returns null.                   */
/*                                                                        */
/* Paths: "res://x" resolves against the nearest ancestor folder of the   */
/* file holding project.godot (fallback: the file's folder, warned once), */
/* or against set_resource_root() when set; relative paths resolve        */
/* against the file's folder; an ext_resource's uid is kept and its path= */
/* is what loads.                                                         */
/*                                                                        */
/* Instancing: every instanced scene (.tscn, glTF...) is parsed once and  */
/* its tree duplicated per instance (meshes and materials shared); the    */
/* parsed template stays alive while an instance does, and is reused by  */
/* later loads unless the file changed. The saver writes an instance as   */
/* instance=ExtResource(...) plus override sections for what differs from */
/* the template.                                                          */

#pragma once

#include "core/io/resource.h"
#include "core/string/ustring.h"

#include <functional>

class Node;

class ResourceFormatText {
public:
	// Instances a scene file (glTF...) for `instance=ExtResource(...)` and for
	// load_scene() of that extension. p_path is a file-system path. Return null
	// with r_error set on failure. The result is used as a template (parsed once).
	typedef std::function<Node *(const String &p_path, String *r_error)> SceneLoaderFunc;
	// Loads a resource file for a property value (textures...). p_type is the
	// ext_resource's type attribute.
	typedef std::function<Ref<Resource>(const String &p_path, const String &p_type, String *r_error)> ResourceLoaderFunc;

	// p_extension without the dot, case-insensitive ("glb", "gltf"). "tscn" and
	// "tres" are built in (a hook replaces them).
	static void add_scene_loader(const String &p_extension, const SceneLoaderFunc &p_func);
	static void remove_scene_loader(const String &p_extension);
	static bool has_scene_loader(const String &p_extension);
	static void add_resource_loader(const String &p_extension, const ResourceLoaderFunc &p_func);
	static void remove_resource_loader(const String &p_extension);

	// Directory that "res://" maps to. Empty (default): found from project.godot.
	static void set_resource_root(const String &p_dir);
	static String get_resource_root();
	// The nearest ancestor folder of p_file holding project.godot, or "" if none.
	static String find_project_root(const String &p_file);
	// Resolves a path as written in a scene file, relative to that scene file.
	static String resolve_path(const String &p_path, const String &p_scene_path);

	// Every occurrence of a load problem is printed too (the CLI's --verbose).
	static void set_verbose(bool p_verbose);
	static bool is_verbose();

	// Returns the root node (owned by the caller) or null with *r_error = "file:line: message".
	// Any extension with a scene loader (.glb/.gltf) opens directly.
	static Node *load_scene(const String &p_path, String *r_error = nullptr);
	// p_path is only used for messages and for resolving relative paths.
	static Node *load_scene_from_string(const String &p_text, const String &p_path, String *r_error = nullptr);
	// A .tres file (or any extension with a resource loader), cached for the
	// duration of the outermost load.
	static Ref<Resource> load_resource(const String &p_path, const String &p_type_hint, String *r_error = nullptr);
	static Ref<Resource> load_resource_from_string(const String &p_text, const String &p_path, String *r_error = nullptr);

	// The number of distinct load problems (kept content, unknown types...) the
	// last top-level load counted; 0 means the scene loaded whole.
	static int get_last_load_problem_count();

	static String save_scene_to_string(const Node *p_root);
	static bool save_scene(const Node *p_root, const String &p_path, String *r_error = nullptr);
};
