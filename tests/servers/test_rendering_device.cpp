/**************************************************************************/
/*  test_rendering_device.cpp                                             */
/**************************************************************************/
/* RenderingDevice tests on the real Vulkan device (lavapipe in CI), all  */
/* with the validation layer on; each ends by asserting zero validation   */
/* errors.                                                                */

#include "servers/rendering/rendering_device.h"

#include "core/error/error_macros.h"
#include "tests/servers/rd_test_fixture.h"
#include "tests/servers/rd_test_shaders.h"

#include <doctest/doctest.h>

#include <cstring>

namespace {

const char *fill_compute = R"(#version 450
layout(local_size_x = 64) in;
layout(set = 0, binding = 0, std430) buffer Out { float values[]; } out_buf;
layout(push_constant, std430) uniform Params { float scale; float offset; uint count; uint pad; } params;
void main() {
	uint i = gl_GlobalInvocationID.x;
	if (i >= params.count) { return; }
	out_buf.values[i] = float(i) * float(i) * params.scale + params.offset;
}
)";

struct FillParams {
	float scale;
	float offset;
	uint32_t count;
	uint32_t pad;
};

float read_float(const std::vector<uint8_t> &p_data, size_t p_index) {
	float f;
	memcpy(&f, p_data.data() + p_index * 4, 4);
	return f;
}

} // namespace

TEST_CASE("[RenderingDevice] initializes and reports device info") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	CHECK(rd == RenderingDevice::get_singleton());
	const RenderingDevice::DeviceInfo &info = rd->get_device_info();
	CHECK(!info.name.empty());
	CHECK(!info.api_version.empty());
	CHECK(info.max_push_constant_size >= 128);
	CHECK(info.validation_enabled);
	String text = rd->get_device_info_string();
	CHECK(text.find(info.name) != String::npos);
	CHECK(text.find("Vulkan API") != String::npos);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] compute shader writes a storage buffer") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	RID shader = rd_test_compile_shader(rd, { { RD::SHADER_STAGE_COMPUTE, fill_compute } }, "fill_compute");
	REQUIRE(shader.is_valid());
	CHECK(rd->shader_is_compute(shader));
	CHECK(rd->shader_get_push_constant_size(shader) == sizeof(FillParams));
	const uint32_t count = 1000;
	RID buffer = rd->storage_buffer_create(count * 4);
	REQUIRE(buffer.is_valid());
	rd->set_resource_name(buffer, "fill output");
	RID set = rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 0, buffer) }, shader, 0);
	REQUIRE(set.is_valid());
	RID pipeline = rd->compute_pipeline_create(shader);
	REQUIRE(pipeline.is_valid());

	FillParams params = { 0.5f, 3.0f, count, 0 };
	RD::ComputeListID list = rd->compute_list_begin();
	rd->compute_list_bind_compute_pipeline(list, pipeline);
	rd->compute_list_bind_uniform_set(list, set, 0);
	rd->compute_list_set_push_constant(list, &params, sizeof(params));
	rd->compute_list_dispatch_threads(list, count, 1, 1);
	rd->compute_list_end();
	rd->submit();
	rd->sync();

	std::vector<uint8_t> data = rd->buffer_get_data(buffer);
	REQUIRE(data.size() == count * 4);
	int mismatches = 0;
	for (uint32_t i = 0; i < count; i++) {
		float expected = float(i) * float(i) * 0.5f + 3.0f;
		if (std::abs(read_float(data, i) - expected) > 1e-3f * std::max(1.0f, expected)) {
			mismatches++;
		}
	}
	CHECK(mismatches == 0);

	// buffer_update then partial readback.
	float patch[2] = { -1.0f, -2.0f };
	CHECK(rd->buffer_update(buffer, 8, 8, patch));
	std::vector<uint8_t> part = rd->buffer_get_data(buffer, 8, 8);
	REQUIRE(part.size() == 8);
	CHECK(read_float(part, 0) == -1.0f);
	CHECK(read_float(part, 1) == -2.0f);

	rd->free(pipeline);
	rd->free(set);
	rd->free(buffer);
	rd->free(shader);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] renders a depth-tested triangle into a float texture") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	const char *vs = R"(#version 450
layout(location = 0) in vec3 in_pos;
void main() { gl_Position = vec4(in_pos, 1.0); }
)";
	const char *fs = R"(#version 450
layout(location = 0) out vec4 frag_color;
layout(push_constant, std430) uniform P { vec4 color; } pc;
void main() { frag_color = pc.color; }
)";
	RID shader = rd_test_compile_shader(rd, { { RD::SHADER_STAGE_VERTEX, vs }, { RD::SHADER_STAGE_FRAGMENT, fs } }, "triangle");
	REQUIRE(shader.is_valid());

	const uint32_t size = 16;
	RD::TextureFormat cf;
	cf.format = RD::DATA_FORMAT_R32G32B32A32_SFLOAT;
	cf.width = cf.height = size;
	cf.usage_bits = RD::TEXTURE_USAGE_COLOR_ATTACHMENT_BIT | RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_CAN_COPY_FROM_BIT;
	RID color = rd->texture_create(cf);
	RD::TextureFormat df = cf;
	df.format = RD::DATA_FORMAT_D32_SFLOAT;
	df.usage_bits = RD::TEXTURE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_CAN_COPY_FROM_BIT;
	RID depth = rd->texture_create(df);
	REQUIRE(color.is_valid());
	REQUIRE(depth.is_valid());
	RID fb = rd->framebuffer_create({ color, depth });
	REQUIRE(fb.is_valid());
	CHECK(rd->framebuffer_get_width(fb) == size);
	CHECK(rd->framebuffer_format_get_color_attachment_count(rd->framebuffer_get_format(fb)) == 1);

	// Big triangle covering the centre at depth 0.5; a second, farther one (depth 0.8) must lose.
	float verts[] = { -0.8f, -0.8f, 0.5f, 0.8f, -0.8f, 0.5f, 0.0f, 0.8f, 0.5f };
	float far_verts[] = { -1.0f, -1.0f, 0.8f, 1.0f, -1.0f, 0.8f, 0.0f, 1.0f, 0.8f };
	RID vb = rd->vertex_buffer_create(sizeof(verts), verts);
	RID vb_far = rd->vertex_buffer_create(sizeof(far_verts), far_verts);
	RD::VertexAttribute attr;
	attr.location = 0;
	attr.format = RD::DATA_FORMAT_R32G32B32_SFLOAT;
	attr.stride = 12;
	RD::VertexFormatID vf = rd->vertex_format_create({ attr });
	REQUIRE(vf != RD::INVALID_ID);
	CHECK(rd->vertex_format_create({ attr }) == vf);
	RID va = rd->vertex_array_create(3, vf, { vb });
	RID va_far = rd->vertex_array_create(3, vf, { vb_far });
	uint16_t indices[] = { 0, 1, 2 };
	RID ib = rd->index_buffer_create(3, RD::INDEX_BUFFER_FORMAT_UINT16, indices);
	RID ia = rd->index_array_create(ib, 0, 3);
	REQUIRE(ia.is_valid());

	RD::PipelineDepthStencilState dss;
	dss.enable_depth_test = true;
	dss.enable_depth_write = true;
	dss.depth_compare_operator = RD::COMPARE_OP_LESS;
	RID pipeline = rd->render_pipeline_create(shader, rd->framebuffer_get_format(fb), vf, RD::RENDER_PRIMITIVE_TRIANGLES, RD::PipelineRasterizationState(), dss, RD::PipelineColorBlendState::create_disabled(1));
	REQUIRE(pipeline.is_valid());

	Color clear(0.1f, 0.2f, 0.3f, 1.0f);
	float red[4] = { 1.0f, 0.0f, 0.0f, 1.0f };
	float green[4] = { 0.0f, 1.0f, 0.0f, 1.0f };
	RD::DrawListID dl = rd->draw_list_begin(fb, RD::INITIAL_ACTION_CLEAR, RD::INITIAL_ACTION_CLEAR, { clear }, 1.0f);
	REQUIRE(dl != RD::INVALID_ID);
	rd->draw_list_bind_render_pipeline(dl, pipeline);
	rd->draw_list_bind_vertex_array(dl, va);
	rd->draw_list_bind_index_array(dl, ia);
	rd->draw_list_set_push_constant(dl, red, sizeof(red));
	rd->draw_list_draw(dl, true);
	rd->draw_list_bind_vertex_array(dl, va_far);
	rd->draw_list_set_push_constant(dl, green, sizeof(green));
	rd->draw_list_draw(dl, false);
	rd->draw_list_end();
	rd->submit_and_sync();

	std::vector<uint8_t> pixels = rd->texture_get_data(color);
	REQUIRE(pixels.size() == size * size * 16);
	auto px = [&](uint32_t x, uint32_t y, int c) { return read_float(pixels, (y * size + x) * 4 + c); };
	// Centre: red triangle in front.
	CHECK(px(8, 8, 0) == doctest::Approx(1.0f));
	CHECK(px(8, 8, 1) == doctest::Approx(0.0f));
	// Vulkan NDC y points down: the far triangle's base (y = -1) is the top row, its apex the bottom.
	// Top-left corner: only the far triangle covers it, green at depth 0.8.
	CHECK(px(0, 0, 0) == doctest::Approx(0.0f));
	CHECK(px(0, 0, 1) == doctest::Approx(1.0f));
	// Bottom-left corner: outside both, clear colour.
	CHECK(px(0, 15, 0) == doctest::Approx(0.1f));
	CHECK(px(0, 15, 1) == doctest::Approx(0.2f));
	CHECK(px(0, 15, 2) == doctest::Approx(0.3f));

	std::vector<uint8_t> depth_data = rd->texture_get_data(depth);
	REQUIRE(depth_data.size() == size * size * 4);
	CHECK(read_float(depth_data, 8 * size + 8) == doctest::Approx(0.5f));
	CHECK(read_float(depth_data, 0) == doctest::Approx(0.8f));
	CHECK(read_float(depth_data, 15 * size) == doctest::Approx(1.0f));

	// Freeing the colour texture frees the framebuffer that uses it.
	rd->free(color);
	CHECK(!rd->framebuffer_is_valid(fb));
	rd->free(pipeline);
	rd->free(depth);
	rd->free(ib);
	rd->free(vb);
	rd->free(vb_far);
	CHECK(!rd->render_pipeline_is_valid(pipeline));
	rd->free(shader);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] renders into one layer of a 2D array through a slice") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	const char *vs = RD_TEST_FULLSCREEN_VS;
	const char *fs = R"(#version 450
layout(location = 0) out vec4 frag_color;
void main() { frag_color = vec4(0.25, 0.5, 0.75, 1.0); }
)";
	RID shader = rd_test_compile_shader(rd, { { RD::SHADER_STAGE_VERTEX, vs }, { RD::SHADER_STAGE_FRAGMENT, fs } }, "fullscreen");
	RD::TextureFormat tf;
	tf.format = RD::DATA_FORMAT_R8G8B8A8_UNORM;
	tf.width = tf.height = 8;
	tf.array_layers = 3;
	tf.texture_type = RD::TEXTURE_TYPE_2D_ARRAY;
	tf.usage_bits = RD::TEXTURE_USAGE_COLOR_ATTACHMENT_BIT | RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_CAN_COPY_FROM_BIT | RD::TEXTURE_USAGE_CAN_UPDATE_BIT;
	RID array = rd->texture_create(tf);
	REQUIRE(array.is_valid());
	RID slice = rd->texture_create_shared_from_slice(array, 1);
	REQUIRE(slice.is_valid());
	RID fb = rd->framebuffer_create({ slice });
	REQUIRE(fb.is_valid());
	RD::VertexFormatID empty = rd->vertex_format_create({});
	RID pipeline = rd->render_pipeline_create(shader, rd->framebuffer_get_format(fb), empty, RD::RENDER_PRIMITIVE_TRIANGLES, RD::PipelineRasterizationState(), RD::PipelineDepthStencilState(), RD::PipelineColorBlendState::create_disabled(1));
	REQUIRE(pipeline.is_valid());

	// Layer 2 gets uploaded data.
	std::vector<uint8_t> layer2(8 * 8 * 4, 200);
	CHECK(rd->texture_update(array, 2, layer2));

	RD::DrawListID dl = rd->draw_list_begin(fb, RD::INITIAL_ACTION_CLEAR, RD::INITIAL_ACTION_CLEAR, { Color(0, 0, 0, 0) });
	rd->draw_list_bind_render_pipeline(dl, pipeline);
	rd->draw_list_draw(dl, false, 1, 3);
	rd->draw_list_end();

	std::vector<uint8_t> l0 = rd->texture_get_data(array, 0);
	std::vector<uint8_t> l1 = rd->texture_get_data(array, 1);
	std::vector<uint8_t> l2 = rd->texture_get_data(array, 2);
	REQUIRE(l1.size() == 8 * 8 * 4);
	CHECK(l0[0] == 0);
	CHECK(l1[0] == 64);
	CHECK(l1[1] == 128);
	CHECK(l1[(7 * 8 + 7) * 4 + 2] == 191);
	CHECK(l2[5] == 200);
	// The slice reads back the same layer.
	CHECK(rd->texture_get_data(slice) == l1);

	rd->free(array); // Frees slice and framebuffer too.
	CHECK(!rd->texture_is_valid(slice));
	rd->free(shader); // Frees the pipeline.
	CHECK(!rd->render_pipeline_is_valid(pipeline));
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] compute samples a texture and writes a storage image") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	const char *cs = R"(#version 450
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D src;
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2D dst;
layout(set = 1, binding = 0, std140) uniform Params { vec4 multiplier; } params;
void main() {
	ivec2 p = ivec2(gl_GlobalInvocationID.xy);
	vec2 uv = (vec2(p) + 0.5) / vec2(textureSize(src, 0));
	imageStore(dst, p, texture(src, uv) * params.multiplier);
}
)";
	RID shader = rd_test_compile_shader(rd, { { RD::SHADER_STAGE_COMPUTE, cs } }, "sample_compute");
	REQUIRE(shader.is_valid());
	RD::TextureFormat sf;
	sf.format = RD::DATA_FORMAT_R8G8B8A8_UNORM;
	sf.width = sf.height = 4;
	sf.usage_bits = RD::TEXTURE_USAGE_SAMPLING_BIT | RD::TEXTURE_USAGE_CAN_UPDATE_BIT;
	std::vector<uint8_t> texels(4 * 4 * 4);
	for (size_t i = 0; i < texels.size(); i += 4) {
		texels[i + 0] = 255;
		texels[i + 1] = 0;
		texels[i + 2] = (uint8_t)(i / 4 * 10);
		texels[i + 3] = 255;
	}
	RID src = rd->texture_create(sf, { texels });
	RD::TextureFormat df;
	df.format = RD::DATA_FORMAT_R32G32B32A32_SFLOAT;
	df.width = df.height = 4;
	df.usage_bits = RD::TEXTURE_USAGE_STORAGE_BIT | RD::TEXTURE_USAGE_CAN_COPY_FROM_BIT;
	RID dst = rd->texture_create(df);
	RID sampler = rd->sampler_create(RD::SamplerState());
	float mult[4] = { 0.5f, 1.0f, 1.0f, 2.0f };
	RID ubo = rd->uniform_buffer_create(sizeof(mult), mult);
	REQUIRE(src.is_valid());
	REQUIRE(dst.is_valid());
	REQUIRE(sampler.is_valid());
	REQUIRE(ubo.is_valid());

	RID set0 = rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_SAMPLER_WITH_TEXTURE, 0, std::vector<RID>{ sampler, src }), RD::Uniform(RD::UNIFORM_TYPE_IMAGE, 1, dst) }, shader, 0);
	RID set1 = rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_UNIFORM_BUFFER, 0, ubo) }, shader, 1);
	REQUIRE(set0.is_valid());
	REQUIRE(set1.is_valid());
	RID pipeline = rd->compute_pipeline_create(shader);
	RD::ComputeListID cl = rd->compute_list_begin();
	rd->compute_list_bind_compute_pipeline(cl, pipeline);
	rd->compute_list_bind_uniform_set(cl, set0, 0);
	rd->compute_list_bind_uniform_set(cl, set1, 1);
	rd->compute_list_dispatch(cl, 1, 1, 1);
	rd->compute_list_end();
	std::vector<uint8_t> out = rd->texture_get_data(dst);
	REQUIRE(out.size() == 4 * 4 * 16);
	CHECK(read_float(out, 0) == doctest::Approx(0.5f));
	CHECK(read_float(out, 3) == doctest::Approx(2.0f));
	// Texel 5: blue = 50/255.
	CHECK(read_float(out, 5 * 4 + 2) == doctest::Approx(50.0f / 255.0f).epsilon(0.01));

	// Freeing the sampler frees set0 (it depended on it).
	rd->free(sampler);
	CHECK(!rd->uniform_set_is_valid(set0));
	CHECK(rd->uniform_set_is_valid(set1));
	rd->free(shader);
	rd->free(src);
	rd->free(dst);
	rd->free(ubo);
	CHECK(!rd->uniform_set_is_valid(set1));
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] timestamps are captured in order") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	if (!rd->get_device_info().timestamps_supported) {
		WARN_MESSAGE(false, "Device has no timestamp support; skipped.");
		return;
	}
	RID shader = rd_test_compile_shader(rd, { { RD::SHADER_STAGE_COMPUTE, fill_compute } }, "fill_compute_ts");
	RID buffer = rd->storage_buffer_create(4096 * 4);
	RID set = rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 0, buffer) }, shader, 0);
	RID pipeline = rd->compute_pipeline_create(shader);
	FillParams params = { 1.0f, 0.0f, 4096, 0 };
	rd->capture_timestamp("Frame Begin");
	RD::ComputeListID cl = rd->compute_list_begin();
	rd->compute_list_bind_compute_pipeline(cl, pipeline);
	rd->compute_list_bind_uniform_set(cl, set, 0);
	rd->compute_list_set_push_constant(cl, &params, sizeof(params));
	rd->compute_list_dispatch(cl, 64, 1, 1);
	rd->capture_timestamp("Dispatch 1");
	rd->compute_list_dispatch(cl, 64, 1, 1);
	rd->compute_list_end();
	rd->capture_timestamp("Frame End");
	rd->submit();
	rd->sync();
	REQUIRE(rd->get_captured_timestamps_count() == 3);
	CHECK(rd->get_captured_timestamp_name(0) == "Frame Begin");
	CHECK(rd->get_captured_timestamp_name(2) == "Frame End");
	CHECK(rd->get_captured_timestamp_gpu_time(0) > 0);
	CHECK(rd->get_captured_timestamp_gpu_time(1) >= rd->get_captured_timestamp_gpu_time(0));
	CHECK(rd->get_captured_timestamp_gpu_time(2) >= rd->get_captured_timestamp_gpu_time(1));
	CHECK(rd->get_captured_timestamp_gpu_time(2) > rd->get_captured_timestamp_gpu_time(0));
	rd->free(shader);
	rd->free(buffer);
	CHECK(!rd->uniform_set_is_valid(set));
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] debug labels nest, are captured per frame and unbalanced ones are reported") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	rd->draw_command_begin_label("Outer Pass", Color(1, 0, 0, 1));
	rd->draw_command_begin_label("Inner Pass");
	rd->draw_command_end_label();
	rd->draw_command_end_label();
	rd->submit();
	rd->sync();
	REQUIRE(rd->get_captured_label_names().size() == 2);
	CHECK(rd->get_captured_label_names()[0] == "Outer Pass");
	CHECK(rd->get_captured_label_names()[1] == "Inner Pass");

	std::vector<String> errors;
	ErrorHandlerList handler;
	handler.callback = [&errors](ErrorHandlerType, const String &p_text) { errors.push_back(p_text); };
	add_error_handler(&handler);
	set_error_print_silenced(true);
	rd->draw_command_end_label(); // Nothing open.
	rd->draw_command_begin_label("Left Open");
	rd->submit(); // Closes it with an error, so the command buffer stays valid.
	rd->sync();
	set_error_print_silenced(false);
	remove_error_handler(&handler);
	REQUIRE(errors.size() == 2);
	CHECK(errors[0].find("no label is open") != String::npos);
	CHECK(errors[1].find("1 debug label(s) still open") != String::npos);
	REQUIRE(rd->get_captured_label_names().size() == 1);
	CHECK(rd->get_captured_label_names()[0] == "Left Open");
	rd->submit();
	rd->sync();
	CHECK(rd->get_captured_label_names().empty()); // A frame without labels.
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] bad input fails cleanly") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	set_error_print_silenced(true);
	CHECK(rd->storage_buffer_create(0).is_null());
	CHECK(rd->buffer_get_data(RID()).empty());
	CHECK(!rd->buffer_update(RID(), 0, 4, "abcd"));
	RID buf = rd->storage_buffer_create(16);
	CHECK(!rd->buffer_update(buf, 12, 8, "abcdefgh"));
	RD::TextureFormat tf;
	tf.width = 0;
	CHECK(rd->texture_create(tf).is_null());
	tf.width = 4;
	tf.array_layers = 2; // 2D with two layers is invalid.
	CHECK(rd->texture_create(tf).is_null());
	tf.array_layers = 1;
	CHECK(rd->texture_create(tf, { std::vector<uint8_t>(3) }).is_null());
	String err;
	std::vector<uint32_t> spirv = rd->shader_compile_spirv_from_source(RD::SHADER_STAGE_COMPUTE, "#version 450\nvoid main() { undefined_thing(); }\n", "broken.glsl", &err);
	CHECK(spirv.empty());
	CHECK(err.find("broken.glsl") != String::npos);
	CHECK(rd->shader_create_from_spirv({}).is_null());
	RD::ShaderStageSPIRVData junk;
	junk.shader_stage = RD::SHADER_STAGE_COMPUTE;
	junk.spirv = { 1, 2, 3, 4, 5, 6 };
	CHECK(rd->shader_create_from_spirv({ junk }).is_null());
	CHECK(rd->framebuffer_create({ RID() }).is_null());
	CHECK(rd->uniform_set_create({}, RID(), 0).is_null());
	RID shader = rd_test_compile_shader(rd, { { RD::SHADER_STAGE_COMPUTE, fill_compute } }, "fill_bad");
	// Missing binding, then wrong type.
	CHECK(rd->uniform_set_create({}, shader, 0).is_null());
	RID ubo = rd->uniform_buffer_create(16);
	CHECK(rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_UNIFORM_BUFFER, 0, ubo) }, shader, 0).is_null());
	CHECK(rd->uniform_set_create({ RD::Uniform(RD::UNIFORM_TYPE_STORAGE_BUFFER, 0, ubo) }, shader, 0).is_null());
	RID pipeline = rd->compute_pipeline_create(shader);
	// Dispatch without the uniform set / push constant: refused, no validation error.
	RD::ComputeListID cl = rd->compute_list_begin();
	rd->compute_list_bind_compute_pipeline(cl, pipeline);
	rd->compute_list_dispatch(cl, 1, 1, 1);
	CHECK(rd->compute_list_begin() == RD::INVALID_ID); // Already open.
	rd->compute_list_end();
	rd->free(RID::from_uint64(0xFFFFFFFFull));
	set_error_print_silenced(false);
	rd->free(shader);
	rd->free(buf);
	rd->free(ubo);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] many buffer updates in one frame apply in order") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	const uint32_t count = 256;
	RID buf = rd->storage_buffer_create(count * 4);
	RID other = rd->storage_buffer_create(count * 4);
	REQUIRE(buf.is_valid());
	for (uint32_t i = 0; i < count; i++) {
		uint32_t v = i * 3;
		rd->buffer_update(buf, i * 4, 4, &v);
	}
	uint32_t overwrite = 777;
	rd->buffer_update(buf, 10 * 4, 4, &overwrite); // Later update of the same bytes wins.
	rd->buffer_copy(buf, other, 0, 0, count * 4);
	CHECK(rd->buffer_clear(buf, 0, 16));
	std::vector<uint8_t> a = rd->buffer_get_data(buf);
	std::vector<uint8_t> b = rd->buffer_get_data(other);
	REQUIRE(a.size() == count * 4);
	REQUIRE(b.size() == count * 4);
	uint32_t v0, v5, v10, b0, blast;
	memcpy(&v0, a.data(), 4);
	memcpy(&v5, a.data() + 20, 4);
	memcpy(&v10, a.data() + 40, 4);
	memcpy(&b0, b.data(), 4);
	memcpy(&blast, b.data() + (count - 1) * 4, 4);
	CHECK(v0 == 0); // Cleared.
	CHECK(v5 == 15);
	CHECK(v10 == 777);
	CHECK(b0 == 0);
	CHECK(blast == (count - 1) * 3);
	// A large update (bigger than one staging block) also works.
	std::vector<uint32_t> big(2 * 1024 * 1024, 9);
	RID large = rd->storage_buffer_create((uint32_t)(big.size() * 4), big.data());
	std::vector<uint8_t> back = rd->buffer_get_data(large, (uint32_t)(big.size() * 4 - 4), 4);
	uint32_t last = 0;
	memcpy(&last, back.data(), 4);
	CHECK(last == 9);
	rd->free(buf);
	rd->free(other);
	rd->free(large);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] buffer_get_data_async delivers after the frame completes, without a flush") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	const uint32_t values[4] = { 11, 22, 33, 44 };
	RID buf = rd->storage_buffer_create(sizeof(values), values);
	REQUIRE(buf.is_valid());
	rd->submit();
	rd->sync();
	const uint64_t submitted = rd->get_frames_submitted();
	std::vector<uint32_t> got;
	int calls = 0;
	CHECK(rd->buffer_get_data_async(
			buf, [&](const std::vector<uint8_t> &p_bytes) {
				calls++;
				got.resize(p_bytes.size() / 4);
				memcpy(got.data(), p_bytes.data(), got.size() * 4);
			},
			4, 8));
	// Written after the copy was recorded: the readback holds the old values.
	const uint32_t later = 99;
	rd->buffer_update(buf, 4, 4, &later);
	CHECK(calls == 0);
	CHECK(rd->get_frames_submitted() == submitted); // Nothing was flushed.
	rd->submit();
	CHECK(calls == 0); // Submitted, not yet waited for.
	rd->sync();
	CHECK(calls == 1);
	CHECK(rd->get_frames_submitted() == submitted + 1);
	REQUIRE(got.size() == 2);
	CHECK(got[0] == 22);
	CHECK(got[1] == 33);
	rd->submit();
	rd->sync();
	CHECK(calls == 1); // Delivered once.
	set_error_print_silenced(true);
	CHECK_FALSE(rd->buffer_get_data_async(RID(), [](const std::vector<uint8_t> &) {}));
	CHECK_FALSE(rd->buffer_get_data_async(
			buf, [](const std::vector<uint8_t> &) {}, 16, 4));
	CHECK_FALSE(rd->buffer_get_data_async(buf, nullptr));
	set_error_print_silenced(false);
	rd->free(buf);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] the debug messenger counts validation errors") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	if (!rd->get_device_info().validation_enabled) {
		// Without the layer nothing can be counted: say so instead of passing.
		MESSAGE("skipped: the Vulkan validation layer is not enabled (GODOT_AREA_VALIDATION=1 and vulkan-validationlayers)");
		return;
	}
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
	// A vertex shader reading location 0 with an empty vertex format is invalid Vulkan usage
	// that RenderingDevice itself does not check; the layer must report it.
	const char *vs = "#version 450\nlayout(location = 0) in vec4 p;\nvoid main() { gl_Position = p; }\n";
	RID shader = rd_test_compile_shader(rd, { { RD::SHADER_STAGE_VERTEX, vs } }, "needs_input");
	RD::TextureFormat tf;
	tf.width = tf.height = 4;
	tf.usage_bits = RD::TEXTURE_USAGE_COLOR_ATTACHMENT_BIT;
	RID tex = rd->texture_create(tf);
	RID fb = rd->framebuffer_create({ tex });
	set_error_print_silenced(true);
	RID pipeline = rd->render_pipeline_create(shader, rd->framebuffer_get_format(fb), rd->vertex_format_create({}), RD::RENDER_PRIMITIVE_TRIANGLES, RD::PipelineRasterizationState(), RD::PipelineDepthStencilState(), RD::PipelineColorBlendState::create_disabled(1));
	set_error_print_silenced(false);
	CHECK(rd->get_validation_error_count() > 0);
	rd->reset_validation_counts();
	CHECK(rd->get_validation_error_count() == 0);
	if (pipeline.is_valid()) {
		rd->free(pipeline);
	}
	rd->free(shader);
	rd->free(tex);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}

TEST_CASE("[RenderingDevice] two colour attachments, additive blending and a sub-region") {
	RenderingDevice *rd = rd_test_get_device();
	REQUIRE(rd != nullptr);
	const char *vs = RD_TEST_FULLSCREEN_VS;
	const char *fs = R"(#version 450
layout(location = 0) out vec4 out0;
layout(location = 1) out vec4 out1;
void main() { out0 = vec4(0.25, 0.0, 0.0, 0.0); out1 = vec4(0.0, 0.5, 0.0, 1.0); }
)";
	RID shader = rd_test_compile_shader(rd, { { RD::SHADER_STAGE_VERTEX, vs }, { RD::SHADER_STAGE_FRAGMENT, fs } }, "mrt");
	RD::TextureFormat tf;
	tf.format = RD::DATA_FORMAT_R16G16B16A16_SFLOAT;
	tf.width = tf.height = 8;
	tf.usage_bits = RD::TEXTURE_USAGE_COLOR_ATTACHMENT_BIT | RD::TEXTURE_USAGE_CAN_COPY_FROM_BIT;
	RID t0 = rd->texture_create(tf);
	tf.format = RD::DATA_FORMAT_R32G32B32A32_SFLOAT;
	RID t1 = rd->texture_create(tf);
	RID fb = rd->framebuffer_create({ t0, t1 });
	REQUIRE(fb.is_valid());
	RD::FramebufferFormatID fmt = rd->framebuffer_get_format(fb);
	CHECK(rd->framebuffer_format_get_color_attachment_count(fmt) == 2);
	RID pipeline = rd->render_pipeline_create(shader, fmt, rd->vertex_format_create({}), RD::RENDER_PRIMITIVE_TRIANGLES, RD::PipelineRasterizationState(), RD::PipelineDepthStencilState(), RD::PipelineColorBlendState::create_additive(2));
	REQUIRE(pipeline.is_valid());

	// Clear everything, draw twice (additive), then draw once more only into the 4x4 top-left region (loaded).
	RD::DrawListID dl = rd->draw_list_begin(fb, RD::INITIAL_ACTION_CLEAR, RD::INITIAL_ACTION_CLEAR, { Color(0, 0, 0, 0), Color(0, 0, 0, 0) });
	rd->draw_list_bind_render_pipeline(dl, pipeline);
	rd->draw_list_draw(dl, false, 1, 3);
	rd->draw_list_draw(dl, false, 1, 3);
	rd->draw_list_end();
	dl = rd->draw_list_begin(fb, RD::INITIAL_ACTION_LOAD, RD::INITIAL_ACTION_LOAD, {}, 1.0f, RD::Rect(0, 0, 4, 4));
	REQUIRE(dl != RD::INVALID_ID);
	rd->draw_list_bind_render_pipeline(dl, pipeline);
	rd->draw_list_draw(dl, false, 1, 3);
	rd->draw_list_end();

	std::vector<uint8_t> d1 = rd->texture_get_data(t1);
	REQUIRE(d1.size() == 8 * 8 * 16);
	auto g = [&](int x, int y) { return read_float(d1, (y * 8 + x) * 4 + 1); };
	CHECK(g(1, 1) == doctest::Approx(1.5f)); // Three draws inside the region.
	CHECK(g(6, 6) == doctest::Approx(1.0f)); // Two draws outside it.
	std::vector<uint8_t> d0 = rd->texture_get_data(t0);
	CHECK(d0.size() == 8 * 8 * 8); // Half floats.
	rd->free(t0);
	rd->free(t1);
	rd->free(shader);
	RD_TEST_CHECK_NO_VALIDATION_ERRORS(rd);
}
