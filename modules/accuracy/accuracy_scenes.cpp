/**************************************************************************/
/*  accuracy_scenes.cpp                                                   */
/**************************************************************************/
/* godot-area: scene generator of the area-light accuracy suite (see the  */
/* header for the placements and the exposure rule).                      */

#include "modules/accuracy/accuracy_scenes.h"

#include "core/error/error_macros.h"
#include "core/math/math_funcs.h"
#include "scene/resources/primitive_meshes.h"

#include <algorithm>
#include <cmath>

namespace {

const float SPHERE_RADIUS = 1.0f;
const float PLANE_SIZE = 10.0f;
const float TARGET_LAMBERT_RADIANCE = 0.5f;

// Light transform whose emission direction (local -Z) is p_emit and whose local X is p_x (orthogonal to p_emit).
Transform3D light_frame(const Vector3 &p_emit, const Vector3 &p_x, const Vector3 &p_origin) {
	Vector3 z = -p_emit.normalized();
	Vector3 x = p_x.normalized();
	Vector3 y = z.cross(x);
	return Transform3D(Basis::from_columns(x, y, z), p_origin);
}

} // namespace

const char *AccuracyScenes::receiver_name(Receiver p_receiver) {
	return p_receiver == RECEIVER_SPHERE ? "sphere" : "plane";
}

const char *AccuracyScenes::placement_name(Placement p_placement) {
	switch (p_placement) {
		case PLACEMENT_FACING:
			return "facing";
		case PLACEMENT_GRAZING:
			return "grazing";
		case PLACEMENT_HORIZON:
			return "horizon";
		case PLACEMENT_TILTED:
			return "tilted";
		case PLACEMENT_CLOSE:
			return "close";
		case PLACEMENT_FAR:
			return "far";
		case PLACEMENT_VERTICAL:
			return "vertical";
		default:
			return "unknown";
	}
}

double AccuracyScenes::irradiance_integral(const Transform3D &p_light, const Vector2 &p_size, const Vector3 &p_point, const Vector3 &p_normal, int p_n) {
	const Vector3 ax = p_light.basis.get_column(0);
	const Vector3 ay = p_light.basis.get_column(1);
	const Vector3 emit = -p_light.basis.get_column(2).normalized();
	const double da = double(p_size.x) * p_size.y / (double(p_n) * p_n);
	double sum = 0.0;
	for (int i = 0; i < p_n; i++) {
		for (int j = 0; j < p_n; j++) {
			Vector3 q = p_light.origin + ax * (p_size.x * ((i + 0.5f) / p_n - 0.5f)) + ay * (p_size.y * ((j + 0.5f) / p_n - 0.5f));
			Vector3 d = q - p_point;
			double r2 = d.length_squared();
			if (r2 <= 0.0) {
				continue;
			}
			Vector3 l = d / float(std::sqrt(r2));
			double cos_i = p_normal.dot(l);
			double cos_l = -emit.dot(l);
			if (cos_i > 0.0 && cos_l > 0.0) {
				sum += cos_i * cos_l / r2 * da;
			}
		}
	}
	return sum;
}

AccuracyScenes::Scene AccuracyScenes::make_scene(Receiver p_receiver, float p_roughness, float p_metallic, const Vector2 &p_light_size, Placement p_placement, float p_view_elevation, RS::LightAreaShape p_shape) {
	Scene s;
	s.shape = p_shape;
	s.receiver = p_receiver;
	s.roughness = p_roughness;
	s.metallic = p_metallic;
	s.light_size = p_light_size;
	s.placement = p_placement;
	ERR_FAIL_COND_V_MSG(p_view_elevation != 0.0f && !(p_view_elevation >= 1.0f && p_view_elevation <= 89.0f), s, vformat("Accuracy scene view elevation must be 0 (standard camera) or in [1, 89] degrees, got %g.", p_view_elevation));
	s.view_elevation = p_view_elevation;
	s.id = vformat("%s_r%g_m%g_%gx%g_%s", receiver_name(p_receiver), p_roughness, p_metallic, p_light_size.x, p_light_size.y, placement_name(p_placement));
	if (p_view_elevation != 0.0f) {
		s.id += vformat("_v%g", p_view_elevation);
	}
	static const char *shape_names[RS::LIGHT_AREA_SHAPE_MAX] = { "rectangle", "disk", "sphere", "tube" };
	if (p_shape != RS::LIGHT_AREA_SHAPE_RECTANGLE && int(p_shape) < int(RS::LIGHT_AREA_SHAPE_MAX)) {
		s.id += String("_") + shape_names[p_shape];
	}

	const Vector3 p = p_receiver == RECEIVER_SPHERE ? Vector3(0, SPHERE_RADIUS, 0) : Vector3();
	const Vector3 n(0, 1, 0), t(1, 0, 0), b(0, 0, 1);
	const float w = std::max(p_light_size.x, p_light_size.y);
	const float h = p_light_size.y;
	const float deg = float(Math::PI) / 180.0f;
	switch (p_placement) {
		case PLACEMENT_FACING:
			s.light_transform = light_frame(-n, t, p + n * 1.5f);
			break;
		case PLACEMENT_GRAZING: {
			// Emits along +t, 10 degrees down; local Y is then nearly +n.
			Vector3 emit = t * std::cos(10.0f * deg) - n * std::sin(10.0f * deg);
			float up = std::cos(10.0f * deg) * h * 0.5f + 0.05f;
			s.light_transform = light_frame(emit, b, p - t * 1.0f + n * up);
		} break;
		case PLACEMENT_HORIZON: {
			Vector3 emit = t * std::cos(30.0f * deg) - n * std::sin(30.0f * deg);
			s.light_transform = light_frame(emit, b, p - t * 1.2f);
		} break;
		case PLACEMENT_TILTED: {
			Vector3 emit = -n * std::cos(60.0f * deg) + t * std::sin(60.0f * deg);
			s.light_transform = light_frame(emit, b, p + n * 1.0f);
		} break;
		case PLACEMENT_CLOSE:
			s.light_transform = light_frame(-n, t, p + n * (0.1f * w));
			break;
		case PLACEMENT_VERTICAL:
			// Upright (local Y along -n), emitting towards the camera side (+b), 1 m behind p.
			s.light_transform = light_frame(b, t, p - b * 1.0f + n * (h * 0.5f + 0.05f));
			break;
		case PLACEMENT_FAR:
		default:
			s.light_transform = light_frame(-n, t, p + n * (10.0f * w));
			break;
	}
	// Exposure: a Lambert surface at p would reflect TARGET_LAMBERT_RADIANCE. With normalised energy,
	// L_e = E pi / A and L_lambert = L_e / pi * I = E I / A.
	double area = double(p_light_size.x) * p_light_size.y;
	double integral = 0.0;
	const double quarter_pi = Math::PI * 0.25;
	switch (p_shape) {
		case RS::LIGHT_AREA_SHAPE_DISK:
			area *= quarter_pi;
			integral = quarter_pi * irradiance_integral(s.light_transform, p_light_size, p, n);
			break;
		case RS::LIGHT_AREA_SHAPE_SPHERE:
			area = Math::PI * p_light_size.x * p_light_size.x;
			integral = quarter_pi * irradiance_integral(s.light_transform, Vector2(p_light_size.x, p_light_size.x), p, n);
			break;
		case RS::LIGHT_AREA_SHAPE_TUBE:
			area = Math::PI * p_light_size.y * (p_light_size.x + p_light_size.y);
			integral = irradiance_integral(s.light_transform, p_light_size, p, n) + quarter_pi * irradiance_integral(s.light_transform, Vector2(p_light_size.y, p_light_size.y), p, n);
			break;
		default:
			integral = irradiance_integral(s.light_transform, p_light_size, p, n);
			break;
	}
	s.light_energy = integral > 1e-9 ? float(std::min(1e4, TARGET_LAMBERT_RADIANCE * area / integral)) : 1.0f;
	// Ten times the farthest lit distance: the range window (area_attenuation 2 leaves only it) is
	// >= 1 - 2e-4 wherever the scene is lit, so the integral stays the physical one.
	s.light_range = 10.0f * ((s.light_transform.origin - p).length() + 20.0f + p_light_size.length());
	return s;
}

std::vector<AccuracyScenes::Scene> AccuracyScenes::full_suite() {
	const float roughnesses[] = { 0.05f, 0.1f, 0.25f, 0.5f, 0.75f, 1.0f };
	const float metallics[] = { 0.0f, 1.0f };
	const Vector2 sizes[] = { Vector2(0.25f, 0.25f), Vector2(1, 1), Vector2(4, 4), Vector2(2, 0.5f) };
	std::vector<Scene> scenes;
	for (int r = 0; r < 2; r++) {
		for (float roughness : roughnesses) {
			for (float metallic : metallics) {
				for (const Vector2 &size : sizes) {
					for (int p = 0; p < PLACEMENT_MAX; p++) {
						scenes.push_back(make_scene(Receiver(r), roughness, metallic, size, Placement(p)));
					}
				}
			}
		}
	}
	const Placement view_placements[] = { PLACEMENT_VERTICAL, PLACEMENT_FACING, PLACEMENT_HORIZON };
	for (float elevation : VIEW_ELEVATIONS) {
		for (float roughness : roughnesses) {
			for (float metallic : metallics) {
				for (const Vector2 &size : { sizes[1], sizes[3] }) {
					for (Placement p : view_placements) {
						scenes.push_back(make_scene(RECEIVER_PLANE, roughness, metallic, size, p, elevation));
					}
				}
			}
		}
	}
	return scenes;
}

std::vector<AccuracyScenes::Scene> AccuracyScenes::shape_suite() {
	const RS::LightAreaShape shapes[3] = { RS::LIGHT_AREA_SHAPE_DISK, RS::LIGHT_AREA_SHAPE_SPHERE, RS::LIGHT_AREA_SHAPE_TUBE };
	const Vector2 sizes[3] = { Vector2(1, 1), Vector2(0.5f, 0.5f), Vector2(1, 0.2f) };
	const float roughnesses[] = { 0.25f, 0.5f, 1.0f };
	const Placement placements[] = { PLACEMENT_FACING, PLACEMENT_GRAZING, PLACEMENT_TILTED, PLACEMENT_CLOSE, PLACEMENT_FAR };
	std::vector<Scene> scenes;
	for (int k = 0; k < 3; k++) {
		for (float roughness : roughnesses) {
			for (float metallic : { 0.0f, 1.0f }) {
				for (Placement p : placements) {
					scenes.push_back(make_scene(RECEIVER_PLANE, roughness, metallic, sizes[k], p, 0.0f, shapes[k]));
				}
			}
		}
	}
	return scenes;
}

std::vector<AccuracyScenes::Scene> AccuracyScenes::shape_ci_subset() {
	std::vector<Scene> s;
	s.push_back(make_scene(RECEIVER_PLANE, 1.0f, 0.0f, Vector2(1, 1), PLACEMENT_FACING, 0.0f, RS::LIGHT_AREA_SHAPE_DISK));
	s.push_back(make_scene(RECEIVER_PLANE, 0.5f, 1.0f, Vector2(1, 1), PLACEMENT_TILTED, 0.0f, RS::LIGHT_AREA_SHAPE_DISK));
	s.push_back(make_scene(RECEIVER_PLANE, 1.0f, 0.0f, Vector2(0.5f, 0.5f), PLACEMENT_FACING, 0.0f, RS::LIGHT_AREA_SHAPE_SPHERE));
	s.push_back(make_scene(RECEIVER_PLANE, 0.5f, 1.0f, Vector2(0.5f, 0.5f), PLACEMENT_TILTED, 0.0f, RS::LIGHT_AREA_SHAPE_SPHERE));
	s.push_back(make_scene(RECEIVER_PLANE, 1.0f, 0.0f, Vector2(1, 0.2f), PLACEMENT_FACING, 0.0f, RS::LIGHT_AREA_SHAPE_TUBE));
	s.push_back(make_scene(RECEIVER_PLANE, 0.5f, 1.0f, Vector2(1, 0.2f), PLACEMENT_TILTED, 0.0f, RS::LIGHT_AREA_SHAPE_TUBE));
	return s;
}

std::vector<AccuracyScenes::Scene> AccuracyScenes::ci_subset() {
	std::vector<Scene> s;
	const Vector2 unit(1, 1), big(4, 4), thin(2, 0.5f);
	// Diffuse only (roughness 1, metallic 0): the Lambert polygon integral is exact.
	for (int p = 0; p < PLACEMENT_MAX; p++) {
		s.push_back(make_scene(RECEIVER_PLANE, 1.0f, 0.0f, unit, Placement(p)));
	}
	s.push_back(make_scene(RECEIVER_SPHERE, 1.0f, 0.0f, thin, PLACEMENT_FACING));
	s.push_back(make_scene(RECEIVER_SPHERE, 1.0f, 0.0f, thin, PLACEMENT_HORIZON));
	s.push_back(make_scene(RECEIVER_SPHERE, 1.0f, 0.0f, big, PLACEMENT_FAR));
	// Metals in the easy placements (LTC fit error only).
	s.push_back(make_scene(RECEIVER_PLANE, 0.05f, 1.0f, unit, PLACEMENT_FACING));
	s.push_back(make_scene(RECEIVER_PLANE, 0.25f, 1.0f, unit, PLACEMENT_FACING));
	s.push_back(make_scene(RECEIVER_PLANE, 0.5f, 1.0f, big, PLACEMENT_CLOSE));
	s.push_back(make_scene(RECEIVER_PLANE, 0.1f, 1.0f, thin, PLACEMENT_FAR));
	s.push_back(make_scene(RECEIVER_SPHERE, 0.25f, 1.0f, unit, PLACEMENT_FACING));
	s.push_back(make_scene(RECEIVER_SPHERE, 0.5f, 1.0f, big, PLACEMENT_FAR));
	// Hard placements with glossy lobes.
	s.push_back(make_scene(RECEIVER_PLANE, 0.25f, 0.0f, unit, PLACEMENT_GRAZING));
	s.push_back(make_scene(RECEIVER_PLANE, 0.5f, 1.0f, unit, PLACEMENT_GRAZING));
	s.push_back(make_scene(RECEIVER_PLANE, 0.75f, 1.0f, big, PLACEMENT_GRAZING));
	s.push_back(make_scene(RECEIVER_PLANE, 0.25f, 0.0f, big, PLACEMENT_HORIZON));
	s.push_back(make_scene(RECEIVER_SPHERE, 0.5f, 1.0f, unit, PLACEMENT_HORIZON));
	s.push_back(make_scene(RECEIVER_PLANE, 0.5f, 0.0f, thin, PLACEMENT_TILTED));
	s.push_back(make_scene(RECEIVER_SPHERE, 0.25f, 1.0f, unit, PLACEMENT_TILTED));
	// Issue #18: a TV / window over a glossy floor seen at grazing angles, and a light crossing the plane.
	s.push_back(make_scene(RECEIVER_PLANE, 0.25f, 1.0f, unit, PLACEMENT_VERTICAL, 10.0f));
	s.push_back(make_scene(RECEIVER_PLANE, 0.5f, 1.0f, unit, PLACEMENT_VERTICAL, 10.0f));
	s.push_back(make_scene(RECEIVER_PLANE, 0.5f, 0.0f, thin, PLACEMENT_VERTICAL, 20.0f));
	s.push_back(make_scene(RECEIVER_PLANE, 0.25f, 1.0f, unit, PLACEMENT_FACING, 10.0f));
	s.push_back(make_scene(RECEIVER_PLANE, 0.5f, 1.0f, unit, PLACEMENT_HORIZON, 10.0f));
	s.push_back(make_scene(RECEIVER_PLANE, 0.25f, 1.0f, unit, PLACEMENT_VERTICAL));
	return s;
}

Transform3D AccuracyScenes::camera_transform() {
	const Vector3 eye(0, 2.5f, 3.2f), target(0, 0.2f, 0);
	return Transform3D(Basis::looking_at(target - eye), eye);
}

Transform3D AccuracyScenes::camera_transform(const Scene &p_scene) {
	if (p_scene.view_elevation == 0.0f) {
		return camera_transform();
	}
	const float e = p_scene.view_elevation * float(Math::PI) / 180.0f;
	const Vector3 target = p_scene.receiver == RECEIVER_SPHERE ? Vector3(0, SPHERE_RADIUS, 0) : Vector3();
	const Vector3 eye = target + Vector3(0, std::sin(e), std::cos(e)) * 3.5f;
	return Transform3D(Basis::looking_at(target - eye), eye);
}

bool AccuracyScenes::build(RenderingServer *p_rs, const Scene &p_scene, int p_resolution, int p_method, Built *r_built, String *r_error) {
	ERR_FAIL_NULL_V_MSG(p_rs, false, "AccuracyScenes::build needs a RenderingServer.");
	ERR_FAIL_NULL_V_MSG(r_built, false, "AccuracyScenes::build needs an output struct.");
	ERR_FAIL_COND_V_MSG(p_resolution < 1 || p_resolution > 4096, false, vformat("Accuracy scene resolution must be in [1, 4096], got %d.", p_resolution));
	Built &b = *r_built;

	RS::SurfaceData surface;
	if (p_scene.receiver == RECEIVER_SPHERE) {
		SphereMesh::create_sphere_arrays(surface, SPHERE_RADIUS, SPHERE_RADIUS * 2.0f, 64, 32);
	} else {
		PlaneMesh::create_plane_arrays(surface, Vector2(PLANE_SIZE, PLANE_SIZE), 0, 0, Vector3(), PlaneMesh::FACE_Y);
	}
	b.mesh = p_rs->mesh_create();
	p_rs->mesh_add_surface(b.mesh, surface);

	RS::MaterialParams mp;
	mp.albedo = Color(0.9f, 0.75f, 0.6f, 1.0f);
	mp.roughness = p_scene.roughness;
	mp.metallic = p_scene.metallic;
	// Lambert: the area-light diffuse term is the exact Lambert polygon integral; Burley has no
	// closed form, so a Burley material would measure Burley-vs-Lambert, not the light method.
	mp.diffuse_mode = RS::MATERIAL_DIFFUSE_LAMBERT;
	mp.cull_back = false;
	b.material = p_rs->material_create();
	p_rs->material_set_params(b.material, mp);
	p_rs->mesh_surface_set_material(b.mesh, 0, b.material);

	b.light = p_rs->area_light_create();
	p_rs->light_area_set_size(b.light, p_scene.light_size);
	p_rs->light_area_set_shape(b.light, p_scene.shape);
	p_rs->light_area_set_normalize_energy(b.light, true);
	p_rs->light_set_param(b.light, RS::LIGHT_PARAM_ENERGY, p_scene.light_energy);
	p_rs->light_set_param(b.light, RS::LIGHT_PARAM_RANGE, p_scene.light_range);
	p_rs->light_set_param(b.light, RS::LIGHT_PARAM_ATTENUATION, 2.0f); // Physical: window only.
	p_rs->light_area_set_shading_method(b.light, RS::LightAreaShadingMethod(p_method));
	if (int(p_rs->light_area_get_shading_method(b.light)) != p_method) {
		if (r_error) {
			*r_error = vformat("The renderer does not accept area shading method %d (it kept %d).", p_method, int(p_rs->light_area_get_shading_method(b.light)));
		}
		free_scene(p_rs, b);
		return false;
	}

	b.environment = p_rs->environment_create();
	p_rs->environment_set_background(b.environment, RS::ENV_BG_COLOR);
	p_rs->environment_set_bg_color(b.environment, Color(0, 0, 0, 1));
	p_rs->environment_set_ambient_light(b.environment, Color(0, 0, 0, 1), RS::ENV_AMBIENT_SOURCE_DISABLED, 0.0f);
	b.scenario = p_rs->scenario_create();
	p_rs->scenario_set_environment(b.scenario, b.environment);

	b.mesh_instance = p_rs->instance_create();
	p_rs->instance_set_base(b.mesh_instance, b.mesh);
	p_rs->instance_set_scenario(b.mesh_instance, b.scenario);
	b.light_instance = p_rs->instance_create();
	p_rs->instance_set_base(b.light_instance, b.light);
	p_rs->instance_set_scenario(b.light_instance, b.scenario);
	p_rs->instance_set_transform(b.light_instance, p_scene.light_transform);

	b.camera = p_rs->camera_create();
	p_rs->camera_set_perspective(b.camera, CAMERA_FOVY, 0.05f, 200.0f);
	p_rs->camera_set_transform(b.camera, camera_transform(p_scene));
	b.viewport = p_rs->viewport_create();
	p_rs->viewport_set_size(b.viewport, p_resolution, p_resolution);
	p_rs->viewport_attach_camera(b.viewport, b.camera);
	p_rs->viewport_set_scenario(b.viewport, b.scenario);
	return true;
}

void AccuracyScenes::free_scene(RenderingServer *p_rs, Built &r_built) {
	ERR_FAIL_NULL_MSG(p_rs, "AccuracyScenes::free_scene needs a RenderingServer.");
	RID *order[] = { &r_built.viewport, &r_built.camera, &r_built.light_instance, &r_built.mesh_instance, &r_built.scenario, &r_built.environment, &r_built.light, &r_built.material, &r_built.mesh };
	for (RID *rid : order) {
		if (rid->is_valid()) {
			p_rs->free(*rid);
			*rid = RID();
		}
	}
}
