/**************************************************************************/
/*  scene_forward_clustered.glsl                                          */
/**************************************************************************/
/* The Forward+ scene shader (Godot's scene_forward_clustered.glsl,       */
/* reduced to our built-in material). Variants (C++:                      */
/* RenderForwardClustered::SceneShaderVariant):                           */
/*   0 "" : colour pass, writes linear HDR radiance to location 0;        */
/*   1 MODE_DEPTH : depth pre-pass, no colour output;                     */
/*   2 USE_AREA_LIGHTS : colour pass with area lights, used only when the */
/*     view has area lights; compiled per version with the AREA_METHOD_*  */
/*     defines of the methods in use (area_light_inc.glsl dispatches) and */
/*     AREA_SHADOWS_PCF / _PCSS only when some light has area shadows.    */
/*   3, 4 MODE_FORCE_ALL_LIGHTS (without / with USE_AREA_LIGHTS): the     */
/*     brute-force reference loops (RS::set_debug_force_all_lights);      */
/*   5, 6 MODE_DEBUG_CLUSTER (same): the cluster debug views.             */
/*   The production variants 0 and 2 carry neither.                       */
/* Any colour variant may carry USE_DIRECTIONAL_LIGHTS (a version of a   */
/* view with a DirectionalLight3D: binding 8 and the directional loop,   */
/* scene_forward_directional_inc.glsl); without it there is no sun code.*/
/* USE_DIRECTIONAL_SHADOWS (with it): the sun shadow lookup, bindings 16-19. */
/* USE_SKY_AMBIENT adds the sky's irradiance SH (binding 9, SkyRD).       */
/* USE_SKY_REFLECTION adds the sky's prefiltered radiance to specular    */
/* (bindings 20-21, SkyRD) times the split-sum DFG fit (brdf_inc.glsl).   */
/* USE_SS_RADIOSITY (SSIL/SSAO on, effects/ss_radiosity_rd.h) also writes */
/* location 1 the view normal, 2 the diffuse albedo albedo * (1 -         */
/* metallic), 3 the ambient part of the colour (image-space radiosity     */
/* inputs; zero albedo and ambient for unshaded and debug pixels).        */
/* Output of the colour pass, per pixel: emission + ambient * albedo *    */
/* (1 - metallic) + sum over lights of (diffuse * albedo * (1 - metallic) */
/* + specular); see scene_forward_lights_inc.glsl for light units.        */

#[vertex]

#version 450

#include "scene_forward_clustered_inc.glsl"

layout(location = 0) in vec3 vertex_attrib; // Object space.
layout(location = 1) in vec3 normal_attrib;
layout(location = 2) in vec4 tangent_attrib; // xyz, w = binormal sign.
layout(location = 3) in vec2 uv_attrib;
layout(location = 4) in vec4 color_attrib; // ARRAY_COLOR (white without one).

// Both variants compute gl_Position with identical code; precise (no FMA contraction or reassociation)
// makes the depth pre-pass and the colour pass produce bit-identical depths, so the colour pass can
// test with LESS_OR_EQUAL safely. ("invariant gl_Position" does the same in GLSL but SPIR-V puts the
// decoration on a gl_PerVertex member, which the validation layer warns about.)
precise gl_Position;

#ifndef MODE_DEPTH
layout(location = 0) out vec3 vertex_interp; // View space.
layout(location = 1) out vec3 normal_interp; // View space.
layout(location = 2) out vec3 tangent_interp; // View space.
layout(location = 3) out vec3 binormal_interp; // View space.
layout(location = 4) out vec2 uv_interp;
layout(location = 5) out vec4 color_interp;
#endif

void main() {
	vec4 world_pos = draw.world_from_model * vec4(vertex_attrib, 1.0);
	vec4 view_pos = scene_data.view_from_world * world_pos;
	gl_Position = scene_data.clip_from_view * view_pos;

#ifndef MODE_DEPTH
	mat3 normal_matrix = mat3(draw.normal_matrix[0].xyz, draw.normal_matrix[1].xyz, draw.normal_matrix[2].xyz);
	mat3 view_basis = mat3(scene_data.view_from_world);
	vertex_interp = view_pos.xyz;
	normal_interp = view_basis * (normal_matrix * normal_attrib);
	vec3 tangent_world = mat3(draw.world_from_model) * tangent_attrib.xyz;
	tangent_interp = view_basis * tangent_world;
	binormal_interp = cross(normal_interp, tangent_interp) * (tangent_attrib.w < 0.0 ? -1.0 : 1.0);
	uv_interp = uv_attrib;
	color_interp = (draw.flags & DRAW_FLAG_HAS_COLOR) != 0u ? color_attrib : vec4(1.0);
#endif
}

#[fragment]

#version 450

#include "scene_forward_clustered_inc.glsl"

#ifndef MODE_DEPTH

#include "../brdf_inc.glsl"
#include "../scene_forward_lights_inc.glsl"
#ifdef USE_DIRECTIONAL_LIGHTS
#include "../scene_forward_directional_inc.glsl"
#endif
#ifdef USE_AREA_LIGHTS
#include "../area_light_inc.glsl"
#if defined(AREA_SHADOWS_PCF) || defined(AREA_SHADOWS_PCSS)
#include "../area_light_shadow_inc.glsl"
#else
// No area light of this view has shadow maps (the version key of RenderForwardClustered): visibility 1
// without any shadow code. A software rasterizer (llvmpipe) runs untaken branches too, so a compiled-in
// lookup would cost every pixel of every area light even when no light casts area shadows.
float light_process_area_shadow(uint p_light_index, vec3 p_vertex, vec3 p_normal) {
	return 1.0;
}
#endif
#endif

layout(location = 0) in vec3 vertex_interp;
layout(location = 1) in vec3 normal_interp;
layout(location = 2) in vec3 tangent_interp;
layout(location = 3) in vec3 binormal_interp;
layout(location = 4) in vec2 uv_interp;
layout(location = 5) in vec4 color_interp;

layout(location = 0) out vec4 frag_color;
#ifdef USE_SS_RADIOSITY
layout(location = 1) out vec4 ss_normal_out; // View normal (xyz), w = 1.
layout(location = 2) out vec4 ss_albedo_out; // Diffuse albedo rho (rgb).
layout(location = 3) out vec4 ss_ambient_out; // Ambient part of frag_color (rgb).
#endif

vec3 srgb_to_linear(vec3 p_c) {
	return mix(pow((p_c + vec3(0.055)) * (1.0 / 1.055), vec3(2.4)), p_c * (1.0 / 12.92), lessThan(p_c, vec3(0.04045)));
}

#endif

void main() {
#ifndef MODE_DEPTH
#ifdef USE_SS_RADIOSITY
	// Defaults for the early returns (unshaded, debug): the pixel emits but receives nothing.
	ss_normal_out = vec4(normalize(normal_interp) * (gl_FrontFacing ? 1.0 : -1.0), 1.0);
	ss_albedo_out = vec4(0.0);
	ss_ambient_out = vec4(0.0);
#endif
#ifdef MODE_DEBUG_CLUSTER
	// Only in the debug variants (a software rasterizer runs untaken branches, so the production variants
	// carry no debug code). The flag stays a run-time test so every variant uses the same bindings.
	if ((scene_data.flags & SCENE_FLAG_DEBUG_CLUSTER) != 0u) {
		// Debug view (RS::VIEWPORT_DEBUG_DRAW_CLUSTER_*): how many elements of one type the cluster of
		// this fragment lists, written to every colour channel.
		uvec2 dtile = uvec2(gl_FragCoord.xy) / scene_data.cluster_tile_size;
		uint dslice = cluster_get_slice(-vertex_interp.z, scene_data.z_far);
		uint doffset = cluster_get_offset(min(scene_data.debug_cluster_type, uint(CLUSTER_ELEMENT_TYPE_MAX - 1)), dtile, dslice, scene_data.cluster_tiles_x, scene_data.cluster_tile_count, scene_data.cluster_words_per_type);
		uint dtype = min(scene_data.debug_cluster_type, uint(CLUSTER_ELEMENT_TYPE_MAX - 1));
		uint dlive = dtype == uint(CLUSTER_ELEMENT_TYPE_OMNI) ? scene_data.omni_light_count : (dtype == uint(CLUSTER_ELEMENT_TYPE_SPOT) ? scene_data.spot_light_count : scene_data.area_light_count);
		uint dwords = min(scene_data.cluster_words_per_type, (dlive + 31u) / 32u); // Only live words are built.
		uint dcount = 0u;
		for (uint w = 0u; w < dwords; w++) {
			dcount += uint(bitCount(cluster_buffer.data[doffset + w]));
		}
		// Green, area lights only: how many of them light this fragment (unshadowed result > 0), so the
		// clusters' overhead (listed / lit pairs, bench --targets P5) can be counted on the image.
		float dlit = 0.0;
#ifdef USE_AREA_LIGHTS
		if (scene_data.debug_cluster_type == uint(CLUSTER_ELEMENT_TYPE_AREA)) {
			vec3 dN = normalize(normal_interp) * (gl_FrontFacing ? 1.0 : -1.0);
			vec3 dV = scene_data.clip_from_view[3][3] == 1.0 ? vec3(0.0, 0.0, 1.0) : normalize(-vertex_interp);
			for (uint w = 0u; w < dwords; w++) {
				uint mask = cluster_buffer.data[doffset + w];
				while (mask != 0u) {
					uint bit = uint(findLSB(mask));
					mask &= ~(1u << bit);
					uint i = w * 32u + bit;
					if (i >= scene_data.area_light_count) {
						continue;
					}
					vec3 dd = vec3(0.0), ds = vec3(0.0);
					light_process_area_method(area_lights.data[i], vertex_interp, dN, dV, material.diffuse_mode, clamp(material.roughness, 0.0, 1.0), vec3(0.04), 1.0, true, dd, ds);
					dlit += (max(max(dd.r, dd.g), dd.b) + max(max(ds.r, ds.g), ds.b)) > 0.0 ? 1.0 : 0.0;
				}
			}
		}
#endif
		frag_color = vec4(float(dcount), dlit, float(dcount), 1.0);
		return;
	}
#endif

	// uv1_scale and uv1_offset (Godot applies them in the vertex shader; the same for a linear map).
	vec2 uv = uv_interp * material.uv1.xy + material.uv1.zw;
	vec3 albedo = material.albedo.rgb;
	float alpha = material.albedo.a;
	if ((material.flags & MATERIAL_FLAG_ALBEDO_TEXTURE) != 0u) {
		vec4 texel = texture(sampler2D(albedo_texture, material_texture_sampler), uv);
		albedo *= srgb_to_linear(texel.rgb);
		alpha *= texel.a;
	}
	if ((material.flags & MATERIAL_FLAG_VERTEX_COLOR) != 0u) {
		// Godot: albedo_tex *= COLOR (vertex_color_is_srgb decodes COLOR.rgb first).
		albedo *= (material.flags & MATERIAL_FLAG_VERTEX_COLOR_SRGB) != 0u ? srgb_to_linear(color_interp.rgb) : color_interp.rgb;
		alpha *= color_interp.a;
	}

	if ((material.flags & MATERIAL_FLAG_UNSHADED) != 0u) {
		if ((material.flags & MATERIAL_FLAG_ALPHA_SCISSOR) != 0u && alpha < material.alpha_scissor_threshold) {
			discard; // Godot's ALPHA_SCISSOR_THRESHOLD.
		}
		frag_color = vec4(albedo, alpha);
		return;
	}

	vec3 vertex = vertex_interp;
	vec3 V = normalize(-vertex); // Perspective: towards the eye at the origin of view space.
	if (scene_data.clip_from_view[3][3] == 1.0) {
		V = vec3(0.0, 0.0, 1.0); // Orthogonal projection: parallel view rays.
	}
	vec3 N = normalize(normal_interp);
	if (!gl_FrontFacing) {
		N = -N; // Two-sided materials shade their back faces with the flipped normal.
	}
	if ((material.flags & MATERIAL_FLAG_NORMAL_MAP) != 0u) {
		vec3 T = normalize(tangent_interp - N * dot(N, tangent_interp));
		vec3 B = normalize(binormal_interp);
		vec3 nm = texture(sampler2D(normal_texture, material_texture_sampler), uv).xyz * 2.0 - 1.0;
		nm.xy *= material.normal_scale;
		N = normalize(T * nm.x + B * nm.y + N * max(nm.z, 1e-4));
	}

	// Godot: ROUGHNESS = roughness * dot(texel, channel), the same for METALLIC.
	float roughness = material.roughness;
	if ((material.flags & MATERIAL_FLAG_ROUGHNESS_TEXTURE) != 0u) {
		roughness *= dot(texture(sampler2D(roughness_texture, material_texture_sampler), uv), material.roughness_channel);
	}
	float metallic = material.metallic;
	if ((material.flags & MATERIAL_FLAG_METALLIC_TEXTURE) != 0u) {
		metallic *= dot(texture(sampler2D(metallic_texture, material_texture_sampler), uv), material.metallic_channel);
	}
	roughness = clamp(roughness, 0.0, 1.0);
	metallic = clamp(metallic, 0.0, 1.0);
	// Alpha scissor after the last texture read (derivatives stay defined for the whole quad).
	if ((material.flags & MATERIAL_FLAG_ALPHA_SCISSOR) != 0u && alpha < material.alpha_scissor_threshold) {
		discard;
	}
	// Godot's f0: dielectrics reflect 0.16 * specular^2 (0.5 -> 4 %), metals their albedo.
	float dielectric = 0.16 * material.specular * material.specular;
	vec3 f0 = dielectric * (1.0 - metallic) + albedo * metallic;
	float f90 = brdf_specular_f90(f0, metallic);
	bool specular_enabled = (material.flags & MATERIAL_FLAG_SPECULAR_DISABLED) == 0u;
	uint diffuse_mode = material.diffuse_mode;

	vec3 diffuse_light = vec3(0.0);
	vec3 specular_light = vec3(0.0);
#if defined(USE_AREA_LIGHTS) && defined(AREA_LIGHT_TEXTURE)
	area_texture_diffuse_albedo = dot(albedo, vec3(1.0 / 3.0)) * (1.0 - metallic); // Weighs the LTC's texture fetch.
#endif

#ifdef MODE_FORCE_ALL_LIGHTS
	if ((scene_data.flags & SCENE_FLAG_FORCE_ALL_LIGHTS) != 0u) {
		// Brute force reference: every light, in index order (same order as the clustered walk, so the
		// sums are bit-identical when clustering drops only lights that contribute exactly 0).
		for (uint i = 0u; i < scene_data.omni_light_count; i++) {
			if ((omni_lights.data[i].cull_mask & draw.layer_mask) == 0u) {
				continue;
			}
			light_process_omni(omni_lights.data[i], vertex, N, V, diffuse_mode, roughness, f0, f90, specular_enabled, diffuse_light, specular_light);
		}
		for (uint i = 0u; i < scene_data.spot_light_count; i++) {
			if ((spot_lights.data[i].cull_mask & draw.layer_mask) == 0u) {
				continue;
			}
			light_process_spot(spot_lights.data[i], vertex, N, V, diffuse_mode, roughness, f0, f90, specular_enabled, diffuse_light, specular_light);
		}
#ifdef USE_AREA_LIGHTS
		for (uint i = 0u; i < scene_data.area_light_count; i++) {
			if ((area_lights.data[i].cull_mask & draw.layer_mask) == 0u) {
				continue;
			}
			vec3 area_diffuse = vec3(0.0), area_specular = vec3(0.0);
			light_process_area_method(area_lights.data[i], vertex, N, V, diffuse_mode, roughness, f0, f90, specular_enabled, area_diffuse, area_specular);
			float area_shadow = light_process_area_shadow(i, vertex, N); // Area soft shadows (area_light_shadow_inc.glsl).
			diffuse_light += area_diffuse * area_shadow;
			specular_light += area_specular * area_shadow;
		}
#endif
	} else
#endif // MODE_FORCE_ALL_LIGHTS
	{
		uvec2 tile = uvec2(gl_FragCoord.xy) / scene_data.cluster_tile_size;
		uint slice = cluster_get_slice(-vertex.z, scene_data.z_far);
		uint words = scene_data.cluster_words_per_type;
		// Each type's loop walks only the mask words that can hold a live light of that type: a SIMD
		// rasterizer runs the loop body once per word for the whole pixel group, so walking all of the
		// capacity's words (16 at 512 lights) costs every pixel even where no light of the type exists.

		uint omni_offset = cluster_get_offset(CLUSTER_ELEMENT_TYPE_OMNI, tile, slice, scene_data.cluster_tiles_x, scene_data.cluster_tile_count, words);
		uint omni_words = min(words, (scene_data.omni_light_count + 31u) / 32u);
		for (uint w = 0u; w < omni_words; w++) {
			uint mask = cluster_buffer.data[omni_offset + w];
			while (mask != 0u) {
				uint bit = uint(findLSB(mask));
				mask &= ~(1u << bit);
				uint i = w * 32u + bit;
				if (i >= scene_data.omni_light_count || (omni_lights.data[i].cull_mask & draw.layer_mask) == 0u) {
					continue;
				}
				light_process_omni(omni_lights.data[i], vertex, N, V, diffuse_mode, roughness, f0, f90, specular_enabled, diffuse_light, specular_light);
			}
		}

		uint spot_offset = cluster_get_offset(CLUSTER_ELEMENT_TYPE_SPOT, tile, slice, scene_data.cluster_tiles_x, scene_data.cluster_tile_count, words);
		uint spot_words = min(words, (scene_data.spot_light_count + 31u) / 32u);
		for (uint w = 0u; w < spot_words; w++) {
			uint mask = cluster_buffer.data[spot_offset + w];
			while (mask != 0u) {
				uint bit = uint(findLSB(mask));
				mask &= ~(1u << bit);
				uint i = w * 32u + bit;
				if (i >= scene_data.spot_light_count || (spot_lights.data[i].cull_mask & draw.layer_mask) == 0u) {
					continue;
				}
				light_process_spot(spot_lights.data[i], vertex, N, V, diffuse_mode, roughness, f0, f90, specular_enabled, diffuse_light, specular_light);
			}
		}

#ifdef USE_AREA_LIGHTS
		// Thesis Listing A.3: the area lights of this cluster.
		uint area_offset = cluster_get_offset(CLUSTER_ELEMENT_TYPE_AREA, tile, slice, scene_data.cluster_tiles_x, scene_data.cluster_tile_count, words);
		uint area_words = min(words, (scene_data.area_light_count + 31u) / 32u);
		for (uint w = 0u; w < area_words; w++) {
			uint mask = cluster_buffer.data[area_offset + w];
			while (mask != 0u) {
				uint bit = uint(findLSB(mask));
				mask &= ~(1u << bit);
				uint i = w * 32u + bit;
				if (i >= scene_data.area_light_count || (area_lights.data[i].cull_mask & draw.layer_mask) == 0u) {
					continue;
				}
				vec3 area_diffuse = vec3(0.0), area_specular = vec3(0.0);
				light_process_area_method(area_lights.data[i], vertex, N, V, diffuse_mode, roughness, f0, f90, specular_enabled, area_diffuse, area_specular);
				if (area_diffuse == vec3(0.0) && area_specular == vec3(0.0)) {
					continue; // Unlit here: no shadow lookup (it could only scale 0).
				}
				float area_shadow = light_process_area_shadow(i, vertex, N); // Area soft shadows (area_light_shadow_inc.glsl).
				diffuse_light += area_diffuse * area_shadow;
				specular_light += area_specular * area_shadow;
			}
		}
#endif
	}

#ifdef USE_DIRECTIONAL_LIGHTS
	// Directional lights: their own loop, outside the clustered walks (Godot's directional light list).
	for (uint i = 0u; i < directional_lights.count; i++) {
		if ((directional_lights.data[i].cull_mask & draw.layer_mask) == 0u) {
			continue;
		}
		float sun_shadow = 1.0;
#ifdef USE_DIRECTIONAL_SHADOWS
		if (directional_lights.data[i].shadow_index >= 0) { // Shadowed lights only (directional_shadow_rd.h).
			sun_shadow = directional_shadow_visibility(uint(directional_lights.data[i].shadow_index), vertex, N, -directional_lights.data[i].direction);
		}
#endif
		light_process_directional(directional_lights.data[i], N, V, diffuse_mode, roughness, f0, f90, specular_enabled, sun_shadow, diffuse_light, specular_light);
	}
#endif

	vec3 ambient_light = scene_data.ambient_light.rgb;
#ifdef USE_SKY_AMBIENT
	{
		// Sky irradiance at the world-space normal from 9 SH coefficients (servers/rendering/sky_model.h).
		vec3 n = normalize(mat3(scene_data.world_from_view) * N);
		ambient_light += sky_ambient.sh[0].rgb * 0.282095;
		ambient_light += sky_ambient.sh[1].rgb * (0.488603 * n.y) + sky_ambient.sh[2].rgb * (0.488603 * n.z) + sky_ambient.sh[3].rgb * (0.488603 * n.x);
		ambient_light += sky_ambient.sh[4].rgb * (1.092548 * n.x * n.y) + sky_ambient.sh[5].rgb * (1.092548 * n.y * n.z);
		ambient_light += sky_ambient.sh[6].rgb * (0.315392 * (3.0 * n.z * n.z - 1.0)) + sky_ambient.sh[7].rgb * (1.092548 * n.x * n.z);
		ambient_light += sky_ambient.sh[8].rgb * (0.546274 * (n.x * n.x - n.y * n.y));
		ambient_light = max(ambient_light, vec3(0.0)); // SH ringing must not make light negative.
	}
#endif
#ifdef USE_SKY_REFLECTION
	if (specular_enabled) {
		// Sky reflections as Godot 4: the reflection vector bent towards the normal by roughness^2 (the
		// dominant direction of a rough lobe), lod = sqrt(roughness) * (mips - 1), a horizon fade against
		// reflections from below the surface, times the environment BRDF.
		float NoV = clamp(dot(N, V), 1e-4, 1.0);
		vec3 n_world = normalize(mat3(scene_data.world_from_view) * N);
		vec3 r_world = normalize(mat3(scene_data.world_from_view) * reflect(-V, N));
		r_world = normalize(mix(r_world, n_world, roughness * roughness));
		float horizon = min(1.0 + dot(r_world, n_world), 1.0);
		float max_lod = float(textureQueryLevels(samplerCube(sky_radiance_texture, sky_radiance_sampler)) - 1);
		vec3 radiance = textureLod(samplerCube(sky_radiance_texture, sky_radiance_sampler), r_world, sqrt(roughness) * max_lod).rgb;
		specular_light += radiance * (horizon * horizon) * brdf_env_approx(f0, f90, NoV, roughness);
	}
#endif
	vec3 color = material.emission.rgb + (ambient_light + diffuse_light) * albedo * (1.0 - metallic) + specular_light;
	frag_color = vec4(color, alpha);
#ifdef USE_SS_RADIOSITY
	ss_normal_out = vec4(N, 1.0);
	ss_albedo_out = vec4(albedo * (1.0 - metallic), 1.0);
	ss_ambient_out = vec4(ambient_light * albedo * (1.0 - metallic), 1.0);
#endif
#endif
}
