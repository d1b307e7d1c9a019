/**************************************************************************/
/*  sky.h                                                                 */
/**************************************************************************/
/* godot-area: Sky (Godot 4's resource: sky_material, process_mode,       */
/* radiance_size), owning one RS sky RID. ProceduralSkyMaterial and      */
/* PhysicalSkyMaterial are drawn (other materials are refused with an     */
/* error); process_mode is stored (the sky is recomputed only when it     */
/* changes, as Godot's automatic mode does for a static sky).             */

#pragma once

#include "core/io/resource.h"
#include "scene/resources/sky_material.h"
#include "servers/rendering_server.h"

class Sky : public Resource {
	GDCLASS(Sky, Resource);

public:
	enum RadianceSize { // Godot's values: 32 .. 2048 pixels.
		RADIANCE_SIZE_32,
		RADIANCE_SIZE_64,
		RADIANCE_SIZE_128,
		RADIANCE_SIZE_256,
		RADIANCE_SIZE_512,
		RADIANCE_SIZE_1024,
		RADIANCE_SIZE_2048,
		RADIANCE_SIZE_MAX
	};
	enum ProcessMode {
		PROCESS_MODE_AUTOMATIC,
		PROCESS_MODE_QUALITY,
		PROCESS_MODE_INCREMENTAL,
		PROCESS_MODE_REALTIME,
		PROCESS_MODE_MAX
	};

private:
	RID sky;
	Ref<Resource> sky_material; // A ProceduralSkyMaterial or a PhysicalSkyMaterial.
	RadianceSize radiance_size = RADIANCE_SIZE_256;
	ProcessMode process_mode = PROCESS_MODE_AUTOMATIC;

protected:
	static void _bind_methods();

public:
	RID get_rid() const override { return sky; }
	void set_material(const Ref<Resource> &p_material);
	Ref<Resource> get_material() const { return sky_material; }
	void set_radiance_size(RadianceSize p_size);
	RadianceSize get_radiance_size() const { return radiance_size; }
	void set_process_mode(ProcessMode p_mode);
	ProcessMode get_process_mode() const { return process_mode; }

	Sky();
	~Sky() override;
};

VARIANT_ENUM_CAST(Sky::RadianceSize);
VARIANT_ENUM_CAST(Sky::ProcessMode);
