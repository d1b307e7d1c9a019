/**************************************************************************/
/*  sampling.cpp                                                          */
/**************************************************************************/
/* godot-area: PCG32 and the adaptive stratified integrator (see .h).     */

#include "modules/reference/sampling.h"

#include "core/error/error_macros.h"

#include <algorithm>
#include <cmath>

/* ReferenceRNG */

uint32_t ReferenceRNG::next_u32() {
	// PCG32 XSH RR: LCG step (Knuth's MMIX multiplier), then xorshift-high and a random rotation.
	uint64_t old = state;
	state = old * 6364136223846793005ULL + inc;
	uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
	uint32_t rot = uint32_t(old >> 59u);
	return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

float ReferenceRNG::next_float() {
	return float(next_u32() >> 8) * (1.0f / 16777216.0f); // 2^-24: exactly representable, < 1.
}

double ReferenceRNG::next_double() {
	uint64_t hi = next_u32() >> 5; // 27 bits.
	uint64_t lo = next_u32() >> 6; // 26 bits.
	return double((hi << 26) | lo) * (1.0 / 9007199254740992.0); // 2^-53.
}

void ReferenceRNG::seed(uint64_t p_seed, uint64_t p_stream) {
	// PCG's seeding procedure: odd increment from the stream, two steps around adding the seed.
	state = 0;
	inc = (p_stream << 1u) | 1u;
	next_u32();
	state += p_seed;
	next_u32();
}

ReferenceRNG ReferenceRNG::for_pixel(uint64_t p_seed, uint64_t p_pixel_index) {
	// Mix the user seed (SplitMix64 finaliser) so seeds 0, 1, 2 give unrelated sequences.
	uint64_t z = p_seed + 0x9e3779b97f4a7c15ULL;
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	z ^= z >> 31;
	return ReferenceRNG(z, p_pixel_index);
}

/* Integration */

// Adds one round's estimate (mean of its samples) into r_round.
static int _run_round(const ReferenceIntegrand &p_integrand, int p_channels, int p_strata, bool p_stratified, ReferenceRNG &r_rng, std::vector<double> &r_round, std::vector<double> &r_tmp) {
	std::fill(r_round.begin(), r_round.end(), 0.0);
	const int n = p_strata * p_strata;
	const double inv = 1.0 / double(p_strata);
	for (int j = 0; j < p_strata; j++) {
		for (int i = 0; i < p_strata; i++) {
			double u, v;
			if (p_stratified) {
				u = (double(i) + r_rng.next_double()) * inv;
				v = (double(j) + r_rng.next_double()) * inv;
			} else {
				u = r_rng.next_double();
				v = r_rng.next_double();
			}
			p_integrand(u, v, r_tmp.data());
			for (int c = 0; c < p_channels; c++) {
				r_round[c] += r_tmp[c];
			}
		}
	}
	for (int c = 0; c < p_channels; c++) {
		r_round[c] /= double(n);
	}
	return n;
}

// Adds one round of a multi-point integrand: strata_per_axis^2 samples; point 0 visits its jittered
// strata in row order, every other point in its own random order (Fisher-Yates), so each point is
// stratified and the combination of strata is random.
static int _run_round_points(const ReferenceIntegrandPoints &p_integrand, int p_points, int p_channels, int p_strata, bool p_stratified, ReferenceRNG &r_rng, std::vector<double> &r_round, std::vector<double> &r_tmp, std::vector<int> &r_order) {
	std::fill(r_round.begin(), r_round.end(), 0.0);
	const int n = p_strata * p_strata;
	const double inv = 1.0 / double(p_strata);
	r_order.resize(size_t(n) * p_points);
	for (int q = 0; q < p_points; q++) {
		int *order = &r_order[size_t(q) * n];
		for (int k = 0; k < n; k++) {
			order[k] = k;
		}
		if (p_stratified && q > 0) {
			for (int k = n - 1; k > 0; k--) {
				const int j = int(r_rng.next_u32() % uint32_t(k + 1));
				std::swap(order[k], order[j]);
			}
		}
	}
	double points[16];
	for (int k = 0; k < n; k++) {
		for (int q = 0; q < p_points; q++) {
			if (p_stratified) {
				const int cell = r_order[size_t(q) * n + k];
				points[q * 2 + 0] = (double(cell % p_strata) + r_rng.next_double()) * inv;
				points[q * 2 + 1] = (double(cell / p_strata) + r_rng.next_double()) * inv;
			} else {
				points[q * 2 + 0] = r_rng.next_double();
				points[q * 2 + 1] = r_rng.next_double();
			}
		}
		p_integrand(points, r_tmp.data());
		for (int c = 0; c < p_channels; c++) {
			r_round[c] += r_tmp[c];
		}
	}
	for (int c = 0; c < p_channels; c++) {
		r_round[c] /= double(n);
	}
	return n;
}

// The adaptive loop shared by both integrand kinds: p_round(round) fills one round's estimate and
// returns its sample count.
template <typename RoundFunc>
static AdaptiveIntegrationResult _integrate_rounds(const RoundFunc &p_round, int p_channels, const AdaptiveIntegrationSettings &p_settings) {
	AdaptiveIntegrationResult result;
	const int per_round = p_settings.strata_per_axis * p_settings.strata_per_axis;
	const int min_rounds = std::max(2, p_settings.min_rounds);
	// At least min_rounds rounds even if that exceeds max_samples: fewer cannot estimate the error.
	const int max_rounds = std::max(min_rounds, p_settings.max_samples / per_round);

	// Welford's running mean and sum of squared deviations of the round estimates, per channel.
	std::vector<double> mean(p_channels, 0.0), m2(p_channels, 0.0), round(p_channels);
	result.value.assign(p_channels, 0.0);
	result.standard_error.assign(p_channels, 0.0);

	for (int r = 0; r < max_rounds; r++) {
		result.samples += p_round(round);
		result.rounds = r + 1;
		for (int c = 0; c < p_channels; c++) {
			double delta = round[c] - mean[c];
			mean[c] += delta / double(r + 1);
			m2[c] += delta * (round[c] - mean[c]);
		}
		if (result.rounds < min_rounds) {
			continue;
		}
		bool done = true;
		double rel_max = 0.0;
		for (int c = 0; c < p_channels; c++) {
			double se = std::sqrt(m2[c] / double(result.rounds - 1) / double(result.rounds));
			result.standard_error[c] = se;
			if (se <= p_settings.absolute_error_floor) {
				continue;
			}
			double rel = std::fabs(mean[c]) > 0.0 ? se / std::fabs(mean[c]) : INFINITY;
			rel_max = std::max(rel_max, rel);
			if (rel > p_settings.target_relative_error) {
				done = false;
			}
		}
		result.relative_error = rel_max;
		if (done) {
			result.converged = true;
			break;
		}
	}
	result.value = mean;
	return result;
}

AdaptiveIntegrationResult integrate_adaptive(const ReferenceIntegrand &p_integrand, int p_channels, const AdaptiveIntegrationSettings &p_settings, ReferenceRNG &r_rng) {
	AdaptiveIntegrationResult result;
	ERR_FAIL_COND_V_MSG(!p_integrand, result, "integrate_adaptive: the integrand is empty.");
	ERR_FAIL_COND_V_MSG(p_channels <= 0 || p_channels > 64, result, "integrate_adaptive: channel count must be 1..64.");
	ERR_FAIL_COND_V_MSG(p_settings.strata_per_axis < 1, result, "integrate_adaptive: strata_per_axis must be >= 1.");
	ERR_FAIL_COND_V_MSG(!(p_settings.target_relative_error >= 0.0), result, "integrate_adaptive: target_relative_error must be >= 0.");
	std::vector<double> tmp(p_channels);
	auto round = [&](std::vector<double> &r_round) {
		return _run_round(p_integrand, p_channels, p_settings.strata_per_axis, p_settings.stratified, r_rng, r_round, tmp);
	};
	return _integrate_rounds(round, p_channels, p_settings);
}

AdaptiveIntegrationResult integrate_adaptive_points(const ReferenceIntegrandPoints &p_integrand, int p_point_count, int p_channels, const AdaptiveIntegrationSettings &p_settings, ReferenceRNG &r_rng) {
	AdaptiveIntegrationResult result;
	ERR_FAIL_COND_V_MSG(!p_integrand, result, "integrate_adaptive_points: the integrand is empty.");
	ERR_FAIL_COND_V_MSG(p_point_count < 1 || p_point_count > 8, result, "integrate_adaptive_points: point count must be 1..8.");
	ERR_FAIL_COND_V_MSG(p_channels <= 0 || p_channels > 64, result, "integrate_adaptive_points: channel count must be 1..64.");
	ERR_FAIL_COND_V_MSG(p_settings.strata_per_axis < 1 || p_settings.strata_per_axis > 1024, result, "integrate_adaptive_points: strata_per_axis must be 1..1024.");
	ERR_FAIL_COND_V_MSG(!(p_settings.target_relative_error >= 0.0), result, "integrate_adaptive_points: target_relative_error must be >= 0.");
	std::vector<double> tmp(p_channels);
	std::vector<int> order;
	auto round = [&](std::vector<double> &r_round) {
		return _run_round_points(p_integrand, p_point_count, p_channels, p_settings.strata_per_axis, p_settings.stratified, r_rng, r_round, tmp, order);
	};
	return _integrate_rounds(round, p_channels, p_settings);
}

std::vector<double> integrate_fixed(const ReferenceIntegrand &p_integrand, int p_channels, int p_sample_count, bool p_stratified, ReferenceRNG &r_rng) {
	std::vector<double> sum(std::max(p_channels, 0), 0.0);
	ERR_FAIL_COND_V_MSG(!p_integrand, sum, "integrate_fixed: the integrand is empty.");
	ERR_FAIL_COND_V_MSG(p_channels <= 0 || p_channels > 64, sum, "integrate_fixed: channel count must be 1..64.");
	ERR_FAIL_COND_V_MSG(p_sample_count <= 0, sum, "integrate_fixed: sample count must be positive.");
	std::vector<double> tmp(p_channels);
	int grid = p_stratified ? int(std::floor(std::sqrt(double(p_sample_count)))) : 0;
	while (grid > 0 && grid * grid > p_sample_count) {
		grid--;
	}
	int taken = 0;
	for (int j = 0; j < grid; j++) {
		for (int i = 0; i < grid; i++) {
			double u = (double(i) + r_rng.next_double()) / double(grid);
			double v = (double(j) + r_rng.next_double()) / double(grid);
			p_integrand(u, v, tmp.data());
			for (int c = 0; c < p_channels; c++) {
				sum[c] += tmp[c];
			}
			taken++;
		}
	}
	for (; taken < p_sample_count; taken++) {
		double u = r_rng.next_double();
		double v = r_rng.next_double();
		p_integrand(u, v, tmp.data());
		for (int c = 0; c < p_channels; c++) {
			sum[c] += tmp[c];
		}
	}
	for (int c = 0; c < p_channels; c++) {
		sum[c] /= double(p_sample_count);
	}
	return sum;
}
