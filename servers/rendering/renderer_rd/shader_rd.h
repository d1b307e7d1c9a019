/**************************************************************************/
/*  shader_rd.h                                                           */
/**************************************************************************/
/* ShaderRD: a GLSL file with #[vertex] / #[fragment] / #[compute]        */
/* sections, compiled per variant (a set of #defines) on first use.       */
/*                                                                        */
/* File format: each section starts with a `#[stage]` line and its first  */
/* real line is `#version 450`. Lines before the first section are        */
/* ignored. `#include "file.glsl"` is expanded textually, resolved        */
/* relative to the including file, then to the shaders/ root.             */
/*                                                                        */
/* Shader files are embedded in the binary at build time (SConstruct      */
/* turns each .glsl of servers/rendering/renderer_rd/shaders/ into a      */
/* .glsl.gen.h beside it),                                                */
/* so a relative name ("forward_clustered/scene_forward_clustered.glsl")  */
/* and its includes never touch the disk. An absolute path reads that     */
/* file (tests); its includes are looked up beside it, then embedded.     */
/* The expanded source carries `#line N "file"` directives, so glslang    */
/* reports errors against the original file and line.                     */
/*                                                                        */
/* Variant v's source gets, right after #version:                         */
/*   <general defines> \n <variant_defines[v]> \n <version defines>       */
/* (each is raw text such as "#define USE_SHADOWS\n"; a plain word        */
/* "FOO" is turned into "#define FOO").                                   */
/*                                                                        */
/* SPIR-V cache: directory $GODOT_AREA_SHADER_CACHE, else                 */
/* $XDG_CACHE_HOME/godot-area/shaders, else ~/.cache/godot-area/shaders   */
/* (XDG Base Directory spec). Key: 128-bit hash of the fully              */
/* preprocessed stage source + stage + compiler tag. Writes are atomic.   */

#pragma once

#include "core/string/ustring.h"
#include "core/templates/rid.h"
#include "servers/rendering/rendering_device.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

class ShaderRD {
public:
	// Loads and splits the file (includes are expanded here). Returns false (and prints the
	// reason) when the file or an include cannot be read. p_path: relative to shaders/ (an
	// embedded file), or absolute (read from the disk). Nothing is compiled yet.
	bool initialize(const String &p_path, const std::vector<String> &p_variant_defines, const String &p_general_defines = "");
	// Same, from source text already in memory; p_name is used in error messages and includes
	// are resolved relative to p_base_dir (absolute: on disk; relative or empty: embedded).
	bool initialize_from_source(const String &p_source, const String &p_name, const std::vector<String> &p_variant_defines, const String &p_general_defines = "", const String &p_base_dir = "");

	// Versions: independent copies with extra defines (Godot uses them for material code).
	// A default version always exists (version_get_shader(int)).
	RID version_create(const String &p_version_defines = "");
	void version_free(RID p_version);
	bool version_is_valid(RID p_version) const;

	// Compiles (or loads from cache) the variant on first call; invalid RID on error (see
	// get_last_error()). The returned shader RID is owned by ShaderRD: do not free it.
	RID version_get_shader(RID p_version, int p_variant);
	RID version_get_shader(int p_variant);
	// True when variant p_variant of the default version has been turned into a shader (compiled or
	// loaded from the cache); never compiles anything.
	bool is_variant_created(int p_variant) const;

	int get_variant_count() const { return (int)variant_defines.size(); }
	// glslang compilations performed (cache misses), cache hits, and variants turned into shaders.
	uint32_t get_compiled_variant_count() const { return compile_count; }
	uint32_t get_cache_hit_count() const { return cache_hit_count; }
	uint32_t get_created_shader_count() const { return created_shader_count; }
	// Message of the last compile/load error ("file:line: ..." from glslang), empty if none.
	String get_last_error() const { return last_error; }
	bool is_compute() const;

	// Directory used for the SPIR-V cache (created on demand).
	static String get_cache_dir();
	// Text of the embedded file at p_path (relative to shaders/), nullptr if there is none.
	static const char *get_embedded_source(const String &p_path);
	// Every embedded file, sorted ("area_light_inc.glsl", "forward_clustered/...").
	static std::vector<String> get_embedded_paths();
	// Fully preprocessed source of one stage of one variant (tests and debugging).
	String get_stage_source(RenderingDevice::ShaderStage p_stage, int p_variant, const String &p_version_defines = "") const;

	// Frees every shader created (call before RenderingDevice::finalize(); the destructor does too).
	void clear();

	ShaderRD() {}
	~ShaderRD();

private:
	struct Version {
		String defines;
		std::vector<RID> shaders; // One per variant, invalid until compiled.
		std::vector<bool> failed;
	};

	String name;
	String stage_code[RenderingDevice::SHADER_STAGE_MAX]; // Expanded, with #line directives, after #version.
	bool has_stage[RenderingDevice::SHADER_STAGE_MAX] = {};
	std::vector<String> variant_defines;
	String general_defines;
	bool initialized = false;

	std::unordered_map<uint64_t, Version> versions;
	uint64_t version_counter = 0;
	RID default_version;

	uint32_t compile_count = 0;
	uint32_t cache_hit_count = 0;
	uint32_t created_shader_count = 0;
	String last_error;

	// Appends p_source with includes expanded; p_first_line is the original line number of its first line.
	bool _expand_includes(const String &p_source, const String &p_file_label, const String &p_base_dir, int p_depth, int p_first_line, String &r_out);
	bool _parse_sections(const String &p_source, const String &p_name, const String &p_base_dir);
	Version *_get_version(RID p_version);
};
