/**************************************************************************/
/*  resource_format_text.h                                                */
/**************************************************************************/
/* Loader and saver for text scenes (.tscn, format=3 subset):             */
/*   [gd_scene load_steps=N format=3 uid="uid://..."]                     */
/*   [ext_resource type="Texture2D" path="res://t.png" id="1_abc"]        */
/*   [sub_resource type="StandardMaterial3D" id="Mat_1"]                  */
/*   albedo_color = Color(1, 0, 0, 1)                                     */
/*   [node name="Main" type="Node3D"]                                     */
/*   [node name="Sun" type="DirectionalLight3D" parent="."]              */
/*   light_energy = 2.0                                                   */
/*   [node name="Model" parent="." instance=ExtResource("2_x")]           */
/* Properties are applied only through Object::set (ClassDB setters).     */
/* Unknown node/resource types and unknown or ill-typed properties give   */
/* a WARNING "file:line: ..." and loading goes on (an unknown node type   */
/* skips the node and its children). Malformed text (bad header, bad      */
/* literal, unterminated string, missing parent...) fails the whole load  */
/* with "file:line: message" and returns null, freeing what was built.    */
/*                                                                        */
/* Paths: "res://x" resolves against the resource root (set_resource_root;*/
/* by default the directory of the scene being loaded); relative paths    */
/* resolve against the scene's directory.                                 */
/*                                                                        */
/* The saver writes the node tree back: stored properties (usage STORAGE) */
/* that differ from the class default, resources with a path as           */
/* ext_resource and path-less ones as sub_resource. Instanced scenes are  */
/* written out in full (the instance link is not kept).                   */

#pragma once

#include "core/io/resource.h"
#include "core/string/ustring.h"

#include <functional>

class Node;

class ResourceFormatText {
public:
	// Instances a scene file (glTF, another .tscn...) for `instance=ExtResource(...)`.
	// p_path is resolved to a file-system path. Return null with r_error set on failure.
	typedef std::function<Node *(const String &p_path, String *r_error)> SceneLoaderFunc;
	// Loads a resource file for a property value (textures...). p_type is the
	// ext_resource's type attribute.
	typedef std::function<Ref<Resource>(const String &p_path, const String &p_type, String *r_error)> ResourceLoaderFunc;

	// p_extension without the dot, case-insensitive ("glb", "gltf"). "tscn" is built in
	// (a hook for "tscn" replaces it).
	static void add_scene_loader(const String &p_extension, const SceneLoaderFunc &p_func);
	static void remove_scene_loader(const String &p_extension);
	static void add_resource_loader(const String &p_extension, const ResourceLoaderFunc &p_func);
	static void remove_resource_loader(const String &p_extension);

	// Directory that "res://" maps to. Empty (default): the loaded scene's directory.
	static void set_resource_root(const String &p_dir);
	static String get_resource_root();
	// Resolves a path as written in a scene file, relative to that scene file.
	static String resolve_path(const String &p_path, const String &p_scene_path);

	// Returns the root node (owned by the caller) or null with *r_error = "file:line: message".
	static Node *load_scene(const String &p_path, String *r_error = nullptr);
	// p_path is only used for messages and for resolving relative paths.
	static Node *load_scene_from_string(const String &p_text, const String &p_path, String *r_error = nullptr);

	static String save_scene_to_string(const Node *p_root);
	static bool save_scene(const Node *p_root, const String &p_path, String *r_error = nullptr);
};
