/**************************************************************************/
/*  sky_material.h                                                        */
/**************************************************************************/
/* godot-area: ProceduralSkyMaterial with Godot 4's properties, groups    */
/* and defaults (sky_top_color ... use_debanding, energy_multiplier). It  */
/* owns one RS sky material RID and pushes RS::ProceduralSkyParams as a   */
/* whole from every setter. The formula it describes is in               */
/* servers/rendering/sky_model.h. sky_cover / sky_cover_modulate are     */
/* stored only (no cloud texture is drawn; a set cover is warned about). */
/* Godot derives sky materials from Material; here they are Resources of */
/* their own (no mesh material to own). PhysicalSkyMaterial (Godot 4's    */
/* properties and defaults) pushes RS::PhysicalSkyParams; its formula     */
/* (Preetham et al. 1999 as Godot documents it) is in sky_model.h.        */

#pragma once

#include "core/io/resource.h"
#include "scene/resources/texture.h"
#include "servers/rendering_server.h"

class ProceduralSkyMaterial : public Resource {
	GDCLASS(ProceduralSkyMaterial, Resource);

	RID material;
	RS::ProceduralSkyParams params;
	Ref<Texture2D> sky_cover;
	Color sky_cover_modulate = Color(1, 1, 1, 1);
	bool use_debanding = true;

	void _push();
	bool _check(float p_value, float p_min, float p_max, const char *p_property);

protected:
	static void _bind_methods();

public:
	RID get_rid() const override { return material; }
	const RS::ProceduralSkyParams &get_params() const { return params; }

	void set_sky_top_color(const Color &p_color);
	Color get_sky_top_color() const { return params.sky_top_color; }
	void set_sky_horizon_color(const Color &p_color);
	Color get_sky_horizon_color() const { return params.sky_horizon_color; }
	void set_sky_curve(float p_curve); // 0..1
	float get_sky_curve() const { return params.sky_curve; }
	void set_sky_energy_multiplier(float p_energy); // >= 0
	float get_sky_energy_multiplier() const { return params.sky_energy_multiplier; }
	void set_sky_cover(const Ref<Texture2D> &p_cover);
	Ref<Texture2D> get_sky_cover() const { return sky_cover; }
	void set_sky_cover_modulate(const Color &p_color);
	Color get_sky_cover_modulate() const { return sky_cover_modulate; }
	void set_ground_bottom_color(const Color &p_color);
	Color get_ground_bottom_color() const { return params.ground_bottom_color; }
	void set_ground_horizon_color(const Color &p_color);
	Color get_ground_horizon_color() const { return params.ground_horizon_color; }
	void set_ground_curve(float p_curve); // 0..1
	float get_ground_curve() const { return params.ground_curve; }
	void set_ground_energy_multiplier(float p_energy); // >= 0
	float get_ground_energy_multiplier() const { return params.ground_energy_multiplier; }
	void set_sun_angle_max(float p_degrees); // 0..360
	float get_sun_angle_max() const { return params.sun_angle_max; }
	void set_sun_curve(float p_curve); // 0..1
	float get_sun_curve() const { return params.sun_curve; }
	void set_use_debanding(bool p_enable);
	bool get_use_debanding() const { return use_debanding; }
	void set_energy_multiplier(float p_energy); // >= 0
	float get_energy_multiplier() const { return params.energy_multiplier; }

	ProceduralSkyMaterial();
	~ProceduralSkyMaterial() override;
};

class PhysicalSkyMaterial : public Resource {
	GDCLASS(PhysicalSkyMaterial, Resource);

	RID material;
	RS::PhysicalSkyParams params;
	Ref<Texture2D> night_sky;

	void _push();
	bool _check(float p_value, float p_min, float p_max, const char *p_property);

protected:
	static void _bind_methods();

public:
	RID get_rid() const override { return material; }
	const RS::PhysicalSkyParams &get_params() const { return params; }

	void set_rayleigh_coefficient(float p_value); // 0..64
	float get_rayleigh_coefficient() const { return params.rayleigh_coefficient; }
	void set_rayleigh_color(const Color &p_color);
	Color get_rayleigh_color() const { return params.rayleigh_color; }
	void set_mie_coefficient(float p_value); // 0..1
	float get_mie_coefficient() const { return params.mie_coefficient; }
	void set_mie_eccentricity(float p_value); // -1..1
	float get_mie_eccentricity() const { return params.mie_eccentricity; }
	void set_mie_color(const Color &p_color);
	Color get_mie_color() const { return params.mie_color; }
	void set_turbidity(float p_value); // 0..1000
	float get_turbidity() const { return params.turbidity; }
	void set_sun_disk_scale(float p_value); // 0..360
	float get_sun_disk_scale() const { return params.sun_disk_scale; }
	void set_ground_color(const Color &p_color);
	Color get_ground_color() const { return params.ground_color; }
	void set_energy_multiplier(float p_value); // 0..128
	float get_energy_multiplier() const { return params.energy_multiplier; }
	void set_use_debanding(bool p_enable);
	bool get_use_debanding() const { return params.use_debanding; }
	void set_night_sky(const Ref<Texture2D> &p_night_sky);
	Ref<Texture2D> get_night_sky() const { return night_sky; }

	PhysicalSkyMaterial();
	~PhysicalSkyMaterial() override;
};
