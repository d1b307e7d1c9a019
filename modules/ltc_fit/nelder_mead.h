/**************************************************************************/
/*  nelder_mead.h                                                         */
/**************************************************************************/
/* godot-area: a small, deterministic Nelder-Mead (downhill simplex)      */
/* minimiser (Nelder and Mead 1965) with the usual coefficients:          */
/* reflection 1, expansion 2, contraction 1/2, shrink 1/2. Used by the    */
/* LTC fitter (thesis section 5.4.1); no randomness, so identical inputs  */
/* give bit-identical results.                                            */

#pragma once

#include <functional>
#include <vector>

class NelderMead {
public:
	using Function = std::function<double(const std::vector<double> &)>;

	struct Result {
		std::vector<double> x; // Best point found.
		double value = 0.0; // Function value at x.
		int iterations = 0; // Simplex iterations performed.
		int evaluations = 0; // Function evaluations performed.
		bool converged = false; // True when the tolerance was reached before max_iterations.
	};

	// Minimises p_function starting from p_start. The initial simplex is p_start plus p_step along each axis.
	// Stops when the spread (max - min) of the simplex values is <= p_tolerance * (|min| + 1e-30)
	// or the simplex is smaller than 1e-12 (absolute, per coordinate), or after p_max_iterations.
	static Result minimize(const Function &p_function, const std::vector<double> &p_start, double p_step, double p_tolerance, int p_max_iterations);
};
