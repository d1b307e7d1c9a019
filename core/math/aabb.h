/**************************************************************************/
/*  aabb.h                                                                */
/**************************************************************************/

#pragma once

#include "core/math/plane.h"

#include <vector>

struct AABB {
	Vector3 position;
	Vector3 size;

	Vector3 get_end() const { return position + size; }
	Vector3 get_center() const { return position + size * real_t(0.5); }
	// Corner p_idx in 0..7; bit 0 selects x, bit 1 y, bit 2 z.
	Vector3 get_endpoint(int p_idx) const {
		return Vector3(position.x + ((p_idx & 1) ? size.x : 0), position.y + ((p_idx & 2) ? size.y : 0), position.z + ((p_idx & 4) ? size.z : 0));
	}
	// The corner furthest along p_dir.
	Vector3 get_support(const Vector3 &p_dir) const {
		return Vector3(p_dir.x > 0 ? position.x + size.x : position.x, p_dir.y > 0 ? position.y + size.y : position.y, p_dir.z > 0 ? position.z + size.z : position.z);
	}
	bool has_point(const Vector3 &p_p) const {
		Vector3 e = get_end();
		return p_p.x >= position.x && p_p.y >= position.y && p_p.z >= position.z && p_p.x <= e.x && p_p.y <= e.y && p_p.z <= e.z;
	}
	bool intersects(const AABB &p_b) const {
		Vector3 ea = get_end(), eb = p_b.get_end();
		return position.x <= eb.x && ea.x >= p_b.position.x && position.y <= eb.y && ea.y >= p_b.position.y && position.z <= eb.z && ea.z >= p_b.position.z;
	}
	// Conservative: false only when the box lies fully outside one plane (outward normals).
	bool intersects_convex_shape(const std::vector<Plane> &p_planes) const {
		for (const Plane &p : p_planes) {
			if (p.is_point_over(get_support(-p.normal))) {
				return false;
			}
		}
		return true;
	}
	void expand_to(const Vector3 &p_p) {
		Vector3 b = position.min(p_p), e = get_end().max(p_p);
		position = b;
		size = e - b;
	}
	AABB merge(const AABB &p_b) const {
		AABB r = *this;
		r.expand_to(p_b.position);
		r.expand_to(p_b.get_end());
		return r;
	}
	AABB grow(real_t p_by) const { return AABB(position - Vector3(p_by, p_by, p_by), size + Vector3(p_by, p_by, p_by) * 2); }
	bool is_equal_approx(const AABB &p_b) const { return position.is_equal_approx(p_b.position) && size.is_equal_approx(p_b.size); }

	AABB() {}
	AABB(const Vector3 &p_pos, const Vector3 &p_size) :
			position(p_pos), size(p_size) {}
};
