/**************************************************************************/
/*  color.h                                                               */
/**************************************************************************/
/* RGBA colour. Scene files store sRGB-encoded colours (Godot's Color);   */
/* the renderer converts to linear once, in light storage.                */

#pragma once

#include "core/math/math_funcs.h"

struct Color {
	float r = 0;
	float g = 0;
	float b = 0;
	float a = 1;

	float &operator[](int p_i) { return p_i == 0 ? r : (p_i == 1 ? g : (p_i == 2 ? b : a)); }
	const float &operator[](int p_i) const { return p_i == 0 ? r : (p_i == 1 ? g : (p_i == 2 ? b : a)); }

	// IEC 61966-2-1 sRGB transfer functions.
	static float srgb_to_linear_channel(float p_c) { return p_c < 0.04045f ? p_c * (1.0f / 12.92f) : std::pow((p_c + 0.055f) * (1.0f / 1.055f), 2.4f); }
	static float linear_to_srgb_channel(float p_c) { return p_c < 0.0031308f ? 12.92f * p_c : 1.055f * std::pow(p_c, 1.0f / 2.4f) - 0.055f; }
	Color srgb_to_linear() const { return Color(srgb_to_linear_channel(r), srgb_to_linear_channel(g), srgb_to_linear_channel(b), a); }
	Color linear_to_srgb() const { return Color(linear_to_srgb_channel(r), linear_to_srgb_channel(g), linear_to_srgb_channel(b), a); }

	bool is_equal_approx(const Color &p_c) const {
		return Math::is_equal_approx(r, p_c.r) && Math::is_equal_approx(g, p_c.g) && Math::is_equal_approx(b, p_c.b) && Math::is_equal_approx(a, p_c.a);
	}
	bool is_finite() const { return Math::is_finite(r) && Math::is_finite(g) && Math::is_finite(b) && Math::is_finite(a); }

	Color operator*(float p_s) const { return Color(r * p_s, g * p_s, b * p_s, a * p_s); }
	Color operator*(const Color &p_c) const { return Color(r * p_c.r, g * p_c.g, b * p_c.b, a * p_c.a); }
	Color operator+(const Color &p_c) const { return Color(r + p_c.r, g + p_c.g, b + p_c.b, a + p_c.a); }
	bool operator==(const Color &p_c) const { return r == p_c.r && g == p_c.g && b == p_c.b && a == p_c.a; }
	bool operator!=(const Color &p_c) const { return !(*this == p_c); }

	Color() {}
	Color(float p_r, float p_g, float p_b, float p_a = 1.0f) :
			r(p_r), g(p_g), b(p_b), a(p_a) {}
};
