/**************************************************************************/
/*  test_shader_rd.cpp                                                    */
/**************************************************************************/
/* ShaderRD: lazy variant compilation, #include with file/line errors and */
/* the on-disk SPIR-V cache. Shader files are written to a temp folder.   */

#include "servers/rendering/renderer_rd/shader_rd.h"

#include "core/error/error_macros.h"
#include "tests/servers/rd_test_fixture.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace {

// A fresh temp directory per process, holding test shaders and the SPIR-V cache.
String shader_test_dir() {
	static String dir;
	if (dir.empty()) {
		char tmpl[] = "/tmp/godot_area_shader_rd_XXXXXX";
		char *d = mkdtemp(tmpl);
		dir = d ? String(d) : String("/tmp/godot_area_shader_rd");
		std::filesystem::create_directories(dir + "/inc");
		setenv("GODOT_AREA_SHADER_CACHE", (dir + "/cache").c_str(), 1);
		if (d) {
			atexit([]() {
				std::error_code ec;
				std::filesystem::remove_all(shader_test_dir(), ec);
			});
		}
	}
	return dir;
}

void write_file(const String &p_path, const String &p_text) {
	std::ofstream f(p_path, std::ios::binary);
	f << p_text;
}

// Line 1: banner; compute section; includes inc/values.glsl; VALUE depends on the variant.
const char *variant_shader = R"(// Test compute shader with variants.
#[compute]
#version 450
#include "inc/values.glsl"
layout(local_size_x = 4) in;
layout(set = 0, binding = 0, std430) buffer Out { uint values[]; } out_buf;
void main() {
	out_buf.values[gl_GlobalInvocationID.x] = VALUE + BASE_VALUE + gl_GlobalInvocationID.x;
}
)";

const char *values_include = R"(// Shared values.
#ifdef MODE_A
#define VALUE 100u
#elif defined(MODE_B)
#define VALUE 200u
#else
#define VALUE 300u
#endif
#include "base.glsl"
)";

const char *base_include = R"(#define BASE_VALUE 5u
)";

uint32_t run_variant(RenderingDevice *p_rd, RID p_shader, uint32_t p_index) {
	RID buf = p_rd->storage_buffer_create(16);
	RID set = p_rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 0, buf) }, p_shader, 0);
	RID pipeline = p_rd->compute_pipeline_create(p_shader);
	RD::ComputeListID cl = p_rd->compute_list_begin();
	p_rd->compute_list_bind_compute_pipeline(cl, pipeline);
	p_rd->compute_list_bind_uniform_set(cl, set, 0);
	p_rd->compute_list_dispatch(cl, 1, 1, 1);
	p_rd->compute_list_end();
	std::vector<uint8_t> data = p_rd->buffer_get_data(buf);
	uint32_t v = 0;
	if (data.size() == 16) {
		memcpy(&v, data.data() + p_index * 4, 4);
	}
	p_rd->free(pipeline);
	p_rd->free(buf);
	return v;
}

void write_variant_files() {
	String dir = shader_test_dir();
	write_file(dir + "/variants.glsl", variant_shader);
	write_file(dir + "/inc/values.glsl", values_include);
	write_file(dir + "/inc/base.glsl", base_include);
}

} // namespace

TEST_CASE("[ShaderRD] compiles only the variants that are requested") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	write_variant_files();
	String dir = shader_test_dir();
	ShaderRD shader;
	REQUIRE(shader.initialize(dir + "/variants.glsl", { "MODE_A", "#define MODE_B\n", "" }));
	CHECK(shader.is_compute());
	CHECK(shader.get_variant_count() == 3);
	CHECK(shader.get_compiled_variant_count() == 0);

	RID v1 = shader.version_get_shader(1);
	REQUIRE(v1.is_valid());
	CHECK(shader.get_compiled_variant_count() + shader.get_cache_hit_count() == 1);
	CHECK(shader.get_created_shader_count() == 1);
	CHECK(shader.version_get_shader(1) == v1); // Cached in memory, no recompilation.
	CHECK(shader.get_created_shader_count() == 1);
	CHECK(run_variant(rd, v1, 2) == 200u + 5u + 2u);

	RID v2 = shader.version_get_shader(2);
	REQUIRE(v2.is_valid());
	CHECK(shader.get_created_shader_count() == 2);
	CHECK(run_variant(rd, v2, 0) == 305u);
	// Variant 0 was never requested, so it was never compiled.
	CHECK(shader.get_compiled_variant_count() + shader.get_cache_hit_count() == 2);

	// A version with extra defines.
	RID version = shader.version_create("BASE_OFFSET=7");
	CHECK(shader.version_is_valid(version));
	CHECK(shader.version_get_shader(version, 0).is_valid());
	String src = shader.get_stage_source(RD::SHADER_STAGE_COMPUTE, 0, "BASE_OFFSET=7");
	CHECK(src.find("#define MODE_A") != String::npos);
	CHECK(src.find("#define BASE_OFFSET 7") != String::npos);
	shader.version_free(version);
	CHECK(!shader.version_is_valid(version));

	shader.clear();
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[ShaderRD] the SPIR-V cache is hit on a second initialize") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	write_variant_files();
	String dir = shader_test_dir();
	// Unique general define so this test starts from a cold cache even after other tests.
	{
		ShaderRD first;
		REQUIRE(first.initialize(dir + "/variants.glsl", { "MODE_A" }, "CACHE_TEST_COLD"));
		REQUIRE(first.version_get_shader(0).is_valid());
		CHECK(first.get_compiled_variant_count() == 1);
		CHECK(first.get_cache_hit_count() == 0);
	}
	CHECK(std::filesystem::exists(ShaderRD::get_cache_dir()));
	ShaderRD second;
	REQUIRE(second.initialize(dir + "/variants.glsl", { "MODE_A" }, "CACHE_TEST_COLD"));
	RID s = second.version_get_shader(0);
	REQUIRE(s.is_valid());
	CHECK(second.get_compiled_variant_count() == 0);
	CHECK(second.get_cache_hit_count() == 1);
	CHECK(run_variant(rd, s, 1) == 106u);
	second.clear();
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[ShaderRD] compile errors name the original file and line") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	String dir = shader_test_dir();
	// Error in the main file after an include: line 9 of main_error.glsl.
	write_file(dir + "/inc/helper.glsl", "// helper\nfloat helper_value() {\n\treturn 1.0;\n}\n");
	write_file(dir + "/main_error.glsl",
			"// banner\n" // 1
			"#[vertex]\n" // 2
			"#version 450\n" // 3
			"#include \"inc/helper.glsl\"\n" // 4
			"void main() {\n" // 5
			"\tgl_Position = vec4(helper_value());\n" // 6
			"}\n" // 7
			"#[fragment]\n" // 8
			"#version 450\n" // 9
			"layout(location = 0) out vec4 c;\n" // 10
			"void main() {\n" // 11
			"\tc = vec4(1.0) +* 2.0;\n" // 12: syntax error
			"}\n");
	set_error_print_silenced(true);
	ShaderRD shader;
	REQUIRE(shader.initialize(dir + "/main_error.glsl", { "" }));
	RID r = shader.version_get_shader(0);
	CHECK(r.is_null());
	String err = shader.get_last_error();
	INFO(err);
	CHECK(err.find("main_error.glsl:12") != String::npos);
	CHECK(shader.version_get_shader(0).is_null()); // Stays failed, no crash.

	// Error inside an included file: line 3 of inc/bad_inc.glsl.
	write_file(dir + "/inc/bad_inc.glsl", "// bad include\nfloat bad() {\n\treturn undefined_symbol;\n}\n");
	write_file(dir + "/uses_bad.glsl", "#[compute]\n#version 450\nlayout(local_size_x = 1) in;\n#include \"inc/bad_inc.glsl\"\nvoid main() {}\n");
	ShaderRD shader2;
	REQUIRE(shader2.initialize(dir + "/uses_bad.glsl", { "" }));
	CHECK(shader2.version_get_shader(0).is_null());
	INFO(shader2.get_last_error());
	CHECK(shader2.get_last_error().find("bad_inc.glsl:3") != String::npos);

	// Missing include and missing file fail at initialize.
	write_file(dir + "/missing_inc.glsl", "#[compute]\n#version 450\n#include \"nope.glsl\"\nvoid main() {}\n");
	ShaderRD shader3;
	CHECK(!shader3.initialize(dir + "/missing_inc.glsl", { "" }));
	CHECK(shader3.get_last_error().find("missing_inc.glsl:3") != String::npos);
	CHECK(shader3.version_get_shader(0).is_null());
	ShaderRD shader4;
	CHECK(!shader4.initialize(dir + "/does_not_exist.glsl", { "" }));
	set_error_print_silenced(false);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}
