/**************************************************************************/
/*  sky_light.h                                                           */
/**************************************************************************/
/* godot-area: the Environment sky as an environment light of the Embree  */
/* reference: the sky radiance (servers/rendering/sky_model.h) tabulated  */
/* on a latitude-longitude grid, directions drawn from the piecewise-     */
/* constant distribution of luminance * sin(theta) (pbrt-v4 12.6,        */
/* "Image Infinite Lights", and A.4 piecewise-constant 2D sampling),      */
/* with a 10 % uniform share so every direction has a positive pdf; each  */
/* sample evaluates the exact sky function, not the table.                */

#pragma once

#include "core/math/vector3.h"
#include "modules/reference/sampling.h"
#include "servers/rendering/sky_model.h"

#include <vector>

class ReferenceSkyLight {
	SkyModel model;
	int rows = 0; // theta (from +Y) cells.
	int cols = 0; // phi cells.
	std::vector<double> cell_cdf; // rows * cols + 1 entries, 0 .. 1.
	std::vector<double> cell_probability;

public:
	void build(const SkyModel &p_model, int p_rows = 64);
	const SkyModel &get_model() const { return model; }
	Vector3 evaluate(const Vector3 &p_dir) const { return model.evaluate(p_dir); }
	// Draws a direction for the unit-square point (u, v); r_pdf is per steradian.
	Vector3 sample(double p_u, double p_v, double &r_pdf) const;
	// pdf of sample() for unit p_dir, per steradian.
	double pdf(const Vector3 &p_dir) const;
};
