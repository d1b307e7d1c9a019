/**************************************************************************/
/*  isr_sweep.cpp                                                         */
/**************************************************************************/

#include "modules/benchmark/isr_sweep.h"

#include "core/io/image.h"
#include "modules/metrics/image_metrics.h"
#include "modules/reference/renderer_compositor_reference.h"
#include "scene/main/godot_instance.h"

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

// The RenderingServer to draw with: the running engine's when it has p_backend, else p_own started
// here (with p_compositor for BACKEND_CUSTOM; owned from here on). Null with r_error otherwise.
static RenderingServer *_isr_server(GodotInstance &p_own, GodotInstance::Backend p_backend, RendererCompositor *p_compositor, String *r_error) {
	GodotInstance *running = GodotInstance::get_singleton();
	if (running && running->is_started()) {
		delete p_compositor;
		if (p_backend != GodotInstance::BACKEND_RD || running->get_backend() != p_backend) {
			if (r_error) {
				*r_error = "IsrSweep: another engine instance is running with a different renderer; stop it first.";
			}
			return nullptr;
		}
		return running->get_rendering_server();
	}
	String error;
	const bool ok = p_compositor ? p_own.start_with_compositor(p_compositor, &error) : p_own.start(p_backend, &error, 64);
	if (!ok) {
		if (r_error) {
			*r_error = "IsrSweep: " + error;
		}
		return nullptr;
	}
	return p_own.get_rendering_server();
}

// Draws frame p_frame of p_scene at p_width x p_height through a RenderingServer of p_backend (see
// _isr_server); p_draw reads the images off the view and returns whether they are whole. On failure
// r_error says what failed (p_renderer names the renderer).
template <class F>
static bool _isr_render(const IsrScene &p_scene, int p_frame, int p_width, int p_height, GodotInstance::Backend p_backend, RendererCompositor *p_compositor, const char *p_renderer, IsrImages &r_images, String *r_error, F p_draw) {
	r_images.width = p_width;
	r_images.height = p_height;
	GodotInstance own;
	RenderingServer *rs = _isr_server(own, p_backend, p_compositor, r_error);
	if (!rs) {
		return false;
	}
	IsrServerScene view;
	bool ok = view.create(rs, p_scene, p_width, p_height);
	if (ok) {
		view.set_frame(p_frame);
		ok = p_draw(view);
	}
	view.free();
	if (!ok && r_error) {
		*r_error = vformat("IsrSweep: the %s failed to render the frame.", p_renderer);
	}
	return ok;
}

bool IsrSweep::render_gpu(const IsrScene &p_scene, int p_frame, int p_width, int p_height, const ScreenSpaceLightingSettings &p_settings, IsrImages &r_images, String *r_error) {
	const size_t pixels = size_t(p_width) * p_height * 4;
	return _isr_render(p_scene, p_frame, p_width, p_height, GodotInstance::BACKEND_RD, nullptr, "Forward+ renderer", r_images, r_error, [&](IsrServerScene &p_view) {
		ScreenSpaceLightingSettings off = p_settings;
		off.ssil_enabled = false;
		p_view.set_screen_space_lighting(off);
		r_images.direct = p_view.draw().get_data();
		p_view.set_screen_space_lighting(p_settings);
		r_images.isr = p_view.draw().get_data();
		return r_images.direct.size() == pixels && r_images.isr.size() == pixels;
	});
}

bool IsrSweep::render_truth(const IsrScene &p_scene, int p_frame, int p_width, int p_height, const ReferenceRenderOptions &p_options, IsrImages &r_images, String *r_error) {
	const size_t pixels = size_t(p_width) * p_height * 4;
	return _isr_render(p_scene, p_frame, p_width, p_height, GodotInstance::BACKEND_CUSTOM, new RendererCompositorReference(p_options), "Embree reference", r_images, r_error, [&](IsrServerScene &p_view) {
		r_images.truth = p_view.draw().get_data();
		return r_images.truth.size() == pixels;
	});
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
