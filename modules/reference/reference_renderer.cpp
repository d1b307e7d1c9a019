/**************************************************************************/
/*  reference_renderer.cpp                                                */
/**************************************************************************/
/* godot-area: the CPU ground-truth renderer (see reference_renderer.h).  */
/* Each step names the GPU code it mirrors: ray setup = the rasteriser's  */
/* pixel centres and clip_from_view of RenderForwardClustered::           */
/* render_scene; vertex data = RendererRD::MeshStorage::                  */
/* _create_surface_gpu and the vertex shader; material units =            */
/* RendererRD::MaterialStorage::_make_ubo; light units = RendererRD::     */
/* LightStorage::fill_light_data; shading = the fragment shader of        */
/* servers/rendering/renderer_rd/shaders/forward_clustered/scene_forward_clustered.glsl.                */

#include "modules/reference/reference_renderer.h"

#include "core/error/error_macros.h"
#include "core/io/image.h"
#include "core/math/math_funcs.h"
#include "modules/reference/area_light_shapes.h"
#include "modules/reference/reference_light_sampling.h"
#include "modules/reference/reference_texture.h"
#include "servers/rendering/storage/texture_mipmaps.h"

#include <embree3/rtcore.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <thread>

using namespace ReferenceBRDF;

/*************************************************************************/
/* Frame                                                                 */
/*************************************************************************/

struct ReferenceRenderer::Frame {
	RTCScene scene = nullptr;
	std::vector<Surface> surfaces; // Index = Embree geometry ID.
	std::vector<Light> lights;
	int width = 0;
	int height = 0;
	Projection view_from_clip; // Inverse of the Vulkan clip_from_view (depth-corrected, y flipped).
	Transform3D world_from_view;
	bool orthogonal = false;
	Vector3 ambient_light; // Linear colour * energy (SceneDataUBO::ambient_light).
	Color clear_color; // Linear bg colour * energy, alpha 1.
	bool sky_background = false; // ENV_BG_SKY: rays that miss see the sky.
	bool sky_ambient = false; // Sky ambient: an importance-sampled environment light (diffuse, as the GPU's SH).
	float ambient_sky_contribution = 1.0f;
	bool sky_reflections = false; // reflected_light_source resolved: the sky lights the specular lobe exactly.
	ReferenceSkyLight sky;
	ReferenceRenderOptions options;
	int thread_count = 1;
	std::atomic<int> next_row{ 0 };
	std::atomic<int> rows_done{ 0 };
	std::atomic<uint64_t> shadow_rays{ 0 };
	std::atomic<uint64_t> bounce_rays{ 0 };
	std::atomic<uint64_t> area_samples{ 0 };
	std::atomic<uint64_t> area_integrals{ 0 };
	std::atomic<uint64_t> area_converged{ 0 };
	std::vector<float> pixel_relative_error; // One per pixel, each written by one worker.
	std::vector<uint32_t> pixel_area_samples;
	std::mutex progress_mutex;
	int progress_printed = -1;
};

// Back-face culling for cull_back materials (primary rays only; shadow rays see both faces, as a
// closed occluder casts the same shadow either way). A hit is front-facing when the ray runs against
// the face normal (c - a) x (b - a), which is the GPU's clockwise-front rule.
float ReferenceRenderer::_surface_alpha(const Surface &p_surface, uint32_t p_prim, float p_b1, float p_b2) {
	const ShadingMaterial &m = p_surface.material;
	const uint32_t *tri = &p_surface.indices[p_prim * 3];
	float alpha = m.alpha;
	if (m.vertex_color && !p_surface.colors.empty()) {
		alpha *= p_surface.colors[tri[0]].a * (1.0f - p_b1 - p_b2) + p_surface.colors[tri[1]].a * p_b1 + p_surface.colors[tri[2]].a * p_b2;
	}
	if (!m.textures[0].image) {
		return alpha;
	}
	const Vector2 uv = (p_surface.uvs[tri[0]] * (1.0f - p_b1 - p_b2) + p_surface.uvs[tri[1]] * p_b1 + p_surface.uvs[tri[2]] * p_b2) * m.uv1_scale + m.uv1_offset;
	const Color texel = m.nearest ? reference_sample_texture_nearest(*m.textures[0].image, uv) : reference_sample_texture_bilinear(*m.textures[0].image, uv);
	return alpha * texel.a;
}

void ReferenceRenderer::_surface_filter(const RTCFilterFunctionNArguments *p_args, bool p_occlusion) {
	const Surface &s = *static_cast<const Surface *>(p_args->geometryUserPtr);
	for (unsigned i = 0; i < p_args->N; i++) {
		if (p_args->valid[i] != -1) {
			continue;
		}
		const unsigned prim = RTCHitN_primID(p_args->hit, p_args->N, i);
		if (p_occlusion ? s.cast_shadows == RS::SHADOW_CASTING_SETTING_OFF : s.cast_shadows == RS::SHADOW_CASTING_SETTING_SHADOWS_ONLY) {
			p_args->valid[i] = 0; // GeometryInstance3D::cast_shadow: Off casts nothing, Shadows Only is seen by no other ray.
			continue;
		}
		if (p_occlusion && s.material.transparency == RS::MATERIAL_TRANSPARENCY_ALPHA) {
			p_args->valid[i] = 0; // Godot: alpha-blended materials cast no shadow.
			continue;
		}
		if (!p_occlusion && s.material.cull_back) {
			const Vector3 dir(RTCRayN_dir_x(p_args->ray, p_args->N, i), RTCRayN_dir_y(p_args->ray, p_args->N, i), RTCRayN_dir_z(p_args->ray, p_args->N, i));
			if (s.face_normals[prim].dot(dir) >= 0.0f) {
				p_args->valid[i] = 0;
				continue;
			}
		}
		if (s.material.transparency == RS::MATERIAL_TRANSPARENCY_ALPHA_SCISSOR) {
			const float alpha = _surface_alpha(s, prim, RTCHitN_u(p_args->hit, p_args->N, i), RTCHitN_v(p_args->hit, p_args->N, i));
			if (alpha < s.material.alpha_scissor_threshold) {
				p_args->valid[i] = 0; // The shader's discard: a hole for every ray.
			}
		}
	}
}

/*************************************************************************/
/* Construction                                                          */
/*************************************************************************/

static void _reference_embree_error(void *p_user, RTCError p_code, const char *p_message) {
	ERR_PRINT(vformat("ReferenceRenderer: Embree error %d: %s", int(p_code), p_message ? p_message : ""));
}

ReferenceRenderer::ReferenceRenderer(RendererLightStorage *p_light_storage, RendererMeshStorage *p_mesh_storage, RendererMaterialStorage *p_material_storage, const ReferenceRenderOptions &p_options) :
		light_storage(p_light_storage), mesh_storage(p_mesh_storage), material_storage(p_material_storage), options(p_options) {
	ERR_FAIL_COND_MSG(!light_storage || !mesh_storage || !material_storage, "ReferenceRenderer needs light, mesh and material storages.");
	RTCDevice device = rtcNewDevice(nullptr);
	if (!device) {
		ERR_PRINT(vformat("ReferenceRenderer: Embree device creation failed (error %d).", int(rtcGetDeviceError(nullptr))));
		return;
	}
	rtcSetDeviceErrorFunction(device, _reference_embree_error, nullptr);
	embree_device = device;
}

ReferenceRenderer::~ReferenceRenderer() {
	if (embree_device) {
		rtcReleaseDevice(static_cast<RTCDevice>(embree_device));
		embree_device = nullptr;
	}
}

/*************************************************************************/
/* Render targets                                                        */
/*************************************************************************/

RID ReferenceRenderer::render_target_create(int p_width, int p_height) {
	ERR_FAIL_COND_V_MSG(p_width <= 0 || p_height <= 0 || p_width > 16384 || p_height > 16384, RID(), vformat("ReferenceRenderer: invalid render target size %dx%d.", p_width, p_height));
	RenderTarget rt;
	rt.width = p_width;
	rt.height = p_height;
	rt.data.assign(size_t(p_width) * p_height * 4, 0.0f);
	for (size_t i = 3; i < rt.data.size(); i += 4) {
		rt.data[i] = 1.0f;
	}
	return render_target_owner.make_rid(rt);
}

bool ReferenceRenderer::render_target_free(RID p_rid) {
	if (!render_target_owner.owns(p_rid)) {
		return false;
	}
	render_target_owner.free(p_rid);
	return true;
}

std::vector<float> ReferenceRenderer::render_target_get_data(RID p_render_target) {
	const RenderTarget *rt = render_target_owner.get_or_null(p_render_target);
	ERR_FAIL_NULL_V_MSG(rt, std::vector<float>(), "ReferenceRenderer::render_target_get_data: invalid render target RID.");
	return rt->data;
}

std::vector<std::pair<String, double>> ReferenceRenderer::get_last_frame_profile() const {
	return { { String("reference"), last_stats.seconds * 1000.0 } };
}

/*************************************************************************/
/* Scene data (mirrors the GPU storages' unit conversions)               */
/*************************************************************************/

ReferenceRenderer::ShadingMaterial ReferenceRenderer::_resolve_material(RID p_material) const {
	// An invalid material falls back to the defaults, as RD's default_material.
	RS::MaterialParams p = material_storage->owns_material(p_material) ? material_storage->material_get_params(p_material) : RS::MaterialParams();
	ShadingMaterial m;
	Color albedo = p.albedo.srgb_to_linear();
	m.albedo = Vector3(albedo.r, albedo.g, albedo.b);
	m.alpha = albedo.a;
	Color emission = p.emission.srgb_to_linear();
	m.emission = Vector3(emission.r, emission.g, emission.b) * p.emission_energy;
	m.roughness = p.roughness;
	m.metallic = p.metallic;
	m.specular = p.specular;
	m.normal_scale = p.normal_scale;
	m.unshaded = p.unshaded;
	m.specular_enabled = p.specular_mode != RS::MATERIAL_SPECULAR_DISABLED;
	// Lambert wrap and toon fall back to Lambert, as on the GPU.
	m.diffuse_mode = p.diffuse_mode == RS::MATERIAL_DIFFUSE_BURLEY ? BRDF_DIFFUSE_BURLEY : BRDF_DIFFUSE_LAMBERT;
	m.cull_back = p.cull_back;
	// The mip chains (made once per texture, here on the main thread) only for the mipmap filters.
	m.mipmaps = p.texture_filter != RS::MATERIAL_TEXTURE_FILTER_NEAREST && p.texture_filter != RS::MATERIAL_TEXTURE_FILTER_LINEAR;
	const RID textures[4] = { p.albedo_texture, p.normal_texture, p.roughness_texture, p.metallic_texture };
	for (int i = 0; i < 4; i++) {
		if (textures[i].is_valid() && material_storage->owns_texture(textures[i])) {
			m.textures[i].image = material_storage->texture_get_image(textures[i]);
			m.textures[i].levels = m.mipmaps ? material_storage->texture_get_mipmaps(textures[i], i == 0) : nullptr;
		}
	}
	// The GPU's conversions (RendererRD::MaterialStorage::_make_ubo).
	RS::material_texture_channel_weights(p.roughness_texture_channel, m.roughness_channel);
	RS::material_texture_channel_weights(p.metallic_texture_channel, m.metallic_channel);
	m.uv1_scale = Vector2(p.uv1_scale.x, p.uv1_scale.y);
	m.uv1_offset = Vector2(p.uv1_offset.x, p.uv1_offset.y);
	m.nearest = RS::material_texture_filter_is_nearest(p.texture_filter);
	m.transparency = p.transparency;
	m.alpha_scissor_threshold = p.alpha_scissor_threshold;
	m.vertex_color = p.vertex_color_use_as_albedo;
	m.vertex_color_srgb = p.vertex_color_is_srgb;
	return m;
}

bool ReferenceRenderer::_build_surface(const RS::SurfaceData &p_data, const Transform3D &p_xform, Surface &r_surface) const {
	const uint32_t count = uint32_t(p_data.vertices.size());
	if (count == 0) {
		return false;
	}
	if (p_data.indices.empty()) {
		r_surface.indices.resize(count - count % 3);
		for (uint32_t i = 0; i < r_surface.indices.size(); i++) {
			r_surface.indices[i] = i;
		}
	} else {
		r_surface.indices = p_data.indices;
	}
	const uint32_t tri_count = uint32_t(r_surface.indices.size() / 3);
	for (uint32_t idx : r_surface.indices) {
		ERR_FAIL_COND_V_MSG(idx >= count, false, "ReferenceRenderer: a surface index is out of range; surface skipped.");
	}

	// Object-space normals: given, or area-weighted face normals (RendererRD::MeshStorage).
	std::vector<Vector3> normals(count);
	if (p_data.normals.size() == count) {
		normals = p_data.normals;
	} else {
		std::vector<Vector3> acc(count);
		for (uint32_t t = 0; t < tri_count; t++) {
			uint32_t a = r_surface.indices[t * 3], b = r_surface.indices[t * 3 + 1], c = r_surface.indices[t * 3 + 2];
			Vector3 n = (p_data.vertices[c] - p_data.vertices[a]).cross(p_data.vertices[b] - p_data.vertices[a]);
			acc[a] += n;
			acc[b] += n;
			acc[c] += n;
		}
		for (uint32_t i = 0; i < count; i++) {
			Vector3 n = acc[i].normalized();
			normals[i] = n == Vector3() ? Vector3(0, 1, 0) : n;
		}
	}
	// Object-space tangents (xyz, w = binormal sign): given, or from a helper axis (RendererRD::MeshStorage).
	std::vector<float> tangents(size_t(count) * 4);
	if (p_data.tangents.size() == size_t(count) * 4) {
		tangents = p_data.tangents;
	} else {
		for (uint32_t i = 0; i < count; i++) {
			Vector3 n = normals[i];
			Vector3 helper = std::fabs(n.x) < 0.9f ? Vector3(1, 0, 0) : Vector3(0, 1, 0);
			Vector3 t = (helper - n * n.dot(helper)).normalized();
			tangents[i * 4 + 0] = t.x;
			tangents[i * 4 + 1] = t.y;
			tangents[i * 4 + 2] = t.z;
			tangents[i * 4 + 3] = 1.0f;
		}
	}

	// World space, as the vertex shader computes it (normal matrix = inverse transpose of the basis).
	Basis normal_basis = p_xform.basis.inverse().transposed();
	r_surface.positions.resize(count);
	r_surface.normals.resize(count);
	r_surface.tangents.resize(count);
	r_surface.binormals.resize(count);
	r_surface.uvs.assign(count, Vector2());
	for (uint32_t i = 0; i < count; i++) {
		r_surface.positions[i] = p_xform.xform(p_data.vertices[i]);
		r_surface.normals[i] = normal_basis.xform(normals[i]);
		Vector3 t(tangents[i * 4 + 0], tangents[i * 4 + 1], tangents[i * 4 + 2]);
		r_surface.tangents[i] = p_xform.basis.xform(t);
		r_surface.binormals[i] = r_surface.normals[i].cross(r_surface.tangents[i]) * (tangents[i * 4 + 3] < 0.0f ? -1.0f : 1.0f);
	}
	if (p_data.uvs.size() == count) {
		r_surface.uvs = p_data.uvs;
	}
	if (p_data.colors.size() == count) {
		r_surface.colors = p_data.colors;
	}
	r_surface.face_normals.resize(tri_count);
	for (uint32_t t = 0; t < tri_count; t++) {
		const Vector3 &a = r_surface.positions[r_surface.indices[t * 3]];
		const Vector3 &b = r_surface.positions[r_surface.indices[t * 3 + 1]];
		const Vector3 &c = r_surface.positions[r_surface.indices[t * 3 + 2]];
		r_surface.face_normals[t] = (c - a).cross(b - a);
	}
	return tri_count > 0;
}

bool ReferenceRenderer::_make_light(const RenderSceneData::LightInstance &p_instance, Light &r_light) const {
	RID rid = p_instance.light;
	ERR_FAIL_COND_V_MSG(!light_storage->owns_light(rid), false, "ReferenceRenderer: a visible light instance has an invalid light RID; skipped.");
	RS::LightType type = light_storage->light_get_type(rid);
	if (type == RS::LIGHT_DIRECTIONAL) {
		// RendererRD::LightStorage::fill_directional_light_data, in world space (sun_light.h).
		r_light.type = type;
		DirectionalLightData &sun = r_light.sun;
		sun = DirectionalLightData();
		Vector3 direction = p_instance.transform.basis.xform(Vector3(0, 0, -1)).normalized();
		sun.direction = direction == Vector3() ? Vector3(0, 0, -1) : direction;
		Color linear = light_storage->light_get_color(rid).srgb_to_linear();
		float energy = light_storage->light_get_param(rid, RS::LIGHT_PARAM_ENERGY) * float(Math::PI) * (light_storage->light_is_negative(rid) ? -1.0f : 1.0f);
		sun.color = Vector3(linear.r * energy, linear.g * energy, linear.b * energy);
		sun.size = Math::deg_to_rad(std::fmin(std::fmax(light_storage->light_get_param(rid, RS::LIGHT_PARAM_SIZE), 0.0f), 90.0f)) * 0.5f;
		sun.specular_amount = light_storage->light_get_param(rid, RS::LIGHT_PARAM_SPECULAR);
		sun.cull_mask = light_storage->light_get_cull_mask(rid);
		sun.shadow = light_storage->light_has_shadow(rid);
		return true;
	}
	if (type == RS::LIGHT_AREA) {
		// The area-light contract's units (area_light.h); scale is ignored, as for every light.
		r_light.type = type;
		AreaLightData &a = r_light.area;
		a = AreaLightData();
		area_light_set_frame(a, p_instance.transform);
		const Vector2 size = light_storage->light_area_get_size(rid);
		a.size_x = size.x;
		a.size_y = size.y;
		a.shape = AreaLightShape(light_storage->light_area_get_shape(rid));
		a.radiance = area_light_emitted_radiance(light_storage->light_get_color(rid), light_storage->light_get_param(rid, RS::LIGHT_PARAM_ENERGY), light_storage->light_is_negative(rid), size, light_storage->light_area_get_normalize_energy(rid), a.shape);
		a.range = light_storage->light_get_param(rid, RS::LIGHT_PARAM_RANGE);
		a.attenuation = std::fmax(light_storage->light_get_param(rid, RS::LIGHT_PARAM_ATTENUATION), 0.0f);
		a.specular_amount = light_storage->light_get_param(rid, RS::LIGHT_PARAM_SPECULAR);
		a.cull_mask = light_storage->light_get_cull_mask(rid);
		const RID texture = light_storage->light_area_get_texture(rid);
		if (texture.is_valid() && material_storage && material_storage->owns_texture(texture)) {
			a.texture = material_storage->texture_get_image(texture);
		}
		return true;
	}
	// RendererRD::LightStorage::fill_light_data, in world instead of view space.
	r_light.type = type;
	LightData &d = r_light.data;
	d = LightData();
	d.position = p_instance.transform.origin;
	Vector3 direction = p_instance.transform.basis.xform(Vector3(0, 0, -1)).normalized();
	d.direction = direction == Vector3() ? Vector3(0, 0, -1) : direction;
	float range = std::fmax(light_storage->light_get_param(rid, RS::LIGHT_PARAM_RANGE), 1e-4f);
	Color linear = light_storage->light_get_color(rid).srgb_to_linear();
	float energy = light_storage->light_get_param(rid, RS::LIGHT_PARAM_ENERGY) * float(Math::PI) * (light_storage->light_is_negative(rid) ? -1.0f : 1.0f);
	d.inv_radius = 1.0f / range;
	d.size = light_storage->light_get_param(rid, RS::LIGHT_PARAM_SIZE);
	d.color = Vector3(linear.r * energy, linear.g * energy, linear.b * energy);
	d.attenuation = light_storage->light_get_param(rid, RS::LIGHT_PARAM_ATTENUATION);
	if (type == RS::LIGHT_SPOT) {
		d.cone_attenuation = light_storage->light_get_param(rid, RS::LIGHT_PARAM_SPOT_ATTENUATION);
		d.cone_angle = std::cos(Math::deg_to_rad(light_storage->light_get_param(rid, RS::LIGHT_PARAM_SPOT_ANGLE)));
	} else {
		d.cone_attenuation = 0.0f;
		d.cone_angle = -1.0f;
	}
	d.specular_amount = light_storage->light_get_param(rid, RS::LIGHT_PARAM_SPECULAR);
	d.cull_mask = light_storage->light_get_cull_mask(rid);
	return true;
}

/*************************************************************************/
/* Rendering                                                             */
/*************************************************************************/

void ReferenceRenderer::render_scene(const RenderSceneData &p_data, RID p_render_target) {
	RenderTarget *rt = render_target_owner.get_or_null(p_render_target);
	ERR_FAIL_NULL_MSG(rt, "ReferenceRenderer::render_scene: invalid render target RID.");
	ERR_FAIL_NULL_MSG(embree_device, "ReferenceRenderer::render_scene: no Embree device (creation failed).");
	auto start = std::chrono::steady_clock::now();
	RTCDevice device = static_cast<RTCDevice>(embree_device);

	Frame frame;
	frame.width = rt->width;
	frame.height = rt->height;
	frame.options = options;

	// Camera: the same clip_from_view as RenderForwardClustered (OpenGL projection, Vulkan correction).
	Projection clip_from_view = Projection::create_depth_correction(true) * p_data.cam_projection;
	frame.view_from_clip = clip_from_view.inverse();
	frame.world_from_view = p_data.cam_transform;
	frame.orthogonal = p_data.cam_projection.columns[3].w == 1.0f;

	// Environment: linearised exactly as RenderForwardClustered::render_scene.
	const RenderSceneData::EnvironmentData &env = p_data.environment;
	Color ambient = env.ambient_color.srgb_to_linear();
	frame.ambient_light = Vector3(ambient.r * env.ambient_energy, ambient.g * env.ambient_energy, ambient.b * env.ambient_energy);
	Color bg = env.bg_color.srgb_to_linear();
	frame.clear_color = Color(bg.r * env.bg_energy, bg.g * env.bg_energy, bg.b * env.bg_energy, 1.0f);
	// Sky: the same model as the GPU's SkyRD (material, background energy, the sun disk of the first sun).
	if (env.has_sky) {
		frame.sky_background = env.background == RS::ENV_BG_SKY;
		frame.sky_ambient = env.sky_ambient && env.ambient_sky_contribution > 0.0f;
		frame.ambient_sky_contribution = env.ambient_sky_contribution;
		frame.sky_reflections = env.sky_reflections;
		frame.sky.build(SkyModel::from_scene_data(p_data, light_storage));
		if (frame.sky_ambient) {
			frame.ambient_light *= 1.0f - env.ambient_sky_contribution; // The colour share; the sky share is integrated.
		}
	}

	// Geometry: every surface of every visible instance, in world space.
	for (const RenderSceneData::GeometryInstance &g : p_data.geometry) {
		int surface_count = mesh_storage->owns_mesh(g.mesh) ? mesh_storage->mesh_get_surface_count(g.mesh) : 0;
		for (int s = 0; s < surface_count; s++) {
			const RS::SurfaceData *data = mesh_storage->mesh_get_surface(g.mesh, s);
			if (!data) {
				continue;
			}
			Surface surface;
			if (!_build_surface(*data, g.transform, surface)) {
				continue;
			}
			RID material = g.material_override.is_valid() ? g.material_override : mesh_storage->mesh_surface_get_material(g.mesh, s);
			surface.material = _resolve_material(material);
			surface.layer_mask = g.layer_mask;
			surface.cast_shadows = g.cast_shadows;
			frame.surfaces.push_back(std::move(surface));
		}
	}
	for (const RenderSceneData::LightInstance &li : p_data.lights) {
		Light light;
		if (_make_light(li, light)) {
			frame.lights.push_back(light);
		}
	}
	for (const RenderSceneData::LightInstance &li : p_data.directional_lights) {
		Light light;
		if (_make_light(li, light)) {
			frame.lights.push_back(light);
		}
	}

	// Embree scene (built per frame; the surfaces vector is not resized after this point).
	frame.scene = rtcNewScene(device);
	uint64_t triangles = 0;
	for (uint32_t i = 0; i < frame.surfaces.size(); i++) {
		Surface &s = frame.surfaces[i];
		RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
		float *vb = static_cast<float *>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), s.positions.size()));
		unsigned *ib = static_cast<unsigned *>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), s.indices.size() / 3));
		if (!vb || !ib) {
			ERR_PRINT("ReferenceRenderer: Embree buffer allocation failed; surface skipped.");
			rtcReleaseGeometry(geom);
			continue;
		}
		for (size_t v = 0; v < s.positions.size(); v++) {
			vb[v * 3 + 0] = s.positions[v].x;
			vb[v * 3 + 1] = s.positions[v].y;
			vb[v * 3 + 2] = s.positions[v].z;
		}
		for (size_t k = 0; k < s.indices.size(); k++) {
			ib[k] = s.indices[k];
		}
		const bool cast_setting = s.cast_shadows == RS::SHADOW_CASTING_SETTING_OFF || s.cast_shadows == RS::SHADOW_CASTING_SETTING_SHADOWS_ONLY;
		if (s.material.cull_back || s.material.transparency != RS::MATERIAL_TRANSPARENCY_DISABLED || cast_setting) {
			rtcSetGeometryUserData(geom, &s);
			rtcSetGeometryIntersectFilterFunction(geom, _surface_intersect_filter);
			if (s.material.transparency != RS::MATERIAL_TRANSPARENCY_DISABLED || cast_setting) {
				rtcSetGeometryOccludedFilterFunction(geom, _surface_occluded_filter);
			}
		}
		rtcCommitGeometry(geom);
		rtcAttachGeometryByID(frame.scene, geom, i);
		rtcReleaseGeometry(geom);
		triangles += s.indices.size() / 3;
	}
	// Robust traversal: no ray slips between two triangles sharing an edge (issue 20: 17 black pixels along a
	// quad's diagonal made every accuracy number carry that error).
	rtcSetSceneFlags(frame.scene, RTC_SCENE_FLAG_ROBUST);
	rtcCommitScene(frame.scene);

	// Workers: rows handed out by an atomic counter; each pixel has its own generator.
	int threads = options.threads > 0 ? options.threads : int(std::thread::hardware_concurrency());
	threads = std::max(1, std::min(threads, frame.height));
	frame.thread_count = threads;
	std::vector<float> pixels(size_t(frame.width) * frame.height * 4, 0.0f);
	frame.pixel_relative_error.assign(size_t(frame.width) * frame.height, 0.0f);
	frame.pixel_area_samples.assign(size_t(frame.width) * frame.height, 0u);
	std::vector<std::thread> workers;
	for (int t = 1; t < threads; t++) {
		workers.emplace_back([&frame, &pixels, t]() { _render_rows(frame, t, pixels); });
	}
	_render_rows(frame, 0, pixels);
	for (std::thread &w : workers) {
		w.join();
	}
	if (options.progress) {
		fprintf(stderr, "\n");
	}
	rtcReleaseScene(frame.scene);
	frame.scene = nullptr;
	rt->data.swap(pixels);

	last_stats = ReferenceRenderStats();
	last_stats.width = frame.width;
	last_stats.height = frame.height;
	last_stats.threads = threads;
	last_stats.primary_rays = uint64_t(frame.width) * frame.height;
	last_stats.shadow_rays = frame.shadow_rays.load();
	last_stats.bounce_rays = frame.bounce_rays.load();
	last_stats.area_light_samples = frame.area_samples.load();
	last_stats.area_light_integrals = frame.area_integrals.load();
	last_stats.area_light_integrals_converged = frame.area_converged.load();
	last_stats.pixel_relative_error.swap(frame.pixel_relative_error);
	last_stats.pixel_area_samples.swap(frame.pixel_area_samples);
	last_stats.triangles = triangles;
	last_stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void ReferenceRenderer::_render_rows(const Frame &p_frame, int p_thread, std::vector<float> &r_pixels) {
	Frame &frame = const_cast<Frame &>(p_frame); // Only the atomics and the progress state change.
	PixelCounters totals;
	while (true) {
		int y = frame.next_row.fetch_add(1);
		if (y >= frame.height) {
			break;
		}
		for (int x = 0; x < frame.width; x++) {
			uint64_t index = uint64_t(y) * frame.width + x;
			ReferenceRNG rng = ReferenceRNG::for_pixel(frame.options.seed, index);
			PixelCounters counters;
			Color c = _shade_pixel(frame, x, y, rng, counters);
			totals.shadow_rays += counters.shadow_rays;
			totals.bounce_rays += counters.bounce_rays;
			totals.area_samples += counters.area_samples;
			totals.area_integrals += counters.area_integrals;
			totals.area_converged += counters.area_converged;
			frame.pixel_relative_error[index] = counters.max_relative_error;
			frame.pixel_area_samples[index] = counters.pixel_samples;
			float *p = &r_pixels[index * 4];
			p[0] = c.r;
			p[1] = c.g;
			p[2] = c.b;
			p[3] = c.a;
		}
		int done = frame.rows_done.fetch_add(1) + 1;
		if (frame.options.progress) {
			int percent = int(int64_t(done) * 100 / frame.height);
			std::lock_guard<std::mutex> lock(frame.progress_mutex);
			if (percent > frame.progress_printed) {
				frame.progress_printed = percent;
				int bar = percent / 5;
				fprintf(stderr, "\r[reference] [%.*s%.*s] %3d%% (%d threads)", bar, "====================", 20 - bar, "                    ", percent, frame.thread_count);
				fflush(stderr);
			}
		}
	}
	frame.shadow_rays.fetch_add(totals.shadow_rays);
	frame.bounce_rays.fetch_add(totals.bounce_rays);
	frame.area_samples.fetch_add(totals.area_samples);
	frame.area_integrals.fetch_add(totals.area_integrals);
	frame.area_converged.fetch_add(totals.area_converged);
}

Color ReferenceRenderer::_shade_pixel(const Frame &p_frame, int p_x, int p_y, ReferenceRNG &r_rng, PixelCounters &r_counters) {
	// Pixel centre in Vulkan NDC (y down, top row first), unprojected at depth 0 (near) and 1 (far):
	// the segment the rasteriser's depth range covers for this pixel.
	float ndc_x = (float(p_x) + 0.5f) / float(p_frame.width) * 2.0f - 1.0f;
	float ndc_y = (float(p_y) + 0.5f) / float(p_frame.height) * 2.0f - 1.0f;
	Vector3 near_view = p_frame.view_from_clip.xform(Vector3(ndc_x, ndc_y, 0.0f));
	Vector3 far_view = p_frame.view_from_clip.xform(Vector3(ndc_x, ndc_y, 1.0f));
	Vector3 origin = p_frame.world_from_view.xform(near_view);
	Vector3 segment = p_frame.world_from_view.xform(far_view) - origin;
	float seg_len = segment.length();
	if (!(seg_len > 0.0f) || !std::isfinite(seg_len)) {
		return p_frame.clear_color;
	}
	Vector3 dir = segment / seg_len;
	// Ray differentials: the rays through the centres of the pixels right of and below this one.
	RayDifferentials diff;
	for (int k = 0; k < 2; k++) {
		const float nx = ndc_x + (k == 0 ? 2.0f / float(p_frame.width) : 0.0f);
		const float ny = ndc_y + (k == 1 ? 2.0f / float(p_frame.height) : 0.0f);
		const Vector3 o = p_frame.world_from_view.xform(p_frame.view_from_clip.xform(Vector3(nx, ny, 0.0f)));
		diff.origins[k] = o;
		diff.dirs[k] = (p_frame.world_from_view.xform(p_frame.view_from_clip.xform(Vector3(nx, ny, 1.0f))) - o).normalized();
	}
	bool hit = false;
	return _shade_ray(p_frame, p_frame.options, origin, dir, seg_len, p_frame.options.bounces, r_rng, r_counters, hit, &diff);
}

Color ReferenceRenderer::_shade_ray(const Frame &p_frame, const ReferenceRenderOptions &p_options, const Vector3 &p_origin, const Vector3 &p_dir, float p_tfar, int p_bounces, ReferenceRNG &r_rng, PixelCounters &r_counters, bool &r_hit, const RayDifferentials *p_diff) {
	const Vector3 &origin = p_origin;
	const Vector3 &dir = p_dir;
	const float seg_len = p_tfar;
	r_hit = false;
	auto background = [&p_frame, &dir]() {
		if (p_frame.sky_background) {
			const Vector3 l = p_frame.sky.evaluate(dir);
			return Color(l.x, l.y, l.z, 1.0f);
		}
		return p_frame.clear_color;
	};

	RTCIntersectContext context;
	rtcInitIntersectContext(&context);
	RTCRayHit rh;
	rh.ray.org_x = origin.x;
	rh.ray.org_y = origin.y;
	rh.ray.org_z = origin.z;
	rh.ray.dir_x = dir.x;
	rh.ray.dir_y = dir.y;
	rh.ray.dir_z = dir.z;
	rh.ray.tnear = 0.0f;
	rh.ray.tfar = seg_len;
	rh.ray.time = 0.0f;
	rh.ray.mask = 0xFFFFFFFF;
	rh.ray.id = 0;
	rh.ray.flags = 0;
	rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
	rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
	rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
	rtcIntersect1(p_frame.scene, &context, &rh);
	if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
		return background();
	}
	r_hit = true;

	// Interpolation with the hit's barycentrics = the rasteriser's perspective-correct interpolation.
	const Surface &s = p_frame.surfaces[rh.hit.geomID];
	const ShadingMaterial &m = s.material;
	const uint32_t prim = rh.hit.primID;
	const uint32_t i0 = s.indices[prim * 3], i1 = s.indices[prim * 3 + 1], i2 = s.indices[prim * 3 + 2];
	const float b1 = rh.hit.u, b2 = rh.hit.v, b0 = 1.0f - b1 - b2;
	Vector3 vertex = s.positions[i0] * b0 + s.positions[i1] * b1 + s.positions[i2] * b2;
	Vector3 normal_interp = s.normals[i0] * b0 + s.normals[i1] * b1 + s.normals[i2] * b2;
	Vector2 uv = s.uvs[i0] * b0 + s.uvs[i1] * b1 + s.uvs[i2] * b2;
	uv = uv * m.uv1_scale + m.uv1_offset;
	// Per-pixel steps of the (scaled) texture coordinate, for the mipmap filters (reference_texture.h).
	Vector2 duv[2];
	bool footprint = false;
	if (m.mipmaps && p_diff) {
		const Vector3 tri[3] = { s.positions[i0], s.positions[i1], s.positions[i2] };
		const Vector2 tri_uv[3] = { s.uvs[i0] * m.uv1_scale + m.uv1_offset, s.uvs[i1] * m.uv1_scale + m.uv1_offset, s.uvs[i2] * m.uv1_scale + m.uv1_offset };
		footprint = true;
		for (int k = 0; k < 2 && footprint; k++) {
			Vector2 neighbour;
			footprint = reference_ray_plane_uv(p_diff->origins[k], p_diff->dirs[k], tri, tri_uv, neighbour);
			duv[k] = neighbour - uv;
		}
	}
	auto sample = [&](const ShadingMaterial::Texture &p_texture, const Vector2 &p_uv) {
		if (!footprint) {
			return m.nearest ? reference_sample_texture_nearest(*p_texture.image, p_uv) : reference_sample_texture_bilinear(*p_texture.image, p_uv);
		}
		const float lod = texture_mipmap_lod(duv[0], duv[1], p_texture.image->get_width(), p_texture.image->get_height());
		return reference_sample_texture_lod(*p_texture.image, p_texture.levels, p_uv, lod, m.nearest);
	};
	const bool front_facing = s.face_normals[prim].dot(dir) < 0.0f;

	// Fragment shader (scene_forward_clustered.glsl).
	Vector3 albedo = m.albedo;
	float alpha = m.alpha;
	if (m.textures[0].image) {
		Color texel = sample(m.textures[0], uv);
		albedo = albedo * Vector3(Color::srgb_to_linear_channel(texel.r), Color::srgb_to_linear_channel(texel.g), Color::srgb_to_linear_channel(texel.b));
		alpha *= texel.a;
	}
	if (m.vertex_color && !s.colors.empty()) {
		// The rasteriser's interpolation of the vertex colours (scene_forward_clustered.glsl: albedo *= COLOR).
		const Color c = s.colors[i0] * b0 + s.colors[i1] * b1 + s.colors[i2] * b2;
		const Color rgb = m.vertex_color_srgb ? c.srgb_to_linear() : c;
		albedo = albedo * Vector3(rgb.r, rgb.g, rgb.b);
		alpha *= c.a;
	}
	// ALPHA: Godot's mix blend over the radiance behind the surface (the same ray continued past it).
	auto composite = [&](const Color &p_color) {
		if (m.transparency != RS::MATERIAL_TRANSPARENCY_ALPHA) {
			return p_color;
		}
		const float a = glsl_clamp(p_color.a, 0.0f, 1.0f);
		const float step = 1e-4f * std::max(1.0f, std::max(std::fabs(vertex.x), std::max(std::fabs(vertex.y), std::fabs(vertex.z))));
		bool behind_hit = false;
		const Color behind = _shade_ray(p_frame, p_options, vertex + dir * step, dir, seg_len - rh.ray.tfar - step, p_bounces, r_rng, r_counters, behind_hit, p_diff);
		Color out = p_color * a + behind * (1.0f - a);
		out.a = a + behind.a * (1.0f - a);
		return out;
	};
	if (m.unshaded) {
		return composite(Color(albedo.x, albedo.y, albedo.z, alpha));
	}

	Vector3 V = p_frame.orthogonal ? p_frame.world_from_view.basis.get_column(2).normalized() : (p_frame.world_from_view.origin - vertex).normalized();
	Vector3 N = normal_interp.normalized();
	if (!front_facing) {
		N = -N;
	}
	if (m.textures[1].image) {
		Vector3 tangent_interp = s.tangents[i0] * b0 + s.tangents[i1] * b1 + s.tangents[i2] * b2;
		Vector3 binormal_interp = s.binormals[i0] * b0 + s.binormals[i1] * b1 + s.binormals[i2] * b2;
		Vector3 T = (tangent_interp - N * N.dot(tangent_interp)).normalized();
		Vector3 B = binormal_interp.normalized();
		Color t = sample(m.textures[1], uv);
		Vector3 nm(t.r * 2.0f - 1.0f, t.g * 2.0f - 1.0f, t.b * 2.0f - 1.0f);
		nm.x *= m.normal_scale;
		nm.y *= m.normal_scale;
		N = (T * nm.x + B * nm.y + N * std::max(nm.z, 1e-4f)).normalized();
	}

	auto channel = [](const Color &p_texel, const float p_weights[4]) { return p_texel.r * p_weights[0] + p_texel.g * p_weights[1] + p_texel.b * p_weights[2] + p_texel.a * p_weights[3]; };
	float roughness = m.roughness;
	if (m.textures[2].image) {
		roughness *= channel(sample(m.textures[2], uv), m.roughness_channel);
	}
	float metallic = m.metallic;
	if (m.textures[3].image) {
		metallic *= channel(sample(m.textures[3], uv), m.metallic_channel);
	}
	roughness = glsl_clamp(roughness, 0.0f, 1.0f);
	metallic = glsl_clamp(metallic, 0.0f, 1.0f);
	float dielectric = 0.16f * m.specular * m.specular;
	Vector3 f0 = Vector3(dielectric, dielectric, dielectric) * (1.0f - metallic) + albedo * metallic;
	float f90 = brdf_specular_f90(f0, metallic);

	Vector3 diffuse_light;
	Vector3 specular_light;

	// Shadow-ray origin: the hit point pushed off the surface towards the light's side.
	Vector3 ng = s.face_normals[prim].normalized();
	float max_coord = std::max(std::fabs(vertex.x), std::max(std::fabs(vertex.y), std::fabs(vertex.z)));
	float offset = 1e-4f * std::max(1.0f, max_coord);

	// Light loop. Punctual (delta) lights: one exact evaluation each. Area lights: an adaptive integral
	// over the rectangle (_reference_shade_area_light), whose result (diffuse already weighted by
	// albedo * (1 - metallic), plus specular) is accumulated in area_light.
	Vector3 area_light;
	AreaLightShadingPoint point;
	point.vertex = vertex;
	point.N = N;
	point.V = V;
	point.ng = ng;
	point.offset = offset;
	point.diffuse_mode = m.diffuse_mode;
	point.roughness = roughness;
	point.f0 = f0;
	point.f90 = f90;
	point.specular_enabled = m.specular_enabled;
	point.diffuse_weight = albedo * (1.0f - metallic);
	for (const Light &light : p_frame.lights) {
		if (light.type == RS::LIGHT_AREA) {
			if ((light.area.cull_mask & s.layer_mask) != 0) {
				const uint64_t before = r_counters.area_samples;
				reference_shade_area_light(p_frame.scene, p_options, light.area, point, r_rng, r_counters.shadow_rays, r_counters.area_samples, r_counters.area_integrals, r_counters.area_converged, r_counters.max_relative_error, area_light);
				r_counters.pixel_samples += uint32_t(r_counters.area_samples - before);
			}
			continue;
		}
		if (light.type == RS::LIGHT_DIRECTIONAL) {
			if ((light.sun.cull_mask & s.layer_mask) != 0) {
				reference_shade_sun(p_frame.scene, p_options, light.sun, point, r_rng, r_counters.shadow_rays, diffuse_light, specular_light);
			}
			continue;
		}
		if ((light.data.cull_mask & s.layer_mask) == 0) {
			continue;
		}
		Vector3 L, radiance;
		float distance = 0.0f;
		bool lit = light.type == RS::LIGHT_SPOT ? light_spot_radiance(light.data, vertex, L, distance, radiance) : light_omni_radiance(light.data, vertex, L, distance, radiance);
		if (!lit) {
			continue;
		}
		if (p_options.shadows && N.dot(L) > 0.0f) {
			Vector3 side = ng.dot(L) >= 0.0f ? ng : -ng;
			Vector3 o = vertex + side * offset;
			Vector3 to_light = light.data.position - o;
			float d = to_light.length();
			if (d > 2.0f * offset) {
				RTCRay ray;
				Vector3 ldir = to_light / d;
				ray.org_x = o.x;
				ray.org_y = o.y;
				ray.org_z = o.z;
				ray.dir_x = ldir.x;
				ray.dir_y = ldir.y;
				ray.dir_z = ldir.z;
				ray.tnear = 0.0f;
				ray.tfar = d - offset;
				ray.time = 0.0f;
				ray.mask = 0xFFFFFFFF;
				ray.id = 0;
				ray.flags = 0;
				RTCIntersectContext ctx;
				rtcInitIntersectContext(&ctx);
				rtcOccluded1(p_frame.scene, &ctx, &ray);
				r_counters.shadow_rays++;
				if (ray.tfar < 0.0f) {
					continue; // Occluded (Embree sets tfar to -inf).
				}
			}
		}
		light_compute(N, L, V, radiance, light.data.specular_amount, m.diffuse_mode, roughness, f0, f90, m.specular_enabled, diffuse_light, specular_light);
	}

	// One diffuse bounce (options.bounces): cosine-distributed rays over the shading normal's hemisphere
	// (pdf cos / pi), each bringing the direct-lit radiance of the first surface it meets. As in
	// sun_light.h, light_compute() takes the sample radiance divided by pdf and count, so
	// Lambert's 1/pi and the cosine cancel against the pdf; only the diffuse lobe receives it.
	if (p_bounces > 0 && !m.unshaded) {
		ReferenceRenderOptions bounce_options = p_options;
		bounce_options.max_samples = std::max(p_options.bounce_light_samples, 1);
		bounce_options.target_relative_error = 1e9f; // Fixed count: the bounce rays average the noise.
		bounce_options.sky_samples = std::max(p_options.bounce_light_samples, 1);
		bounce_options.sun_samples = 1;
		const int count = std::max(p_options.bounce_samples, 1);
		Vector3 t, b;
		const Vector3 axis = std::fabs(N.x) < 0.9f ? Vector3(1, 0, 0) : Vector3(0, 1, 0);
		t = N.cross(axis).normalized();
		b = N.cross(t);
		const Vector3 side = ng.dot(N) >= 0.0f ? ng : -ng;
		PixelCounters scratch;
		for (int i = 0; i < count; i++) {
			const float u1 = r_rng.next_float(), u2 = r_rng.next_float();
			const float r = std::sqrt(u1), phi = 2.0f * float(Math::PI) * u2;
			const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
			const Vector3 wi = (t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + N * z).normalized();
			if (wi.dot(ng) * side.dot(ng) <= 0.0f) {
				continue; // Below the geometric surface (a shading normal tilted past it).
			}
			bool bounce_hit = false;
			const Color li = _shade_ray(p_frame, bounce_options, vertex + side * offset, wi, std::numeric_limits<float>::infinity(), p_bounces - 1, r_rng, scratch, bounce_hit);
			r_counters.bounce_rays++;
			if (!bounce_hit) {
				continue;
			}
			const Vector3 radiance = Vector3(li.r, li.g, li.b) * (float(Math::PI) / (z * float(count)));
			Vector3 unused_specular;
			light_compute(N, wi, V, radiance, 0.0f, m.diffuse_mode, roughness, f0, f90, false, diffuse_light, unused_specular);
		}
		r_counters.shadow_rays += scratch.shadow_rays;
	}

	Vector3 ambient_light = p_frame.ambient_light;
	if (p_frame.sky_ambient) {
		ambient_light += reference_sky_irradiance(p_frame.scene, p_options, p_frame.sky, point, r_rng, r_counters.shadow_rays) * p_frame.ambient_sky_contribution;
	}
	if (p_frame.sky_reflections && m.specular_enabled && !m.unshaded) {
		specular_light += reference_sky_specular(p_frame.scene, p_options, p_frame.sky, point, r_rng, r_counters.shadow_rays);
	}
	Vector3 color = m.emission + (ambient_light + diffuse_light) * albedo * (1.0f - metallic) + specular_light + area_light;
	return composite(Color(color.x, color.y, color.z, alpha));
}
