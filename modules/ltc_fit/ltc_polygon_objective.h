/**************************************************************************/
/*  ltc_polygon_objective.h                                               */
/**************************************************************************/
/* godot-area: the scene-error objective of the LTC fit (issue #18). The  */
/* shader never evaluates the lobe D at a direction: it integrates D over */
/* the polygon of a light (Heitz et al. 2016, eq. 1 and section 3.2). So  */
/* a cell is scored by what a scene measures, the error of those          */
/* integrals over a fixed set of test lights:                             */
/*   E = sum_k (I_D(P_k) - I_rho(P_k))^2 / sum_k I_rho(P_k)^2,            */
/* the relative RMSE of radiance a set of lights would show. I_D is the   */
/* exact LTC integral as the shader computes it (clip to the receiver's   */
/* horizon, M^-1, clip to z >= 0, Lambert edge sum); I_rho is the         */
/* integral of the normalised lobe rho = f cos / fn over P_k, estimated   */
/* once per cell with stratified visible-normal samples (Heitz 2018).     */
/* Test lights (fitter frame: normal +z, view in the xz-plane, x >= 0):   */
/* squares seen at half-angles 3, 10 and 25 degrees and a wide 25 x 8     */
/* degree "TV" rectangle, centred at elevations theta_c in {0, 15, 30,    */
/* 45, 60, 70, 78, 84, 88} degrees from the normal and azimuths {180      */
/* (mirror side), 150, 120, 90, 0} degrees: 180 rectangles, the ones      */
/* near the horizon crossing it (clipped as in the shader).               */

#pragma once

#include <vector>

class LTCPolygonObjective {
public:
	static constexpr int SAMPLES = 256; // Per axis, for the I_rho estimate.

	// p_directions: unit directions (x, y, z triples); p_weights: rho / pdf of each (estimator weight).
	void build(const std::vector<double> &p_directions, const std::vector<double> &p_weights);
	// E for the stored matrix (a, b, c, d, e); 1e300 for a singular matrix.
	double error(const double *p_m) const;
	// E for a mixture of p_lobes LTCs (two-lobe LTC, issue #18): I_D = sum_j p_weights[j] I_Dj, with
	// p_m the lobes' matrices one after the other (5 doubles each).
	double error_mixture(const double *p_m, const double *p_weights, int p_lobes) const;
	int get_polygon_count() const { return int(targets.size()); }
	double get_target(int p_k) const { return targets[p_k]; }

	// Cosine form factor (1 / pi) integral of max(z, 0) over the n-gon p_v (x, y, z triples), clipped to
	// z >= 0 first; exact in double (atan2 edge angles).
	static double form_factor(const double *p_v, int p_n);
	// The shader's specular integral: clip to z >= 0, transform by M^-1, form_factor.
	static double ltc_integral(const double *p_m, const double *p_quad);

private:
	std::vector<double> quads; // 12 doubles per test light (4 corners, unit vectors).
	std::vector<double> targets; // I_rho per test light.
	double target_energy = 0.0; // sum_k I_rho^2.
};
