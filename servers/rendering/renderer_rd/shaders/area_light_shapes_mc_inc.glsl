/**************************************************************************/
/*  area_light_shapes_mc_inc.glsl                                         */
/**************************************************************************/
/* Disk, sphere and tube lights by Monte Carlo integration (thesis 5.2's  */
/* estimator, area_light_mc_inc.glsl's seeds, hash and GGX VNDF): an      */
/* UNBIASED estimate of W(d) integral f L_e cos dw for each shape:        */
/*   SPHERE uniform in the solid angle of the sphere's cap (the cone of   */
/*          half angle sigma, sin sigma = r / d: cos theta = 1 - u (1 -   */
/*          cos sigma), phi = 2 pi v, pdf = 1 / Omega, Omega = 2 pi (1 -   */
/*          cos sigma); pbrt-v4's Sphere::Sample, Shirley and Wang 1992); */
/*          inside the sphere uniform over all directions (Omega = 4 pi); */
/*   DISK   uniform over the ellipse's area (rho = sqrt(u), phi = 2 pi v; */
/*          pdf_w = dist^2 / (A cos theta_l), A = pi a b);                */
/*   TUBE   uniform over the part of the capsule that faces the shading   */
/*          point p (a convex body: what faces p is what p sees): on the  */
/*          cylinder the points with (p - q).n > 0 are the arc            */
/*          |phi - phi_p| < acos(r / rho) around the direction of p from  */
/*          the axis (rho its distance), at every height: area            */
/*          2 acos(r / rho) r l; on each end sphere (centre C, D = |p -   */
/*          C|) the cap cos theta > r / D around p - C: area              */
/*          2 pi r^2 (1 - r / D), uniform in cos theta. One of the three  */
/*          is picked by area, so the density is 1 / A_vis over their     */
/*          union; a cap point on the inner half of its sphere is inside  */
/*          the cylinder (not the surface) and counts 0. Every sample     */
/*          lands on the visible side (uniform over the whole capsule,    */
/*          about half faced away and counted 0).                         */
/* Specular: N light samples combined with N GGX VNDF samples (balance   */
/* heuristic, as the rectangle; a BRDF sample counts when its ray's first */
/* hit is the shape: cone test, disk plane, ray / capsule).               */

#ifndef AREA_LIGHT_SHAPES_MC_INC_GLSL
#define AREA_LIGHT_SHAPES_MC_INC_GLSL

// Solid-angle pdf of direction p_l towards the disk (0 when its ray misses the ellipse or its back).
float area_mc_disk_pdf(AreaLightData p_light, vec3 p_vertex, vec3 p_l, float p_area) {
	float dn = dot(p_l, p_light.normal);
	if (!(dn < 0.0)) {
		return 0.0;
	}
	float t = dot(p_vertex - p_light.position, p_light.normal) / -dn;
	vec3 hit = p_vertex + p_l * t - p_light.position;
	float a2 = dot(p_light.half_axis_x, p_light.half_axis_x);
	float b2 = dot(p_light.half_axis_y, p_light.half_axis_y);
	float u = dot(hit, p_light.half_axis_x) / a2;
	float v = dot(hit, p_light.half_axis_y) / b2;
	if (u * u + v * v > 1.0) {
		return 0.0;
	}
	return t * t / (p_area * -dn);
}

// First hit of the ray p_o + t p_d (p_o relative to the capsule's centre, p_d unit) with the capsule of
// unit axis p_axis, half segment p_half and radius p_r, from outside: the nearest entry into the
// cylinder or either end sphere (their union is the capsule). r_n: outward unit normal there.
bool area_mc_ray_capsule(vec3 p_o, vec3 p_d, vec3 p_axis, float p_half, float p_r, out float r_t, out vec3 r_n) {
	r_t = 1e30;
	r_n = vec3(0.0);
	vec3 dp = p_d - p_axis * dot(p_d, p_axis);
	vec3 op = p_o - p_axis * dot(p_o, p_axis);
	float qa = dot(dp, dp);
	float qb = dot(op, dp);
	float qc = dot(op, op) - p_r * p_r;
	float disc = qb * qb - qa * qc;
	if (qa > 1e-12 && disc >= 0.0) {
		float t = (-qb - sqrt(disc)) / qa;
		if (t > 0.0 && abs(dot(p_o, p_axis) + t * dot(p_d, p_axis)) <= p_half) {
			r_t = t;
			r_n = normalize(op + dp * t);
		}
	}
	for (int e = 0; e < 2; e++) {
		vec3 oe = p_o - p_axis * (e == 0 ? -p_half : p_half);
		float b = dot(oe, p_d);
		float ds = b * b - (dot(oe, oe) - p_r * p_r);
		if (ds >= 0.0) {
			float t = -b - sqrt(ds);
			if (t > 0.0 && t < r_t) {
				r_t = t;
				r_n = (oe + p_d * t) / p_r;
			}
		}
	}
	return r_t < 1e30;
}

void light_process_area_shape_mc(AreaLightData p_light, uint p_shape, vec3 p_radiance, vec3 p_vertex, vec3 N, vec3 V, uint p_diffuse_mode, float p_roughness, vec3 p_f0, float p_f90, bool p_specular_enabled, inout vec3 r_diffuse, inout vec3 r_specular) {
	uint n = area_light_get_stochastic_samples(p_light);
	float inv_n = 1.0 / float(n);
	vec3 c = p_light.position - p_vertex;
	float d = length(c);
	// Seeds as the rectangle's (thesis 5.2: specular per pixel, diffuse per world cell).
	uint light_seed = area_mc_hash(floatBitsToUint(p_light.color.r) ^ area_mc_hash(floatBitsToUint(p_light.color.g) ^ area_mc_hash(floatBitsToUint(p_light.color.b) ^ area_mc_hash(floatBitsToUint(p_light.inv_radius)))));
	uvec2 pixel = uvec2(gl_FragCoord.xy);
	uint specular_seed = area_mc_hash(pixel.x ^ area_mc_hash(pixel.y ^ area_mc_hash(light_seed ^ 0x5BD1E995u)));
	vec3 world = (scene_data.world_from_view * vec4(p_vertex, 1.0)).xyz;
	ivec3 cell = ivec3(floor(world * (1.0 / AREA_MC_DIFFUSE_SEED_STEP)));
	uint diffuse_seed = area_mc_hash(uint(cell.x) ^ area_mc_hash(uint(cell.y) ^ area_mc_hash(uint(cell.z) ^ light_seed)));

	// Shape set-up.
	float radius = length(p_shape == AREA_SHAPE_SPHERE ? p_light.half_axis_x : p_light.half_axis_y);
	bool inside = p_shape == AREA_SHAPE_SPHERE && d <= radius;
	float one_minus_cos = inside ? 2.0 : radius * radius / max(d * d, 1e-30); // 1 - cos sigma, below.
	vec3 lc = d > 0.0 ? c / d : N;
	vec3 t1;
	vec3 t2;
	area_shape_basis(lc, t1, t2);
	if (p_shape == AREA_SHAPE_SPHERE && !inside) {
		float s2 = one_minus_cos;
		one_minus_cos = s2 / (1.0 + sqrt(max(1.0 - s2, 0.0)));
	}
	float omega = 2.0 * M_PI * one_minus_cos; // Sphere.
	float disk_area = M_PI * length(p_light.half_axis_x) * length(p_light.half_axis_y);
	float seg = 2.0 * length(p_light.half_axis_x); // Tube.
	vec3 tube_axis = seg > 0.0 ? p_light.half_axis_x / (0.5 * seg) : normalize(cross(p_light.half_axis_y, p_light.normal));
	vec3 tube_e1 = radius > 0.0 ? p_light.half_axis_y / radius : t1;
	vec3 tube_e2 = cross(tube_axis, tube_e1);
	// Tube: the part facing the shading point (-c from the centre), see the header.
	vec3 from_centre = -c;
	vec3 radial = from_centre - tube_axis * dot(from_centre, tube_axis);
	float axis_dist = length(radial);
	vec3 arc_e1 = axis_dist > 0.0 ? radial / axis_dist : tube_e1;
	vec3 arc_e2 = cross(tube_axis, arc_e1);
	float arc_half = axis_dist > radius ? acos(radius / axis_dist) : 0.0;
	float arc_area = 2.0 * arc_half * radius * seg;
	// End spheres: 0 at +seg/2 along the axis, 1 at -seg/2 (named, not arrays: no indexed local memory).
	vec3 to_p0 = from_centre - tube_axis * (0.5 * seg);
	vec3 to_p1 = from_centre + tube_axis * (0.5 * seg);
	float dist0 = length(to_p0);
	float dist1 = length(to_p1);
	vec3 cap_w0 = dist0 > 0.0 ? to_p0 / dist0 : tube_axis;
	vec3 cap_w1 = dist1 > 0.0 ? to_p1 / dist1 : -tube_axis;
	float cap_cos0 = dist0 > radius ? radius / dist0 : 1.0;
	float cap_cos1 = dist1 > radius ? radius / dist1 : 1.0;
	float cap_area0 = 2.0 * M_PI * radius * radius * (1.0 - cap_cos0);
	float cap_area1 = 2.0 * M_PI * radius * radius * (1.0 - cap_cos1);
	float tube_area = arc_area + cap_area0 + cap_area1; // Visible area (0 inside the capsule).

	// Samples: direction l and its solid-angle pdf (0: counts nothing).
	vec3 diffuse = vec3(0.0);
	vec3 unused_specular = vec3(0.0);
	vec3 spec_sum = vec3(0.0);
	for (uint strategy_pass = 0u; strategy_pass < 2u; strategy_pass++) {
		if (strategy_pass == 1u && !p_specular_enabled) {
			break;
		}
		uint seed = strategy_pass == 0u ? diffuse_seed : specular_seed;
		for (uint i = 0u; i < n; i++) {
			vec2 u = area_mc_random2(seed, 3u * i);
			float pdf = 0.0;
			vec3 l = lc;
			if (p_shape == AREA_SHAPE_SPHERE) {
				float omc = u.x * one_minus_cos; // 1 - cos theta.
				float cos_t = 1.0 - omc;
				float sin_t = sqrt(max(omc * (2.0 - omc), 0.0));
				float phi = 2.0 * M_PI * u.y;
				l = lc * cos_t + (t1 * cos(phi) + t2 * sin(phi)) * sin_t;
				pdf = 1.0 / omega;
			} else if (p_shape == AREA_SHAPE_DISK) {
				float rho = sqrt(u.x);
				float phi = 2.0 * M_PI * u.y;
				vec3 q = c + p_light.half_axis_x * (rho * cos(phi)) + p_light.half_axis_y * (rho * sin(phi));
				float dist2 = dot(q, q);
				l = q * inversesqrt(dist2);
				float cos_l = -dot(l, p_light.normal);
				pdf = cos_l > 0.0 ? dist2 / (disk_area * cos_l) : 0.0;
			} else {
				float pick = area_mc_random2(seed, 3u * i + 2u).x * tube_area;
				vec3 q;
				vec3 nq;
				bool on_surface = true;
				if (pick < arc_area) {
					float phi = (2.0 * u.y - 1.0) * arc_half;
					nq = arc_e1 * cos(phi) + arc_e2 * sin(phi);
					q = c + tube_axis * (seg * (u.x - 0.5)) + nq * radius;
				} else {
					bool first = pick < arc_area + cap_area0;
					vec3 w = first ? cap_w0 : cap_w1;
					float cap_cos = first ? cap_cos0 : cap_cos1;
					vec3 b1;
					vec3 b2;
					area_shape_basis(w, b1, b2);
					float z = 1.0 - u.x * (1.0 - cap_cos); // Uniform in cos theta over the cap: uniform area.
					float phi = 2.0 * M_PI * u.y;
					float sr = sqrt(max(1.0 - z * z, 0.0));
					nq = w * z + b1 * (sr * cos(phi)) + b2 * (sr * sin(phi));
					q = c + tube_axis * (first ? 0.5 * seg : -0.5 * seg) + nq * radius;
					// Only the outer half of each end sphere is the capsule's surface (the inner half lies
					// inside the cylinder). Split by the sign along the axis, so that a tube of length 0 (one
					// sphere, both caps the same) still counts each point once.
					float along = dot(nq, tube_axis);
					on_surface = first ? along >= 0.0 : along < 0.0;
				}
				float dist2 = dot(q, q);
				l = q * inversesqrt(max(dist2, 1e-30));
				float cos_l = -dot(l, nq);
				pdf = on_surface && cos_l > 0.0 && tube_area > 0.0 ? dist2 / (tube_area * cos_l) : 0.0;
			}
			if (!(pdf > 0.0)) {
				continue;
			}
			if (strategy_pass == 0u) {
				light_compute(N, l, V, p_radiance * (inv_n / pdf), 0.0, p_diffuse_mode, p_roughness, p_f0, p_f90, false, diffuse, unused_specular);
				continue;
			}
			vec3 lobe = area_mc_specular_lobe(N, V, l, p_roughness, p_f0, p_f90);
			if (lobe == vec3(0.0)) {
				continue;
			}
			float pdf_brdf = 0.0;
			float nov = dot(N, V);
			if (nov > 1e-4) {
				pdf_brdf = area_mc_vndf_pdf(N, V, l, nov, max(p_roughness * p_roughness, 2e-3));
			}
			spec_sum += lobe / (pdf + pdf_brdf);
		}
	}
	r_diffuse += diffuse;
	if (!p_specular_enabled) {
		return;
	}
	// BRDF strategy: GGX VNDF samples whose rays reach the light.
	float nov = dot(N, V);
	if (nov > 1e-4) {
		float alpha = max(p_roughness * p_roughness, 2e-3);
		vec3 b1 = abs(N.z) < 0.999 ? normalize(cross(vec3(0.0, 0.0, 1.0), N)) : vec3(1.0, 0.0, 0.0);
		vec3 b2 = cross(N, b1);
		vec3 v_local = vec3(dot(V, b1), dot(V, b2), nov);
		for (uint i = 0u; i < n; i++) {
			vec3 m = area_mc_sample_vndf(v_local, alpha, area_mc_random2(specular_seed ^ 0x68E31DA4u, i));
			vec3 h = b1 * m.x + b2 * m.y + N * m.z;
			vec3 lb = reflect(-V, h);
			if (dot(N, lb) <= 0.0) {
				continue;
			}
			float pdf_light = 0.0;
			if (p_shape == AREA_SHAPE_SPHERE) {
				pdf_light = (inside || dot(lb, lc) >= 1.0 - one_minus_cos) ? 1.0 / omega : 0.0;
			} else if (p_shape == AREA_SHAPE_DISK) {
				pdf_light = area_mc_disk_pdf(p_light, p_vertex, lb, disk_area);
			} else {
				float t;
				vec3 nh;
				if (area_mc_ray_capsule(-c, lb, tube_axis, 0.5 * seg, radius, t, nh)) {
					float cos_h = -dot(lb, nh);
					pdf_light = cos_h > 0.0 && tube_area > 0.0 ? t * t / (tube_area * cos_h) : 0.0;
				}
			}
			if (!(pdf_light > 0.0)) {
				continue;
			}
			vec3 lobe_b = area_mc_specular_lobe(N, V, lb, p_roughness, p_f0, p_f90);
			spec_sum += lobe_b / (pdf_light + area_mc_vndf_pdf(N, V, lb, nov, alpha));
		}
	}
	r_specular += p_radiance * p_light.specular_amount * spec_sum * inv_n;
}

#endif // AREA_LIGHT_SHAPES_MC_INC_GLSL
