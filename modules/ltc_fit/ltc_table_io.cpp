/**************************************************************************/
/*  ltc_table_io.cpp                                                      */
/**************************************************************************/
/* godot-area: LTC table include writer/reader (see ltc_table_io.h).      */

#include "modules/ltc_fit/ltc_table_io.h"

#include "core/error/error_macros.h"
#include "core/io/file_io.h"
#include "modules/ltc_fit/ltc_fitter.h"

#include "servers/rendering/renderer_rd/ltc_lut_data.inc"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

const char *LTCTableIO::DEFAULT_INC_PATH = "servers/rendering/renderer_rd/ltc_lut_data.inc";

int LTCTableIO::get_builtin_size() {
	return LTC_LUT_SIZE;
}

const float *LTCTableIO::get_builtin_table(LTCBRDFVariant p_variant) {
	ERR_FAIL_INDEX_V_MSG((int)p_variant, (int)LTC_BRDF_MAX, nullptr, "Unknown LTC BRDF variant.");
	return p_variant == LTC_BRDF_ENGINE_GGX ? LTC_LUT_ENGINE_GGX : LTC_LUT_SMITH_GGX;
}

String LTCTableIO::format_array(const char *p_name, int p_size, int p_floats_per_cell, const std::vector<float> &p_table) {
	ERR_FAIL_COND_V_MSG(p_table.size() != (size_t)p_size * p_size * p_floats_per_cell, String(), "LTC table has the wrong size.");
	std::ostringstream o;
	o << "static const float " << p_name << "[" << p_size << " * " << p_size << " * " << p_floats_per_cell << "] = {\n";
	char buf[64];
	for (int t = 0; t < p_size; t++) {
		for (int r = 0; r < p_size; r++) {
			const float *cell = &p_table[((size_t)t * p_size + r) * p_floats_per_cell];
			o << "\t";
			for (int k = 0; k < p_floats_per_cell; k++) {
				snprintf(buf, sizeof(buf), "%.9g", (double)cell[k]);
				String s = buf;
				// "%.9g" may print an integer ("1", "-0"); give it a ".0" so that the "f" suffix makes a valid literal.
				if (s.find_first_of(".e") == String::npos && s.find("inf") == String::npos && s.find("nan") == String::npos) {
					s += ".0";
				}
				o << s << "f" << (k < p_floats_per_cell - 1 ? ", " : ",");
			}
			o << " // t " << t << ", r " << r << "\n";
		}
	}
	o << "};\n";
	return o.str();
}

String LTCTableIO::format_inc(int p_size, const std::vector<float> &p_engine, const std::vector<float> &p_smith, const String &p_command, const String &p_stats) {
	const size_t n = (size_t)p_size * p_size * 8;
	ERR_FAIL_COND_V_MSG(p_size < 2, String(), "LTC table size must be at least 2.");
	ERR_FAIL_COND_V_MSG(p_engine.size() != n || p_smith.size() != n, String(), "LTC tables do not hold size^2 * 8 floats.");
	std::ostringstream o;
	o << "/**************************************************************************/\n";
	o << "/*  ltc_lut_data.inc                                                      */\n";
	o << "/**************************************************************************/\n";
	o << "/* GENERATED FILE, do not edit: godot-area LTC lookup tables (thesis\n";
	o << " * section 5.4, Heitz, Dupuy, Hill and Neubelt 2016), written by\n";
	o << " * modules/ltc_fit with the command:\n";
	o << " *   " << p_command << "\n";
	o << " *\n";
	o << " * Fit statistics:\n";
	std::istringstream stats(p_stats);
	String line;
	while (std::getline(stats, line)) {
		o << " *   " << line << "\n";
	}
	o << " *\n";
	o << " * TABLES: LTC_LUT_ENGINE_GGX fits the engine's lobe (servers/rendering/renderer_rd/shaders/brdf_inc.glsl: D_GGX *\n";
	o << " * V_SmithGGXCorrelatedFast, F = 1); LTC_LUT_SMITH_GGX fits GGX with the exact\n";
	o << " * height-correlated Smith G2 (Heitz 2014). Both: alpha = max(r^2, " << LTCFitter::MIN_ALPHA << ").\n";
	o << " *\n";
	o << " * LAYOUT: N = LTC_LUT_SIZE; cell (ti, ri) starts at float (ti * N + ri) * 8; row = view-angle\n";
	o << " * index ti, column = roughness index ri (as a texture: x = roughness, y = view angle, two\n";
	o << " * RGBA32F texels per cell or two textures (a, b, c, d) and (e, fn, fg, 0)).\n";
	o << " * The 8 floats of a cell: a, b, c, d, e, fn, fg, 0.\n";
	o << " *\n";
	o << " * PARAMETRISATION (cell centres sit exactly on the sample values):\n";
	o << " *   perceptual roughness r = ri / (N - 1)   (Godot material roughness; GGX alpha = r^2)\n";
	o << " *   u = ti / (N - 1) = sqrt(1 - cos(theta_v)), cos(theta_v) = dot(N, V)\n";
	o << " *   (the last row, u = 1, was fitted at theta_v = " << LTCFitter::MAX_THETA << " rad, not exactly pi / 2).\n";
	o << " * GLSL sampling of an N x N texture with linear filtering and clamp-to-edge:\n";
	o << " *   vec2 uv = vec2(roughness, sqrt(1.0 - NoV));\n";
	o << " *   uv = uv * (float(N - 1) / float(N)) + 0.5 / float(N);\n";
	o << " * (a texel centre (i + 0.5) / N then reads exactly cell i).\n";
	o << " *\n";
	o << " * MATRIX: M = [[a, 0, b], [0, c, 0], [d, 0, e]] (thesis eq. 5.6), NOT its inverse, in the\n";
	o << " * local frame z = surface normal, x = normalize(V - N NoV) (the view vector lies in the xz-plane\n";
	o << " * with x >= 0: V = (sin theta_v, 0, cos theta_v)), y = z cross x. M maps clamped-cosine\n";
	o << " * directions to lobe directions: D(l) = D_o(M^-1 l / |M^-1 l|) |M^-1| / |M^-1 l|^3, D_o = max(0, z) / pi.\n";
	o << " * The lobe leans to -x (mirror direction), so b <= 0 and d >= 0 in most cells; det M = c (a e - b d) > 0.\n";
	o << " * Invert at run time with eqs. 5.7-5.8: s = 1 / (a e - b d),\n";
	o << " *   M^-1 = [[s e, 0, -s b], [0, 1 / c, 0], [-s d, 0, s a]].\n";
	o << " * The scale of M is arbitrary (M and k M give the same distribution); here M's third column is\n";
	o << " * m13 X + Z with Z the lobe's dominant direction, X = Y x Z.\n";
	o << " *\n";
	o << " * FIT: per cell, Nelder-Mead minimises the L3 error integral |rho - D|^3 dl between the\n";
	o << " * normalised lobe rho = f cos(theta_l) / fn and D (Heitz et al. 2016; thesis section 5.4.1),\n";
	o << " * estimated with fixed stratified samples (" << LTCFitter::FIT_SAMPLES << "^2 from the GGX visible normals + "
	  << LTCFitter::FIT_SAMPLES << "^2 from the LTC,\n";
	o << " * balance heuristic), over m11, m22, m13 of M = [X Y Z] [[m11, 0, m13], [0, m22, 0], [0, 0, 1]],\n";
	o << " * Z = the lobe's average direction (isotropic m11 = m22, m13 = 0 on row ti = 0). Each row ti is\n";
	o << " * one chain from ri = N - 1 (start m11 = m22 = 1, m13 = 0) down to ri = 0; every other cell starts\n";
	o << " * from the stored floats of cell ri + 1. fn, fg and Z use " << LTCFitter::ALBEDO_SAMPLES << "^2 visible-normal samples.\n";
	o << " * Deterministic: the same build writes the same file for any thread count.\n";
	o << " *\n";
	o << " * FRESNEL (thesis eq. 5.10): fn = integral f cos dl (directional albedo with F = 1),\n";
	o << " * fg = integral f cos (1 - dot(V, H))^5 dl, so the integrated specular Fresnel is\n";
	o << " *   F = f0 * fn + (f90 - f0) * fg.\n";
	o << " */\n\n";
	o << "#pragma once\n\n";
	o << "static const int LTC_LUT_SIZE = " << p_size << ";\n\n";
	o << format_array("LTC_LUT_ENGINE_GGX", p_size, 8, p_engine);
	o << "\n";
	o << format_array("LTC_LUT_SMITH_GGX", p_size, 8, p_smith);
	return o.str();
}

bool LTCTableIO::save_inc(const String &p_path, const String &p_text) {
	ERR_FAIL_COND_V_MSG(p_text.empty(), false, "Refusing to write an empty LTC table include.");
	String error; // Atomic and checked through close (core/io/file_io.h): no partial table on failure.
	ERR_FAIL_COND_V_MSG(!file_write_atomic(p_path, p_text, &error), false, error);
	return true;
}

static bool _parse_array(const String &p_text, const char *p_name, size_t p_count, std::vector<float> *r_values, String *r_error) {
	const size_t at = p_text.find(String(p_name) + "[");
	if (at == String::npos) {
		*r_error = vformat("Array %s not found.", p_name);
		return false;
	}
	size_t pos = p_text.find('{', at);
	const size_t end = p_text.find('}', at);
	if (pos == String::npos || end == String::npos || end < pos) {
		*r_error = vformat("Array %s has no initialiser.", p_name);
		return false;
	}
	r_values->clear();
	r_values->reserve(p_count);
	const char *s = p_text.c_str() + pos + 1;
	const char *stop = p_text.c_str() + end;
	while (s < stop) {
		if (*s == '/' && s + 1 < stop && s[1] == '/') {
			while (s < stop && *s != '\n') {
				s++;
			}
			continue;
		}
		if (std::strchr(" \t\r\n,f", *s)) {
			s++;
			continue;
		}
		char *next = nullptr;
		float v = std::strtof(s, &next);
		if (next == s) {
			*r_error = vformat("Array %s: unexpected character '%c'.", p_name, *s);
			return false;
		}
		r_values->push_back(v);
		s = next;
	}
	if (r_values->size() != p_count) {
		*r_error = vformat("Array %s holds %d floats, expected %d.", p_name, (int)r_values->size(), (int)p_count);
		return false;
	}
	return true;
}

bool LTCTableIO::parse_inc(const String &p_text, int *r_size, std::vector<float> *r_engine, std::vector<float> *r_smith, String *r_error) {
	String dummy;
	String *err = r_error ? r_error : &dummy;
	const char *key = "LTC_LUT_SIZE = ";
	const size_t at = p_text.find(key);
	if (at == String::npos) {
		*err = "LTC_LUT_SIZE not found.";
		return false;
	}
	const int size = std::atoi(p_text.c_str() + at + std::strlen(key));
	if (size < 2 || size > 1024) {
		*err = vformat("Bad LTC_LUT_SIZE %d.", size);
		return false;
	}
	const size_t n = (size_t)size * size * 8;
	if (!_parse_array(p_text, "LTC_LUT_ENGINE_GGX", n, r_engine, err) || !_parse_array(p_text, "LTC_LUT_SMITH_GGX", n, r_smith, err)) {
		return false;
	}
	*r_size = size;
	return true;
}

bool LTCTableIO::load_inc(const String &p_path, int *r_size, std::vector<float> *r_engine, std::vector<float> *r_smith, String *r_error) {
	std::ifstream f(p_path, std::ios::binary);
	if (!f) {
		if (r_error) {
			*r_error = vformat("Cannot open '%s'.", p_path.c_str());
		}
		return false;
	}
	std::stringstream ss;
	ss << f.rdbuf();
	return parse_inc(ss.str(), r_size, r_engine, r_smith, r_error);
}
