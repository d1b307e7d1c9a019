/**************************************************************************/
/*  light_storage.h                                                       */
/**************************************************************************/
/* godot-area: CPU-only light storage (like Godot's dummy rasterizer),    */
/* used by the server when no GPU backend is plugged in, and by tests.    */
/* The light record and its setters/getters live in LightStorageCommon.   */

#pragma once

#include "servers/rendering/storage/light_storage_common.h"

namespace RendererDummy {

class LightStorage : public LightStorageCommon {
public:
	LightStorage() :
			LightStorageCommon("Light", RS::LIGHT_OMNI_SHADOW_DUAL_PARABOLOID) {}
};

} // namespace RendererDummy
