/**************************************************************************/
/*  mesh_instance_3d.cpp                                                  */
/**************************************************************************/

#include "scene/3d/mesh_instance_3d.h"

#include "core/error/error_macros.h"
#include "servers/rendering_server.h"

#include <cstdlib>
#include <cstring>

static const char *SURFACE_OVERRIDE_PREFIX = "surface_material_override/";

void MeshInstance3D::set_mesh(const Ref<Mesh> &p_mesh) {
	mesh = p_mesh;
	// Resize, not clear: a scene file may set surface_material_override/<i> before `mesh`.
	surface_override_materials.resize(mesh.is_valid() ? mesh->get_surface_count() : 0);
	set_base(mesh.is_valid() ? mesh->get_rid() : RID());
	_update_material_override();
	notify_property_list_changed();
}

void MeshInstance3D::set_surface_override_material(int p_surface, const Ref<Material> &p_material) {
	ERR_FAIL_INDEX_MSG(p_surface, (int)surface_override_materials.size(), vformat("MeshInstance3D \"%s\": surface %d does not exist (the mesh has %d surfaces).", get_name().c_str(), p_surface, (int)surface_override_materials.size()));
	surface_override_materials[p_surface] = p_material;
	_update_material_override();
}

Ref<Material> MeshInstance3D::get_surface_override_material(int p_surface) const {
	ERR_FAIL_INDEX_V_MSG(p_surface, (int)surface_override_materials.size(), Ref<Material>(), vformat("MeshInstance3D \"%s\": surface %d does not exist (the mesh has %d surfaces).", get_name().c_str(), p_surface, (int)surface_override_materials.size()));
	return surface_override_materials[p_surface];
}

Ref<Material> MeshInstance3D::get_active_material(int p_surface) const {
	if (get_material_override().is_valid()) {
		return get_material_override();
	}
	if (p_surface >= 0 && p_surface < (int)surface_override_materials.size() && surface_override_materials[p_surface].is_valid()) {
		return surface_override_materials[p_surface];
	}
	if (mesh.is_valid() && p_surface >= 0 && p_surface < mesh->get_surface_count()) {
		return mesh->surface_get_material(p_surface);
	}
	return Ref<Material>();
}

void MeshInstance3D::_update_material_override() {
	RS *rs = RS::get_singleton();
	if (!rs || !get_instance().is_valid()) {
		return;
	}
	Ref<Material> effective = get_material_override();
	if (effective.is_null() && surface_override_materials.size() == 1) {
		effective = surface_override_materials[0];
	} else if (effective.is_null() && surface_override_materials.size() > 1) {
		for (const Ref<Material> &m : surface_override_materials) {
			if (m.is_valid()) {
				WARN_PRINT_ONCE("surface_material_override on a mesh with several surfaces is not supported by the RenderingServer yet; it is stored but not drawn.");
				break;
			}
		}
	}
	rs->instance_geometry_set_material_override(get_instance(), effective.is_valid() ? effective->get_rid() : RID());
}

AABB MeshInstance3D::get_aabb() const {
	return mesh.is_valid() ? mesh->get_aabb() : AABB();
}

bool MeshInstance3D::_set(const String &p_name, const Variant &p_value) {
	if (!string_begins_with(p_name, SURFACE_OVERRIDE_PREFIX)) {
		return false;
	}
	String index_text = p_name.substr(strlen(SURFACE_OVERRIDE_PREFIX));
	char *end = nullptr;
	long index = std::strtol(index_text.c_str(), &end, 10);
	if (index_text.empty() || *end != '\0' || index < 0) {
		return false;
	}
	if (index >= (long)surface_override_materials.size()) {
		// Scene files may list overrides before the mesh is known in odd orders; grow to fit.
		ERR_FAIL_COND_V_MSG(index >= 256, false, vformat("%s: surface index %ld is too large.", p_name.c_str(), index));
		surface_override_materials.resize(index + 1);
	}
	surface_override_materials[index] = Ref<Material>(p_value);
	_update_material_override();
	return true;
}

bool MeshInstance3D::_get(const String &p_name, Variant &r_ret) const {
	if (!string_begins_with(p_name, SURFACE_OVERRIDE_PREFIX)) {
		return false;
	}
	String index_text = p_name.substr(strlen(SURFACE_OVERRIDE_PREFIX));
	char *end = nullptr;
	long index = std::strtol(index_text.c_str(), &end, 10);
	if (index_text.empty() || *end != '\0' || index < 0 || index >= (long)surface_override_materials.size()) {
		return false;
	}
	r_ret = surface_override_materials[index];
	return true;
}

void MeshInstance3D::_get_property_list(std::vector<PropertyInfo> *r_list) const {
	for (size_t i = 0; i < surface_override_materials.size(); i++) {
		r_list->push_back(PropertyInfo(Variant::OBJECT, SURFACE_OVERRIDE_PREFIX + itos(i), PROPERTY_HINT_RESOURCE_TYPE, "BaseMaterial3D,ShaderMaterial", PROPERTY_USAGE_DEFAULT, "Material"));
	}
}

void MeshInstance3D::_bind_methods() {
	ClassDB::bind_method(D_METHOD("set_mesh", "mesh"), &MeshInstance3D::set_mesh);
	ClassDB::bind_method(D_METHOD("get_mesh"), &MeshInstance3D::get_mesh);
	ClassDB::bind_method(D_METHOD("get_surface_override_material_count"), &MeshInstance3D::get_surface_override_material_count);
	ClassDB::bind_method(D_METHOD("set_surface_override_material", "surface", "material"), &MeshInstance3D::set_surface_override_material);
	ClassDB::bind_method(D_METHOD("get_surface_override_material", "surface"), &MeshInstance3D::get_surface_override_material);
	ClassDB::bind_method(D_METHOD("get_active_material", "surface"), &MeshInstance3D::get_active_material);

	ADD_PROPERTY(PropertyInfo(Variant::OBJECT, "mesh", PROPERTY_HINT_RESOURCE_TYPE, "Mesh"), "set_mesh", "get_mesh");
}
