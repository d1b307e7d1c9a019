#!/usr/bin/env python3
"""Directional albedo of the specular lobe (the split sum's second factor) for the scene shader's BRDF
(servers/rendering/renderer_rd/shaders/brdf_inc.glsl: GGX D, Hammon 2017's fast Smith V, Schlick F), by
GGX importance sampling, beside Karis' analytic fit (brdf_env_approx, "Physically Based Shading on
Mobile", 2014) that the sky reflections use. doc/sun_sky.md quotes its output.

Usage: misc/scripts/env_brdf_check.py [f0]   (default 0.93, the metal of tests/servers/test_sky_reflections.cpp)
"""

import math
import sys


def karis_fit(f0, f90, no_v, roughness):
	c0 = (-1.0, -0.0275, -0.572, 0.022)
	c1 = (1.0, 0.0425, 1.04, -0.04)
	r = [roughness * c0[i] + c1[i] for i in range(4)]
	a004 = min(r[0] * r[0], 2.0 ** (-9.28 * no_v)) * r[0] + r[1]
	return f0 * (-1.04 * a004 + r[2]) + f90 * (1.04 * a004 + r[3])


def sampled(f0, f90, no_v, roughness, count=20000):
	alpha = roughness * roughness
	a2 = alpha * alpha
	v = (math.sqrt(1.0 - no_v * no_v), 0.0, no_v)
	total = 0.0
	side = int(math.sqrt(count))
	for i in range(side):
		for j in range(side):
			u = (i + 0.5) / side
			phi = 2.0 * math.pi * (j + 0.5) / side
			cos_h = math.sqrt((1.0 - u) / (1.0 + (a2 - 1.0) * u))
			sin_h = math.sqrt(max(0.0, 1.0 - cos_h * cos_h))
			h = (sin_h * math.cos(phi), sin_h * math.sin(phi), cos_h)
			vo_h = v[0] * h[0] + v[1] * h[1] + v[2] * h[2]
			if vo_h <= 0.0:
				continue
			no_l = 2.0 * vo_h * h[2] - v[2]
			if no_l <= 0.0:
				continue
			fresnel = f0 + (f90 - f0) * (1.0 - vo_h) ** 5
			vis = 0.5 / ((1.0 - alpha) * 2.0 * no_l * no_v + alpha * (no_l + no_v))
			total += fresnel * 4.0 * vis * no_l * vo_h / cos_h  # f (N.L) / pdf, D cancelled.
	return total / (side * side)


def main():
	f0 = float(sys.argv[1]) if len(sys.argv) > 1 else 0.93
	f90 = 1.0
	print("f0 %.3f, f90 %.1f: roughness, N.V, sampled (this BRDF), Karis fit, fit / sampled" % (f0, f90))
	for roughness in (0.05, 0.3, 0.6, 1.0):
		for no_v in (0.2, 0.5, 0.9):
			e = sampled(f0, f90, no_v, roughness)
			k = karis_fit(f0, f90, no_v, roughness)
			print("%.2f  %.1f  %.4f  %.4f  %.3f" % (roughness, no_v, e, k, k / e))


if __name__ == "__main__":
	main()
