/**************************************************************************/
/*  shadows_sweep.cpp                                                     */
/**************************************************************************/
/* godot-area: the area soft-shadow sweep (see the header).               */

#include "modules/benchmark/shadows_sweep.h"
#include "core/io/file_io.h"

#include "core/math/math_funcs.h"
#include "modules/benchmark/penumbra_scene.h"
#include "modules/reference/reference_renderer.h"
#include "servers/rendering/dummy/storage/light_storage.h"
#include "servers/rendering/dummy/storage/material_storage.h"
#include "servers/rendering/dummy/storage/mesh_storage.h"
#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

double visibility_rmse(const std::vector<float> &p_open, const std::vector<float> &p_shadowed, const std::vector<float> &p_ref_open, const std::vector<float> &p_ref_shadowed, int p_res) {
	double rmse = 1.0;
	PenumbraScene::visibility_error(p_open, p_shadowed, p_res, p_ref_open, p_ref_shadowed, p_res, p_res, 1, rmse);
	return rmse;
}

double shadow_pass_ms(const RenderForwardClustered &p_renderer) {
	for (const std::pair<String, double> &e : p_renderer.get_last_frame_profile()) {
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

	// 1. The reference, open and with shadow rays.
	std::vector<float> ref_open, ref_shadowed;
	if (p_options.errors) {
		RendererDummy::LightStorage ls;
		RendererDummy::MeshStorage ms;
		RendererDummy::MaterialStorage mats;
		ReferenceRenderOptions options;
		options.threads = 0;
		options.target_relative_error = p_options.reference_error;
		options.max_samples = 4096;
		ReferenceRenderer ref(&ls, &ms, &mats, options);
		RenderSceneData d = PenumbraScene::make_top_view(res);
		PenumbraScene objects;
		if (!objects.create(&ls, &ms, &mats, d)) {
			return fail("the reference scene could not be created.");
		}
		RID rt = ref.render_target_create(res, res);
		ref.render_scene(d, rt);
		ref_open = ref.render_target_get_data(rt);
		options.shadows = true;
		ref.set_options(options);
		ref.render_scene(d, rt);
		ref_shadowed = ref.render_target_get_data(rt);
		ref.render_target_free(rt);
		objects.free();
		if (p_options.progress) {
			printf("[reference] %dx%d done\n", res, res);
			fflush(stdout);
		}
	}

	// 2. The engine.
	String error;
	RenderingDevice *owned_device = nullptr;
	if (!RenderingDevice::get_singleton()) {
		owned_device = new RenderingDevice;
		if (!owned_device->initialize(&error)) {
			delete owned_device;
			return fail("No usable Vulkan device: " + error);
		}
	}
	bool ok = true;
	{
		RendererRD::LightStorage light_storage;
		RendererRD::MeshStorage mesh_storage;
		RendererRD::MaterialStorage material_storage;
		RenderForwardClustered renderer(&light_storage, &mesh_storage, &material_storage);
		if (!(material_storage.initialize_gpu() && light_storage.initialize_gpu(8) && renderer.initialize(8))) {
			ok = false;
			error = "The Forward+ renderer could not be initialized (see the errors above).";
		}
		RenderSceneData scene = PenumbraScene::make_top_view(res);
		PenumbraScene objects;
		RID rt;
		if (ok && !objects.create(&light_storage, &mesh_storage, &material_storage, scene)) {
			ok = false;
			error = "The scene could not be created.";
		}
		if (ok) {
			rt = renderer.render_target_create(res, res);
			ok = rt.is_valid();
			error = ok ? String() : String("The render target could not be created.");
		}
		auto render = [&]() {
			renderer.render_scene(scene, rt);
			return renderer.render_target_get_data(rt);
		};
		const RID light = objects.get_light();
		const Transform3D rest = PenumbraScene::light_transform(PenumbraScene::Settings());
		for (size_t a = 0; ok && a < p_options.atlas_sizes.size(); a++) {
			const int atlas = p_options.atlas_sizes[a];
			for (size_t g = 0; ok && g < p_options.grids.size(); g++) {
				const int grid = p_options.grids[g];
				const int sub = subdivision_for_grid(grid);
				if (!renderer.area_shadow_atlas_set_size(atlas, sub)) {
					ok = false;
					error = vformat("atlas %d px with %d x %d tiles was rejected.", atlas, sub, sub);
					break;
				}
				light_storage.light_area_set_shadow_mode(light, RS::LIGHT_AREA_SHADOW_FIXED);
				light_storage.light_area_set_shadow_grid(light, grid);
				scene.lights[0].transform = rest;
				Row base;
				base.mode = "FIXED";
				base.atlas = atlas;
				base.subdivision = sub;
				base.tile = atlas / sub;
				base.maps = grid * grid;
				if (p_options.errors) {
					for (float blur : p_options.blurs) {
						light_storage.light_set_shadow(light, false);
						std::vector<float> open = render();
						light_storage.light_set_param(light, RS::LIGHT_PARAM_SHADOW_BLUR, blur);
						light_storage.light_set_shadow(light, true);
						std::vector<float> shadowed = render();
						uint32_t tiles = renderer.get_area_shadow_renderer().get_atlas().light_get_tile_count(light.get_id());
						if (tiles != uint32_t(grid * grid)) {
							ok = false;
							error = vformat("the light got %u maps instead of %d (atlas %d, subdivision %d).", tiles, grid * grid, atlas, sub);
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
						if (!renderer.area_shadow_atlas_set_size(atlas, subs[t])) {
							ok = false;
							error = vformat("atlas %d px with %d x %d tiles was rejected.", atlas, subs[t], subs[t]);
							break;
						}
						light_storage.light_set_param(light, RS::LIGHT_PARAM_SHADOW_BLUR, 1.0f);
						light_storage.light_set_shadow(light, true);
						std::vector<double> ms;
						for (int frame = 0; frame < p_options.frames + 1; frame++) {
							scene.lights[0].transform.origin.x = (frame % 2) ? 0.01f : 0.0f; // Every map redraws.
							renderer.render_scene(scene, rt);
							if (frame > 0) {
								ms.push_back(shadow_pass_ms(renderer));
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
				if (!renderer.area_shadow_atlas_set_size(atlas, p_options.pcss_subdivision)) {
					ok = false;
					error = vformat("atlas %d px with %d x %d tiles was rejected.", atlas, p_options.pcss_subdivision, p_options.pcss_subdivision);
					break;
				}
				light_storage.light_area_set_shadow_mode(light, RS::LIGHT_AREA_SHADOW_PCSS_BASELINE);
				scene.lights[0].transform = rest;
				for (float blur : p_options.blurs) {
					light_storage.light_set_shadow(light, false);
					std::vector<float> open = render();
					light_storage.light_set_param(light, RS::LIGHT_PARAM_SHADOW_BLUR, blur);
					light_storage.light_set_shadow(light, true);
					std::vector<float> shadowed = render();
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
		if (rt.is_valid()) {
			renderer.render_target_free(rt);
		}
		objects.free();
		renderer.finalize();
		light_storage.finalize_gpu();
		material_storage.finalize_gpu();
	}
	if (owned_device) {
		owned_device->finalize();
		delete owned_device;
	}
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
