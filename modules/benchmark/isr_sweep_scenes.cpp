/**************************************************************************/
/*  isr_sweep_scenes.cpp                                                  */
/**************************************************************************/

#include "modules/benchmark/isr_sweep_scenes.h"

#include "core/math/math_funcs.h"
#include "scene/resources/primitive_meshes.h"
#include "servers/rendering_server.h"

// Appends a quad centred at p_center with half axes p_u, p_v; its front (normal p_u x p_v) is clockwise
// as seen from the front (Godot's winding).
static void _isr_add_quad(RS::SurfaceData &r_s, const Vector3 &p_center, const Vector3 &p_u, const Vector3 &p_v) {
	const uint32_t base = uint32_t(r_s.vertices.size());
	const Vector3 n = p_u.cross(p_v).normalized();
	const Vector3 corners[4] = { p_center - p_u - p_v, p_center + p_u - p_v, p_center + p_u + p_v, p_center - p_u + p_v };
	for (const Vector3 &c : corners) {
		r_s.vertices.push_back(c);
		r_s.normals.push_back(n);
	}
	const uint32_t idx[6] = { 0, 2, 1, 0, 3, 2 };
	for (uint32_t i : idx) {
		r_s.indices.push_back(base + i);
	}
}

// A closed box (outward faces) of half extents p_half centred at p_center (BoxMesh's arrays, moved).
static RS::SurfaceData _isr_box(const Vector3 &p_center, const Vector3 &p_half) {
	RS::SurfaceData s;
	BoxMesh::create_box_arrays(s, p_half * 2, 0, 0, 0);
	for (Vector3 &v : s.vertices) {
		v += p_center;
	}
	return s;
}

static RS::MaterialParams _isr_material(const Color &p_albedo) {
	RS::MaterialParams m;
	m.albedo = p_albedo;
	m.roughness = 1.0f;
	m.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
	return m;
}

static IsrScene::Object _isr_object(const RS::SurfaceData &p_surface, const Color &p_albedo) {
	IsrScene::Object o;
	o.surface = p_surface;
	o.material = _isr_material(p_albedo);
	return o;
}

IsrScene IsrScene::make_room(RoomColors p_colors) {
	IsrScene s;
	const Color white(0.8f, 0.8f, 0.8f, 1);
	const Color red = p_colors == ROOM_CORNELL ? Color(0.8f, 0.1f, 0.1f, 1) : white;
	const Color green = p_colors == ROOM_CORNELL ? Color(0.1f, 0.8f, 0.1f, 1) : white;
	// Interior faces of the room x, z in -1..1, y in 0..2 (fronts face inwards).
	RS::SurfaceData floor, ceiling, back, front, left, right;
	_isr_add_quad(floor, Vector3(0, 0, 0), Vector3(0, 0, 1), Vector3(1, 0, 0));
	_isr_add_quad(ceiling, Vector3(0, 2, 0), Vector3(1, 0, 0), Vector3(0, 0, 1));
	_isr_add_quad(back, Vector3(0, 1, -1), Vector3(1, 0, 0), Vector3(0, 1, 0));
	_isr_add_quad(front, Vector3(0, 1, 1), Vector3(0, 1, 0), Vector3(1, 0, 0));
	_isr_add_quad(left, Vector3(-1, 1, 0), Vector3(0, 1, 0), Vector3(0, 0, 1));
	_isr_add_quad(right, Vector3(1, 1, 0), Vector3(0, 0, 1), Vector3(0, 1, 0));
	s.objects.push_back(_isr_object(floor, white));
	s.objects.push_back(_isr_object(ceiling, white));
	s.objects.push_back(_isr_object(back, white));
	s.objects.push_back(_isr_object(front, white));
	s.objects.push_back(_isr_object(left, red));
	s.objects.push_back(_isr_object(right, green));
	s.objects.push_back(_isr_object(_isr_box(Vector3(0.35f, 0.3f, -0.35f), Vector3(0.3f, 0.3f, 0.3f)), white));
	AreaLightDesc l;
	l.transform = Transform3D(Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.5f), Vector3(0, 1.98f, 0)); // Faces down.
	l.size = Vector2(0.6f, 0.6f);
	l.energy = 4.0f;
	l.range = 6.0f;
	s.lights.push_back(l);
	// A short dolly and pan from the front wall (seed §5.2.3: snapshots along a path).
	for (int i = 0; i < 4; i++) {
		const float t = float(i) / 3.0f;
		const Vector3 eye(-0.3f + 0.6f * t, 1.0f + 0.1f * t, 0.95f - 0.15f * t);
		const Vector3 target(0.2f - 0.4f * t, 0.6f, -1.0f);
		s.camera_path.push_back(Transform3D(Basis::looking_at(target - eye, Vector3(0, 1, 0)), eye));
	}
	s.fovy_degrees = 70.0f;
	return s;
}

IsrScene IsrScene::make_open() {
	IsrScene s;
	RS::SurfaceData ground;
	_isr_add_quad(ground, Vector3(0, 0, 0), Vector3(0, 0, 6), Vector3(6, 0, 0));
	s.objects.push_back(_isr_object(ground, Color(0.7f, 0.7f, 0.7f, 1)));
	s.objects.push_back(_isr_object(_isr_box(Vector3(-1.2f, 0.5f, 0.0f), Vector3(0.5f, 0.5f, 0.5f)), Color(0.85f, 0.2f, 0.1f, 1)));
	s.objects.push_back(_isr_object(_isr_box(Vector3(0.6f, 0.35f, -0.6f), Vector3(0.35f, 0.35f, 0.35f)), Color(0.2f, 0.4f, 0.85f, 1)));
	s.objects.push_back(_isr_object(_isr_box(Vector3(1.4f, 0.25f, 0.7f), Vector3(0.25f, 0.25f, 0.25f)), Color(0.9f, 0.8f, 0.2f, 1)));
	s.objects.push_back(_isr_object(_isr_box(Vector3(0.0f, 0.8f, -1.8f), Vector3(2.0f, 0.8f, 0.1f)), Color(0.8f, 0.8f, 0.8f, 1)));
	AreaLightDesc l;
	l.transform = Transform3D(Basis::from_axis_angle(Vector3(1, 0, 0), -float(Math::PI) * 0.35f), Vector3(0.2f, 2.6f, 1.2f));
	l.size = Vector2(1.2f, 0.8f);
	l.energy = 6.0f;
	l.range = 10.0f;
	s.lights.push_back(l);
	for (int i = 0; i < 4; i++) {
		const float a = -0.5f + float(i) * 0.33f;
		const Vector3 eye(4.0f * std::sin(a), 1.6f, 4.0f * std::cos(a));
		s.camera_path.push_back(Transform3D(Basis::looking_at(Vector3(0, 0.4f, -0.4f) - eye, Vector3(0, 1, 0)), eye));
	}
	s.fovy_degrees = 55.0f;
	return s;
}

void IsrScene::build(RendererMeshStorage &p_mesh, RendererMaterialStorage &p_material, RendererLightStorage &p_light, RenderSceneData &r_data, std::vector<RID> &r_meshes, std::vector<RID> &r_materials, std::vector<RID> &r_lights) const {
	for (const Object &o : objects) {
		RID mesh = p_mesh.mesh_create();
		p_mesh.mesh_add_surface(mesh, o.surface);
		RID mat = p_material.material_create();
		p_material.material_set_params(mat, o.material);
		p_mesh.mesh_surface_set_material(mesh, 0, mat);
		r_meshes.push_back(mesh);
		r_materials.push_back(mat);
		RenderSceneData::GeometryInstance g;
		g.mesh = mesh;
		g.transform = o.transform;
		r_data.geometry.push_back(g);
	}
	for (const AreaLightDesc &l : lights) {
		RID light = p_light.light_create(RS::LIGHT_AREA);
		p_light.light_area_set_size(light, l.size);
		p_light.light_set_param(light, RS::LIGHT_PARAM_ENERGY, l.energy);
		p_light.light_set_param(light, RS::LIGHT_PARAM_RANGE, l.range);
		p_light.light_set_color(light, l.color);
		r_lights.push_back(light);
		RenderSceneData::LightInstance li;
		li.light = light;
		li.type = RS::LIGHT_AREA;
		li.transform = l.transform;
		r_data.lights.push_back(li);
	}
}

RenderSceneData IsrScene::make_view(int p_frame, int p_width, int p_height) const {
	RenderSceneData d;
	d.cam_transform = camera_path[size_t(p_frame) % camera_path.size()];
	d.z_near = 0.05f;
	d.z_far = 50.0f;
	d.fovy_degrees = fovy_degrees;
	d.cam_projection = Projection::create_perspective(fovy_degrees, float(p_width) / float(p_height), d.z_near, d.z_far);
	d.viewport_width = p_width;
	d.viewport_height = p_height;
	d.environment.has_environment = true;
	d.environment.background = RS::ENV_BG_COLOR;
	d.environment.bg_color = Color(0, 0, 0, 1);
	d.environment.ambient_source = RS::ENV_AMBIENT_SOURCE_DISABLED;
	d.environment.ambient_energy = 0.0f;
	return d;
}

bool IsrServerScene::create(RenderingServer *p_rs, const IsrScene &p_scene, int p_width, int p_height) {
	free();
	if (!p_rs || p_scene.camera_path.empty() || p_width <= 0 || p_height <= 0) {
		return false;
	}
	rs = p_rs;
	scene = &p_scene;
	environment = rs->environment_create();
	rids.push_back(environment);
	rs->environment_set_background(environment, RS::ENV_BG_COLOR);
	rs->environment_set_bg_color(environment, Color(0, 0, 0, 1));
	rs->environment_set_ambient_light(environment, Color(0, 0, 0, 1), RS::ENV_AMBIENT_SOURCE_DISABLED, 0.0f);
	const RID scenario = rs->scenario_create();
	rids.push_back(scenario);
	rs->scenario_set_environment(scenario, environment);
	for (const IsrScene::Object &o : p_scene.objects) {
		const RID mesh = rs->mesh_create();
		rids.push_back(mesh);
		rs->mesh_add_surface(mesh, o.surface);
		const RID material = rs->material_create();
		rids.push_back(material);
		rs->material_set_params(material, o.material);
		rs->mesh_surface_set_material(mesh, 0, material);
		const RID instance = rs->instance_create();
		rids.push_back(instance);
		rs->instance_set_base(instance, mesh);
		rs->instance_set_scenario(instance, scenario);
		rs->instance_set_transform(instance, o.transform);
	}
	for (const IsrScene::AreaLightDesc &l : p_scene.lights) {
		const RID light = rs->area_light_create();
		rids.push_back(light);
		rs->light_area_set_size(light, l.size);
		rs->light_set_param(light, RS::LIGHT_PARAM_ENERGY, l.energy);
		rs->light_set_param(light, RS::LIGHT_PARAM_RANGE, l.range);
		rs->light_set_color(light, l.color);
		const RID instance = rs->instance_create();
		rids.push_back(instance);
		rs->instance_set_base(instance, light);
		rs->instance_set_scenario(instance, scenario);
		rs->instance_set_transform(instance, l.transform);
	}
	camera = rs->camera_create();
	rids.push_back(camera);
	rs->camera_set_perspective(camera, p_scene.fovy_degrees, 0.05f, 50.0f);
	viewport = rs->viewport_create();
	rids.push_back(viewport);
	rs->viewport_set_size(viewport, p_width, p_height);
	rs->viewport_attach_camera(viewport, camera);
	rs->viewport_set_scenario(viewport, scenario);
	set_frame(0);
	return true;
}

void IsrServerScene::set_frame(int p_frame) {
	if (rs && scene) {
		rs->camera_set_transform(camera, scene->camera_path[size_t(p_frame) % scene->camera_path.size()]);
	}
}

void IsrServerScene::set_screen_space_lighting(const ScreenSpaceLightingSettings &p_settings) {
	if (!rs) {
		return;
	}
	rs->environment_set_ssil(environment, p_settings.ssil_enabled, p_settings.ssil_radius, p_settings.ssil_intensity, p_settings.ssil_sharpness, p_settings.ssil_normal_rejection);
	rs->environment_set_ssil_quality(RS::EnvironmentSSILQuality(p_settings.ssil_quality), p_settings.ssil_half_size, p_settings.ssil_blur_passes);
}

void IsrServerScene::set_active(bool p_active) {
	if (rs) {
		rs->viewport_set_active(viewport, p_active);
	}
}

Image IsrServerScene::draw() {
	if (!rs) {
		return Image();
	}
	rs->draw();
	return rs->viewport_get_texture_data(viewport);
}

void IsrServerScene::free() {
	for (size_t i = rids.size(); i > 0; i--) {
		rs->free(rids[i - 1]);
	}
	rids.clear();
	rs = nullptr;
	scene = nullptr;
	environment = camera = viewport = RID();
}
