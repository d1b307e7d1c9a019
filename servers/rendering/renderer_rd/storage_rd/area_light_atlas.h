/**************************************************************************/
/*  area_light_atlas.h                                                    */
/**************************************************************************/
/* godot-area: the area-light texture atlas (AreaLight3D.area_texture,    */
/* upstream Godot 4.7's separate atlas with prefiltered mip levels).      */
/*                                                                        */
/* Each texture becomes one SLOT: its linear, alpha-premultiplied colour  */
/* resampled to C x C texels (C = the project setting SETTING_SIZE) and   */
/* the prefiltered levels 0..log2(C), each upsampled back to C x C        */
/* (bilinear) and stored (half floats, RGBA16F) as the depth slices of a  */
/* 3D texture: slice L is level L. Slots stack vertically (atlas C x     */
/* rows * C x (log2(C) + 1), rows a power of two, grown on demand).       */
/* Half floats: the same error against the reference as floats, half the */
/* memory (and no faster on llvmpipe, doc/methods.md section 12).        */
/* A 3D texture instead of a mip chain: RenderingDevice uploads mip 0     */
/* only, and linear filtering along the depth blends two levels in ONE    */
/* fetch (the shader's cost).                                             */
/*                                                                        */
/* Prefilter (Heitz, Dupuy, Hill and Neubelt 2016, section 6: the texture */
/* is prefiltered with Gaussians so a fetch returns the average under the */
/* LTC footprint): level L is level 0 convolved with a Gaussian of        */
/* sigma_L = 2^L level-0 texels, built incrementally (level L-1 blurred   */
/* by sqrt(sigma_L^2 - sigma_(L-1)^2), then 2 x 2 box-downsampled).       */
/* A Gaussian, not a box pyramid: the projected cosine lobe the fetch     */
/* stands for is smooth and radially symmetric, and a box pyramid's       */
/* square footprint shows its texel grid in glossy reflections. The blur  */
/* is normalised (taps outside the slot are dropped and the weights       */
/* renormalised), so a constant texture stays exactly constant at every  */
/* level: a white texture shades exactly like no texture.                 */
/*                                                                        */
/* Cost model: nothing exists until a visible area light has a texture;   */
/* a slot is built (CPU prefilter) and the atlas uploaded only when the   */
/* set of textures changes, never per frame.                              */

#pragma once

#include "core/io/image.h"
#include "core/templates/rid.h"

#include <cstdint>
#include <map>
#include <vector>

namespace RendererRD {

class AreaLightAtlas {
public:
	/* Definition */

	// Texels per side of one texture's level 0 (a power of two, 16..2048).
	static constexpr const char *SETTING_SIZE = "rendering/lights_and_shadows/area_light_atlas/size";
	static constexpr uint32_t DEFAULT_SIZE = 256;
	static constexpr uint32_t MIN_SIZE = 16;
	static constexpr uint32_t MAX_SIZE = 2048;
	// The atlas height limit (Vulkan's guaranteed maxImageDimension2D is 4096; every desktop driver and
	// lavapipe give 16384, which we use): at most MAX_ATLAS_HEIGHT / C textures at once.
	static constexpr uint32_t MAX_ATLAS_HEIGHT = 16384;
	// Updates without a request after which an unused slot is released (a light leaving the view for a
	// moment does not rebuild its texture).
	static constexpr uint32_t KEEP_UNUSED_UPDATES = 120;

	// The setting's value (an invalid one is reported and DEFAULT_SIZE used).
	static uint32_t get_project_size();

	// Prefiltered levels 0..log2(p_size) of p_image (float RGBA texels, colour sRGB-encoded): linear rgb
	// times alpha, alpha kept; level L is p_size / 2^L texels per side.
	static std::vector<Image> build_levels(const Image &p_image, uint32_t p_size);
	// The Gaussian sigma of level p_level in level-0 texels (0 for level 0).
	static float get_level_sigma(uint32_t p_level) { return p_level == 0 ? 0.0f : float(1u << p_level); }
	// The levels packed as one slot: slice L (level L upsampled to C x C, bilinear between texel centres,
	// clamped at the edges) at floats [L * C * C * 4, (L + 1) * C * C * 4), rows top first.
	static std::vector<float> pack_slot(const std::vector<Image> &p_levels);

private:
	/* Private Members */

	struct Slot {
		RID source; // The material storage texture.
		uint32_t row = 0;
		uint32_t unused_updates = 0;
		bool used = false; // Requested in the current update.
		std::vector<float> texels; // pack_slot() (kept to rebuild the atlas when it grows).
	};

	uint32_t size = 0; // C of the current atlas (0 before the first texture).
	uint32_t rows = 0; // Atlas capacity in slots.
	std::map<uint64_t, Slot> slots; // By source RID id.
	bool dirty = false; // The atlas content changed in this update.
	uint32_t builds = 0; // Slots prefiltered so far (tests: uploads on change only).
	uint32_t uploads = 0; // Atlas uploads so far.
	uint32_t dropped = 0; // Textures of the last update that found no slot.
	uint32_t warned_dropped = 0;
	RID texture; // RGBA16F 3D, C x rows * C x (log2(C) + 1).
	RID sampler; // Linear, clamp to edge, no mipmaps.

	bool _find_free_row(uint32_t &r_row) const;
	void _rebuild_texture();

public:
	/* Public Methods */

	// Per LightStorage::update_light_buffers(): begin_update(), request() per textured light, end_update(),
	// then get_rect() per textured light (the rects change when the atlas grows).
	void begin_update();
	// Makes sure p_texture has a slot (built on first use). False when p_image is null/empty or no slot
	// is free (counted in the warning of end_update(); the light is drawn untextured).
	bool request(RID p_texture, const Image *p_image);
	// The uv rect (x, y, w, h) of p_texture's level 0 in the atlas; false (r_rect zero) without a slot.
	bool get_rect(RID p_texture, float r_rect[4]) const;
	// Releases slots unused for KEEP_UNUSED_UPDATES, and uploads the atlas when its content changed.
	// Records a texture update: call outside draw lists.
	void end_update();
	void finalize();

	bool is_allocated() const { return texture.is_valid(); }
	RID get_texture() const { return texture; }
	RID get_sampler() const { return sampler; }
	uint32_t get_slot_count() const { return uint32_t(slots.size()); }
	uint32_t get_build_count() const { return builds; }
	uint32_t get_upload_count() const { return uploads; }
	uint32_t get_dropped_count() const { return dropped; }
	uint32_t get_size() const { return size; }

	AreaLightAtlas() {}
	~AreaLightAtlas();
};

} // namespace RendererRD
