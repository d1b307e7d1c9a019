/**************************************************************************/
/*  sky_light.cpp                                                         */
/**************************************************************************/
/* godot-area: importance-sampled sky of the reference (see sky_light.h). */

#include "modules/reference/sky_light.h"

#include "core/math/math_funcs.h"

#include <algorithm>
#include <cmath>

void ReferenceSkyLight::build(const SkyModel &p_model, int p_rows) {
	model = p_model;
	rows = std::max(p_rows, 4);
	cols = rows * 2;
	const double d_theta = Math::PI / rows, d_phi = 2.0 * Math::PI / cols;
	std::vector<double> w(size_t(rows) * cols);
	double total = 0.0;
	for (int i = 0; i < rows; i++) {
		const double theta = (i + 0.5) * d_theta;
		for (int j = 0; j < cols; j++) {
			const double phi = (j + 0.5) * d_phi;
			const Vector3 dir(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(std::sin(theta) * std::sin(phi)));
			const Vector3 l = model.evaluate(dir);
			const double lum = std::max(0.0, 0.2126 * l.x + 0.7152 * l.y + 0.0722 * l.z);
			w[size_t(i) * cols + j] = lum * std::sin(theta) * d_theta * d_phi;
			total += w[size_t(i) * cols + j];
		}
	}
	cell_probability.assign(w.size(), 0.0);
	cell_cdf.assign(w.size() + 1, 0.0);
	for (size_t k = 0; k < w.size(); k++) {
		// Uniform share: the cell's solid angle over 4 pi.
		const double theta = (int(k / cols) + 0.5) * d_theta;
		const double uniform = std::sin(theta) * d_theta * d_phi / (4.0 * Math::PI);
		cell_probability[k] = total > 0.0 ? 0.9 * w[k] / total + 0.1 * uniform : uniform;
		cell_cdf[k + 1] = cell_cdf[k] + cell_probability[k];
	}
	const double norm = cell_cdf.back();
	for (size_t k = 0; k < w.size(); k++) {
		cell_probability[k] /= norm;
		cell_cdf[k + 1] /= norm;
	}
}

Vector3 ReferenceSkyLight::sample(double p_u, double p_v, double &r_pdf) const {
	const size_t n = cell_probability.size();
	size_t k = size_t(std::upper_bound(cell_cdf.begin(), cell_cdf.end(), p_u) - cell_cdf.begin());
	k = k == 0 ? 0 : std::min(k - 1, n - 1);
	const double p = cell_probability[k];
	const double within = p > 0.0 ? std::min(std::max((p_u - cell_cdf[k]) / p, 0.0), 1.0) : 0.5; // Reused for theta.
	const int i = int(k / cols), j = int(k % cols);
	const double d_theta = Math::PI / rows, d_phi = 2.0 * Math::PI / cols;
	const double theta = (i + within) * d_theta;
	const double phi = (j + p_v) * d_phi;
	const double st = std::sin(theta);
	r_pdf = st > 1e-12 ? p / (d_theta * d_phi * st) : 0.0;
	return Vector3(float(st * std::cos(phi)), float(std::cos(theta)), float(st * std::sin(phi)));
}

double ReferenceSkyLight::pdf(const Vector3 &p_dir) const {
	const double theta = std::acos(std::min(std::max(double(p_dir.y), -1.0), 1.0));
	double phi = std::atan2(double(p_dir.z), double(p_dir.x));
	if (phi < 0.0) {
		phi += 2.0 * Math::PI;
	}
	const double d_theta = Math::PI / rows, d_phi = 2.0 * Math::PI / cols;
	const int i = std::min(int(theta / d_theta), rows - 1), j = std::min(int(phi / d_phi), cols - 1);
	const double st = std::sin(theta);
	return st > 1e-12 ? cell_probability[size_t(i) * cols + j] / (d_theta * d_phi * st) : 0.0;
}
