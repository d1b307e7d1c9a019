/**************************************************************************/
/*  shadows_sweep.cpp                                                     */
/**************************************************************************/
/* godot-area: the area soft-shadow sweep (see the header).               */

#include "modules/benchmark/shadows_sweep.h"
#include "core/io/file_io.h"

#include "core/math/math_funcs.h"
#include "drivers/png/png_writer.h"
#include "modules/benchmark/penumbra_scene.h"
#include "modules/reference/renderer_compositor_reference.h"
#include "scene/main/godot_instance.h"
#include "servers/rendering_server.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

double visibility_rmse(const std::vector<float> &p_open, const std::vector<float> &p_shadowed, const std::vector<float> &p_ref_open, const std::vector<float> &p_ref_shadowed, int p_res) {
	double rmse = 1.0;
	PenumbraScene::visibility_error(p_open, p_shadowed, p_res, p_ref_open, p_ref_shadowed, p_res, p_res, 1, rmse);
	return rmse;
}

double shadow_pass_ms(const std::vector<std::pair<String, double>> &p_profile) {
	for (const std::pair<String, double> &e : p_profile) {
		if (e.first == "area_shadows") {
			return e.second;
		}
	}
	return -1.0;
}

} // namespace

int ShadowsSweep::subdivision_for_grid(int p_grid) {
	int s = 1;
	while (s < p_grid) {
		s *= 2;
	}
	return s;
}

// Visibility (clamped to [0, 1], unlit pixels black) as an 8-bit grey PNG, each pixel p_scale x p_scale.
static bool write_visibility_png(const std::vector<float> &p_visibility, int p_res, int p_scale, const String &p_path, String &r_error) {
	std::vector<uint8_t> px(size_t(p_res * p_scale) * size_t(p_res * p_scale) * 4);
	for (int y = 0; y < p_res * p_scale; y++) {
		for (int x = 0; x < p_res * p_scale; x++) {
			float v = p_visibility[size_t(y / p_scale) * p_res + x / p_scale];
			uint8_t c = uint8_t(std::lround(std::min(std::max(v, 0.0f), 1.0f) * 255.0f));
			size_t i = (size_t(y) * p_res * p_scale + x) * 4;
			px[i] = px[i + 1] = px[i + 2] = c;
			px[i + 3] = 255;
		}
	}
	return PNGWriter::save_rgba8(px, p_res * p_scale, p_res * p_scale, p_path, &r_error);
}

bool ShadowsSweep::_write_images(const Options &p_options, RenderingServer *p_rs, PenumbraScene &p_objects, GodotInstance &p_engine, const std::vector<float> &p_ref_open, const std::vector<float> &p_ref_shadowed, String &r_error) {
	const int res = p_options.resolution;
	if (p_engine.get_backend() != GodotInstance::BACKEND_RD) {
		r_error = "the images need the Forward+ renderer.";
		return false;
	}
	if (p_ref_open.empty()) {
		r_error = "--images needs the reference (drop --no-errors).";
		return false;
	}
	const RID light = p_objects.get_light();
	p_rs->area_shadow_atlas_set_size(p_objects.get_viewport(), 0, 0); // The renderer's default atlas.
	p_rs->light_set_param(light, RS::LIGHT_PARAM_SHADOW_BLUR, 1.0f); // The default.
	p_rs->light_set_shadow(light, false);
	std::vector<float> open = p_objects.render();
	const String dir = p_options.images_dir + "/";
	if (!write_visibility_png(PenumbraScene::visibility_image(p_ref_open, p_ref_shadowed), res, 2, dir + "penumbra_reference.png", r_error)) {
		return false;
	}
	struct Shot {
		const char *file;
		RS::LightAreaShadowMode mode;
		int grid;
		bool filter;
	};
	const Shot shots[5] = {
		{ "penumbra_pcss.png", RS::LIGHT_AREA_SHADOW_PCSS_BASELINE, 2, true },
		{ "penumbra_9_pcf.png", RS::LIGHT_AREA_SHADOW_FIXED, 3, false },
		{ "penumbra_9_filtered.png", RS::LIGHT_AREA_SHADOW_FIXED, 3, true },
		{ "penumbra_25_pcf.png", RS::LIGHT_AREA_SHADOW_FIXED, 5, false },
		{ "penumbra_25_filtered.png", RS::LIGHT_AREA_SHADOW_FIXED, 5, true },
	};
	p_rs->light_set_shadow(light, true);
	for (const Shot &shot : shots) {
		p_rs->light_area_set_shadow_mode(light, shot.mode);
		p_rs->light_area_set_shadow_grid(light, shot.grid);
		p_rs->area_shadow_filter_set_mode(shot.filter ? RS::AREA_SHADOW_FILTER_PENUMBRA : RS::AREA_SHADOW_FILTER_PCF);
		std::vector<float> shadowed = p_objects.render();
		std::vector<float> v = PenumbraScene::visibility_image(open, shadowed);
		PenumbraScene::ShadowError e = PenumbraScene::shadow_error(open, shadowed, res, p_ref_open, p_ref_shadowed, res, res, 1);
		int penumbra = 0;
		int banded = PenumbraScene::count_banded_pixels(v, res, res, &penumbra);
		printf("%s: visibility rel-RMSE %.4f, p99 relative error %.3f (%d shadow pixels), banded %d of %d penumbra pixels\n", shot.file, e.rel_rmse, e.p99, e.pixels, banded, penumbra);
		if (!write_visibility_png(v, res, 2, dir + shot.file, r_error)) {
			p_rs->area_shadow_filter_set_mode(RS::AREA_SHADOW_FILTER_PENUMBRA);
			return false;
		}
	}
	p_rs->area_shadow_filter_set_mode(RS::AREA_SHADOW_FILTER_PENUMBRA);
	return true;
}

bool ShadowsSweep::run(const Options &p_options, std::vector<Row> &r_rows, String *r_error) {
	auto fail = [&](const String &p_message) {
		if (r_error) {
			*r_error = p_message;
		}
		return false;
	};
	const int res = p_options.resolution;
	if (res < 8 || res > 1024) {
		return fail(vformat("resolution %d is out of range (8..1024).", res));
	}

	// 1. The reference, open and with shadow rays: the same scene through the server, drawn by the
	// Embree reference compositor.
	std::vector<float> ref_open, ref_shadowed;
	if (p_options.errors) {
		ReferenceRenderOptions options;
		options.threads = 0;
		options.target_relative_error = p_options.reference_error;
		options.max_samples = 4096;
		RendererCompositorReference *compositor = new RendererCompositorReference(options);
		GodotInstance reference;
		String error;
		if (!reference.start_with_compositor(compositor, &error)) {
			return fail(error);
		}
		PenumbraScene objects;
		if (!objects.create_in_server(reference.get_rendering_server(), res, res)) {
			return fail("the reference scene could not be created.");
		}
		ref_open = objects.render();
		options.shadows = true;
		compositor->get_reference_renderer()->set_options(options);
		ref_shadowed = objects.render();
		objects.free();
		if (p_options.progress) {
			printf("[reference] %dx%d done\n", res, res);
			fflush(stdout);
		}
	}

	// 2. The engine.
	String error;
	GodotInstance engine;
	if (!engine.start(GodotInstance::BACKEND_RD, &error, 8)) {
		return fail(error);
	}
	RenderingServer *rs = engine.get_rendering_server();
	bool ok = true;
	{
		PenumbraScene objects;
		if (!objects.create_in_server(rs, res, res)) {
			ok = false;
			error = "The scene could not be created.";
		}
		const RID viewport = objects.get_viewport();
		auto set_atlas = [&](int p_size, int p_subdivision) {
			rs->area_shadow_atlas_set_size(viewport, p_size, p_subdivision);
			if (rs->area_shadow_atlas_get_size(viewport) != p_size || rs->area_shadow_atlas_get_subdivision(viewport) != p_subdivision) {
				ok = false;
				error = vformat("atlas %d px with %d x %d tiles was rejected.", p_size, p_subdivision, p_subdivision);
			}
			return ok;
		};
		const RID light = objects.get_light();
		const Transform3D rest = PenumbraScene::light_transform(PenumbraScene::Settings());
		if (ok && !p_options.images_dir.empty()) {
			ok = _write_images(p_options, rs, objects, engine, ref_open, ref_shadowed, error);
			objects.free();
			engine.stop();
			return ok ? true : fail(error);
		}
		for (size_t a = 0; ok && a < p_options.atlas_sizes.size(); a++) {
			const int atlas = p_options.atlas_sizes[a];
			for (size_t g = 0; ok && g < p_options.grids.size(); g++) {
				const int grid = p_options.grids[g];
				const int sub = subdivision_for_grid(grid);
				if (!set_atlas(atlas, sub)) {
					break;
				}
				rs->light_area_set_shadow_mode(light, RS::LIGHT_AREA_SHADOW_FIXED);
				rs->light_area_set_shadow_grid(light, grid);
				objects.set_light_transform(rest);
				Row base;
				base.mode = "FIXED";
				base.atlas = atlas;
				base.subdivision = sub;
				base.tile = atlas / sub;
				base.maps = grid * grid;
				if (p_options.errors) {
					for (float blur : p_options.blurs) {
						rs->light_set_shadow(light, false);
						std::vector<float> open = objects.render();
						rs->light_set_param(light, RS::LIGHT_PARAM_SHADOW_BLUR, blur);
						rs->light_set_shadow(light, true);
						std::vector<float> shadowed = objects.render();
						const uint64_t maps = rs->get_rendering_info(RS::RENDERING_INFO_AREA_SHADOW_MAPS_IN_FRAME);
						if (maps != uint32_t(grid * grid)) {
							ok = false;
							error = vformat("the light got %llu maps instead of %d (atlas %d, subdivision %d).", (unsigned long long)maps, grid * grid, atlas, sub);
							break;
						}
						Row row = base;
						row.section = "error";
						row.blur = blur;
						row.visibility_rmse = visibility_rmse(open, shadowed, ref_open, ref_shadowed, res);
						r_rows.push_back(row);
						if (p_options.progress) {
							printf("[error] atlas %d tile %d maps %d blur %.0f: visibility RMSE %.4f\n", atlas, row.tile, row.maps, blur, row.visibility_rmse);
							fflush(stdout);
						}
					}
				}
				if (ok && p_options.timing) {
					// Timing twice: with the sweep's subdivision (fill grows with the tile area) and with a
					// fixed tile size (p_options.timing_subdivision), whose slope is the cost per map.
					const int subs[2] = { sub, p_options.timing_subdivision };
					for (int t = 0; t < 2 && ok; t++) {
						if (!set_atlas(atlas, subs[t])) {
							break;
						}
						rs->light_set_param(light, RS::LIGHT_PARAM_SHADOW_BLUR, 1.0f);
						rs->light_set_shadow(light, true);
						std::vector<double> ms;
						for (int frame = 0; frame < p_options.frames + 1; frame++) {
							Transform3D moved = rest;
							moved.origin.x = (frame % 2) ? 0.01f : 0.0f; // Every map redraws.
							objects.set_light_transform(moved);
							rs->draw();
							if (frame > 0) {
								ms.push_back(shadow_pass_ms(rs->get_frame_profile()));
							}
						}
						std::sort(ms.begin(), ms.end());
						Row row = base;
						row.section = t == 0 ? "timing" : "timing_fixed_tile";
						row.subdivision = subs[t];
						row.tile = atlas / subs[t];
						row.blur = 1.0f;
						row.shadow_ms = ms.empty() ? -1.0 : ms[ms.size() / 2];
						r_rows.push_back(row);
						if (p_options.progress) {
							printf("[%s] atlas %d tile %d maps %d: shadow pass %.2f ms (median of %d)\n", row.section.c_str(), atlas, row.tile, row.maps, row.shadow_ms, p_options.frames);
							fflush(stdout);
						}
					}
				}
			}
			// The one-map PCSS baseline, in a tile of atlas / pcss_subdivision (its blocker search and filter are
			// capped in texels, 24 and 32, so it gets worse, not better, in bigger tiles; see doc/shadows.md).
			if (ok && p_options.errors) {
				if (!set_atlas(atlas, p_options.pcss_subdivision)) {
					break;
				}
				rs->light_area_set_shadow_mode(light, RS::LIGHT_AREA_SHADOW_PCSS_BASELINE);
				objects.set_light_transform(rest);
				for (float blur : p_options.blurs) {
					rs->light_set_shadow(light, false);
					std::vector<float> open = objects.render();
					rs->light_set_param(light, RS::LIGHT_PARAM_SHADOW_BLUR, blur);
					rs->light_set_shadow(light, true);
					std::vector<float> shadowed = objects.render();
					Row row;
					row.section = "error";
					row.mode = "PCSS";
					row.atlas = atlas;
					row.subdivision = p_options.pcss_subdivision;
					row.tile = atlas / p_options.pcss_subdivision;
					row.maps = 1;
					row.blur = blur;
					row.visibility_rmse = visibility_rmse(open, shadowed, ref_open, ref_shadowed, res);
					r_rows.push_back(row);
				}
			}
		}
		objects.free();
	}
	engine.stop();
	return ok ? true : fail(error);
}

bool ShadowsSweep::write_csv(const String &p_path, const std::vector<Row> &p_rows, String *r_error) {
	FileWriteBuffer out; // Written atomically by commit(): no partial CSV on a full disk.
	FILE *f = out.file();
	if (!f) {
		if (r_error) {
			*r_error = "cannot write " + p_path + ": out of memory";
		}
		return false;
	}
	fprintf(f, "section,mode,atlas,subdivision,tile,maps,blur,visibility_rmse,shadow_ms\n");
	for (const Row &r : p_rows) {
		fprintf(f, "%s,%s,%d,%d,%d,%d,%g,%.6f,%.4f\n", r.section.c_str(), r.mode.c_str(), r.atlas, r.subdivision, r.tile, r.maps, double(r.blur), r.visibility_rmse, r.shadow_ms);
	}
	return out.commit(p_path, r_error);
}
