/**************************************************************************/
/*  ltc_polygon_objective.cpp                                             */
/**************************************************************************/
/* godot-area: the scene-error objective of the LTC fit (see the header). */

#include "modules/ltc_fit/ltc_polygon_objective.h"

#include <cmath>

namespace {

const double PI = 3.14159265358979323846;

inline void cross3(const double *p_a, const double *p_b, double *r_c) {
	r_c[0] = p_a[1] * p_b[2] - p_a[2] * p_b[1];
	r_c[1] = p_a[2] * p_b[0] - p_a[0] * p_b[2];
	r_c[2] = p_a[0] * p_b[1] - p_a[1] * p_b[0];
}

inline double dot3(const double *p_a, const double *p_b) {
	return p_a[0] * p_b[0] + p_a[1] * p_b[1] + p_a[2] * p_b[2];
}

// Sutherland-Hodgman of the n-gon p_v against z >= 0 into r_out (room for n + 1 vertices).
int clip_z(const double *p_v, int p_n, double *r_out) {
	int n = 0;
	for (int i = 0; i < p_n; i++) {
		const double *a = p_v + 3 * i;
		const double *b = p_v + 3 * ((i + 1) % p_n);
		const bool a_in = a[2] > 0.0, b_in = b[2] > 0.0;
		if (a_in) {
			r_out[3 * n] = a[0], r_out[3 * n + 1] = a[1], r_out[3 * n + 2] = a[2];
			n++;
		}
		if (a_in != b_in) {
			const double t = a[2] / (a[2] - b[2]);
			r_out[3 * n] = a[0] + (b[0] - a[0]) * t, r_out[3 * n + 1] = a[1] + (b[1] - a[1]) * t, r_out[3 * n + 2] = 0.0;
			n++;
		}
	}
	return n;
}

} // namespace

double LTCPolygonObjective::form_factor(const double *p_v, int p_n) {
	double c[3 * 8];
	if (p_n > 7) {
		return 0.0;
	}
	const int n = clip_z(p_v, p_n, c);
	if (n < 3) {
		return 0.0;
	}
	for (int i = 0; i < n; i++) {
		const double l = std::sqrt(dot3(c + 3 * i, c + 3 * i));
		if (l <= 0.0) {
			return 0.0;
		}
		c[3 * i] /= l, c[3 * i + 1] /= l, c[3 * i + 2] /= l;
	}
	double sum = 0.0;
	for (int i = 0; i < n; i++) {
		const double *a = c + 3 * i;
		const double *b = c + 3 * ((i + 1) % n);
		double x[3];
		cross3(a, b, x);
		const double s = std::sqrt(dot3(x, x));
		if (s > 0.0) {
			sum += std::atan2(s, dot3(a, b)) * x[2] / s;
		}
	}
	return std::fabs(sum) * 0.5 / PI;
}

double LTCPolygonObjective::ltc_integral(const double *p_m, const double *p_quad) {
	const double a = p_m[0], b = p_m[1], c = p_m[2], d = p_m[3], e = p_m[4];
	const double det = a * e - b * d;
	if (det <= 0.0 || c <= 0.0) {
		return -1.0;
	}
	const double s = 1.0 / det;
	double h[3 * 5];
	const int n = clip_z(p_quad, 4, h); // The receiver's horizon (the shader's surface-horizon clip).
	if (n < 3) {
		return 0.0;
	}
	for (int i = 0; i < n; i++) {
		const double x = h[3 * i], y = h[3 * i + 1], z = h[3 * i + 2];
		h[3 * i] = s * (e * x - b * z);
		h[3 * i + 1] = y / c;
		h[3 * i + 2] = s * (a * z - d * x);
	}
	return form_factor(h, n);
}

void LTCPolygonObjective::build(const std::vector<double> &p_directions, const std::vector<double> &p_weights) {
	quads.clear();
	targets.clear();
	const double deg = PI / 180.0;
	const double elevations[] = { 0.0, 15.0, 30.0, 45.0, 60.0, 70.0, 78.0, 84.0, 88.0 };
	const double azimuths[] = { 180.0, 150.0, 120.0, 90.0, 0.0 };
	const double shapes[4][2] = { { 3.0, 3.0 }, { 10.0, 10.0 }, { 25.0, 25.0 }, { 25.0, 8.0 } };
	for (double te : elevations) {
		for (double az : azimuths) {
			for (const auto &shape : shapes) {
				const double ct[3] = { std::sin(te * deg) * std::cos(az * deg), std::sin(te * deg) * std::sin(az * deg), std::cos(te * deg) };
				// u: horizontal (z x c, or x at the pole), v = c x u (towards the zenith).
				double u[3] = { -ct[1], ct[0], 0.0 };
				double ul = std::sqrt(dot3(u, u));
				if (ul < 1e-9) {
					u[0] = 0.0, u[1] = 1.0, u[2] = 0.0;
					ul = 1.0;
				}
				u[0] /= ul, u[1] /= ul;
				double v[3];
				cross3(ct, u, v);
				const double tu = std::tan(shape[0] * deg), tv = std::tan(shape[1] * deg);
				const double su[4] = { -1, 1, 1, -1 }, sv[4] = { -1, -1, 1, 1 };
				for (int k = 0; k < 4; k++) {
					double p[3];
					for (int j = 0; j < 3; j++) {
						p[j] = ct[j] + su[k] * tu * u[j] + sv[k] * tv * v[j];
					}
					const double l = std::sqrt(dot3(p, p));
					for (int j = 0; j < 3; j++) {
						quads.push_back(p[j] / l);
					}
				}
			}
		}
	}
	const int count = int(quads.size() / 12);
	targets.assign(count, 0.0);
	// Inward edge normals of each quad (corners counter-clockwise seen from outside? either winding:
	// a direction is inside when it is on the same side of all four edge planes as the centre).
	const size_t samples = p_weights.size();
	for (int k = 0; k < count; k++) {
		const double *q = &quads[12 * k];
		double centre[3] = { 0.0, 0.0, 0.0 };
		for (int i = 0; i < 4; i++) {
			for (int j = 0; j < 3; j++) {
				centre[j] += q[3 * i + j];
			}
		}
		double normals[4][3];
		for (int i = 0; i < 4; i++) {
			cross3(q + 3 * i, q + 3 * ((i + 1) & 3), normals[i]);
			if (dot3(normals[i], centre) < 0.0) {
				normals[i][0] = -normals[i][0], normals[i][1] = -normals[i][1], normals[i][2] = -normals[i][2];
			}
		}
		double sum = 0.0;
		for (size_t s = 0; s < samples; s++) {
			const double *l = &p_directions[3 * s];
			if (dot3(l, centre) <= 0.0) {
				continue;
			}
			bool inside = true;
			for (int i = 0; i < 4 && inside; i++) {
				inside = dot3(l, normals[i]) >= 0.0;
			}
			if (inside) {
				sum += p_weights[s];
			}
		}
		targets[k] = samples > 0 ? sum / double(samples) : 0.0;
	}
	target_energy = 0.0;
	for (double t : targets) {
		target_energy += t * t;
	}
}

double LTCPolygonObjective::error(const double *p_m) const {
	if (target_energy <= 0.0) {
		return 0.0;
	}
	double sum = 0.0;
	const int count = int(targets.size());
	for (int k = 0; k < count; k++) {
		const double i_d = ltc_integral(p_m, &quads[12 * k]);
		if (i_d < 0.0) {
			return 1e300;
		}
		const double diff = i_d - targets[k];
		sum += diff * diff;
	}
	return sum / target_energy;
}

double LTCPolygonObjective::error_mixture(const double *p_m, const double *p_weights, int p_lobes) const {
	if (target_energy <= 0.0) {
		return 0.0;
	}
	double sum = 0.0;
	const int count = int(targets.size());
	for (int k = 0; k < count; k++) {
		double i_d = 0.0;
		for (int j = 0; j < p_lobes; j++) {
			const double i_j = ltc_integral(p_m + 5 * j, &quads[12 * k]);
			if (i_j < 0.0) {
				return 1e300;
			}
			i_d += p_weights[j] * i_j;
		}
		const double diff = i_d - targets[k];
		sum += diff * diff;
	}
	return sum / target_energy;
}
