/**************************************************************************/
/*  gizmo_overlay.cpp                                                     */
/**************************************************************************/
/* godot-area: GizmoOverlay (see the header).                             */

#include "editor/gizmo_overlay.h"

#include "core/error/error_macros.h"
#include "editor/plugins/gizmos/light_3d_gizmo_plugin.h"
#include "editor/plugins/node_3d_editor_gizmos.h"
#include "scene/3d/camera_3d.h"
#include "scene/3d/light_3d.h"
#include "scene/main/scene_tree.h"

#include <algorithm>
#include <cmath>
#include <functional>

// ---------------------------------------------------------------------------------------------
// Icon glyphs: the shapes of editor/icons/Gizmo*.svg, in their 32x32 viewBox (y down). Keep each
// table in step with its SVG file (must match editor/icons/<name>.svg).

namespace {

struct GlyphShape {
	enum Type {
		RECT, // x, y, w, h
		CIRCLE, // cx, cy, r
		TRIANGLE, // x0, y0, x1, y1, x2, y2
	};
	Type type;
	float v[6];
};

// GizmoAreaLight.svg: the emitting panel and three rays leaving its front.
const GlyphShape GLYPH_AREA[] = {
	{ GlyphShape::RECT, { 5, 4, 22, 13, 0, 0 } },
	{ GlyphShape::RECT, { 8, 20, 2, 8, 0, 0 } },
	{ GlyphShape::RECT, { 15, 20, 2, 9, 0, 0 } },
	{ GlyphShape::RECT, { 22, 20, 2, 8, 0, 0 } },
};
// GizmoLight.svg (omni): a bulb and its base.
const GlyphShape GLYPH_OMNI[] = {
	{ GlyphShape::CIRCLE, { 16, 13, 9, 0, 0, 0 } },
	{ GlyphShape::RECT, { 12, 24, 8, 2, 0, 0 } },
	{ GlyphShape::RECT, { 13, 27, 6, 2, 0, 0 } },
};
// GizmoSpotLight.svg: a lamp housing, its cone and three rays.
const GlyphShape GLYPH_SPOT[] = {
	{ GlyphShape::RECT, { 11, 3, 10, 7, 0, 0 } },
	{ GlyphShape::TRIANGLE, { 11, 10, 21, 10, 27, 19 } },
	{ GlyphShape::TRIANGLE, { 11, 10, 27, 19, 5, 19 } },
	{ GlyphShape::RECT, { 9, 22, 2, 6, 0, 0 } },
	{ GlyphShape::RECT, { 15, 22, 2, 7, 0, 0 } },
	{ GlyphShape::RECT, { 21, 22, 2, 6, 0, 0 } },
};
// GizmoDirectionalLight.svg: a sun (disc, four straight and four diagonal rays).
const GlyphShape GLYPH_DIRECTIONAL[] = {
	{ GlyphShape::CIRCLE, { 16, 16, 6, 0, 0, 0 } },
	{ GlyphShape::RECT, { 15, 2, 2, 7, 0, 0 } },
	{ GlyphShape::RECT, { 15, 23, 2, 7, 0, 0 } },
	{ GlyphShape::RECT, { 2, 15, 7, 2, 0, 0 } },
	{ GlyphShape::RECT, { 23, 15, 7, 2, 0, 0 } },
	{ GlyphShape::CIRCLE, { 7, 7, 2, 0, 0, 0 } },
	{ GlyphShape::CIRCLE, { 25, 7, 2, 0, 0, 0 } },
	{ GlyphShape::CIRCLE, { 7, 25, 2, 0, 0, 0 } },
	{ GlyphShape::CIRCLE, { 25, 25, 2, 0, 0, 0 } },
};
// Unknown icons: a plain disc.
const GlyphShape GLYPH_FALLBACK[] = {
	{ GlyphShape::CIRCLE, { 16, 16, 12, 0, 0, 0 } },
};

bool _ends_with(const String &p_s, const String &p_suffix) {
	return p_s.size() >= p_suffix.size() && p_s.compare(p_s.size() - p_suffix.size(), p_suffix.size(), p_suffix) == 0;
}

void _get_glyph(const String &p_icon_path, const GlyphShape **r_shapes, int *r_count) {
#define GLYPH_CASE(m_file, m_table)                           \
	if (_ends_with(p_icon_path, m_file)) {                    \
		*r_shapes = m_table;                                  \
		*r_count = int(sizeof(m_table) / sizeof(m_table[0])); \
		return;                                               \
	}
	GLYPH_CASE("GizmoAreaLight.svg", GLYPH_AREA);
	GLYPH_CASE("GizmoLight.svg", GLYPH_OMNI);
	GLYPH_CASE("GizmoSpotLight.svg", GLYPH_SPOT);
	GLYPH_CASE("GizmoDirectionalLight.svg", GLYPH_DIRECTIONAL);
#undef GLYPH_CASE
	*r_shapes = GLYPH_FALLBACK;
	*r_count = 1;
}

float _edge(float p_ax, float p_ay, float p_bx, float p_by, float p_px, float p_py) {
	return (p_bx - p_ax) * (p_py - p_ay) - (p_by - p_ay) * (p_px - p_ax);
}

bool _glyph_inside(const GlyphShape *p_shapes, int p_count, float p_u, float p_v) {
	for (int i = 0; i < p_count; i++) {
		const float *v = p_shapes[i].v;
		switch (p_shapes[i].type) {
			case GlyphShape::RECT:
				if (p_u >= v[0] && p_u <= v[0] + v[2] && p_v >= v[1] && p_v <= v[1] + v[3]) {
					return true;
				}
				break;
			case GlyphShape::CIRCLE:
				if ((p_u - v[0]) * (p_u - v[0]) + (p_v - v[1]) * (p_v - v[1]) <= v[2] * v[2]) {
					return true;
				}
				break;
			case GlyphShape::TRIANGLE: {
				const float e0 = _edge(v[0], v[1], v[2], v[3], p_u, p_v);
				const float e1 = _edge(v[2], v[3], v[4], v[5], p_u, p_v);
				const float e2 = _edge(v[4], v[5], v[0], v[1], p_u, p_v);
				if ((e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0)) {
					return true;
				}
			} break;
		}
	}
	return false;
}

// sRGB straight-alpha gizmo colour to the linear colour blended into the HDR image.
Color _to_linear(const Color &p_srgb) {
	Color c = p_srgb.srgb_to_linear();
	c.a = Math::clamp(p_srgb.a, 0.0f, 1.0f);
	return c;
}

float _fpart(float p_x) {
	return p_x - std::floor(p_x);
}

} // namespace

// ---------------------------------------------------------------------------------------------

bool GizmoOverlay::setup(const Camera3D *p_camera, int p_width, int p_height) {
	valid = false;
	ERR_FAIL_NULL_V_MSG(p_camera, false, "GizmoOverlay::setup(): the camera is null.");
	ERR_FAIL_COND_V_MSG(p_width <= 0 || p_height <= 0, false, vformat("GizmoOverlay::setup(): the image size %dx%d is empty.", p_width, p_height));
	width = p_width;
	height = p_height;
	world_from_view = p_camera->get_camera_transform();
	view_from_world = world_from_view.affine_inverse();
	const Vector2 size(p_width, p_height);
	clip_from_view = EditorNode3DGizmoPlugin::get_clip_from_view(p_camera, size);
	z_near = p_camera->get_near();
	tan_half_fovy = std::tan(Math::deg_to_rad(p_camera->get_vertical_fov(size.x / size.y)) * 0.5f);
	valid = world_from_view.is_finite() && tan_half_fovy > 0;
	ERR_FAIL_COND_V_MSG(!valid, false, "GizmoOverlay::setup(): the camera transform or field of view is not usable.");
	return true;
}

Vector2 GizmoOverlay::_view_to_pixel(const Vector3 &p_view) const {
	const Vector3 ndc = clip_from_view.xform(p_view);
	// Vulkan NDC (y already points down) to pixels; pixel (x, y) covers [x, x + 1) x [y, y + 1).
	return Vector2((ndc.x + 1) * real_t(0.5) * width, (ndc.y + 1) * real_t(0.5) * height);
}

bool GizmoOverlay::project(const Vector3 &p_world, Vector2 &r_pixel) const {
	ERR_FAIL_COND_V_MSG(!valid, false, "GizmoOverlay::project(): call setup() first.");
	const Vector3 v = view_from_world.xform(p_world);
	if (!(v.z <= -z_near)) {
		return false;
	}
	r_pixel = _view_to_pixel(v);
	return r_pixel.is_finite();
}

void GizmoOverlay::_plot(Image &r_image, int p_x, int p_y, const Color &p_linear, float p_coverage) const {
	if (p_x < 0 || p_y < 0 || p_x >= r_image.get_width() || p_y >= r_image.get_height()) {
		return;
	}
	const float a = Math::clamp(p_coverage, 0.0f, 1.0f) * p_linear.a;
	if (!(a > 0.0f)) {
		return;
	}
	float *px = r_image.ptrw() + (size_t(p_y) * r_image.get_width() + p_x) * Image::CHANNELS;
	px[0] = px[0] * (1.0f - a) + p_linear.r * a;
	px[1] = px[1] * (1.0f - a) + p_linear.g * a;
	px[2] = px[2] * (1.0f - a) + p_linear.b * a;
	px[3] = px[3] * (1.0f - a) + a;
}

void GizmoOverlay::_draw_line_2d(Image &r_image, Vector2 p_a, Vector2 p_b, const Color &p_linear) const {
	if (!p_a.is_finite() || !p_b.is_finite()) {
		return;
	}
	// Clip to the image grown by two pixels (Liang-Barsky), which bounds the loop below.
	const real_t lo[2] = { -2, -2 };
	const real_t hi[2] = { real_t(r_image.get_width() + 2), real_t(r_image.get_height() + 2) };
	real_t t0 = 0, t1 = 1;
	const Vector2 d = p_b - p_a;
	for (int axis = 0; axis < 2; axis++) {
		const real_t p[2] = { -d[axis], d[axis] };
		const real_t q[2] = { p_a[axis] - lo[axis], hi[axis] - p_a[axis] };
		for (int k = 0; k < 2; k++) {
			if (p[k] == 0) {
				if (q[k] < 0) {
					return; // Parallel to this edge and outside.
				}
				continue;
			}
			const real_t t = q[k] / p[k];
			if (p[k] < 0) {
				t0 = std::max(t0, t);
			} else {
				t1 = std::min(t1, t);
			}
		}
	}
	if (t0 > t1) {
		return;
	}
	Vector2 a = p_a + d * t0;
	Vector2 b = p_a + d * t1;
	// Move pixel centres onto integers, then Wu's anti-aliased line.
	float x0 = a.x - 0.5f, y0 = a.y - 0.5f, x1 = b.x - 0.5f, y1 = b.y - 0.5f;
	const bool steep = std::fabs(y1 - y0) > std::fabs(x1 - x0);
	if (steep) {
		std::swap(x0, y0);
		std::swap(x1, y1);
	}
	if (x0 > x1) {
		std::swap(x0, x1);
		std::swap(y0, y1);
	}
	auto plot = [&](int p_major, int p_minor, float p_cov) {
		if (steep) {
			_plot(r_image, p_minor, p_major, p_linear, p_cov);
		} else {
			_plot(r_image, p_major, p_minor, p_linear, p_cov);
		}
	};
	const float dx = x1 - x0;
	const float gradient = dx < 1e-6f ? 0.0f : (y1 - y0) / dx;
	// First end point.
	float xend = std::round(x0);
	float yend = y0 + gradient * (xend - x0);
	float xgap = 1.0f - _fpart(x0 + 0.5f);
	const int xpxl1 = int(xend);
	plot(xpxl1, int(std::floor(yend)), (1.0f - _fpart(yend)) * xgap);
	plot(xpxl1, int(std::floor(yend)) + 1, _fpart(yend) * xgap);
	float intery = yend + gradient;
	// Second end point.
	xend = std::round(x1);
	yend = y1 + gradient * (xend - x1);
	xgap = _fpart(x1 + 0.5f);
	const int xpxl2 = int(xend);
	if (xpxl2 != xpxl1) {
		plot(xpxl2, int(std::floor(yend)), (1.0f - _fpart(yend)) * xgap);
		plot(xpxl2, int(std::floor(yend)) + 1, _fpart(yend) * xgap);
	}
	for (int x = xpxl1 + 1; x < xpxl2; x++) {
		plot(x, int(std::floor(intery)), 1.0f - _fpart(intery));
		plot(x, int(std::floor(intery)) + 1, _fpart(intery));
		intery += gradient;
	}
}

void GizmoOverlay::draw_line(Image &r_image, const Vector3 &p_world_a, const Vector3 &p_world_b, const Color &p_color) const {
	ERR_FAIL_COND_MSG(!valid, "GizmoOverlay::draw_line(): call setup() first.");
	Vector3 a = view_from_world.xform(p_world_a);
	Vector3 b = view_from_world.xform(p_world_b);
	if (!a.is_finite() || !b.is_finite()) {
		return;
	}
	// Keep the part with z <= -near (in front of the near plane); the camera looks down -Z.
	const real_t limit = -z_near;
	const bool a_in = a.z <= limit;
	const bool b_in = b.z <= limit;
	if (!a_in && !b_in) {
		return;
	}
	if (!a_in || !b_in) {
		const real_t t = (limit - a.z) / (b.z - a.z);
		const Vector3 cut = a + (b - a) * t;
		if (!a_in) {
			a = cut;
		} else {
			b = cut;
		}
		a.z = std::min(a.z, limit);
		b.z = std::min(b.z, limit);
	}
	_draw_line_2d(r_image, _view_to_pixel(a), _view_to_pixel(b), _to_linear(p_color));
}

void GizmoOverlay::draw_handle(Image &r_image, const Vector3 &p_world, const Color &p_color) const {
	ERR_FAIL_COND_MSG(!valid, "GizmoOverlay::draw_handle(): call setup() first.");
	Vector2 c;
	if (!project(p_world, c)) {
		return;
	}
	const int half = HANDLE_SIZE / 2;
	const int cx = int(std::floor(c.x));
	const int cy = int(std::floor(c.y));
	const Color fill = _to_linear(p_color);
	const Color border = Color(0.0f, 0.0f, 0.0f, fill.a);
	for (int y = cy - half - 1; y <= cy + half + 1; y++) {
		for (int x = cx - half - 1; x <= cx + half + 1; x++) {
			const bool edge = std::abs(x - cx) == half + 1 || std::abs(y - cy) == half + 1;
			_plot(r_image, x, y, edge ? border : fill, 1.0f);
		}
	}
}

void GizmoOverlay::draw_icon(Image &r_image, const Vector3 &p_world, const String &p_icon_path, real_t p_scale, const Color &p_color) const {
	ERR_FAIL_COND_MSG(!valid, "GizmoOverlay::draw_icon(): call setup() first.");
	Vector2 c;
	if (!project(p_world, c)) {
		return;
	}
	// A constant-size billboard of half-extent scale * distance covers height * scale / tan(fovy / 2)
	// pixels; clamped so icons stay legible in tiny renders and modest in large ones.
	const float size = Math::clamp(float(height * p_scale / tan_half_fovy), float(ICON_MIN_SIZE), float(ICON_MAX_SIZE));
	const GlyphShape *shapes = nullptr;
	int count = 0;
	_get_glyph(p_icon_path, &shapes, &count);
	const Color color = _to_linear(p_color);
	const float x0 = c.x - size * 0.5f;
	const float y0 = c.y - size * 0.5f;
	const int px_min = std::max(0, int(std::floor(x0)));
	const int py_min = std::max(0, int(std::floor(y0)));
	const int px_max = std::min(r_image.get_width() - 1, int(std::floor(x0 + size)));
	const int py_max = std::min(r_image.get_height() - 1, int(std::floor(y0 + size)));
	const int SS = 4; // 4x4 samples per pixel.
	for (int py = py_min; py <= py_max; py++) {
		for (int px = px_min; px <= px_max; px++) {
			int hits = 0;
			for (int sy = 0; sy < SS; sy++) {
				for (int sx = 0; sx < SS; sx++) {
					const float u = (px + (sx + 0.5f) / SS - x0) / size * 32.0f;
					const float v = (py + (sy + 0.5f) / SS - y0) / size * 32.0f;
					if (u >= 0 && v >= 0 && u < 32 && v < 32 && _glyph_inside(shapes, count, u, v)) {
						hits++;
					}
				}
			}
			if (hits) {
				_plot(r_image, px, py, color, float(hits) / float(SS * SS));
			}
		}
	}
}

bool GizmoOverlay::icon_covers(const String &p_icon_path, float p_u, float p_v) {
	const GlyphShape *shapes = nullptr;
	int count = 0;
	_get_glyph(p_icon_path, &shapes, &count);
	return _glyph_inside(shapes, count, p_u, p_v);
}

void GizmoOverlay::draw_gizmo(Image &r_image, const EditorNode3DGizmo &p_gizmo) const {
	ERR_FAIL_COND_MSG(!valid, "GizmoOverlay::draw_gizmo(): call setup() first.");
	const Node3D *node = p_gizmo.get_node_3d();
	ERR_FAIL_NULL_MSG(node, "GizmoOverlay::draw_gizmo(): the gizmo has no node.");
	const Transform3D gt = node->get_global_transform();
	// Billboard parts: (x, y, z) offsets along the camera's right, up and back axes from the node's
	// origin (unscaled, like Godot's billboard gizmo lines).
	const Basis cam = world_from_view.basis;
	auto billboard_point = [&](const Vector3 &p_p) {
		return gt.origin + cam.get_column(0) * p_p.x + cam.get_column(1) * p_p.y + cam.get_column(2) * p_p.z;
	};
	for (const EditorNode3DGizmo::LineSet &set : p_gizmo.get_lines()) {
		const Color color = (set.material.is_valid() ? set.material->color : Color(1, 1, 1, 1)) * set.modulate;
		for (size_t i = 0; i + 1 < set.points.size(); i += 2) {
			const Vector3 a = set.billboard ? billboard_point(set.points[i]) : gt.xform(set.points[i]);
			const Vector3 b = set.billboard ? billboard_point(set.points[i + 1]) : gt.xform(set.points[i + 1]);
			draw_line(r_image, a, b, color);
		}
	}
	for (const EditorNode3DGizmo::Billboard &bb : p_gizmo.get_billboards()) {
		const Color color = (bb.material.is_valid() ? bb.material->color : Color(1, 1, 1, 1)) * bb.modulate;
		draw_icon(r_image, gt.origin, bb.material.is_valid() ? bb.material->icon_path : String(), bb.scale, color);
	}
	// Handles last, so they stay visible on top of lines and icons.
	for (const EditorNode3DGizmo::HandleSet &set : p_gizmo.get_handles()) {
		const Color color = set.material.is_valid() ? set.material->color : Color(1, 1, 1, 1);
		for (const Vector3 &p : set.points) {
			draw_handle(r_image, set.billboard ? billboard_point(p) : gt.xform(p), color);
		}
	}
}

int GizmoOverlay::draw(Image &r_image, Node *p_root, const Camera3D *p_camera, bool p_selected) {
	ERR_FAIL_COND_V_MSG(r_image.is_empty(), -1, "GizmoOverlay::draw(): the image is empty.");
	ERR_FAIL_NULL_V_MSG(p_root, -1, "GizmoOverlay::draw(): the root node is null.");
	ERR_FAIL_NULL_V_MSG(p_camera, -1, "GizmoOverlay::draw(): there is no camera to draw the gizmos from.");
	GizmoOverlay overlay;
	if (!overlay.setup(p_camera, r_image.get_width(), r_image.get_height())) {
		return -1;
	}
	Ref<Light3DGizmoPlugin> plugin;
	plugin.instantiate();
	int drawn = 0;
	std::function<void(Node *)> visit = [&](Node *p_node) {
		Node3D *n3d = Object::cast_to<Node3D>(p_node);
		if (n3d && n3d->is_visible_in_tree() && plugin->has_gizmo(n3d)) {
			Ref<EditorNode3DGizmo> gizmo = plugin->create_gizmo(n3d);
			gizmo->set_selected(p_selected);
			gizmo->redraw();
			overlay.draw_gizmo(r_image, *gizmo.ptr());
			drawn++;
		}
		for (int i = 0; i < p_node->get_child_count(); i++) {
			visit(p_node->get_child(i));
		}
	};
	visit(p_root);
	return drawn;
}

int GizmoOverlay::draw(Image &r_image, SceneTree &p_tree, bool p_selected) {
	ERR_FAIL_NULL_V_MSG(p_tree.get_camera_3d(), -1, "GizmoOverlay::draw(): the SceneTree has no current Camera3D.");
	return draw(r_image, p_tree.get_root(), p_tree.get_camera_3d(), p_selected);
}
