/**************************************************************************/
/*  isr_sweep.cpp                                                         */
/**************************************************************************/

#include "modules/benchmark/isr_sweep.h"

#include "core/io/image.h"
#include "modules/metrics/image_metrics.h"
#include "servers/rendering/dummy/storage/light_storage.h"
#include "servers/rendering/dummy/storage/material_storage.h"
#include "servers/rendering/dummy/storage/mesh_storage.h"
#include "servers/rendering/renderer_rd/forward_clustered/render_forward_clustered.h"
#include "servers/rendering/renderer_rd/storage_rd/light_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/material_storage.h"
#include "servers/rendering/renderer_rd/storage_rd/mesh_storage.h"

#include <cmath>

ScreenSpaceLightingSettings IsrSweep::default_settings() {
	ScreenSpaceLightingSettings s;
	s.ssil_enabled = true;
	return s;
}

ReferenceRenderOptions IsrSweep::truth_options(int p_bounce_samples) {
	ReferenceRenderOptions o;
	o.bounces = 1;
	o.bounce_samples = p_bounce_samples;
	o.bounce_light_samples = 4;
	o.max_samples = 256;
	o.target_relative_error = 0.01f;
	o.shadows = false; // As the GPU renderer (no area shadows in these scenes).
	return o;
}

bool IsrSweep::render_gpu(const IsrScene &p_scene, int p_frame, int p_width, int p_height, const ScreenSpaceLightingSettings &p_settings, IsrImages &r_images, String *r_error) {
	RenderingDevice *rd = RenderingDevice::get_singleton();
	if (!rd || !rd->is_initialized()) {
		if (r_error) {
			*r_error = "IsrSweep: no initialized RenderingDevice (Vulkan) for the Forward+ renderer.";
		}
		return false;
	}
	bool ok = true;
	{
		RendererRD::LightStorage light_storage;
		RendererRD::MeshStorage mesh_storage;
		RendererRD::MaterialStorage material_storage;
		RenderForwardClustered renderer(&light_storage, &mesh_storage, &material_storage);
		ok = material_storage.initialize_gpu() && light_storage.initialize_gpu(64) && renderer.initialize(64);
		std::vector<RID> meshes, materials, lights;
		RID rt;
		if (ok) {
			RenderSceneData d = p_scene.make_view(p_frame, p_width, p_height);
			p_scene.build(mesh_storage, material_storage, light_storage, d, meshes, materials, lights);
			rt = renderer.render_target_create(p_width, p_height);
			ok = rt.is_valid();
			if (ok) {
				renderer.render_scene(d, rt);
				r_images.direct = renderer.render_target_get_data(rt);
				d.environment.ss_lighting = p_settings;
				renderer.render_scene(d, rt);
				r_images.isr = renderer.render_target_get_data(rt);
				ok = r_images.direct.size() == size_t(p_width) * p_height * 4 && r_images.isr.size() == r_images.direct.size();
				renderer.render_target_free(rt);
			}
		}
		for (RID m : meshes) {
			mesh_storage.mesh_free(m);
		}
		for (RID m : materials) {
			material_storage.material_free(m);
		}
		for (RID l : lights) {
			light_storage.light_free(l);
		}
		renderer.finalize();
		light_storage.finalize_gpu();
		material_storage.finalize_gpu();
	}
	if (!ok && r_error) {
		*r_error = "IsrSweep: the Forward+ renderer failed to render the frame.";
	}
	r_images.width = p_width;
	r_images.height = p_height;
	return ok;
}

bool IsrSweep::render_truth(const IsrScene &p_scene, int p_frame, int p_width, int p_height, const ReferenceRenderOptions &p_options, IsrImages &r_images, String *r_error) {
	RendererDummy::LightStorage light_storage;
	RendererDummy::MeshStorage mesh_storage;
	RendererDummy::MaterialStorage material_storage;
	std::vector<RID> meshes, materials, lights;
	bool ok = false;
	{
		ReferenceRenderer renderer(&light_storage, &mesh_storage, &material_storage, p_options);
		RenderSceneData d = p_scene.make_view(p_frame, p_width, p_height);
		p_scene.build(mesh_storage, material_storage, light_storage, d, meshes, materials, lights);
		RID rt = renderer.render_target_create(p_width, p_height);
		if (rt.is_valid()) {
			renderer.render_scene(d, rt);
			r_images.truth = renderer.render_target_get_data(rt);
			renderer.render_target_free(rt);
			ok = r_images.truth.size() == size_t(p_width) * p_height * 4;
		}
	}
	for (RID m : meshes) {
		mesh_storage.mesh_free(m);
	}
	for (RID m : materials) {
		material_storage.material_free(m);
	}
	for (RID l : lights) {
		light_storage.light_free(l);
	}
	if (!ok && r_error) {
		*r_error = "IsrSweep: the Embree reference failed to render the frame.";
	}
	r_images.width = p_width;
	r_images.height = p_height;
	return ok;
}

static Image _isr_to_image(const std::vector<float> &p_rgba, int p_w, int p_h) {
	Image img(p_w, p_h);
	for (int y = 0; y < p_h; y++) {
		for (int x = 0; x < p_w; x++) {
			const float *p = &p_rgba[(size_t(y) * p_w + x) * 4];
			img.set_pixel(x, y, Color(p[0], p[1], p[2], 1.0f));
		}
	}
	return img;
}

bool IsrSweep::evaluate(const IsrImages &p_images, IsrQuality &r_quality, String *r_error) {
	const int w = p_images.width, h = p_images.height;
	const size_t n = size_t(w) * h * 4;
	if (w <= 0 || h <= 0 || p_images.direct.size() != n || p_images.isr.size() != n || p_images.truth.size() != n) {
		if (r_error) {
			*r_error = vformat("IsrSweep::evaluate: the three images must be %dx%d RGBA.", w, h);
		}
		return false;
	}
	const Image truth = _isr_to_image(p_images.truth, w, h);
	ImageMetrics::Options options;
	options.hdr_flip = false;
	ImageMetrics::Result dl, isr;
	if (!ImageMetrics::compare(_isr_to_image(p_images.direct, w, h), truth, &dl, r_error, options) || !ImageMetrics::compare(_isr_to_image(p_images.isr, w, h), truth, &isr, r_error, options)) {
		return false;
	}
	r_quality = IsrQuality();
	r_quality.mean_error_dl = dl.mae;
	r_quality.mean_error_isr = isr.mae;
	r_quality.mean_error_gain = dl.mae > 0.0 ? (dl.mae - isr.mae) / dl.mae : 0.0;
	r_quality.pearson_dl = dl.pearson;
	r_quality.pearson_isr = isr.pearson;
	r_quality.quality = isr.mae < dl.mae ? 1 : (isr.mae > dl.mae ? -1 : 0); // Eq. 21 with I_1 = ISR, I_2 = DL.
	for (size_t i = 0; i < n; i += 4) {
		const float *d = &p_images.direct[i], *s = &p_images.isr[i], *t = &p_images.truth[i];
		const double lt = ImageMetrics::luminance(t[0], t[1], t[2]), ld = ImageMetrics::luminance(d[0], d[1], d[2]);
		if (lt - ld <= INDIRECT_RELATIVE * lt + INDIRECT_ABSOLUTE) {
			continue;
		}
		r_quality.indirect_pixels++;
		double e_dl = 0.0, e_isr = 0.0; // Eq. 19 for one pixel (the three channels).
		for (int c = 0; c < 3; c++) {
			e_dl += std::fabs(double(t[c]) - double(d[c]));
			e_isr += std::fabs(double(t[c]) - double(s[c]));
		}
		r_quality.improved_pixels += e_isr < e_dl ? 1 : 0;
	}
	r_quality.improved_share = r_quality.indirect_pixels > 0 ? double(r_quality.improved_pixels) / r_quality.indirect_pixels : 0.0;
	return true;
}
