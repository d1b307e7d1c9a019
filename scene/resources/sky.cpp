/**************************************************************************/
/*  sky.cpp                                                               */
/**************************************************************************/

#include "scene/resources/sky.h"

#include "core/error/error_macros.h"

void Sky::set_material(const Ref<Resource> &p_material) {
	ERR_FAIL_COND_MSG(p_material.is_valid() && !Object::cast_to<ProceduralSkyMaterial>(p_material.ptr()) && !Object::cast_to<PhysicalSkyMaterial>(p_material.ptr()),
			vformat("Sky: sky_material must be a ProceduralSkyMaterial or a PhysicalSkyMaterial; got %s. The old value is kept.", p_material->get_class().c_str()));
	sky_material = p_material;
	RS *rs = RS::get_singleton();
	if (rs && sky.is_valid()) {
		rs->sky_set_material(sky, p_material.is_valid() ? p_material->get_rid() : RID());
	}
	emit_changed();
}

void Sky::set_radiance_size(RadianceSize p_size) {
	ERR_FAIL_INDEX_MSG((int)p_size, RADIANCE_SIZE_MAX, vformat("Sky: radiance_size must be 0..%d (32..2048 pixels); got %d. The old value is kept.", RADIANCE_SIZE_MAX - 1, (int)p_size));
	radiance_size = p_size;
	RS *rs = RS::get_singleton();
	if (rs && sky.is_valid()) {
		rs->sky_set_radiance_size(sky, 32 << int(p_size));
	}
	emit_changed();
}

void Sky::set_process_mode(ProcessMode p_mode) {
	ERR_FAIL_INDEX_MSG((int)p_mode, PROCESS_MODE_MAX, vformat("Sky: process_mode must be 0..%d; got %d. The old value is kept.", PROCESS_MODE_MAX - 1, (int)p_mode));
	process_mode = p_mode;
	emit_changed();
}

void Sky::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_material", "material"), &Sky::set_material);
	ClassDB::bind_method(D_METHOD("get_material"), &Sky::get_material);
	ClassDB::bind_method(D_METHOD("set_radiance_size", "size"), &Sky::set_radiance_size);
	ClassDB::bind_method(D_METHOD("get_radiance_size"), &Sky::get_radiance_size);
	ClassDB::bind_method(D_METHOD("set_process_mode", "mode"), &Sky::set_process_mode);
	ClassDB::bind_method(D_METHOD("get_process_mode"), &Sky::get_process_mode);
	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "sky_material", PROPERTY_HINT_RESOURCE_TYPE, "ProceduralSkyMaterial,PhysicalSkyMaterial"), "set_material", "get_material");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "process_mode", PROPERTY_HINT_ENUM, "Automatic,High-Quality,High-Quality Incremental,Real-Time"), "set_process_mode", "get_process_mode");
	ADD_PROPERTY(PropertyInfo(Variant::INT, "radiance_size", PROPERTY_HINT_ENUM, "32,64,128,256,512,1024,2048"), "set_radiance_size", "get_radiance_size");
	BIND_ENUM_CONSTANT(RADIANCE_SIZE_32);
	BIND_ENUM_CONSTANT(RADIANCE_SIZE_64);
	BIND_ENUM_CONSTANT(RADIANCE_SIZE_128);
	BIND_ENUM_CONSTANT(RADIANCE_SIZE_256);
	BIND_ENUM_CONSTANT(RADIANCE_SIZE_512);
	BIND_ENUM_CONSTANT(RADIANCE_SIZE_1024);
	BIND_ENUM_CONSTANT(RADIANCE_SIZE_2048);
	BIND_ENUM_CONSTANT(PROCESS_MODE_AUTOMATIC);
	BIND_ENUM_CONSTANT(PROCESS_MODE_QUALITY);
	BIND_ENUM_CONSTANT(PROCESS_MODE_INCREMENTAL);
	BIND_ENUM_CONSTANT(PROCESS_MODE_REALTIME);
}

Sky::Sky() {
	RS *rs = RS::get_singleton();
	ERR_FAIL_NULL_MSG(rs, "Sky needs a RenderingServer; create one first.");
	sky = rs->sky_create();
	rs->sky_set_radiance_size(sky, 32 << int(radiance_size));
}

Sky::~Sky() {
	RS *rs = RS::get_singleton();
	if (rs && sky.is_valid()) {
		rs->free(sky);
	}
}
