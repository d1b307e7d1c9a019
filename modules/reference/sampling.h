/**************************************************************************/
/*  sampling.h                                                            */
/**************************************************************************/
/* godot-area: random numbers and Monte Carlo integration for the CPU     */
/* reference renderer. ReferenceRNG is a PCG32 generator (O'Neill 2014,   */
/* "PCG: A Family of Simple Fast Space-Efficient Statistically Good       */
/* Algorithms for Random Number Generation"), seeded per pixel so images  */
/* are bit-identical for any thread count. integrate_adaptive() estimates */
/* a vector-valued integral over [0,1]^2 with stratified (jittered)       */
/* samples in rounds until the relative standard error of every channel   */
/* is below a target (area lights use it; the self-tests check it).       */
/* integrate_adaptive_points() does the same for integrands of several    */
/* points of the unit square (one sample per strategy of multiple         */
/* importance sampling), each stratified, the strata paired at random.    */

#pragma once

#include <cstdint>
#include <functional>
#include <vector>

// PCG32 (XSH RR variant): 64-bit state, 32-bit output.
class ReferenceRNG {
	uint64_t state = 0x853c49e6748fea9bULL;
	uint64_t inc = 0xda3e39cb94b95bdbULL;

public:
	// Returns the next 32 random bits.
	uint32_t next_u32();
	// Returns a float uniform in [0, 1) (24 random bits, never 1).
	float next_float();
	// Returns a double uniform in [0, 1) (53 random bits, never 1).
	double next_double();
	// Re-seeds: p_stream selects one of 2^63 independent sequences.
	void seed(uint64_t p_seed, uint64_t p_stream);

	// The generator of one pixel: stream = pixel index (y * width + x), so the result does not depend
	// on which thread renders the pixel.
	static ReferenceRNG for_pixel(uint64_t p_seed, uint64_t p_pixel_index);

	ReferenceRNG() {}
	ReferenceRNG(uint64_t p_seed, uint64_t p_stream) { seed(p_seed, p_stream); }
};

// An integrand over the unit square: writes p_channels values for the point (u, v) to r_value.
// The integral is the mean over [0,1]^2 (so an integrand that maps (u, v) to a surface point must
// multiply by the area / divide by the pdf itself).
typedef std::function<void(double p_u, double p_v, double *r_value)> ReferenceIntegrand;

struct AdaptiveIntegrationSettings {
	// Each round is one independent stratified estimate with strata_per_axis^2 jittered samples.
	int strata_per_axis = 4;
	// Rounds taken before the error is first checked (the error estimate needs several rounds).
	int min_rounds = 8;
	// Hard cap on the samples of one integral (the "spp cap"); stops even if not converged.
	int max_samples = 4096;
	// Stop when standard_error <= target_relative_error * |mean| for every channel.
	double target_relative_error = 0.002;
	// Channels whose standard error is below this absolute value count as converged (a black pixel
	// has mean 0 and error 0 and must not run to max_samples).
	double absolute_error_floor = 1e-7;
	// False: independent uniform samples instead of jittered strata (plain Monte Carlo).
	bool stratified = true;
};

struct AdaptiveIntegrationResult {
	std::vector<double> value; // Estimated integral per channel.
	std::vector<double> standard_error; // Standard error of value per channel (from the round spread).
	int samples = 0; // Integrand evaluations.
	int rounds = 0;
	bool converged = false; // True when the target was met before max_samples.
	// max over channels of standard_error / |value| (0 for channels under the absolute floor).
	double relative_error = 0.0;
};

// Integrates p_integrand (p_channels values) over [0,1]^2 in rounds of strata_per_axis^2 stratified
// samples until the relative standard error target is met or max_samples is reached. The standard
// error is the spread of the per-round estimates (independent, identically distributed) over
// sqrt(rounds), which is unbiased for stratified rounds where the per-sample variance is not.
AdaptiveIntegrationResult integrate_adaptive(const ReferenceIntegrand &p_integrand, int p_channels, const AdaptiveIntegrationSettings &p_settings, ReferenceRNG &r_rng);

// An integrand of several points of the unit square (e.g. one sample of each strategy of multiple
// importance sampling): point k is (p_points[2k], p_points[2k + 1]). Writes p_channels values to
// r_value. The integral is the mean over ([0,1]^2)^point_count.
typedef std::function<void(const double *p_points, double *r_value)> ReferenceIntegrandPoints;

// integrate_adaptive for a multi-point integrand (1..8 points): each round draws strata_per_axis^2
// jittered samples of every point, the strata of points 1.. visited in a random order (a permutation
// per point and round), so the points are independent while each is stratified on its own.
// max_samples and AdaptiveIntegrationResult::samples count integrand evaluations.
AdaptiveIntegrationResult integrate_adaptive_points(const ReferenceIntegrandPoints &p_integrand, int p_point_count, int p_channels, const AdaptiveIntegrationSettings &p_settings, ReferenceRNG &r_rng);

// Plain estimate with exactly p_sample_count samples: independent uniform samples, or (p_stratified)
// a jittered grid of floor(sqrt(N))^2 samples plus uniform ones for the rest. Returns the mean.
std::vector<double> integrate_fixed(const ReferenceIntegrand &p_integrand, int p_channels, int p_sample_count, bool p_stratified, ReferenceRNG &r_rng);
